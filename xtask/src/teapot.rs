//! `cargo xtask teapot`: the Utah teapot from Newell's public Bézier patch data
//! (`assets/teapot/newell.txt`: 32 bicubic patches over 306 control points, `z` up) to a
//! Wavefront OBJ of positions and triangles, the example model of `cargo xtask bake-obj`.
//!
//! Each patch is evaluated on an `n x n` grid of its `(s, t)` parameters with the Bernstein
//! basis `B0 = (1−s)³, B1 = 3s(1−s)², B2 = 3s²(1−s), B3 = s³`, in f64. Points that coincide
//! (patch borders, the degenerate rows at the lid's knob and the bottom's centre) are
//! welded (rounded to 1e-6), and triangles that lose an edge to the weld are dropped. The
//! model is turned to `y` up (`(x, y, z) -> (x, z, −y)`, a rotation) and moved so its
//! height is centred on the origin; the body's axis stays at `x = z = 0`. The OBJ has no
//! normals and no texture coordinates: `bake-obj` generates both.

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use clap::Args;

use crate::bake::BakeError;

/// Patches (16 one-based control-point indices each) and control points.
type Patches = (Vec<[usize; 16]>, Vec<[f64; 3]>);

/// Parses the patch file: the patch count, that many lines of 16 indices, the point count,
/// that many `x,y,z` lines.
pub fn parse(text: &str) -> Result<Patches, String> {
    let lines: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    let count = |k: usize, what: &str| -> Result<usize, String> {
        lines
            .get(k)
            .ok_or(format!("missing the {what} count"))?
            .parse::<usize>()
            .map_err(|e| format!("bad {what} count: {e}"))
    };
    let np = count(0, "patch")?;
    let nv = count(1 + np, "point")?;
    let row = |k: usize, what: &str| -> Result<&str, String> {
        lines.get(k).copied().ok_or(format!("{what} missing"))
    };
    let mut patches = Vec::with_capacity(np);
    for k in 0..np {
        let ix: Vec<usize> = row(1 + k, &format!("patch {k}"))?
            .split(',')
            .map(|v| v.trim().parse::<usize>())
            .collect::<Result<_, _>>()
            .map_err(|e| format!("patch {k}: {e}"))?;
        let ix: [usize; 16] = ix
            .try_into()
            .map_err(|v: Vec<usize>| format!("patch {k}: {} indices, not 16", v.len()))?;
        if let Some(&bad) = ix.iter().find(|&&i| i == 0 || i > nv) {
            return Err(format!("patch {k}: index {bad} outside 1..={nv}"));
        }
        patches.push(ix);
    }
    let mut points = Vec::with_capacity(nv);
    for k in 0..nv {
        let c: Vec<f64> = row(2 + np + k, &format!("point {k}"))?
            .split(',')
            .map(|v| v.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|e| format!("point {k}: {e}"))?;
        let c: [f64; 3] = c
            .try_into()
            .map_err(|v: Vec<f64>| format!("point {k}: {} coordinates, not 3", v.len()))?;
        points.push(c);
    }
    Ok((patches, points))
}

fn bernstein(s: f64) -> [f64; 4] {
    let r = 1.0 - s;
    [r * r * r, 3.0 * s * r * r, 3.0 * s * s * r, s * s * s]
}

