//! `cargo xtask budget MODEL --chip CHIP`: flash, RAM and frame time of a model on a part,
//! before flashing it.
//!
//! MODEL is a glTF 2.0 file (baked in memory as `cargo xtask bake-gltf --center` bakes it,
//! scaled to 3.1 units, texture 128 on its longer side, then drawn on the host as the model
//! firmwares draw the samples, to count its pixels, triangles and band pieces) or a
//! benchmark scene's name (`cube`, `sphere`, `teapot`, `floor`, `fox`, `cesium_man`: their
//! committed counts, and their measured figures beside the prediction). The instructions
//! come from the cost model of `fit.rs`, fitted to `docs/mcu.md` (written by `cargo xtask
//! mcu --docs`); the frame times from the frame model `cargo xtask fps` uses
//! (`frame_model`).

pub mod fit;
mod memory;
pub mod render;
mod report;

use std::fs;
use std::path::Path;
use std::process::ExitCode;

use clap::Args;
use embedded_graphics_core::pixelcolor::Rgb565;

use crate::bake_gltf::{self, GltfOpts};
use crate::cmd::root;
use crate::frame_model::chips::CHIPS;
use crate::frame_model::Chip;
use fit::{fit, parse_measured, parse_scenes, samples, Counts};
use render::{BandLoad, Model};

/// Longest side of a glTF model's bounding box once baked, in scene units (the Fox's
/// length in its firmware scene).
pub const FIT_UNITS: f64 = 3.1;
/// Longer side of a glTF model's baked texture (the samples' bake).
pub const TEXTURE: u32 = 128;

/// Flags of `cargo xtask budget`.
#[derive(Args, Clone, Debug)]
pub struct BudgetArgs {
    /// A glTF 2.0 model (.glb, or .gltf with its buffers and images), or a benchmark
    /// scene: cube, sphere, teapot, floor, fox, cesium_man
    #[arg(value_name = "MODEL")]
    pub model: String,
    /// The part: rp2040, rp2350, stm32f4 or esp32c3
    #[arg(long, value_name = "CHIP", value_parser = parse_chip)]
    pub chip: &'static Chip,
    /// Frame size, WIDTHxHEIGHT (a glTF model; a benchmark scene has its own) [default: 240x320]
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    pub size: Option<(u32, u32)>,
    /// Share of the frame the model covers, 0 to 1, in place of the pixels the host render
    /// counts (band pieces and triangles stay as drawn)
    #[arg(long, value_name = "F", value_parser = parse_coverage)]
    pub coverage: Option<f64>,
}

/// `--chip`: a part of [`CHIPS`], by its name in lower case without dashes.
pub fn parse_chip(v: &str) -> Result<&'static Chip, String> {
    let key = |s: &str| s.to_ascii_lowercase().replace(['-', '_'], "");
    CHIPS.iter().find(|c| key(c.name) == key(v)).ok_or_else(|| {
        let names: Vec<String> = CHIPS.iter().map(|c| key(c.name)).collect();
        format!("no chip `{v}`; the chips are {}", names.join(", "))
    })
}

/// `--size`: `WIDTHxHEIGHT`, each side 8 to 2048 pixels.
pub fn parse_size(v: &str) -> Result<(u32, u32), String> {
    let bad = || format!("`{v}` is not a frame size: WIDTHxHEIGHT, each 8 to 2048 (240x320)");
    let (w, h) = v.split_once(['x', 'X']).ok_or_else(bad)?;
    let side = |s: &str| {
        s.trim()
            .parse::<u32>()
            .ok()
            .filter(|n| (8..=2048).contains(n))
    };
    match (side(w), side(h)) {
        (Some(w), Some(h)) => Ok((w, h)),
        _ => Err(bad()),
    }
}

/// `--coverage`: a share of the frame, above 0 and at most 1.
pub fn parse_coverage(v: &str) -> Result<f64, String> {
    v.parse::<f64>()
        .ok()
        .filter(|f| f.is_finite() && *f > 0.0 && *f <= 1.0)
        .ok_or_else(|| format!("`{v}` is not a coverage: a number above 0, at most 1 (0.15)"))
}

/// The committed counts of the benchmark scenes.
fn scenes() -> Result<Vec<Counts>, String> {
    let p = root().join("xtask").join("budget").join("scenes.csv");
    let s = fs::read_to_string(&p).map_err(|e| format!("{}: {e}", p.display()))?;
    parse_scenes(&s)
}

