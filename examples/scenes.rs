//! Renders the three benchmark scenes of `docs/scenes.md` (cube, sphere, floor with nearest and
//! bilinear filtering) to PNG files with fixel's fixed-point pipeline, printing where they
//! went and how many pixels each drew.
//!
//! Each scene uses stages chosen as types, exactly as a firmware would:
//! `cargo run --release --example scenes`.

#[path = "common/mod.rs"]
mod common;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::pipeline::{Affine, DepthLess, Exact, ModulateIntensity, Pipeline, Replace};
use fixel::prelude::*;
use fixel::scene::{draw_mesh, DirectionalLight};
use fixel::texture::{
    chain_len, full_levels, generate_mips, Bilinear, MipTexture, Nearest, Repeat, Trilinear,
};
use fixel_scenes as demo;

type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
type FloorNearest = Pipeline<Exact, Nearest, Repeat, Repeat, Replace, DepthLess>;
type FloorBilinear = Pipeline<Exact, Bilinear, Repeat, Repeat, Replace, DepthLess>;
type FloorTrilinear = Pipeline<Exact, Trilinear, Repeat, Repeat, Replace, DepthLess>;
#[allow(dead_code)]
type Cheapest = Pipeline<Affine, Nearest, Repeat, Repeat, Replace, DepthLess>;

fn main() -> Result<(), Error> {
    let (w, h) = (demo::WIDTH, demo::HEIGHT);
    let vp = Viewport::new(0, 0, w, h)?;
    let light = DirectionalLight::default();
    let dir = common::out_dir();
    let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    let mut depth = vec![0u16; (w * h) as usize];

    let mut render = |name: &str,
                      draw: &Draw<'_, Rgb565>,
                      mesh: &fixel::scene::Mesh<'_>,
                      model: &Mat4,
                      far: i32,
                      lit: bool|
     -> Result<(), Error> {
        let mut frame = Frame::new(&mut color, w, h)?.with_depth(&mut depth)?;
        frame.clear(Rgb565::new(0, 0, 0));
        let camera = demo::camera(far);
        let pixels = draw_mesh(
            draw,
            mesh,
            model,
            &camera,
            lit.then_some(&light),
            &mut frame,
        )?;
        let path = dir.join(format!("{name}.png"));
        common::write_png(&path, w, h, frame.pixels());
        println!("{name:>16}: {pixels:6} pixels drawn -> {}", path.display());
        Ok(())
    };

    let mut t128 = vec![Rgb565::new(0, 0, 0); 128 * 128];
    demo::checker_texture(128, 128, &mut t128)?;
    let tex = Texture::new(&t128, 128, 128)?;
    let cube = demo::cube();
    render(
        "cube",
        &Draw::new::<Lit>(Some(tex), vp, Cull::Back)?,
        &cube.mesh()?,
        &demo::cube_model(0),
        20,
        true,
    )?;

    let mut t256 = vec![Rgb565::new(0, 0, 0); 256 * 128];
    demo::checker_texture(256, 128, &mut t256)?;
    let tex = Texture::new(&t256, 256, 128)?;
    let sphere = demo::sphere();
    render(
        "sphere",
        &Draw::new::<Lit>(Some(tex), vp, Cull::Back)?,
        &sphere.mesh()?,
        &demo::sphere_model(0),
        20,
        true,
    )?;

    let mut t64 = vec![Rgb565::new(0, 0, 0); 64 * 64];
    demo::checker_texture(64, 64, &mut t64)?;
    let tex = Texture::new(&t64, 64, 64)?;
    let floor = demo::floor();
    render(
        "floor-nearest",
        &Draw::new::<FloorNearest>(Some(tex), vp, Cull::Back)?,
        &floor.mesh()?,
        &Mat4::IDENTITY,
        200,
        false,
    )?;
    render(
        "floor-bilinear",
        &Draw::new::<FloorBilinear>(Some(tex), vp, Cull::Back)?,
        &floor.mesh()?,
        &Mat4::IDENTITY,
        200,
        false,
    )?;

    // The floor with a full mip chain (64 x 64 down to 1 x 1, 4/3 of the base) and trilinear
    // filtering.
    let levels = full_levels(64, 64);
    let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(64, 64, levels)];
    chain[..64 * 64].copy_from_slice(&t64);
    generate_mips(&mut chain, 64, 64, levels)?;
    let mips = MipTexture::new(&chain, 64, 64, levels)?;
    let draw = Draw::new_mip::<FloorTrilinear>(Some(mips), vp, Cull::Back)?;
    render(
        "floor-trilinear",
        &draw,
        &floor.mesh()?,
        &Mat4::IDENTITY,
        200,
        false,
    )?;
    Ok(())
}
