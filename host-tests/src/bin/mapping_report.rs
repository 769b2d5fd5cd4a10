//! `cargo xtask report`, texture-coordinate generation: one row per generator
//! over the 860 vertices of the Utah teapot baked from OBJ, and one for the triplanar teapot
//! frame (240 x 180).
//!
//! ```text
//! mapping_report --out DIR [--runs N] [--mcu mcu.tsv]
//! ```
//!
//! Columns: host ns per vertex (or per pixel; median of N runs on this machine), exact M0+
//! and M4F instructions per vertex (or per pixel) of the firmware `report_mapping` (from
//! `mcu.tsv`, checksums checked against the host's), and the error against the f64
//! reference: the largest coordinate error in units of 2^-16 texture (the median too), or
//! for triplanar the frame's max / p99 RGB565 LSB and PSNR. Writes `DIR/mapping.md` and
//! `DIR/mapping.png` (cost against error).

#[path = "../../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "../../../examples/firmware/src/mapping.rs"]
#[allow(dead_code)]
mod mapping;

#[allow(dead_code)]
mod teapot {
    include!("../../../assets/teapot/teapot_mesh.rs");
}

use std::path::Path;
use std::time::Instant;

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use fixel::geometry::Vertex;
use fixel::math::{Fx, Vec3};
use fixel::scene::{Camera, DirectionalLight};
use fixel::shading::triplanar::TriplanarMesh;
use fixel::texture::Texture;
use fixel::Rgb565;
use host_tests::adapter;
use host_tests::metrics::compare;
use host_tests::reference::two_stage::{RefRule, RefSurface};
use host_tests::reference::uv_gen::{RefAxis, RefUvMapping};
use host_tests::reference::{triplanar, RefFilter};
use host_tests::report_args::ReportArgs;
use host_tests::scenes::procedural_texture;

struct Row {
    name: String,
    unit: &'static str,
    ns: f64,
    mcu: Option<(f64, f64)>,
    error: String,
    /// For the plot: error in a common scale (units of 2^-16, or 100 − PSNR for frames).
    err_x: f64,
}

fn f(p: Vec3) -> [f64; 3] {
    [p.x.to_num(), p.y.to_num(), p.z.to_num()]
}

