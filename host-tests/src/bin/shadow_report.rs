//! Report rows for shadow maps: map sizes 32, 64, 128 x the three filters, for the demo
//! scene under the high directional light and the spot light. Per row: host ns per
//! lit-pass pixel (best of 5), light-pass ns per map texel, the error against the f64
//! reference with a map of the same size (fixel's own error) and against the f64 reference
//! with a 1024 x 1024 single-tap map (the aliasing of a small map). Writes
//! `target/report/shadow.md`.
//!
//! `cargo run --release -p host-tests --bin shadow_report [-- --out DIR]` (`cargo xtask
//! report` runs it, with `--mcu target/report/mcu.tsv`). The Cortex-M0+ and Cortex-M4F
//! instruction counts of every row are the report firmware `report_shadow`'s
//! (`examples/firmware/src/shadow_modes.rs`: whole 320 x 240 frame, textured and lit, light
//! pass and lit pass counted apart), checked against the same code's checksums run here;
//! the `shadow_*` scenes of `cargo xtask mcu` (bands of 4 rows, 64 x 64 map) are quoted
//! from `target/mcu/scenes.md` when it exists.

#[path = "../../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "../../../examples/firmware/src/shadow_modes.rs"]
#[allow(dead_code)]
mod shadow_modes;

use std::path::PathBuf;
use std::time::Instant;

use clap::Parser;
use fixel::shading::pcf::{Pcf2x2, Pcf3x3, ShadowFilter, SingleTap};
use fixel::shading::shadow::{Bias, LightKind, LightSpace, Outside};
use fixel_scenes::shadow::{self as scene, SceneLight};
use host_tests::reference::shadow::{light_map, lit_pass, RefShadowFilter};
use host_tests::shadow_scene::{
    demo_meshes, fixel_shadow, fixel_shadow_uv, lit_error, ref_bias, ref_scene, Setup,
};

fn ref_filter<F: ShadowFilter>() -> RefShadowFilter {
    match F::NAME {
        "single tap" => RefShadowFilter::Single,
        "PCF 2x2 bilinear" => RefShadowFilter::Pcf2x2,
        _ => RefShadowFilter::Pcf3x3,
    }
}

/// Exact instructions per pixel of firmware scene `scene` on `core` from `cargo xtask mcu`'s
/// table, or "-".
fn mcu(table: &str, scene: &str, core: &str) -> String {
    table
        .lines()
        .find(|l| l.starts_with(&format!("| {scene} | {core} |")))
        .and_then(|l| l.split('|').nth(3))
        .map(|v| v.trim().to_string())
        .unwrap_or_else(|| "-".into())
}

/// The firmware scene of a light, map size and filter (only the 64 x 64 map has one).
fn scene_of(light: &str, size: u32, filter: &str) -> Option<&'static str> {
    match (light, size, filter) {
        ("directional", 64, "single tap") => Some("shadow_single"),
        ("directional", 64, "PCF 2x2 bilinear") => Some("shadow_pcf2x2"),
        ("directional", 64, "PCF 3x3") => Some("shadow_pcf3x3"),
        ("spot", 64, "PCF 2x2 bilinear") => Some("shadow_spot"),
        _ => None,
    }
}

/// One point of the plot: light, map size, filter, host ns/px, wrong-side share (%) vs the
/// 1024² map.
type Point = (&'static str, u32, &'static str, f64, f64);

