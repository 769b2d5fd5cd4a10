//! `cargo xtask report`, surface detail: the brick sphere of
//! `fixel_scenes::surface` (frame 0, light 0, 160 x 160) lit per vertex (Gouraud), per pixel
//! (Phong, Blinn-Phong, textured), bump-mapped (precomputed derivatives, exact and
//! subdivided by 8; height differences per pixel) and normal-mapped, through the firmware's
//! own code (`examples/firmware/src/surface.rs`).
//!
//! ```text
//! surface_report --out DIR [--runs N] [--mcu mcu.tsv]
//! ```
//!
//! Columns: host ns per drawn pixel (median of N frames, vertices included), exact M0+ and
//! M4F instructions per drawn pixel of `report_surface` (checksums checked against the
//! host's), and the error against the f64 per-pixel reference
//! (`host_tests::reference::lighting`): max and 99th-percentile RGB565 LSB, share of pixels
//! over 2 LSB, PSNR. Gouraud is measured against the per-pixel ideal. Writes
//! `DIR/surface.md` and `DIR/surface.png`.

#[path = "../../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "../../../examples/firmware/src/surface.rs"]
#[allow(dead_code)]
mod surface;

use std::time::Instant;

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use host_tests::metrics::compare;
use host_tests::report_args::ReportArgs;
use host_tests::surface_scene::{self as scene, Assets, Variant};

struct Row {
    name: &'static str,
    ns: f64,
    mcu: Option<(f64, f64)>,
    max: u32,
    p99: u32,
    over2: f64,
    psnr: f64,
}

fn variant(name: &str) -> Variant {
    match name {
        "gouraud" => Variant::Gouraud,
        "phong" => Variant::PhongPlain,
        "blinn" => Variant::BlinnPlain,
        "blinn-textured" => Variant::Textured,
        "bump-heights" => Variant::BumpHeights,
        "normal-map" => Variant::NormalMap,
        _ => Variant::BumpDerivatives,
    }
}

