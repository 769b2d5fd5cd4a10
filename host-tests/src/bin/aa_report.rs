//! `cargo xtask report`, anti-aliasing: the benchmark cube (frame 0) at 1x,
//! regular-grid 2 x 2 and 4 x 4 supersampling in bands, and the rotated grid of 4 and 16
//! stratified jittered samples accumulated through bands (`examples/firmware/src/aa.rs`, the
//! firmware's code), 1x with post-process edge smoothing, and the `aa_edge` firmware's frame
//! (the `cube` scene's draw, each band smoothed at depth discontinuities,
//! `examples/firmware/src/edge_scene.rs`).
//!
//! ```text
//! aa_report --out DIR [--runs N] [--mcu mcu.tsv]
//! ```
//!
//! Columns: host ns per display pixel (median of N frames), exact M0+ and M4F instructions
//! per display pixel of `report_aa` (checksums checked against the host's), band RAM, and
//! the error against a 16 x 16 supersampled f64 reference (four 8 x 8 renders offset by a
//! quarter of their pixel): mean and max RGB565 LSB over edge pixels (those the reference
//! covers partly) and the whole frame's mean and PSNR. Writes `DIR/aa.md` and `DIR/aa.png`.

#[path = "../../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "../../../examples/firmware/src/aa.rs"]
#[allow(dead_code)]
mod aa;

#[path = "../../../examples/firmware/src/edge_scene.rs"]
mod edge_scene;

#[path = "../../../examples/firmware/src/alpha.rs"]
#[allow(dead_code)]
mod alpha;

use std::path::Path;
use std::time::Instant;

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use fixel::scene::SamplePattern;
use fixel::texture::Texture;
use fixel::Rgb565;
use fixel_scenes as demo;
use host_tests::reference::{self, RefTriangle};
use host_tests::report_args::ReportArgs;
use host_tests::scenes as ref_scenes;

const W: u32 = 320;
const H: u32 = 240;

struct Row {
    name: String,
    ns: f64,
    mcu: Option<(f64, f64)>,
    ram: String,
    edge_mean: f64,
    edge_max: f64,
    frame_mean: f64,
    psnr: f64,
}

fn texels() -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); 128 * 128];
    demo::checker_texture(128, 128, &mut t).unwrap();
    t
}

/// 16 x 16 samples per pixel: four 8 x 8 renders, each shifted by a quarter of its pixel.
fn reference16() -> (Vec<[f64; 3]>, Vec<f64>) {
    let scene = ref_scenes::cube(0);
    let base = ref_scenes::to_ref_triangles(&scene);
    let s = 8u32;
    let (sw, sh) = (f64::from(W * s), f64::from(H * s));
    let mut rgb = vec![[0.0; 3]; (W * H) as usize];
    let mut cov = vec![0.0; (W * H) as usize];
    for (dx, dy) in [(-0.25, -0.25), (0.25, -0.25), (-0.25, 0.25), (0.25, 0.25)] {
        let tris: Vec<RefTriangle> = base
            .iter()
            .map(|t| {
                let mut t = *t;
                for v in t.0.iter_mut() {
                    v.clip[0] += 2.0 * dx / sw * v.clip[3];
                    v.clip[1] -= 2.0 * dy / sh * v.clip[3];
                }
                t
            })
            .collect();
        let img = reference::render(&tris, Some(&scene.texture), &scene.mode, W * s, H * s);
        for y in 0..H * s {
            for x in 0..W * s {
                let i = (y * W * s + x) as usize;
                let o = ((y / s) * W + x / s) as usize;
                for (acc, v) in rgb[o].iter_mut().zip(img.rgb[i]) {
                    *acc += v;
                }
                if img.covered[i] {
                    cov[o] += 1.0;
                }
            }
        }
    }
    let n = 256.0;
    (
        rgb.into_iter().map(|c| c.map(|v| v / n)).collect(),
        cov.into_iter().map(|c| c / n).collect(),
    )
}

