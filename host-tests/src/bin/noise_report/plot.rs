//! `noise_plot.png`: cost against PSNR to the ideal, the marble sphere beside the granite
//! floor.

use std::path::Path;

use host_tests::png_io::write_png_rgb8;

use crate::rows::Row;

/// Left: M4F instructions per pixel (host ns/px without MCU figures) against PSNR to the
/// ideal on the sphere; right: host ns/px against PSNR to the ideal on the floor.
pub fn plot(rows: &[Row], floor: &[Row], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    let (w, h) = (1200u32, 520u32);
    let mut buf = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (left, right) = root.split_horizontally(w / 2);
        let mcu = rows.iter().all(|r| r.m4.is_some());
        for (area, rows, title, xdesc, use_m4, strip) in [
            (
                &left,
                rows,
                "marble sphere (firmware scene)",
                if mcu {
                    "Cortex-M4F instructions / pixel"
                } else {
                    "host ns / pixel"
                },
                mcu,
                "marble-",
            ),
            (
                &right,
                floor,
                "granite floor to the horizon",
                "host ns / pixel",
                false,
                "granite-",
            ),
        ] {
            let pts: Vec<(f64, f64, &str)> = rows
                .iter()
                .map(|r| {
                    let x = if use_m4 {
                        r.m4.map_or(r.ns_px, |m| m.0)
                    } else {
                        r.ns_px
                    };
                    (x, r.vs_ideal.psnr_db.min(99.0), r.name.as_str())
                })
                .collect();
            let x1 = pts.iter().map(|p| p.0).fold(0.0, f64::max) * 1.25;
            let (y0, y1) = pts
                .iter()
                .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
            let mut chart = ChartBuilder::on(area)
                .caption(title, ("sans-serif", 18))
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(50)
                .build_cartesian_2d(0.0..x1.max(1.0), (y0 - 1.0)..(y1 + 1.0))
                .map_err(|e| e.to_string())?;
            chart
                .configure_mesh()
                .x_desc(xdesc)
                .y_desc("PSNR vs supersampled, dB")
                .label_style(("sans-serif", 13))
                .draw()
                .map_err(|e| e.to_string())?;
            for (x, y, name) in pts {
                let band = name.contains("band");
                let c = if band {
                    RGBColor(200, 60, 40)
                } else {
                    RGBColor(40, 80, 200)
                };
                chart
                    .draw_series(std::iter::once(Circle::new((x, y), 5, c.filled())))
                    .map_err(|e| e.to_string())?;
                chart
                    .draw_series(std::iter::once(Text::new(
                        name.replace(strip, ""),
                        (x, y),
                        ("sans-serif", 12).into_font(),
                    )))
                    .map_err(|e| e.to_string())?;
            }
        }
        root.present().map_err(|e| e.to_string())?;
    }
    write_png_rgb8(path, w, h, &buf).map_err(|e| e.to_string())
}
