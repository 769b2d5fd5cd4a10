//! The budget's cost model: a frame's instructions as a sum of measured unit costs times
//! what the frame does, fitted per instruction set to the benchmark scenes.
//!
//! What a frame does ([`Counts`], from a host render of the scene: `scenes.csv` for the
//! benchmark scenes, `budget::render` for a model):
//!
//! * **frame pixels** (W x H): the clear of colour and depth, band by band or whole;
//! * **vertices** of the mesh: transformed (and lit) once, in the binning pass of a banded
//!   frame or in the whole frame's walk;
//! * **binned** screen triangles (after culling and clipping): clipped, projected and set
//!   up once (the walk past a culled triangle has no cost of its own: the benchmark
//!   scenes cannot tell it from the vertices' and binned triangles' costs, and with it
//!   the fit is singular);
//! * **pixels** written, at the per-pixel cost of the draw's mode (one unit cost per mode);
//! * in bands only: **bands** (each band's fixed cost), **band pieces** (a binned triangle
//!   in one band: with band ranges re-projected and set up again unless its set-up was
//!   kept; with bins its spans started again) and **range scans** (bands x mesh triangles:
//!   with band ranges each band looks at every triangle's range).
//!
//! The unit costs are found by least squares over the benchmark scenes, banded and whole
//! (`docs/mcu.md`, written by `cargo xtask mcu --docs`: the instructions of each frame are
//! its instructions per pixel times its pixels), with every cost kept at zero or above
//! (a cost that would come out negative is dropped and the rest refitted). A simple
//! pixels-plus-triangles line misses the meshes in bands by 30 to 60 %: the pieces and
//! range scans are what a banded mesh adds to the same frame drawn whole.

use std::collections::HashMap;

/// The draw modes the benchmark scenes measure, by their per-pixel cost.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mode {
    /// Lit (per-vertex intensity), bilinear, repeat, perspective exact every 64 pixels,
    /// depth-tested: the sphere, the teapot and the glTF models (`LitSphere`).
    LitBilinear,
    /// The cube's draw: lit per face, bilinear footprints, exact every 16 pixels.
    CubeFootprint,
    /// The floor's draw: nearest, unlit, exact every 64 pixels.
    FloorNearest,
}

impl Mode {
    const ALL: [Mode; 3] = [Mode::LitBilinear, Mode::CubeFootprint, Mode::FloorNearest];

    /// The mode's name in tables.
    pub fn name(self) -> &'static str {
        match self {
            Mode::LitBilinear => "lit bilinear (the model scenes' draw)",
            Mode::CubeFootprint => "lit per face, bilinear footprints (cube)",
            Mode::FloorNearest => "nearest, unlit (floor)",
        }
    }
}

/// How a banded frame keeps its geometry between bands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Binning {
    /// Screen triangles kept in bins (few triangles: cube, floor).
    Bins,
    /// A band range per mesh triangle, each re-projected in the bands it covers.
    Ranges,
}

/// What one frame does (the cost model's inputs).
#[derive(Clone, Debug, PartialEq)]
pub struct Counts {
    /// Scene or model name.
    pub scene: String,
    /// Its draw mode.
    pub mode: Mode,
    /// Bands or whole, and how the bands keep the geometry.
    pub binning: Binning,
    /// Frame width and height, pixels.
    pub size: (u32, u32),
    /// Rows per band.
    pub rows: u32,
    /// Mesh vertices.
    pub vertices: u64,
    /// Mesh triangles.
    pub triangles: u64,
    /// Screen triangles binned (after culling and clipping).
    pub binned: u64,
    /// Band pieces: binned triangles counted once per band they cross.
    pub pieces: u64,
    /// Pixels written.
    pub pixels: u64,
}

impl Counts {
    /// Bands of the frame.
    pub fn bands(&self) -> u64 {
        u64::from(self.size.1.div_ceil(self.rows.max(1)))
    }
}

