//! The text `cargo xtask budget` prints: memory, the frame's counts, the predicted
//! instructions and frame times, the fit's check against the measured benchmark scenes,
//! and the assumptions.

use std::collections::HashMap;
use std::fmt::Write as _;

use super::fit::{Costs, Counts, Measured, Sample, TERMS};
use super::memory;
use super::render::{BandLoad, Model};
use crate::frame_model::{frame_times, Chip, Work};

/// The largest error of the fit on a benchmark frame that `budget` accepts.
pub const BAR: f64 = 0.15;

/// Everything the report shows.
pub struct Inputs<'a> {
    /// The part.
    pub chip: &'static Chip,
    /// What the frame does.
    pub counts: &'a Counts,
    /// Each band's pixels and pieces.
    pub loads: &'a [BandLoad],
    /// The baked model (`None` for a benchmark scene).
    pub model: Option<&'a Model>,
    /// The fitted unit costs of the part's instruction set.
    pub costs: &'a Costs,
    /// The benchmark frames they were fitted to.
    pub samples: &'a [Sample],
    /// `docs/mcu.md`'s rows.
    pub measured: &'a HashMap<(String, String), Measured>,
    /// `--coverage`, when given.
    pub coverage: Option<f64>,
}

/// The predicted work of the frame in instructions: the binning pass and each band (the
/// band terms of each band, and the set-ups and vertex work the binning pass leaves,
/// shared by the bands in proportion to their pieces).
pub fn band_insns(costs: &Costs, c: &Counts, loads: &[BandLoad]) -> (f64, Vec<f64>) {
    let v = &costs.values;
    let (geometry, rest) = costs.split(c);
    let drawn: u64 = loads.iter().map(|l| l.pixels).sum();
    let pieces: u64 = loads.iter().map(|l| l.pieces).sum();
    let n = loads.len().max(1) as f64;
    let px_cost = costs.predict(
        &Counts {
            pixels: 1,
            vertices: 0,
            binned: 0,
            triangles: 0,
            pieces: 0,
            size: (0, 0),
            ..c.clone()
        },
        true,
    );
    let raw: Vec<f64> = loads
        .iter()
        .enumerate()
        .map(|(k, l)| {
            let rows = c.rows.min(c.size.1.saturating_sub(k as u32 * c.rows));
            let share = if drawn == 0 {
                c.pixels as f64 / n
            } else {
                l.pixels as f64 * c.pixels as f64 / drawn as f64
            };
            v[0] * f64::from(c.size.0) * f64::from(rows)
                + v[6]
                + v[7] * l.pieces as f64
                + v[8] * c.triangles as f64
                + px_cost * share
        })
        .collect();
    let left = rest - raw.iter().sum::<f64>();
    let bands = raw
        .iter()
        .zip(loads)
        .map(|(r, l)| {
            let w = if pieces == 0 {
                1.0 / n
            } else {
                l.pieces as f64 / pieces as f64
            };
            (r + left * w).max(0.0)
        })
        .collect();
    (geometry, bands)
}

fn kib(b: u64) -> String {
    format!("{b} B ({:.1} KiB)", b as f64 / 1024.0)
}

fn ms(t: f64) -> String {
    format!("{:.1} ms ({:.1} fps)", t * 1e3, 1.0 / t)
}

