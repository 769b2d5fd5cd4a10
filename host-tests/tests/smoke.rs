use host_tests::{adapter, metrics, png_io, reference, scenes};

#[test]
fn cube_against_reference() {
    let s = scenes::cube(0);
    let tris = scenes::to_ref_triangles(&s);
    let r = reference::render(&tris, Some(&s.texture), &s.mode, s.width, s.height);
    let mode = adapter::draw_mode(&s.mode, None, true);
    let f = adapter::render(
        &adapter::clip_triangles(&tris),
        Some(&s.texture),
        mode,
        s.width,
        s.height,
    );
    let rep = metrics::compare(&f.pixels, &f.covered, &r);
    println!("{rep}");
    std::fs::create_dir_all("../target").ok();
    png_io::write_png_rgb565("../target/fixel-cube.png", 320, 240, &f.pixels).unwrap();
    png_io::write_png_rgb8(
        "../target/fixel-cube-err.png",
        320,
        240,
        &metrics::error_image(&f.pixels, &f.covered, &r),
    )
    .unwrap();
}