/// Positions (y up, centred in height) and triangles (counter-clockwise from outside) of
/// the patches on an `n x n` grid each, welded, degenerate triangles dropped.
pub fn tessellate(patches: &[[usize; 16]], points: &[[f64; 3]], n: u32) -> Patches3 {
    let mut pos: Vec<[f64; 3]> = Vec::new();
    let mut weld: HashMap<[i64; 3], usize> = HashMap::new();
    let mut tris = Vec::new();
    let mut id = |p: [f64; 3], pos: &mut Vec<[f64; 3]>| -> usize {
        let key = p.map(|c| (c * 1e6).round() as i64);
        *weld.entry(key).or_insert_with(|| {
            pos.push(p);
            pos.len() - 1
        })
    };
    for patch in patches {
        let cp = |i: usize, j: usize| points[patch[i * 4 + j] - 1];
        let mut grid = vec![0usize; ((n + 1) * (n + 1)) as usize];
        for a in 0..=n {
            for b in 0..=n {
                let (bs, bt) = (
                    bernstein(f64::from(a) / f64::from(n)),
                    bernstein(f64::from(b) / f64::from(n)),
                );
                let mut p = [0.0; 3];
                for (i, wi) in bs.iter().enumerate() {
                    for (j, wj) in bt.iter().enumerate() {
                        let c = cp(i, j);
                        for (pk, ck) in p.iter_mut().zip(c) {
                            *pk += wi * wj * ck;
                        }
                    }
                }
                // z up to y up.
                let p = [p[0], p[2], -p[1]];
                grid[(a * (n + 1) + b) as usize] = id(p, &mut pos);
            }
        }
        let g = |a: u32, b: u32| grid[(a * (n + 1) + b) as usize];
        for a in 0..n {
            for b in 0..n {
                let (p00, p10, p11, p01) = (g(a, b), g(a + 1, b), g(a + 1, b + 1), g(a, b + 1));
                // Newell's patches run clockwise seen from outside in these coordinates.
                for t in [[p00, p01, p11], [p00, p11, p10]] {
                    if t[0] != t[1] && t[1] != t[2] && t[0] != t[2] {
                        tris.push(t);
                    }
                }
            }
        }
    }
    let (lo, hi) = pos.iter().fold((f64::MAX, f64::MIN), |(lo, hi), p| {
        (lo.min(p[1]), hi.max(p[1]))
    });
    let mid = 0.5 * (lo + hi);
    for p in &mut pos {
        p[1] -= mid;
    }
    (tris, pos)
}

/// Triangles and positions.
pub type Patches3 = (Vec<[usize; 3]>, Vec<[f64; 3]>);

/// The OBJ text.
pub fn obj(tris: &[[usize; 3]], pos: &[[f64; 3]], n: u32) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "# The Utah teapot (Martin Newell, 1975), from its public Bezier patch data,\n\
         # tessellated {n} x {n} per patch by `cargo xtask teapot`; y up. {} vertices, {} triangles.",
        pos.len(),
        tris.len()
    );
    for p in pos {
        let _ = writeln!(o, "v {:.6} {:.6} {:.6}", p[0], p[1], p[2]);
    }
    for t in tris {
        let _ = writeln!(o, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    o
}

/// Arguments of `cargo xtask teapot`.
#[derive(Args, Clone, Debug)]
pub struct TeapotArgs {
    /// Samples per patch side, 1..=32
    #[arg(long, value_name = "N", default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=32))]
    pub grid: u32,
    /// Newell's patch data [default: assets/teapot/newell.txt]
    #[arg(long, value_name = "FILE")]
    pub patches: Option<PathBuf>,
    /// The OBJ to write [default: assets/teapot/teapot.obj]
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// Tessellates the patches of `args` into an OBJ.
pub fn run(args: &TeapotArgs) -> Result<(), BakeError> {
    let root = crate::cmd::root();
    let grid = args.grid;
    let input = args
        .patches
        .clone()
        .unwrap_or_else(|| root.join("assets/teapot/newell.txt"));
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| root.join("assets/teapot/teapot.obj"));
    let text = std::fs::read_to_string(&input)
        .map_err(|e| BakeError::Failed(format!("{}: {e}", input.display())))?;
    let (patches, points) =
        parse(&text).map_err(|e| BakeError::Failed(format!("{}: {e}", input.display())))?;
    let (tris, pos) = tessellate(&patches, &points, grid);
    std::fs::write(&out, obj(&tris, &pos, grid))
        .map_err(|e| BakeError::Failed(format!("{}: {e}", out.display())))?;
    println!(
        "teapot: {} patches at {grid} x {grid} -> {} vertices, {} triangles -> {}",
        patches.len(),
        pos.len(),
        tris.len(),
        Path::new(&out).display()
    );
    Ok(())
}