/// The reference coordinates of generator `k` (as `mapping::generate`).
fn reference(k: usize, p: [f64; 3], n: [f64; 3]) -> ([f64; 2], bool) {
    let c = [0.0; 3];
    match k {
        0 => RefUvMapping::Planar {
            origin: f(Vec3::from_num(-3, 1.75, 0)),
            s: f(Vec3::from_num(1.0 / 6.5, 0, 0)),
            t: f(Vec3::from_num(0, -1.0 / 3.5, 0)),
        }
        .uv(p),
        1 => RefUvMapping::Cylindrical {
            center: c,
            axis: RefAxis::Y,
            top: 1.6,
            bottom: -1.6,
        }
        .uv(p),
        2 => RefUvMapping::Spherical {
            center: c,
            axis: RefAxis::Y,
        }
        .uv(p),
        3 => RefSurface::Cylinder {
            center: c,
            axis: RefAxis::Y,
            radius: 4.0,
            top: 2.0,
            bottom: -2.0,
        }
        .uv(RefRule::Normal, p, n),
        _ => RefSurface::Sphere {
            center: c,
            axis: RefAxis::Y,
            radius: 4.0,
        }
        .uv(
            RefRule::Reflected {
                eye: [0.0, 3.0, 10.0],
            },
            p,
            n,
        ),
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let ReportArgs {
        out,
        runs,
        mcu: mcu_path,
    } = ReportArgs::parse(
        "mapping_report",
        "Speed against error for texture-coordinate generation (run by `cargo xtask report`)",
        "5",
    );
    std::fs::create_dir_all(&out).expect("output directory");
    let mcu = mcu_path
        .as_deref()
        .map(|p| host_tests::report_mcu::read(p, "mapping"))
        .unwrap_or_default();
    let (p, n) = (&teapot::TEAPOT_POSITIONS[..], &teapot::TEAPOT_NORMALS[..]);
    let mut rows = Vec::new();
    let mut uvs = vec![[Fx::ZERO; 2]; p.len()];
    for (k, name) in mapping::GENERATORS.iter().enumerate() {
        let times: Vec<f64> = (0..runs.max(1))
            .map(|_| {
                let t0 = Instant::now();
                mapping::generate(k, p, n, &mut uvs).expect("generator");
                t0.elapsed().as_secs_f64() * 1e9 / p.len() as f64
            })
            .collect();
        let mut errs: Vec<f64> = p
            .iter()
            .zip(n)
            .zip(&uvs)
            .map(|((&pp, &nn), got)| {
                let (want, _) = reference(k, f(pp), f(nn));
                let wraps = k != 0;
                (0..2)
                    .map(|c| {
                        let mut d = got[c].to_num::<f64>() - want[c];
                        if c == 0 && wraps {
                            d -= d.round();
                        }
                        d.abs() * 65536.0
                    })
                    .fold(0.0, f64::max)
            })
            .collect();
        errs.sort_by(f64::total_cmp);
        let (med, max) = (errs[errs.len() / 2], errs[errs.len() - 1]);
        let p99 = errs[errs.len() * 99 / 100];
        rows.push(Row {
            name: name.to_string(),
            unit: "vertex",
            ns: median(times),
            mcu: host_tests::report_mcu::of(&mcu, name, mapping::checksum(&uvs)),
            error: format!("median {med:.2}, p99 {p99:.2}, max {max:.2} (2^-16 texture)"),
            err_x: p99,
        });
    }
    // The triplanar frame.
    let rt = procedural_texture(64, 64);
    let texels = adapter::texels(&rt);
    let tex = Texture::new(&texels, 64, 64).expect("texture");
    let (w, h) = (mapping::W, mapping::H);
    let (mut color, mut depth) = (
        vec![Rgb565::new(0, 0, 0); (w * h) as usize],
        vec![0u16; (w * h) as usize],
    );
    let mut times = Vec::new();
    let mut result = (0, 0);
    for _ in 0..runs.max(1) {
        let t0 = Instant::now();
        result = mapping::triplanar_frame(
            mapping::PerPixel::Triplanar,
            tex,
            p,
            n,
            &teapot::TEAPOT_INDICES,
            &mut color,
            &mut depth,
            &mut || {},
            &mut || {},
        )
        .expect("triplanar frame");
        times.push(t0.elapsed().as_secs_f64());
    }
    let camera = Camera::perspective(
        fixel::math::Angle::from_degrees(Fx::from_num(40)),
        Fx::from_num(4) / 3,
        Fx::from_num(0.5),
        Fx::from_num(30),
    )
    .expect("camera");
    let mut tris: Vec<[Vertex<7>; 3]> = Vec::new();
    TriplanarMesh {
        positions: p,
        normals: n,
        indices: &teapot::TEAPOT_INDICES,
        texels_per_unit: Fx::from_num(40),
    }
    .triangles(
        &mapping::triplanar_model(),
        &camera,
        Some(&DirectionalLight::default()),
        |t| tris.push(*t),
    );
    let reference = triplanar::render(&tris, &rt, RefFilter::Bilinear, 0.5, w, h);
    let raw: Vec<u16> = color
        .iter()
        .map(|&c| RawU16::from(c).into_inner())
        .collect();
    let covered: Vec<bool> = depth.iter().map(|&d| d != u16::MAX).collect();
    let rep = compare(&raw, &covered, &reference);
    rows.push(Row {
        name: "triplanar".into(),
        unit: "pixel",
        ns: median(times) * 1e9 / f64::from(result.1.max(1)),
        mcu: host_tests::report_mcu::of(&mcu, "triplanar", result.0),
        error: format!(
            "max {} / p99 {} LSB, {:.1} dB",
            rep.max, rep.p99, rep.psnr_db
        ),
        err_x: 100.0 - rep.psnr_db,
    });
    // Cylindrical coordinates per pixel.
    {
        let mut times = Vec::new();
        let mut result = (0, 0);
        for _ in 0..runs.max(1) {
            let t0 = Instant::now();
            result = mapping::triplanar_frame(
                mapping::PerPixel::Cylindrical,
                tex,
                p,
                n,
                &teapot::TEAPOT_INDICES,
                &mut color,
                &mut depth,
                &mut || {},
                &mut || {},
            )
            .expect("per-pixel frame");
            times.push(t0.elapsed().as_secs_f64());
        }
        let mut tri3: Vec<[Vertex<4>; 3]> = Vec::new();
        fixel::shading::uv_per_pixel::PerPixelMesh {
            positions: p,
            normals: Some(n),
            indices: &teapot::TEAPOT_INDICES,
        }
        .triangles(
            &mapping::triplanar_model(),
            &camera,
            Some(&DirectionalLight::default()),
            |t| tri3.push(*t),
        );
        let r = RefUvMapping::Cylindrical {
            center: [0.0; 3],
            axis: RefAxis::Y,
            top: 1.6,
            bottom: -1.6,
        };
        let reference = host_tests::reference::uv_gen::render_per_pixel(
            &tri3,
            &r,
            &rt,
            RefFilter::Bilinear,
            w,
            h,
        );
        let raw: Vec<u16> = color
            .iter()
            .map(|&c| RawU16::from(c).into_inner())
            .collect();
        let covered: Vec<bool> = depth.iter().map(|&d| d != u16::MAX).collect();
        let rep = compare(&raw, &covered, &reference);
        rows.push(Row {
            name: "uv-per-pixel-cylindrical".into(),
            unit: "pixel",
            ns: median(times) * 1e9 / f64::from(result.1.max(1)),
            mcu: host_tests::report_mcu::of(&mcu, "uv-per-pixel-cylindrical", result.0),
            error: format!(
                "max {} / p99 {} LSB, {:.1} dB",
                rep.max, rep.p99, rep.psnr_db
            ),
            err_x: 100.0 - rep.psnr_db,
        });
    }
    let mut md = String::from(
        "# Texture-coordinate generation\n\n\
         The Utah teapot baked from OBJ (`cargo xtask teapot`, `cargo xtask bake-obj`; 860 vertices, \
         1560 triangles). Generators per vertex, no seam handling (`examples/firmware/src/mapping.rs`); \
         triplanar and cylindrical per pixel: the lit teapot, 240 x 180, exact perspective, bilinear, \
         per pixel (geometry included). Error: against the f64 reference (`host_tests::reference::{uv_gen, two_stage, triplanar}`).\n\n\
         | variant | per | host ns | M0+ instructions | M4F instructions | error against f64 |\n|---|---|---:|---:|---:|---|\n",
    );
    for r in &rows {
        let (m0, m4) = r.mcu.map_or(("-".into(), "-".into()), |(a, b)| {
            (format!("{a:.1}"), format!("{b:.1}"))
        });
        md.push_str(&format!(
            "| `{}` | {} | {:.1} | {m0} | {m4} | {} |\n",
            r.name, r.unit, r.ns, r.error
        ));
    }
    md.push_str(
        "\nReproduce: `cargo xtask report` (or `cargo run --release -p host-tests --bin mapping_report -- --out target/report [--mcu target/report/mcu.tsv]`).\n\n![cost against error](mapping.png)\n",
    );
    std::fs::write(out.join("mapping.md"), md).expect("mapping.md");
    if let Err(e) = plot(&rows, &out.join("mapping.png")) {
        eprintln!("mapping_report: no plot: {e}");
    }
    println!("mapping_report: wrote {}", out.join("mapping.md").display());
}

fn plot(rows: &[Row], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    host_tests::plot_font::register()?;
    let (w, h) = (900u32, 420u32);
    let mut buf = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let mcu = rows.iter().all(|r| r.mcu.is_some());
        let pts: Vec<(f64, f64, &str)> = rows
            .iter()
            .filter(|r| r.unit == "vertex")
            .map(|r| {
                (
                    if mcu {
                        r.mcu.map_or(r.ns, |m| m.1)
                    } else {
                        r.ns
                    },
                    r.err_x,
                    r.name.as_str(),
                )
            })
            .collect();
        let x1 = pts.iter().map(|p| p.0).fold(1.0, f64::max) * 1.3;
        let y1 = pts.iter().map(|p| p.1).fold(1.0, f64::max) * 1.3;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                "generators per vertex: cost against error",
                ("sans-serif", 18),
            )
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d((10.0..x1).log_scale(), 0.0..y1)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc(if mcu {
                "Cortex-M4F instructions / vertex (log)"
            } else {
                "host ns / vertex (log)"
            })
            .y_desc("p99 error, 2^-16 texture")
            .label_style(("sans-serif", 13))
            .draw()
            .map_err(|e| e.to_string())?;
        for (x, y, name) in pts {
            chart
                .draw_series([Circle::new((x, y), 5, BLUE.filled())])
                .map_err(|e| e.to_string())?;
            chart
                .draw_series([Text::new(
                    name.to_string(),
                    (x * 1.05, y + y1 * 0.02),
                    ("sans-serif", 13),
                )])
                .map_err(|e| e.to_string())?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    host_tests::png_io::write_png_rgb8(path, w, h, &buf).map_err(|e| e.to_string())
}