/// Reads and bakes a glTF model as the budget places it.
pub fn load_model(path: &Path) -> Result<Model, String> {
    let imported = bake_gltf::load(path)?;
    let (mut lo, mut hi) = ([f64::MAX; 3], [f64::MIN; 3]);
    for p in &imported.mesh.positions {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let extent = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
    if !(extent.is_finite() && extent > 0.0) {
        return Err(format!("{}: the model has no extent", path.display()));
    }
    let opts = GltfOpts {
        name: "MODEL".into(),
        scale: FIT_UNITS / extent,
        center: true,
        texture_size: Some(TEXTURE),
        levels: None,
        max_texture_kib: 256,
        krate: "fixel".into(),
        rgb565: crate::bake::DEFAULT_RGB565.into(),
        order_by_height: false,
    };
    model_from(path, imported, &opts)
}

/// Bakes `imported` with `opts` into a [`Model`].
pub fn model_from(
    path: &Path,
    imported: bake_gltf::Imported,
    opts: &GltfOpts,
) -> Result<Model, String> {
    let name = path
        .file_name()
        .map_or_else(|| "model".into(), |f| f.to_string_lossy().into_owned());
    let b = bake_gltf::bake(imported, opts).map_err(|e| format!("{}: {e}", path.display()))?;
    let (texels, texture) = match &b.texture {
        Some(t) => (
            t.texels
                .iter()
                .map(|c| Rgb565::new(c[0], c[1], c[2]))
                .collect(),
            (t.width, t.height, t.levels),
        ),
        None => (vec![Rgb565::new(31, 63, 31)], (1, 1, 1)),
    };
    Ok(Model {
        name,
        mesh: b.mesh,
        texels,
        texture,
        colors: b.colors.is_some(),
    })
}

/// The counts and band loads of `args.model` at `size`, with a progress line per step; the
/// model when it is a glTF file.
fn counts(
    args: &BudgetArgs,
    bench: &[Counts],
) -> Result<(Counts, Vec<BandLoad>, Option<Model>), String> {
    if let Some(c) = bench.iter().find(|c| c.scene == args.model) {
        if let Some(s) = args.size.filter(|s| *s != c.size) {
            return Err(format!(
                "{} is measured at {} x {}, not {} x {}; pass a glTF file for other sizes",
                c.scene, c.size.0, c.size.1, s.0, s.1
            ));
        }
        // The committed counts have no per-band split: each band gets an equal share.
        let bands = c.bands();
        let loads = (0..bands)
            .map(|_| BandLoad {
                pixels: c.pixels / bands,
                pieces: c.pieces / bands,
            })
            .collect();
        return Ok((c.clone(), loads, None));
    }
    let path = Path::new(&args.model);
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if !matches!(ext.as_deref(), Some("glb" | "gltf")) {
        let names: Vec<&str> = bench.iter().map(|c| c.scene.as_str()).collect();
        return Err(format!(
            "`{}` is neither a .glb/.gltf file nor a benchmark scene ({})",
            args.model,
            names.join(", ")
        ));
    }
    eprintln!("budget: reading and baking {}", path.display());
    let model = load_model(path)?;
    let size = args.size.unwrap_or((240, 320));
    eprintln!(
        "budget: drawing it at {} x {} on the host, in bands of {} rows",
        size.0,
        size.1,
        render::ROWS
    );
    let (c, loads) = render::count(&model, size, &render::view())?;
    Ok((c, loads, Some(model)))
}

/// `cargo xtask budget`.
pub fn budget(args: &BudgetArgs) -> ExitCode {
    match run(args) {
        Ok(text) => {
            println!("{text}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("xtask: budget: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: &BudgetArgs) -> Result<String, String> {
    let bench = scenes()?;
    let (mut counts, mut loads, model) = counts(args, &bench)?;
    if let Some(f) = args.coverage {
        let total = (f * f64::from(counts.size.0) * f64::from(counts.size.1)).round() as u64;
        let drawn: u64 = loads.iter().map(|l| l.pixels).sum();
        let n = loads.len().max(1) as u64;
        for l in &mut loads {
            l.pixels = if drawn == 0 {
                total / n
            } else {
                (l.pixels as f64 * total as f64 / drawn as f64).round() as u64
            };
        }
        counts.pixels = total;
    }
    let target = args.chip.counts_from;
    eprintln!("budget: fitting the cost model to docs/mcu.md ({target})");
    let docs = root().join("docs").join("mcu.md");
    let md = fs::read_to_string(&docs).map_err(|e| format!("{}: {e}", docs.display()))?;
    let measured = parse_measured(&md);
    let s = samples(&bench, &measured, target);
    let costs = fit(&s, target)?;
    report::text(&report::Inputs {
        chip: args.chip,
        counts: &counts,
        loads: &loads,
        model: model.as_ref(),
        costs: &costs,
        samples: &s,
        measured: &measured,
        coverage: args.coverage,
    })
}

#[cfg(test)]
mod tests;