/// The report firmware's counts: lit pass per (light, size, filter) and light pass per
/// (light, size), M0+ and M4F, each checked against this machine's run of the same code.
#[derive(Default)]
struct Firmware {
    lit: std::collections::HashMap<(&'static str, u32, &'static str), Counts>,
    light: std::collections::HashMap<(&'static str, u32), Counts>,
}

/// M0+ and M4F instructions per pixel (or texel), when measured.
type Counts = Option<(f64, f64)>;

impl Firmware {
    fn new(path: Option<&std::path::Path>) -> Self {
        use embedded_graphics_core::pixelcolor::Rgb565;
        let rows = path
            .map(|p| host_tests::report_mcu::read(p, "shadow"))
            .unwrap_or_default();
        let mut fw = Firmware::default();
        let (mut t128, mut t64) = (
            vec![Rgb565::new(0, 0, 0); 128 * 128],
            vec![Rgb565::new(0, 0, 0); 64 * 64],
        );
        fixel_scenes::checker_texture(128, 128, &mut t128).unwrap();
        fixel_scenes::checker_texture(64, 64, &mut t64).unwrap();
        let tex = [
            fixel::texture::Texture::new(&t128, 128, 128).unwrap(),
            fixel::texture::Texture::new(&t64, 64, 64).unwrap(),
        ];
        let px = (shadow_modes::W * shadow_modes::H) as usize;
        let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); px], vec![0u16; px]);
        let mut map = vec![0u16; shadow_modes::MAP_TEXELS];
        let names = ["single tap", "PCF 2x2 bilinear", "PCF 3x3"];
        for (l, light) in shadow_modes::LIGHTS.iter().enumerate() {
            for size in shadow_modes::SIZES {
                shadow_modes::light_pass(l, size, &mut map).unwrap();
                let n = (size * size) as usize;
                let c = shadow_modes::map_checksum(&map[..n]);
                let mode = format!("{light}-{size}-light");
                fw.light
                    .insert((light, size), host_tests::report_mcu::of(&rows, &mode, c));
                for (f, filter) in shadow_modes::FILTERS.iter().enumerate() {
                    shadow_modes::lit_pass(l, f, size, &map, tex, &mut color, &mut depth).unwrap();
                    let c = shadow_modes::checksum(&color);
                    let mode = format!("{light}-{size}-{filter}");
                    fw.lit.insert(
                        (light, size, names[f]),
                        host_tests::report_mcu::of(&rows, &mode, c),
                    );
                }
            }
        }
        fw
    }
}

fn row<K: LightKind, F: ShadowFilter, const M: usize>(
    space: &LightSpace<K>,
    size: u32,
    truth: &host_tests::reference::shadow::RefShadowImage,
    table: &str,
    fw: &Firmware,
    points: &mut Vec<Point>,
) -> String {
    let m = demo_meshes();
    let cam = scene::camera();
    let s = Setup::new::<F>(size);
    // Timing: the whole render (both passes), best of 5, per lit pixel.
    let mut best = f64::MAX;
    let mut fx = fixel_shadow::<K, F, M>(&m, &cam, space, &s);
    for _ in 0..5 {
        let t = Instant::now();
        fx = fixel_shadow::<K, F, M>(&m, &cam, space, &s);
        best = best.min(t.elapsed().as_secs_f64());
    }
    let sc = ref_scene(&m, &cam, space.matrix(), s.w, s.h);
    let map = light_map(&sc, size, false);
    let r = lit_pass(&sc, &map, ref_filter::<F>(), &ref_bias(&s.bias), 1.0);
    let own = lit_error(&fx.lit, &fx.covered, &r.lit, &r.covered);
    let alias = lit_error(&fx.lit, &fx.covered, &truth.lit, &truth.covered);
    let ns = best * 1e9 / f64::from(fx.pixels);
    let share = 100.0 * alias.wrong as f64 / alias.both.max(1) as f64;
    points.push((K::NAME, size, F::NAME, ns, share));
    let _ = (table, scene_of(K::NAME, size, F::NAME));
    let (m0, m4) = fw
        .lit
        .get(&(K::NAME, size, F::NAME))
        .copied()
        .flatten()
        .map_or(("-".into(), "-".into()), |(a, b)| {
            (format!("{a:.1}"), format!("{b:.1}"))
        });
    format!(
        "| {} | {size} | {} | {:.1} | {m0} | {m4} | {:.4} | {} | {:.4} | {} ({:.2} %) |",
        K::NAME,
        F::NAME,
        ns,
        own.mean,
        own.wrong,
        alias.mean,
        alias.wrong,
        share
    )
}