fn errors(px: &[Rgb565], refr: &[[f64; 3]], cov: &[f64]) -> (f64, f64, f64, f64) {
    let (mut es, mut en, mut em, mut all, mut sq) = (0.0, 0usize, 0.0f64, 0.0, 0.0);
    for ((p, r), c) in px.iter().zip(refr).zip(cov) {
        let v = RawU16::from(*p).into_inner();
        let ch = [
            f64::from(v >> 11),
            f64::from((v >> 5) & 63),
            f64::from(v & 31),
        ];
        let max = [31.0, 63.0, 31.0];
        let e = (0..3)
            .map(|k| (ch[k] - r[k] * max[k]).abs())
            .fold(0.0, f64::max);
        for k in 0..3 {
            sq += (255.0 * (ch[k] / max[k] - r[k])).powi(2);
        }
        all += e;
        if *c > 0.0 && *c < 1.0 {
            es += e;
            en += 1;
            em = em.max(e);
        }
    }
    let mse = sq / (3.0 * px.len() as f64);
    (
        es / en.max(1) as f64,
        em,
        all / px.len() as f64,
        10.0 * (255.0f64 * 255.0 / mse.max(1e-12)).log10(),
    )
}

fn main() {
    let ReportArgs {
        out,
        runs,
        mcu: mcu_path,
    } = ReportArgs::parse(
        "aa_report",
        "Speed against error for anti-aliasing (run by `cargo xtask report`)",
        "3",
    );
    std::fs::create_dir_all(&out).expect("output directory");
    let mcu = mcu_path
        .as_deref()
        .map(|p| host_tests::report_mcu::read(p, "aa"))
        .unwrap_or_default();
    let t = texels();
    let tex = Texture::new(&t, 128, 128).unwrap();
    let (refr, cov) = reference16();
    let mut buf = Box::new(aa::AaBuffers::new());
    let mut rows = Vec::new();
    let display_px = |img: &[Rgb565]| {
        img.iter()
            .filter(|&&p| p != Rgb565::new(0, 0, 0))
            .count()
            .max(1) as f64
    };
    for k in [1u32, 2, 4] {
        let mut img = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        let mut times = Vec::new();
        let mut checksum = 0;
        for _ in 0..runs.max(1) {
            let t0 = Instant::now();
            let r = aa::cube(k, tex, 0, &mut buf, Some(&mut img), &mut || {}, &mut || {}).unwrap();
            times.push(t0.elapsed().as_secs_f64());
            checksum = r.checksum;
        }
        let mode = format!("cube-{k}x{k}");
        let mcu_v = host_tests::report_mcu::of(&mcu, &mode, checksum);
        let e = errors(&img, &refr, &cov);
        times.sort_by(f64::total_cmp);
        rows.push(Row {
            name: if k == 1 {
                "1x (no anti-aliasing)".into()
            } else {
                format!("{k} x {k} regular grid, bands")
            },
            ns: times[times.len() / 2] * 1e9 / display_px(&img),
            mcu: mcu_v,
            ram: format!("{:.1} KB", f64::from(aa::band_ram(k)) / 1024.0),
            edge_mean: e.0,
            edge_max: e.1,
            frame_mean: e.2,
            psnr: e.3,
        });
    }
    let mut acc_buf = Box::new(aa::AccumBuffers::new());
    for (name, mode, p) in [
        (
            "rotated grid 4, accumulated in bands",
            "cube-rgss4-bands",
            SamplePattern::RotatedGrid4,
        ),
        (
            "jittered 16, accumulated in bands",
            "cube-jitter16-bands",
            SamplePattern::Jittered { n: 16, seed: 1 },
        ),
    ] {
        let mut img = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        let mut times = Vec::new();
        let mut checksum = 0;
        for _ in 0..runs.max(1) {
            let t0 = Instant::now();
            let r = aa::cube_accumulated(
                p,
                tex,
                0,
                &mut acc_buf,
                Some(&mut img),
                &mut || {},
                &mut || {},
            )
            .unwrap();
            times.push(t0.elapsed().as_secs_f64());
            checksum = r.checksum;
        }
        let e = errors(&img, &refr, &cov);
        times.sort_by(f64::total_cmp);
        rows.push(Row {
            name: name.into(),
            ns: times[times.len() / 2] * 1e9 / display_px(&img),
            mcu: host_tests::report_mcu::of(&mcu, mode, checksum),
            ram: format!("{:.1} KB", f64::from(aa::ACCUM_RAM) / 1024.0),
            edge_mean: e.0,
            edge_max: e.1,
            frame_mean: e.2,
            psnr: e.3,
        });
    }
    {
        let mut sm = Box::new(aa::SmoothBuffers::new());
        let mut img = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        let mut times = Vec::new();
        let mut checksum = 0;
        for _ in 0..runs.max(1) {
            let t0 = Instant::now();
            let r =
                aa::cube_smoothed(tex, 0, &mut sm, Some(&mut img), &mut || {}, &mut || {}).unwrap();
            times.push(t0.elapsed().as_secs_f64());
            checksum = r.checksum;
        }
        let e = errors(&img, &refr, &cov);
        times.sort_by(f64::total_cmp);
        rows.push(Row {
            name: format!(
                "1x + edge smoothing (threshold {}), bands",
                aa::SMOOTH_THRESHOLD
            ),
            ns: times[times.len() / 2] * 1e9 / display_px(&img),
            mcu: host_tests::report_mcu::of(&mcu, "cube-smoothed", checksum),
            ram: format!("{:.1} KB", f64::from(aa::SMOOTH_RAM) / 1024.0),
            edge_mean: e.0,
            edge_max: e.1,
            frame_mean: e.2,
            psnr: e.3,
        });
    }
    {
        // The `aa_edge` scene: the `cube` scene's draw from the texture's footprints.
        let mut fp = vec![0u64; t.len()];
        fixel::texture::write_footprints(&tex, &mut fp).unwrap();
        let mip = fixel::texture::MipTexture::single(tex)
            .with_footprints(&fp)
            .unwrap();
        let mut small = Box::new(scenes::SmallBuffers::with_storage());
        let mut edge = Box::new(edge_scene::EdgeBuffers::new());
        let mut img = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        let mut times = Vec::new();
        let mut checksum = 0;
        for _ in 0..runs.max(1) {
            let t0 = Instant::now();
            let r = edge_scene::aa_edge(
                &mut small,
                &mut edge,
                mip,
                0,
                Some(&mut img),
                &mut || {},
                &mut || {},
            )
            .unwrap();
            times.push(t0.elapsed().as_secs_f64());
            checksum = r.checksum;
        }
        let e = errors(&img, &refr, &cov);
        times.sort_by(f64::total_cmp);
        rows.push(Row {
            name: format!(
                "1x + silhouettes from depth (`aa_edge`, threshold {}), bands",
                edge_scene::THRESHOLD
            ),
            ns: times[times.len() / 2] * 1e9 / display_px(&img),
            mcu: host_tests::report_mcu::of(&mcu, "cube-edge", checksum),
            ram: format!(
                "{:.1} KB",
                f64::from(2 * W * 8 * 2 + edge_scene::EDGE_RAM) / 1024.0
            ),
            edge_mean: e.0,
            edge_max: e.1,
            frame_mean: e.2,
            psnr: e.3,
        });
    }
    let mut md = String::from(
        "# Anti-aliasing\n\n\
         The benchmark cube, frame 0, 320 x 240, lit bilinear. Error against a 16 x 16 supersampled f64 \
         reference: edges = pixels the reference covers partly. Per display pixel (35,485 covered). \
         Band RAM: the k-times colour and depth band plus one display band (8 rows).\n\n\
         | variant | host ns/px | M0+ instr/px | M4F instr/px | RAM | edges mean / max LSB | frame mean LSB | PSNR dB |\n\
         |---|---:|---:|---:|---|---:|---:|---:|\n",
    );
    for r in &rows {
        let (m0, m4) = r.mcu.map_or(("-".into(), "-".into()), |(a, b)| {
            (format!("{a:.1}"), format!("{b:.1}"))
        });
        md.push_str(&format!(
            "| {} | {:.1} | {m0} | {m4} | {} | {:.2} / {:.1} | {:.3} | {:.1} |\n",
            r.name, r.ns, r.ram, r.edge_mean, r.edge_max, r.frame_mean, r.psnr
        ));
    }
    md.push_str("\nReproduce: `cargo xtask report` (or `cargo run --release -p host-tests --bin aa_report -- --out target/report [--mcu target/report/mcu.tsv]`).\n\n![cost against edge error](aa.png)\n");
    // Transparency: the quad of `alpha.rs` over the floor, per pixel the quad writes.
    let amcu = mcu_path
        .as_deref()
        .map(|p| host_tests::report_mcu::read(p, "alpha"))
        .unwrap_or_default();
    let mut t8 = vec![Rgb565::new(0, 0, 0); 64];
    demo::checker_texture(8, 8, &mut t8).unwrap();
    let q = Texture::new(&t8, 8, 8).unwrap();
    let mut t64 = vec![Rgb565::new(0, 0, 0); 64 * 64];
    demo::checker_texture(64, 64, &mut t64).unwrap();
    let f64t = Texture::new(&t64, 64, 64).unwrap();
    let plane = alpha::plane();
    md.push_str(
        "\n## Transparency\n\nThe floor drawn opaque into a 240 x 180 frame, then a 2 x 2 quad with an alpha \
         shader (`examples/firmware/src/alpha.rs`); only the quad's draw is counted, per pixel it writes. Error: \
         `host-tests/tests/alpha.rs` (over against an f64 blend of the reference floor and quad: 98.7 % of \
         pixels within 1.5 LSB, the rest at alpha-texel edges; alpha 0 and 255 exact).\n\n\
         | variant | host ns/px | M0+ instr/px | M4F instr/px |\n|---|---:|---:|---:|\n",
    );
    for (k, name) in alpha::MODES.iter().enumerate() {
        let (w, h) = (alpha::W, alpha::H);
        let (mut c, mut d) = (
            vec![Rgb565::new(0, 0, 0); (w * h) as usize],
            vec![0u16; (w * h) as usize],
        );
        let mut times = Vec::new();
        let mut px = 0;
        for _ in 0..runs.max(1) {
            alpha::floor(f64t, &mut c, &mut d).unwrap();
            let t0 = Instant::now();
            px = alpha::quad_mode(k, q, &plane, &mut c, &mut d).unwrap();
            times.push(t0.elapsed().as_secs_f64());
        }
        times.sort_by(f64::total_cmp);
        let m = host_tests::report_mcu::of(&amcu, name, alpha::checksum(&c));
        let (m0, m4) = m.map_or(("-".into(), "-".into()), |(a, b)| {
            (format!("{a:.1}"), format!("{b:.1}"))
        });
        md.push_str(&format!(
            "| `{name}` | {:.1} | {m0} | {m4} |\n",
            times[times.len() / 2] * 1e9 / f64::from(px.max(1))
        ));
    }
    std::fs::write(out.join("aa.md"), md).expect("aa.md");
    if let Err(e) = plot(&rows, &out.join("aa.png")) {
        eprintln!("aa_report: no plot: {e}");
    }
    println!("aa_report: wrote {}", out.join("aa.md").display());
}