/// The unit costs, in the order of [`Costs::values`].
pub const TERMS: [&str; 9] = [
    "per frame pixel (clear)",
    "per mesh vertex",
    "per binned triangle",
    "per pixel, lit bilinear",
    "per pixel, cube footprint",
    "per pixel, floor nearest",
    "per band",
    "per band piece (ranges)",
    "per band x mesh triangle (ranges)",
];

/// The design row of a frame: how many of each unit it does; `whole`: drawn into one
/// whole frame (no bands).
fn terms(c: &Counts, whole: bool) -> [f64; 9] {
    let mut t = [0.0; 9];
    t[0] = f64::from(c.size.0) * f64::from(c.size.1);
    t[1] = c.vertices as f64;
    t[2] = c.binned as f64;
    let px = 3 + Mode::ALL.iter().position(|&m| m == c.mode).unwrap_or(0);
    t[px] = c.pixels as f64;
    if !whole {
        t[6] = c.bands() as f64;
        if c.binning == Binning::Ranges {
            t[7] = c.pieces as f64;
            t[8] = (c.bands() * c.triangles) as f64;
        }
    }
    t
}

/// Fitted unit costs of one instruction set (instructions per unit).
#[derive(Clone, Debug, PartialEq)]
pub struct Costs {
    /// The MCU label (`Cortex-M0+`).
    pub target: String,
    /// Instructions per unit, in the order of [`TERMS`].
    pub values: [f64; 9],
    /// The binning pass of a banded frame: instructions per mesh vertex and per mesh
    /// triangle (fitted to the measured binning passes; zero when none is measured).
    pub geometry: [f64; 2],
}

impl Costs {
    /// Predicted instructions of a frame.
    pub fn predict(&self, c: &Counts, whole: bool) -> f64 {
        terms(c, whole)
            .iter()
            .zip(&self.values)
            .map(|(n, k)| n * k)
            .sum()
    }

    /// Predicted instructions of the binning pass of a banded frame (walk, transform,
    /// cull, project, band ranges: its own fit, [`fit_geometry`]) and of its bands (the
    /// rest of [`Costs::predict`]).
    pub fn split(&self, c: &Counts) -> (f64, f64) {
        let total = self.predict(c, false);
        let geometry = (self.geometry[0] * c.vertices as f64
            + self.geometry[1] * c.triangles as f64)
            .min(total);
        (geometry, total - geometry)
    }
}

/// One measured frame: its counts, whether whole, its instructions.
#[derive(Clone, Debug)]
pub struct Sample {
    /// What it does.
    pub counts: Counts,
    /// Drawn whole (the firmware `whole_<scene>`).
    pub whole: bool,
    /// Exact instructions under QEMU.
    pub measured: f64,
    /// Instructions of its binning pass, when banded and measured.
    pub geometry: Option<f64>,
}

/// Parses `scenes.csv` (the benchmark scenes' counts, `host-tests/tests/budget_counts.rs`).
pub fn parse_scenes(csv: &str) -> Result<Vec<Counts>, String> {
    let mut out = Vec::new();
    for (n, line) in csv.lines().enumerate() {
        if line.starts_with('#') || line.starts_with("scene,") || line.trim().is_empty() {
            continue;
        }
        let f: Vec<&str> = line.split(',').collect();
        let bad = || format!("scenes.csv line {}: `{line}`", n + 1);
        if f.len() != 10 {
            return Err(bad());
        }
        let num = |k: usize| f[k].parse::<u64>().map_err(|_| bad());
        let mode = match f[0] {
            "cube" => Mode::CubeFootprint,
            "floor" => Mode::FloorNearest,
            _ => Mode::LitBilinear,
        };
        let binning = match f[1] {
            "bins" => Binning::Bins,
            "ranges" => Binning::Ranges,
            _ => return Err(bad()),
        };
        out.push(Counts {
            scene: f[0].to_string(),
            mode,
            binning,
            size: (num(2)? as u32, num(3)? as u32),
            rows: num(4)? as u32,
            vertices: num(5)?,
            triangles: num(6)?,
            binned: num(7)?,
            pieces: num(8)?,
            pixels: num(9)?,
        });
    }
    Ok(out)
}

