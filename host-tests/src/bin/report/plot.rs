//! The cost-against-PSNR plots, one per scene and target, with their Pareto fronts.

use std::path::Path;

use host_tests::png_io::write_png_rgb8;

use crate::bench_scenes::Scene;
use crate::modes::{self, Filt, Mode, Proj};
use crate::rows::{psnr, Row};

pub fn cost_unit(t: &str) -> &'static str {
    if t == "host" {
        "ns/px"
    } else {
        "instructions/px"
    }
}

pub fn plot_file(scene: Scene, t: &str) -> String {
    let t = match t {
        "host" => "host",
        "Cortex-M0+" => "m0plus",
        _ => "m4f",
    };
    format!("{}-{t}.png", scene.name())
}

fn proj_colour(p: Proj) -> plotters::style::RGBColor {
    use plotters::style::RGBColor;
    match p {
        Proj::Affine => RGBColor(214, 39, 40),
        Proj::Sub4 => RGBColor(227, 119, 194),
        Proj::Sub8 => RGBColor(255, 127, 14),
        Proj::Sub16 => RGBColor(188, 160, 0),
        Proj::Sub32 => RGBColor(140, 86, 75),
        Proj::Sub64 => RGBColor(127, 127, 127),
        Proj::Quad16 => RGBColor(148, 103, 189),
        Proj::Quad32 => RGBColor(23, 190, 207),
        Proj::Exact => RGBColor(31, 119, 180),
        Proj::Adaptive => RGBColor(44, 160, 44),
    }
}

fn filt_short(f: Filt) -> &'static str {
    match f {
        Filt::Nearest => "N",
        Filt::Bilinear => "B",
        Filt::BilinearFootprint => "Bf",
        Filt::NearestMip => "NMN",
        Filt::Trilinear => "T",
        Filt::TrilinearSpan => "Ts",
    }
}