fn plot(rows: &[Row], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    host_tests::plot_font::register()?;
    let (w, h) = (900u32, 420u32);
    let mut buf = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let pts: Vec<(f64, f64, &str)> = rows
            .iter()
            .map(|r| (r.ns, r.edge_mean, r.name.as_str()))
            .collect();
        let x1 = pts.iter().map(|p| p.0).fold(1.0, f64::max) * 1.6;
        let y1 = pts.iter().map(|p| p.1).fold(1.0, f64::max) * 1.2;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                "anti-aliasing: host cost against edge error",
                ("sans-serif", 18),
            )
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d((1.0..x1).log_scale(), 0.0..y1)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc("host ns / display pixel (log)")
            .y_desc("mean edge error, RGB565 LSB")
            .label_style(("sans-serif", 13))
            .draw()
            .map_err(|e| e.to_string())?;
        // The Pareto front (cheaper or less wrong than every other), joined; the labels
        // off it grey.
        let on = host_tests::cost_plot::front(
            &pts.iter().map(|p| (p.0, p.1)).collect::<Vec<_>>(),
            false,
        );
        chart
            .draw_series(LineSeries::new(
                on.iter().map(|&i| (pts[i].0, pts[i].1)),
                BLUE.mix(0.5).stroke_width(2),
            ))
            .map_err(|e| e.to_string())?;
        for (k, (x, y, name)) in pts.into_iter().enumerate() {
            let ink = if on.contains(&k) {
                BLACK
            } else {
                RGBColor(150, 150, 150)
            };
            chart
                .draw_series([Circle::new((x, y), 5, BLUE.filled())])
                .map_err(|e| e.to_string())?;
            chart
                .draw_series([Text::new(
                    name.to_string(),
                    (x * 1.04, y + y1 * 0.02),
                    ("sans-serif", 12).into_font().color(&ink),
                )])
                .map_err(|e| e.to_string())?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    host_tests::png_io::write_png_rgb8(path, w, h, &buf).map_err(|e| e.to_string())
}