/// One row of `docs/mcu.md`'s first table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    /// Instructions of the frame: instructions per pixel (exact to 0.01) times pixels.
    pub insns: f64,
    /// Estimated cycles per instruction (the static cycle model's, over the frame).
    pub cycles_per_insn: f64,
    /// Flash of the firmware, bytes.
    pub flash: u64,
    /// RAM of the firmware (static data and measured stack), bytes.
    pub ram: u64,
    /// Instructions of the binning pass (banded frames, from the bands table's share).
    pub geometry: Option<f64>,
}

/// The rows of `docs/mcu.md`'s first table, by (firmware, MCU label).
pub fn parse_measured(md: &str) -> HashMap<(String, String), Measured> {
    let mut out = HashMap::new();
    for line in md.lines() {
        let f: Vec<&str> = line.split('|').map(str::trim).collect();
        // | scene | target | insns/px | cycles/px | pixels | checksum | = host | flash | RAM (..)
        if f.len() < 10 {
            continue;
        }
        let (Ok(ipp), Ok(cpp), Ok(px), Ok(flash)) = (
            f[3].parse::<f64>(),
            f[4].parse::<f64>(),
            f[5].parse::<f64>(),
            f[8].parse::<u64>(),
        ) else {
            continue;
        };
        let Some(Ok(ram)) = f[9].split_whitespace().next().map(str::parse::<u64>) else {
            continue;
        };
        out.entry((f[1].to_string(), f[2].to_string()))
            .or_insert(Measured {
                insns: ipp * px,
                cycles_per_insn: cpp / ipp.max(f64::MIN_POSITIVE),
                flash,
                ram,
                geometry: None,
            });
    }
    // | scene | target | bands insns/px | geometry | ...: the binning pass's share, to 0.1 %.
    for line in md.lines() {
        let f: Vec<&str> = line.split('|').map(str::trim).collect();
        if f.len() < 6 || !f[4].ends_with(" %") {
            continue;
        }
        let Ok(pct) = f[4].trim_end_matches(" %").parse::<f64>() else {
            continue;
        };
        if let Some(m) = out.get_mut(&(f[1].to_string(), f[2].to_string())) {
            m.geometry = Some(pct / 100.0 * m.insns);
        }
    }
    out
}

/// The samples of `target`: each benchmark scene banded and whole, where measured.
pub fn samples(
    scenes: &[Counts],
    measured: &HashMap<(String, String), Measured>,
    target: &str,
) -> Vec<Sample> {
    let mut out = Vec::new();
    for c in scenes {
        for whole in [false, true] {
            let name = if whole {
                format!("whole_{}", c.scene)
            } else {
                c.scene.clone()
            };
            if let Some(m) = measured.get(&(name, target.to_string())) {
                out.push(Sample {
                    counts: c.clone(),
                    whole,
                    measured: m.insns,
                    geometry: if whole { None } else { m.geometry },
                });
            }
        }
    }
    out
}

/// Solves the square system `a x = b` by Gaussian elimination with partial pivoting;
/// `None` when singular.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    for col in 0..n {
        let p = (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[p][col].abs() < 1e-9 {
            return None;
        }
        a.swap(col, p);
        b.swap(col, p);
        let (pivot, below) = a.split_at_mut(col + 1);
        let pivot = &pivot[col];
        for (k, row) in below.iter_mut().enumerate() {
            let f = row[col] / pivot[col];
            for (x, p) in row[col..].iter_mut().zip(&pivot[col..]) {
                *x -= f * p;
            }
            b[col + 1 + k] -= f * b[col];
        }
    }
    let mut x = vec![0.0; n];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|k| a[r][k] * x[k]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    Some(x)
}