/// A row of the real-time form (`ShadowedUv`, light coordinates from texture coordinates),
/// 64 x 64 map: host ns/px, the banded firmware scene's instructions per pixel where there is
/// one, and the errors as [`row`]'s. `M` is 2 plus the light's varyings.
fn row_uv<K: LightKind, F: ShadowFilter, const M: usize>(
    space: &LightSpace<K>,
    truth: &host_tests::reference::shadow::RefShadowImage,
    table: &str,
) -> String {
    let m = demo_meshes();
    let cam = scene::camera();
    let s = Setup::new::<F>(64);
    let mut best = f64::MAX;
    let mut fx = fixel_shadow_uv::<K, F, M>(&m, &cam, space, &s);
    for _ in 0..5 {
        let t = Instant::now();
        fx = fixel_shadow_uv::<K, F, M>(&m, &cam, space, &s);
        best = best.min(t.elapsed().as_secs_f64());
    }
    let sc = ref_scene(&m, &cam, space.matrix(), s.w, s.h);
    let map = light_map(&sc, 64, false);
    let r = lit_pass(&sc, &map, ref_filter::<F>(), &ref_bias(&s.bias), 1.0);
    let own = lit_error(&fx.lit, &fx.covered, &r.lit, &r.covered);
    let alias = lit_error(&fx.lit, &fx.covered, &truth.lit, &truth.covered);
    let firmware = match (K::NAME, F::NAME) {
        ("directional", "single tap") => Some("shadow_single_uv"),
        _ => None,
    };
    let (m0, m4) = firmware.map_or(("-".into(), "-".into()), |f| {
        (mcu(table, f, "Cortex-M0+"), mcu(table, f, "Cortex-M4F"))
    });
    format!(
        "| {} | {} | {:.1} | {m0} | {m4} | {:.4} | {} | {:.4} | {} ({:.2} %) |",
        K::NAME,
        F::NAME,
        best * 1e9 / f64::from(fx.pixels),
        own.mean,
        own.wrong,
        alias.mean,
        alias.wrong,
        100.0 * alias.wrong as f64 / alias.both.max(1) as f64
    )
}

fn truth<K: LightKind>(space: &LightSpace<K>) -> host_tests::reference::shadow::RefShadowImage {
    let m = demo_meshes();
    let sc = ref_scene(&m, &scene::camera(), space.matrix(), 320, 240);
    let map = light_map(&sc, 1024, false);
    let b = Bias {
        constant: 16,
        slope: 192,
        max: 8192 * 16,
    };
    let _ = Outside::Lit;
    lit_pass(&sc, &map, RefShadowFilter::Single, &ref_bias(&b), 1.0)
}

/// Command line (`cargo xtask report` passes `--out` and `--mcu`).
#[derive(Parser)]
#[command(
    name = "shadow_report",
    about = "Report rows for shadow maps: map sizes 32, 64, 128 x the three filters",
    long_about = None
)]
struct Args {
    /// Output directory for shadow.md and shadow.png [default: the workspace's target/report]
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Microcontroller instruction counts (mcu.tsv, written by `cargo xtask report`)
    #[arg(long, value_name = "FILE")]
    mcu: Option<PathBuf>,
}