/// One plot: cost on x, PSNR against the ideal on y, one point per mode.
pub fn plot(scene: Scene, t: &str, rows: &[Row], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    let pts: Vec<(&Row, f64, f64)> = rows
        .iter()
        .filter_map(|r| r.cost(t).map(|c| (r, c, psnr(&r.ideal))))
        .collect();
    if pts.is_empty() {
        return Ok(());
    }
    let (w, h) = (960u32, 640u32);
    let mut buf = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (area, legend) = root.split_horizontally(w - 120);
        let (x0, x1) = pts
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
        let (y0, y1) = pts
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.2), b.max(p.2)));
        let (dx, dy) = ((x1 - x0).max(1e-9) * 0.08, (y1 - y0).max(0.5) * 0.08);
        let title = format!(
            "{}: {} cost vs PSNR against the {}",
            scene.name(),
            t,
            scene.ideal()
        );
        let mut chart = ChartBuilder::on(&area)
            .caption(title, ("sans-serif", 20))
            .margin(12)
            .margin_bottom(30)
            .x_label_area_size(44)
            .y_label_area_size(56)
            .build_cartesian_2d((x0 - dx).max(0.0)..x1 + dx * 2.0, y0 - dy..y1 + dy)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc(format!(
                "{} ({}, lower is faster)",
                cost_unit(t),
                if t == "host" {
                    "median".to_string()
                } else {
                    format!("exact, QEMU, frame 0, {t}")
                }
            ))
            .y_desc("PSNR, dB (higher is more accurate)")
            .label_style(("sans-serif", 14))
            .draw()
            .map_err(|e| e.to_string())?;
        // Pareto fronts, one per lighting.
        for lit in [true, false] {
            let mut front: Vec<(f64, f64)> = pts
                .iter()
                .filter(|p| p.0.mode.lit == lit && !p.0.dominated.contains(&t))
                .map(|p| (p.1, p.2))
                .collect();
            front.sort_by(|a, b| a.0.total_cmp(&b.0));
            if front.len() > 1 {
                let style = if lit {
                    RGBColor(120, 120, 120).stroke_width(2)
                } else {
                    RGBColor(190, 190, 190).stroke_width(2)
                };
                chart
                    .draw_series(LineSeries::new(front, style))
                    .map_err(|e| e.to_string())?;
            }
        }
        // Points first, then labels placed where they overlap no other label and no point
        // (in pixels): beside the point, above, below or to its left; a label equal to one
        // already drawn within a few pixels is left out (the report's table has every mode).
        let mut boxes: Vec<(i32, i32, i32, i32)> = vec![];
        for (r, x, y) in &pts {
            let c = proj_colour(r.mode.proj);
            let style = if r.mode.lit || !scene.lit() {
                c.filled()
            } else {
                c.stroke_width(2)
            };
            chart
                .draw_series(std::iter::once(Circle::new((*x, *y), 6, style)))
                .map_err(|e| e.to_string())?;
            let (px, py) = chart.backend_coord(&(*x, *y));
            boxes.push((px - 7, py - 7, px + 7, py + 7));
        }
        let overlaps = |a: &(i32, i32, i32, i32), b: &(i32, i32, i32, i32)| {
            a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
        };
        let mut placed: Vec<(String, i32, i32)> = vec![];
        for (r, x, y) in &pts {
            let label = format!(
                "{}{}",
                filt_short(r.mode.filter),
                if scene.lit() && !r.mode.lit {
                    " unlit"
                } else if r.mode.facet {
                    " facet"
                } else {
                    ""
                }
            );
            let (px, py) = chart.backend_coord(&(*x, *y));
            let near_same = placed
                .iter()
                .any(|(l, qx, qy)| *l == label && (qx - px).abs() < 16 && (qy - py).abs() < 10);
            if near_same {
                continue;
            }
            let lw = 7 * label.len() as i32 + 2;
            let spot = [
                (9, -7),
                (9, -20),
                (9, 6),
                (-lw - 9, -7),
                (-lw / 2, -24),
                (-lw / 2, 10),
            ]
            .into_iter()
            .map(|(dx, dy)| (px + dx, py + dy, px + dx + lw, py + dy + 14))
            .find(|b| !boxes.iter().any(|o| overlaps(b, o)));
            let Some(b) = spot else {
                continue;
            };
            boxes.push(b);
            placed.push((label.clone(), px, py));
            let colour = if r.dominated.contains(&t) {
                RGBColor(150, 150, 150)
            } else {
                RGBColor(0, 0, 0)
            };
            let font = ("sans-serif", 13).into_font().color(&colour);
            area.draw(&Text::new(label, (b.0, b.1), font))
                .map_err(|e| e.to_string())?;
        }
        // Legend: the colours of the projections that have a point here.
        let shown = modes::PROJS
            .into_iter()
            .filter(|p| pts.iter().any(|(r, _, _)| r.mode.proj == *p));
        for (k, p) in shown.enumerate() {
            let m = Mode {
                lit: false,
                facet: false,
                filter: Filt::Nearest,
                proj: p,
            };
            let y = 60 + 20 * k as i32;
            legend
                .draw(&Circle::new((12, y), 6, proj_colour(p).filled()))
                .map_err(|e| e.to_string())?;
            legend
                .draw(&Text::new(m.proj_name(), (24, y - 7), ("sans-serif", 14)))
                .map_err(|e| e.to_string())?;
        }
        let notes = if scene.lit() {
            "N nearest, B bilinear, Bf bilinear from footprints, facet = light per triangle; filled = lit, ring = unlit; grey label = dominated; lines = Pareto fronts"
        } else {
            "N nearest, B bilinear, Bf from footprints, NMN nearest-mipmap-nearest, T trilinear (LOD per pixel), Ts (per span); grey label = dominated"
        };
        root.draw(&Text::new(notes, (70, h as i32 - 16), ("sans-serif", 13)))
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    write_png_rgb8(path, w, h, &buf).map_err(|e| e.to_string())
}