/// Least squares of `samples` on the terms in `active`, each sample weighted by one over
/// its measured count (so the fit minimises relative errors), each term scaled by its
/// largest weighted value (so the system is well conditioned).
fn least_squares(samples: &[Sample], active: &[usize]) -> Option<Vec<f64>> {
    let n = active.len();
    let rows: Vec<(Vec<f64>, f64)> = samples
        .iter()
        .map(|s| {
            let t = terms(&s.counts, s.whole);
            let w = 1.0 / s.measured.max(1.0);
            (active.iter().map(|&k| t[k] * w).collect(), s.measured * w)
        })
        .collect();
    let scale: Vec<f64> = (0..n)
        .map(|i| {
            rows.iter()
                .map(|r| r.0[i].abs())
                .fold(0.0, f64::max)
                .max(1e-300)
        })
        .collect();
    let mut ata = vec![vec![0.0; n]; n];
    let mut atb = vec![0.0; n];
    for (x, y) in &rows {
        for i in 0..n {
            atb[i] += x[i] / scale[i] * y;
            for j in 0..n {
                ata[i][j] += x[i] / scale[i] * x[j] / scale[j];
            }
        }
    }
    let x = solve(ata, atb)?;
    Some(x.iter().zip(&scale).map(|(v, s)| v / s).collect())
}

/// The binning pass's costs per mesh vertex and per mesh triangle: least squares (of
/// instructions, so the large passes weigh most) over the banded samples with a measured
/// binning pass; one of the two alone when both together would make one negative. It
/// places work in time (the binning pass before the first band), not the frame's total;
/// it is rough: the sphere's face planes make its culling cheaper than the other meshes'.
pub fn fit_geometry(samples: &[Sample]) -> [f64; 2] {
    let pts: Vec<([f64; 2], f64)> = samples
        .iter()
        .filter_map(|s| {
            let g = s.geometry.filter(|g| *g > 0.0)?;
            Some(([s.counts.vertices as f64, s.counts.triangles as f64], g))
        })
        .collect();
    let dot = |i: usize, j: usize| pts.iter().map(|(x, _)| x[i] * x[j]).sum::<f64>();
    let rhs = |i: usize| pts.iter().map(|(x, y)| x[i] * y).sum::<f64>();
    let (a, b, d) = (dot(0, 0), dot(0, 1), dot(1, 1));
    let det = a * d - b * b;
    if det.abs() > 1e-12 * (a * d).max(f64::MIN_POSITIVE) {
        let v = (d * rhs(0) - b * rhs(1)) / det;
        let t = (a * rhs(1) - b * rhs(0)) / det;
        if v >= 0.0 && t >= 0.0 {
            return [v, t];
        }
    }
    // One term alone: the one that fits better.
    let one = |i: usize| {
        let k = if dot(i, i) > 0.0 {
            rhs(i) / dot(i, i)
        } else {
            0.0
        };
        let err: f64 = pts.iter().map(|(x, y)| (x[i] * k - y).powi(2)).sum();
        (k.max(0.0), err)
    };
    let ((v, ev), (t, et)) = (one(0), one(1));
    if ev <= et {
        [v, 0.0]
    } else {
        [0.0, t]
    }
}

/// Fits the unit costs of `target` to `samples`, none negative: a term no sample uses is
/// left at zero, and while a cost comes out negative the most negative one is dropped and
/// the rest refitted.
pub fn fit(samples: &[Sample], target: &str) -> Result<Costs, String> {
    let mut active: Vec<usize> = (0..TERMS.len())
        .filter(|&k| samples.iter().any(|s| terms(&s.counts, s.whole)[k] != 0.0))
        .collect();
    loop {
        let x = least_squares(samples, &active)
            .ok_or_else(|| format!("{target}: the benchmark scenes do not determine the costs"))?;
        let worst = x
            .iter()
            .enumerate()
            .filter(|(_, v)| **v < 0.0)
            .min_by(|a, b| a.1.total_cmp(b.1))
            .map(|(i, _)| i);
        match worst {
            Some(i) => {
                active.remove(i);
            }
            None => {
                let mut values = [0.0; 9];
                for (k, v) in active.iter().zip(x) {
                    values[*k] = v;
                }
                return Ok(Costs {
                    target: target.to_string(),
                    values,
                    geometry: fit_geometry(samples),
                });
            }
        }
    }
}
