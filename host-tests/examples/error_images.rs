//! Writes fixel's render, the f64 reference and the amplified error image
//! (black 0 LSB, blue 1, green 2, red 3+, magenta coverage disagreement) of
//! the cube (frame 0) and the floor (nearest and bilinear) to `docs/images/`,
//! for the README. Run by hand and commit the PNGs:
//!
//! ```text
//! cargo run -p host-tests --example error_images
//! ```

use host_tests::png_io::{write_png_rgb565, write_png_rgb8};
use host_tests::reference::{self, RefFilter, RefMode};
use host_tests::{adapter, metrics, scenes};
use std::path::Path;

fn main() -> std::io::Result<()> {
    let out = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/images");
    std::fs::create_dir_all(&out)?;
    let floor = scenes::floor();
    let cases = [
        ("cube", scenes::cube(0), None),
        ("floor-nearest", floor.clone(), Some(RefFilter::Nearest)),
        ("floor-bilinear", floor, Some(RefFilter::Bilinear)),
    ];
    for (name, s, filter) in cases {
        let mode = RefMode {
            filter: filter.unwrap_or(s.mode.filter),
            ..s.mode
        };
        let tris = scenes::to_ref_triangles(&s);
        let r = reference::render(&tris, Some(&s.texture), &mode, s.width, s.height);
        let f = adapter::render(
            &adapter::clip_triangles(&tris),
            Some(&s.texture),
            adapter::draw_mode(&mode, None, true),
            s.width,
            s.height,
        );
        let (w, h) = (s.width, s.height);
        write_png_rgb565(out.join(format!("{name}-fixel.png")), w, h, &f.pixels)?;
        write_png_rgb565(
            out.join(format!("{name}-reference.png")),
            w,
            h,
            &r.quantize_rgb565(),
        )?;
        write_png_rgb8(
            out.join(format!("{name}-error.png")),
            w,
            h,
            &metrics::error_image(&f.pixels, &f.covered, &r),
        )?;
        println!("{name}: {}", metrics::compare(&f.pixels, &f.covered, &r));
    }
    println!("wrote {}", out.display());
    Ok(())
}
