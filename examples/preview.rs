//! A desktop preview: one frame drawn whole into a `Frame` and written as a PNG, the
//! smallest complete fixel program on a PC (the guide's step 4, `fixel::guide`).
//!
//! ```text
//! cargo run --release --example preview   # writes target/pictures/preview.png
//! ```

use std::error::Error as StdError;
use std::path::PathBuf;

use fixel::math::fx;
use fixel::pipeline::{DepthLess, Exact, ModulateIntensity};
use fixel::prelude::*;
use fixel::scene::{draw_mesh, Camera, DirectionalLight};
use fixel::texture::{Bilinear, Repeat};

type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;

/// Writes `frame` as an 8-bit RGB PNG (RGB565 channels bit-replicated to 8 bits).
fn write_png(path: &PathBuf, frame: &Frame<'_, Rgb565>, w: u32) -> Result<(), Box<dyn StdError>> {
    let rgb: Vec<u8> = frame
        .pixels()
        .iter()
        .flat_map(|c| {
            let (r, g, b) = (c.r(), c.g(), c.b());
            [r << 3 | r >> 2, g << 2 | g >> 4, b << 3 | b >> 2]
        })
        .collect();
    let mut png = png::Encoder::new(std::fs::File::create(path)?, w, frame.height());
    png.set_color(png::ColorType::Rgb);
    png.set_depth(png::BitDepth::Eight);
    png.write_header()?.write_image_data(&rgb)?;
    Ok(())
}

fn main() -> Result<(), Box<dyn StdError>> {
    let (w, h) = (320, 240);
    let mut texels = vec![Rgb565::BLACK; 128 * 128];
    fixel_scenes::checker_texture(128, 128, &mut texels)?;
    let texture = Texture::new(&texels, 128, 128)?;
    let draw = Draw::new::<Lit>(Some(texture), Viewport::new(0, 0, w, h)?, Cull::Back)?;

    let cube = fixel_scenes::cube();
    let camera = Camera::perspective(Angle::from_degrees(fx(45)), fx(4) / 3, fx(0.5), fx(20))?;
    let model = Mat4::translation(Vec3::from_num(0, 0, -4))
        .mul(&Mat4::rotation_x(Angle::from_degrees(fx(20))))
        .mul(&Mat4::rotation_y(Angle::from_degrees(fx(40))));
    let light = DirectionalLight::default();

    let mut color = vec![Rgb565::BLACK; (w * h) as usize];
    let mut depth = vec![0u16; (w * h) as usize];
    let mut frame = Frame::new(&mut color, w, h)?.with_depth(&mut depth)?;
    let drawn = draw_mesh(
        &draw,
        &cube.mesh()?,
        &model,
        &camera,
        Some(&light),
        &mut frame,
    )?;

    let dir = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target"))
        .join("pictures");
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("preview.png");
    write_png(&path, &frame, w)?;
    println!("preview: {drawn} pixels drawn -> {}", path.display());
    Ok(())
}