fn main() {
    let args = Args::parse();
    let high = scene::directional(SceneLight::High).unwrap();
    let spot = scene::spot().unwrap();
    let (th, ts) = (truth(&high), truth(&spot));
    let table = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/mcu/scenes.md"),
    )
    .unwrap_or_default();
    let fw = Firmware::new(args.mcu.as_deref());
    let mut out = String::from(
        "Shadow maps on the demo scene (cube on a floor, 320x240). host ns/px: both passes, \
         white inner shader, best of 5 (noisy on a shared machine). M0+ / M4F: exact \
         instructions per pixel of the lit pass (textured, lit, whole frame) of the report \
         firmware `report_shadow` (`examples/firmware/src/shadow_modes.rs`, checksums equal \
         to the host's). Errors in lit fraction (0..1) per covered pixel; wrong side = \
         |Δlit| > 0.5.\n\n",
    );
    let light_row = |light: &'static str| {
        let cell = |size: u32| {
            fw.light
                .get(&(light, size))
                .copied()
                .flatten()
                .map_or("- / -".to_string(), |(a, b)| format!("{a:.1} / {b:.1}"))
        };
        format!(
            "| {light} | {} | {} | {} |\n",
            cell(32),
            cell(64),
            cell(128)
        )
    };
    out +=
        "Light pass (cube + floor, geometry included), instructions per map texel, M0+ / M4F:\n\n\
            | light | 32² | 64² | 128² |\n|---|---|---|---|\n";
    out += &light_row("directional");
    out += &light_row("spot");
    out += "\n";
    if table.is_empty() {
        out += "(`target/mcu/scenes.md` missing: run `cargo xtask mcu` for the M0+ / M4F columns.)\n\n";
    }
    out += &format!(
        "Light pass per map texel (64x64): M0+ {}, M4F {}. Lit pass without shadows: M0+ {}, M4F {}.\n\n",
        mcu(&table, "shadow_light", "Cortex-M0+"),
        mcu(&table, "shadow_light", "Cortex-M4F"),
        mcu(&table, "shadow_none", "Cortex-M0+"),
        mcu(&table, "shadow_none", "Cortex-M4F"),
    );
    out += "| light | map | filter | host ns/px | M0+ instr/px | M4F instr/px | mean \\|Δlit\\| vs f64, same map | wrong-side px vs f64, same map | mean \\|Δlit\\| vs f64 1024² | wrong-side px vs f64 1024² |\n|---|---|---|---|---|---|---|---|---|---|\n";
    let mut pts = Vec::new();
    for size in [32, 64, 128] {
        out += &row::<_, SingleTap, 3>(&high, size, &th, &table, &fw, &mut pts);
        out += "\n";
        out += &row::<_, Pcf2x2, 3>(&high, size, &th, &table, &fw, &mut pts);
        out += "\n";
        out += &row::<_, Pcf3x3, 3>(&high, size, &th, &table, &fw, &mut pts);
        out += "\n";
    }
    for size in [32, 64, 128] {
        out += &row::<_, SingleTap, 4>(&spot, size, &ts, &table, &fw, &mut pts);
        out += "\n";
        out += &row::<_, Pcf2x2, 4>(&spot, size, &ts, &table, &fw, &mut pts);
        out += "\n";
        out += &row::<_, Pcf3x3, 4>(&spot, size, &ts, &table, &fw, &mut pts);
        out += "\n";
    }
    out += "\nThe real-time form (`ShadowedUv`: each pixel's light coordinates from its texture \
        coordinates, solved per triangle; the span loop interpolates no light varying), 64x64 \
        map, the same errors; M0+ / M4F: the banded firmware scene `shadow_single_uv` of \
        `cargo xtask mcu` (beside `shadow_single`: M0+ ";
    out += &format!(
        "{}, M4F {}; `shadow_none`: M0+ {}, M4F {}).\n\n",
        mcu(&table, "shadow_single", "Cortex-M0+"),
        mcu(&table, "shadow_single", "Cortex-M4F"),
        mcu(&table, "shadow_none", "Cortex-M0+"),
        mcu(&table, "shadow_none", "Cortex-M4F"),
    );
    out += "| light | filter | host ns/px | M0+ instr/px (bands) | M4F instr/px (bands) | mean \\|Δlit\\| vs f64, same map | wrong-side px vs f64, same map | mean \\|Δlit\\| vs f64 1024² | wrong-side px vs f64 1024² |\n|---|---|---|---|---|---|---|---|---|\n";
    out += &row_uv::<_, SingleTap, 5>(&high, &th, &table);
    out += "\n";
    out += &row_uv::<_, Pcf2x2, 5>(&high, &th, &table);
    out += "\n";
    out += &row_uv::<_, Pcf3x3, 5>(&high, &th, &table);
    out += "\n";
    out += &row_uv::<_, Pcf2x2, 6>(&spot, &ts, &table);
    out += "\n";
    out += "\n![shadow maps: host cost against aliasing](shadow.png)\n";
    print!("{out}");
    let dir = args.out.unwrap_or_else(|| {
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/report")
    });
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("shadow.md"), &out).unwrap();
    if let Err(e) =
        host_tests::plot_font::register().and_then(|()| plot(&pts, &dir.join("shadow.png")))
    {
        eprintln!("shadow_report: plot: {e}");
    }
}