/// The report.
pub fn text(i: &Inputs<'_>) -> Result<String, String> {
    let (chip, c, costs) = (i.chip, i.counts, i.costs);
    let target = chip.counts_from;
    let mut t = String::new();
    let _ = writeln!(
        t,
        "# Budget: {} on the {} ({}), {} x {}, bands of {} rows\n",
        c.scene, chip.name, chip.core, c.size.0, c.size.1, c.rows
    );

    // Memory.
    let cap = memory::capacity(chip.name);
    let bench_name = i.model.is_none();
    let code = memory::code_flash(i.measured, &bench_scenes(i.samples), target);
    let other = memory::other_ram(i.measured, &bench_scenes(i.samples), target);
    let _ = writeln!(t, "## Memory\n");
    if let Some(m) = i.model {
        let parts = memory::model_flash(c, m.colors, m.texture);
        let data: u64 = parts.iter().map(|p| p.1).sum();
        let _ = writeln!(t, "flash, the baked model: {}", kib(data));
        for (what, b) in &parts {
            let _ = writeln!(t, "  {what}: {b} B");
        }
        if let Some(code) = code {
            let _ = writeln!(
                t,
                "flash, the firmware's code (fixel's draw, bands, harness; the `fox` firmware \
                 on {target} less the Fox's arrays): {}",
                kib(code)
            );
            let total = data + code;
            let _ = writeln!(t, "flash, total: {}", kib(total));
            if let Some((f, _, board)) = cap {
                let _ = writeln!(t, "  {:.0} % of {board}", 100.0 * total as f64 / f as f64);
            }
        }
    } else if let Some(m) = i.measured.get(&(c.scene.clone(), target.to_string())) {
        let _ = writeln!(
            t,
            "flash (the `{}` firmware, measured): {}",
            c.scene,
            kib(m.flash)
        );
    }
    if bench_name {
        if let Some(m) = i.measured.get(&(c.scene.clone(), target.to_string())) {
            let _ = writeln!(
                t,
                "RAM (the `{}` firmware, measured): {}",
                c.scene,
                kib(m.ram)
            );
        }
    } else {
        let parts = memory::band_ram(c);
        let bands: u64 = parts.iter().map(|p| p.1).sum();
        for (what, b) in &parts {
            let _ = writeln!(t, "RAM, {what}: {b} B");
        }
        if let Some(o) = other {
            let _ = writeln!(
                t,
                "RAM, stack and statics (the `fox` firmware on {target} less its bands): {o} B"
            );
            let total = bands + o;
            let _ = writeln!(t, "RAM, total: {}", kib(total));
            if let Some((_, r, board)) = cap {
                let _ = writeln!(t, "  {:.0} % of {board}", 100.0 * total as f64 / r as f64);
            }
        }
    }

    // The frame's counts and instructions.
    let predicted = costs.predict(c, false);
    let (geometry, bands) = band_insns(costs, c, i.loads);
    let _ = writeln!(t, "\n## The frame\n");
    let _ = writeln!(
        t,
        "{} vertices, {} triangles ({} drawn after culling and clipping), {} band pieces \
         over {} bands, {} pixels written ({:.1} % of the frame{})",
        c.vertices,
        c.triangles,
        c.binned,
        c.pieces,
        c.bands(),
        c.pixels,
        100.0 * c.pixels as f64 / (f64::from(c.size.0) * f64::from(c.size.1)),
        if i.coverage.is_some() {
            ", from --coverage"
        } else {
            ", as drawn on the host"
        }
    );
    let _ = writeln!(t, "draw: {}", c.mode.name());
    let cpi = cycles_per_insn(i.measured, target);
    let _ = writeln!(
        t,
        "predicted {target} instructions: {:.0} (binning pass {:.0}, bands {:.0}); \
         {:.0} per pixel written",
        predicted,
        geometry,
        predicted - geometry,
        predicted / c.pixels.max(1) as f64
    );
    if let Some(m) = i.measured.get(&(c.scene.clone(), target.to_string())) {
        let _ = writeln!(
            t,
            "measured (`cargo xtask mcu`): {:.0} ({:+.1} %)",
            m.insns,
            100.0 * (predicted / m.insns - 1.0)
        );
    }
    let _ = writeln!(
        t,
        "cycles: instructions x {cpi:.3} cycles per instruction (the `fox` frame's on {target}, \
         the static cycle model of xtask/mcu/cycles.py)"
    );

    // Frame times.
    let band_pixels = (0..bands.len() as u32)
        .map(|k| u64::from(c.size.0) * u64::from(c.rows.min(c.size.1.saturating_sub(k * c.rows))))
        .collect();
    let work = Work {
        geometry: geometry * cpi,
        bands: bands.iter().map(|b| b * cpi).collect(),
        band_pixels,
    };
    let f = frame_times(chip, &work);
    let _ = writeln!(t, "\n## Frame time on the {} (a model)\n", chip.name);
    let _ = writeln!(t, "| way | frame time |\n|---|---:|");
    let _ = writeln!(t, "| drawing alone, 1 core | {} |", ms(f.render));
    let _ = writeln!(t, "| the link alone | {} |", ms(f.link));
    let _ = writeln!(t, "| serial, 1 core | {} |", ms(f.serial));
    let _ = writeln!(t, "| overlapped, 1 core | {} |", ms(f.overlapped));
    if let Some(two) = f.two_cores {
        let _ = writeln!(t, "| overlapped, 2 cores | {} |", ms(two));
    }

    // The check.
    let _ = writeln!(
        t,
        "\n## The cost model on {target} against `cargo xtask mcu` (docs/mcu.md)\n"
    );
    let _ = writeln!(t, "| unit | instructions |\n|---|---:|");
    for (name, v) in TERMS.iter().zip(&costs.values) {
        let _ = writeln!(t, "| {name} | {v:.2} |");
    }
    let _ = writeln!(
        t,
        "| binning pass, per mesh vertex | {:.2} |\n| binning pass, per mesh triangle | {:.2} |",
        costs.geometry[0], costs.geometry[1]
    );
    let _ = writeln!(t);
    t.push_str(&check_table(costs, i.samples));
    let worst = worst_error(costs, i.samples);
    let _ = writeln!(
        t,
        "\nlargest error {:.1} % (the bar: {:.0} %)",
        100.0 * worst,
        100.0 * BAR
    );
    let _ = writeln!(t, "\n## Assumptions\n\n{ASSUMPTIONS}");
    if worst > BAR {
        return Err(format!(
            "{t}\nthe cost model misses a benchmark scene by {:.1} %, more than {:.0} %",
            100.0 * worst,
            100.0 * BAR
        ));
    }
    Ok(t)
}

