//! The speed-against-error plot of the technique reports: one labelled point per variant,
//! cost on a log x axis (Cortex-M4F instructions per pixel when every variant has them, else
//! host ns per pixel), PSNR against the f64 reference on the y axis; a line joins the
//! Pareto front (the variants no other is both cheaper and more accurate than) and the
//! labels of the variants off it are grey.

use std::path::Path;

/// One variant of a report.
#[derive(Clone, Debug)]
pub struct Point {
    /// The variant's name, printed beside its point.
    pub name: String,
    /// Host ns per pixel.
    pub host_ns: f64,
    /// Cortex-M4F instructions per pixel, if measured.
    pub m4f: Option<f64>,
    /// PSNR against the reference, dB (capped at 60 on the plot).
    pub psnr: f64,
}

/// Indices of the Pareto front of `points` (cost, quality), cheapest first: the points
/// that no other point matches or beats in both (cost no higher, quality no worse, one of
/// them strictly). Quality is better higher when `higher_is_better`, else lower (an error).
pub fn front(points: &[(f64, f64)], higher_is_better: bool) -> Vec<usize> {
    let better = |a: f64, b: f64| if higher_is_better { a > b } else { a < b };
    let no_worse = |a: f64, b: f64| if higher_is_better { a >= b } else { a <= b };
    let mut on: Vec<usize> = (0..points.len())
        .filter(|&i| {
            let (c, q) = points[i];
            !points.iter().enumerate().any(|(j, &(cj, qj))| {
                j != i && cj <= c && no_worse(qj, q) && (cj < c || better(qj, q))
            })
        })
        .collect();
    on.sort_by(|&a, &b| points[a].0.total_cmp(&points[b].0));
    on
}

/// Writes the plot of `points` to `path` (900 x 420 PNG) with `title`; the y axis spans
/// `psnr_range` dB.
pub fn write(
    points: &[Point],
    title: &str,
    psnr_range: (f64, f64),
    path: &Path,
) -> Result<(), String> {
    use plotters::prelude::*;
    crate::plot_font::register()?;
    let (w, h) = (900u32, 420u32);
    let mut buf = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let measured = points.iter().all(|p| p.m4f.is_some());
        let pts: Vec<(f64, f64, &str)> = points
            .iter()
            .map(|p| {
                let x = if measured {
                    p.m4f.unwrap_or(p.host_ns)
                } else {
                    p.host_ns
                };
                let y = p.psnr.clamp(psnr_range.0, psnr_range.1.min(60.0));
                (x, y, p.name.as_str())
            })
            .collect();
        let x0 = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min) * 0.8;
        let x1 = pts.iter().map(|p| p.0).fold(1.0, f64::max) * 1.6;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 18))
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d((x0..x1).log_scale(), psnr_range.0..psnr_range.1)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc(if measured {
                "Cortex-M4F instructions / pixel (log)"
            } else {
                "host ns / pixel (log)"
            })
            .y_desc("PSNR against the f64 reference, dB")
            .label_style(("sans-serif", 13))
            .draw()
            .map_err(|e| e.to_string())?;
        let dy = (psnr_range.1 - psnr_range.0) / 60.0;
        let on = front(&pts.iter().map(|p| (p.0, p.1)).collect::<Vec<_>>(), true);
        chart
            .draw_series(LineSeries::new(
                on.iter().map(|&i| (pts[i].0, pts[i].1)),
                BLUE.mix(0.5).stroke_width(2),
            ))
            .map_err(|e| e.to_string())?;
        // Labels go right of their point; one that would overlap an earlier label (close
        // in log x and in y) moves below its point, then above.
        let mut placed: Vec<(f64, f64)> = Vec::new();
        for (k, (x, y, name)) in pts.into_iter().enumerate() {
            let ink = if on.contains(&k) {
                BLACK
            } else {
                RGBColor(150, 150, 150)
            };
            chart
                .draw_series([Circle::new((x, y), 5, BLUE.filled())])
                .map_err(|e| e.to_string())?;
            let clash = |ly: f64| {
                placed
                    .iter()
                    .any(|&(px, py)| (x / px).ln().abs() < 0.25 && (py - ly).abs() < 2.5 * dy)
            };
            let ly = [y + dy, y - 3.0 * dy, y + 4.0 * dy, y - 6.0 * dy]
                .into_iter()
                .find(|&ly| !clash(ly))
                .unwrap_or(y + dy);
            placed.push((x, ly));
            chart
                .draw_series([Text::new(
                    name.to_string(),
                    (x * 1.03, ly),
                    ("sans-serif", 12).into_font().color(&ink),
                )])
                .map_err(|e| e.to_string())?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    crate::png_io::write_png_rgb8(path, w, h, &buf).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::front;

    #[test]
    fn the_front_keeps_only_the_undominated_points() {
        // (cost, PSNR): the second is dominated by the first, the fourth ties the third's
        // cost with a worse PSNR.
        let p = [
            (10.0, 30.0),
            (12.0, 29.0),
            (20.0, 40.0),
            (20.0, 35.0),
            (5.0, 20.0),
        ];
        assert_eq!(front(&p, true), vec![4, 0, 2]);
        // As errors (lower is better): the cheapest is also the least wrong here.
        assert_eq!(front(&p, false), vec![4]);
        assert!(front(&[], true).is_empty());
    }
}