/// Host ns/px (x) against the share of pixels on the wrong side of a shadow edge compared
/// with a 1024² f64 map (y, lower is better): one point per light, map size and filter.
fn plot(pts: &[Point], path: &std::path::Path) -> Result<(), String> {
    use plotters::prelude::*;
    let (w, h) = (900u32, 560u32);
    let mut buf = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let xmax = pts.iter().map(|p| p.3).fold(0.0, f64::max) * 1.15;
        let ymax = pts.iter().map(|p| p.4).fold(0.0, f64::max) * 1.15;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                "shadow maps: host cost vs aliasing (against a 1024² f64 map)",
                ("sans-serif", 20),
            )
            .margin(14)
            .margin_bottom(30)
            .x_label_area_size(44)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0..xmax.max(1.0), 0.0..ymax.max(1.0))
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc("host ns per lit pixel, both passes (best of 5, lower is faster)")
            .y_desc("pixels on the wrong side of a shadow edge, % (lower is better)")
            .label_style(("sans-serif", 14))
            .draw()
            .map_err(|e| e.to_string())?;
        let colour = |f: &str| match f {
            "single tap" => RGBColor(214, 39, 40),
            "PCF 2x2 bilinear" => RGBColor(31, 119, 180),
            _ => RGBColor(44, 160, 44),
        };
        // The Pareto front over every map size and filter (faster or fewer wrong pixels
        // than every other), joined.
        let xy: Vec<(f64, f64)> = pts.iter().map(|p| (p.3, p.4)).collect();
        let on = host_tests::cost_plot::front(&xy, false);
        chart
            .draw_series(LineSeries::new(
                on.iter().map(|&i| xy[i]),
                BLACK.mix(0.4).stroke_width(2),
            ))
            .map_err(|e| e.to_string())?;
        for (light, size, filter, x, y) in pts {
            let c = colour(filter);
            let style = if *light == "spot" {
                c.stroke_width(2)
            } else {
                c.filled()
            };
            chart
                .draw_series(std::iter::once(Circle::new((*x, *y), 6, style)))
                .map_err(|e| e.to_string())?;
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((*x, *y))
                        + Text::new(format!("{size}"), (8, -6), ("sans-serif", 12)),
                ))
                .map_err(|e| e.to_string())?;
        }
        for (k, f) in ["single tap", "PCF 2x2 bilinear", "PCF 3x3"]
            .iter()
            .enumerate()
        {
            let y = 70 + 20 * k as i32;
            root.draw(&Circle::new((w as i32 - 200, y), 6, colour(f).filled()))
                .map_err(|e| e.to_string())?;
            root.draw(&Text::new(*f, (w as i32 - 188, y - 7), ("sans-serif", 14)))
                .map_err(|e| e.to_string())?;
        }
        root.draw(&Text::new(
            "filled = directional light, ring = spot light; labels = map size; line = Pareto front",
            (w as i32 - 560, h as i32 - 20),
            ("sans-serif", 13),
        ))
        .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    host_tests::png_io::write_png_rgb8(path, w, h, &buf).map_err(|e| e.to_string())
}