fn main() {
    let ReportArgs {
        out,
        runs,
        mcu: mcu_path,
    } = ReportArgs::parse(
        "surface_report",
        "Speed against error for surface detail (run by `cargo xtask report`)",
        "3",
    );
    std::fs::create_dir_all(&out).expect("output directory");
    let mcu = mcu_path
        .as_deref()
        .map(|p| host_tests::report_mcu::read(p, "surface"))
        .unwrap_or_default();
    let (w, h) = (surface::W, surface::H);
    let mut assets = Box::new(surface::SurfaceAssets::zeroed());
    assets.build().expect("assets");
    let refs = Assets::new();
    let sphere = scene::sphere();
    let light = fixel_scenes::surface::light(0);
    let mut rows = Vec::new();
    for (k, name) in surface::VARIANTS.iter().enumerate() {
        let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
        let mut depth = vec![0u16; (w * h) as usize];
        let mut times = Vec::new();
        let mut px = 0;
        for _ in 0..runs.max(1) {
            let t0 = Instant::now();
            px = surface::render(k, &mut assets, &mut color, &mut depth).expect("render");
            times.push(t0.elapsed().as_secs_f64());
        }
        times.sort_by(f64::total_cmp);
        let checksum = surface::checksum(&color);
        let raw: Vec<u16> = color.iter().map(|c| c.into_storage()).collect();
        let cov: Vec<bool> = depth.iter().map(|&d| d != 0xFFFF).collect();
        let r = scene::render_reference(variant(name), 0, &light, &refs, &sphere, w, h);
        let rep = compare(&raw, &cov, &r);
        rows.push(Row {
            name,
            ns: times[times.len() / 2] * 1e9 / f64::from(px.max(1)),
            mcu: host_tests::report_mcu::of(&mcu, name, checksum),
            max: rep.max,
            p99: rep.p99,
            over2: rep.share_over_2,
            psnr: rep.psnr_db,
        });
    }
    let mut md = String::from(
        "# Surface detail: per-pixel lighting, bump and normal maps\n\n\
         The brick sphere of `fixel_scenes::surface` (2208 triangles, 64 x 64 brick maps, strength 0.02), \
         frame 0 under the point light of frame 0, 160 x 160, exact perspective unless stated; vertices \
         prepared once per frame and counted. Per drawn pixel. Error against the f64 per-pixel reference \
         (`host_tests::reference::lighting`; Gouraud against the same per-pixel ideal).\n\n\
         | variant | host ns/px | M0+ instr/px | M4F instr/px | max LSB | p99 LSB | > 2 LSB | PSNR dB |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in &rows {
        let (m0, m4) = r.mcu.map_or(("-".into(), "-".into()), |(a, b)| {
            (format!("{a:.1}"), format!("{b:.1}"))
        });
        md.push_str(&format!(
            "| `{}` | {:.1} | {m0} | {m4} | {} | {} | {:.2} % | {:.1} |\n",
            r.name,
            r.ns,
            r.max,
            r.p99,
            100.0 * r.over2,
            r.psnr
        ));
    }
    md.push_str(&resolved_section());
    md.push_str(
        "\nReproduce: `cargo xtask report` (or `cargo run --release -p host-tests --bin surface_report -- \
         --out target/report [--mcu target/report/mcu.tsv]`).\n\n![cost against error](surface.png)\n",
    );
    std::fs::write(out.join("surface.md"), md).expect("surface.md");
    let points: Vec<host_tests::cost_plot::Point> = rows
        .iter()
        .map(|r| host_tests::cost_plot::Point {
            name: r.name.to_string(),
            host_ns: r.ns,
            m4f: r.mcu.map(|m| m.1),
            psnr: r.psnr,
        })
        .collect();
    if let Err(e) = host_tests::cost_plot::write(
        &points,
        "surface detail: cost against PSNR",
        (30.0, 50.0),
        &out.join("surface.png"),
    ) {
        eprintln!("surface_report: no plot: {e}");
    }
    println!("surface_report: wrote {}", out.join("surface.md").display());
}

/// The real-time form, the lighting resolved into the texture (`bump_fast`): its own table,
/// as its scene differs (the benchmark sphere at 320 x 240, the light fixed in object
/// space). Error against its own f64 definition; the counts are the banded firmware
/// scene's, quoted from `cargo xtask mcu`'s table (`target/mcu/scenes.md`) when it exists.
fn resolved_section() -> String {
    let m = host_tests::bump_fast_scene::maps();
    let (got, e, seconds) = host_tests::bump_fast_scene::resolved_frame_timed(&m);
    let pixels = got.covered.iter().filter(|c| **c).count().max(1);
    let table = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/mcu/scenes.md"),
    )
    .unwrap_or_default();
    let count = |core: &str| {
        table
            .lines()
            .find(|l| l.starts_with(&format!("| bump_fast | {core} |")))
            .and_then(|l| l.split('|').nth(3))
            .map_or("-".to_string(), |v| v.trim().to_string())
    };
    format!(
        "\nThe real-time form: the lighting resolved into the sphere's texture for a light fixed in \
         object space (`bump::resolve_sphere`, once per light), then a plain textured draw of the \
         benchmark sphere (320 x 240, frame 0). Error against its own f64 definition (the f64 \
         resolve, drawn by the f64 renderer); M0+ / M4F: the banded firmware scene `bump_fast` of \
         `cargo xtask mcu`.\n\n\
         | variant | host ns/px | M0+ instr/px (bands) | M4F instr/px (bands) | max LSB | p99 LSB | > 2 LSB | PSNR dB |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|\n\
         | `bump-resolved` | {:.1} | {} | {} | {} | {} | {:.2} % | {:.1} |\n",
        seconds * 1e9 / pixels as f64,
        count("Cortex-M0+"),
        count("Cortex-M4F"),
        e.max,
        e.p99,
        100.0 * e.share_over_2,
        e.psnr_db
    )
}