/// The benchmark scenes' counts behind `samples`.
fn bench_scenes(samples: &[Sample]) -> Vec<Counts> {
    samples.iter().map(|s| s.counts.clone()).collect()
}

/// The `fox` frame's cycles per instruction on `target` (1 when not measured).
fn cycles_per_insn(measured: &HashMap<(String, String), Measured>, target: &str) -> f64 {
    measured
        .get(&("fox".to_string(), target.to_string()))
        .map_or(1.0, |m| m.cycles_per_insn)
}

/// Predicted against measured, each benchmark frame (Markdown).
pub fn check_table(costs: &Costs, samples: &[Sample]) -> String {
    let mut t =
        String::from("| frame | measured insns | predicted | error |\n|---|---:|---:|---:|\n");
    for s in samples {
        let p = costs.predict(&s.counts, s.whole);
        let name = if s.whole {
            format!("whole_{}", s.counts.scene)
        } else {
            s.counts.scene.clone()
        };
        let _ = writeln!(
            t,
            "| {name} | {:.0} | {p:.0} | {:+.1} % |",
            s.measured,
            100.0 * (p / s.measured - 1.0)
        );
    }
    t
}

/// The largest relative error of the fit over `samples`.
pub fn worst_error(costs: &Costs, samples: &[Sample]) -> f64 {
    samples
        .iter()
        .map(|s| (costs.predict(&s.counts, s.whole) / s.measured - 1.0).abs())
        .fold(0.0, f64::max)
}

/// What the budget assumes, printed with it.
pub const ASSUMPTIONS: &str = "\
This is a model, not a board measurement. The instructions: unit costs (above) fitted by \
least squares, none negative, to the exact instruction counts of the benchmark frames \
under QEMU (docs/mcu.md: cube, floor, sphere, teapot, fox, cesium_man, in bands and \
whole), times what this frame does as the host draws it: the model scenes' draw (lit per \
vertex, bilinear, perspective exact every 64 pixels, depth-tested, back faces culled), \
bands of 8 rows through band ranges, a 64-entry vertex cache and 36 kept set-ups. The fit \
has 9 costs for 12 frames per instruction set: it is checked on the frames it was fitted \
to, not on unseen ones. The binning pass (before the first band) has its own rough fit per \
mesh vertex and triangle to the measured passes; it places work in time, not in the total. A glTF model is baked as `cargo xtask bake-gltf --center` does, \
scaled to 3.1 units on its longest side, its texture 128 texels on its longer side with \
the full mip chain, and seen as the Fox is in its firmware scene (turned 60 degrees, 5.2 \
units away, 45 degree field of view). Cycles: the static cycle model's cycles per \
instruction of the fox frame (zero-wait-state memory). The RP2350's Cortex-M33 is counted \
with the Cortex-M4F build. Flash and RAM: the model's arrays in fixel's formats, plus the \
`fox` firmware's measured code and stack less the Fox's own arrays and bands. Frame times: \
the frame model of `cargo xtask fps` (an ST7789-class display over SPI, RGB565; serial, \
overlapped with two band buffers and DMA, two cores), with the same links.";
