//! Transparency: the benchmark floor and cube drawn opaque (trilinear), then a picket fence
//! cut out by alpha test (it writes depth), a stained-glass window blended over with an
//! alpha plane, and an additive glow, the translucent quads sorted back to front.
//!
//! `cargo run --release --example transparency` (picture in `target/pictures/transparency.png`).

#[path = "common/mod.rs"]
mod common;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthLess, DepthTest, Draw, DrawMode, Exact, Projection, ShadedDraw};
use fixel::scene::{draw_mesh, sort_back_to_front, DirectionalLight};
use fixel::shading::alpha::{AlphaBlend, AlphaSource, AlphaTest, BlendMode};
use fixel::surface::Frame;
use fixel::texture::{
    chain_len, full_levels, generate_mips, Bilinear, Filter, MipFilter, MipTexture, Nearest,
    Texture,
};
use fixel::Error;
use fixel_scenes as demo;

const W: u32 = 320;
const H: u32 = 240;
const N: u32 = 64;

fn rgb(r: f64, g: f64, b: f64) -> Rgb565 {
    let q = |v: f64, m: f64| (v.clamp(0.0, 1.0) * m).round() as u8;
    Rgb565::new(q(r, 31.0), q(g, 63.0), q(b, 31.0))
}

/// Stained glass: coloured panes in a lead grid (opaque), panes at 55 % alpha.
fn glass() -> (Vec<Rgb565>, Vec<u8>) {
    let panes = [
        (0.9, 0.2, 0.2),
        (0.2, 0.5, 0.95),
        (0.95, 0.8, 0.2),
        (0.3, 0.85, 0.4),
    ];
    let mut c = Vec::new();
    let mut a = Vec::new();
    for k in 0..N * N {
        let (x, y) = (k % N, k / N);
        let lead = x % 16 < 2 || y % 16 < 2 || x >= N - 2 || y >= N - 2;
        if lead {
            c.push(rgb(0.12, 0.12, 0.14));
            a.push(255);
        } else {
            let (r, g, b) = panes[((x / 16 + 3 * (y / 16)) % 4) as usize];
            c.push(rgb(r, g, b));
            a.push(140);
        }
    }
    (c, a)
}

/// A picket fence: white boards with gaps (alpha 0) and pointed tops.
fn fence() -> (Vec<Rgb565>, Vec<u8>) {
    let mut c = Vec::new();
    let mut a = Vec::new();
    for k in 0..N * N {
        let (x, y) = (k % N, k / N);
        let bx = x % 16;
        let board = (3..13).contains(&bx);
        let tip = y < 8 && (bx as i32 - 8).unsigned_abs() > y / 2 + 1;
        let rail = (24..28).contains(&y) || (48..52).contains(&y);
        let solid = (board && !tip) || rail;
        c.push(if solid {
            rgb(0.92, 0.9, 0.85)
        } else {
            rgb(0.0, 0.0, 0.0)
        });
        a.push(if solid { 255 } else { 0 });
    }
    (c, a)
}

/// A soft glow: a radial falloff, additive.
fn glow() -> (Vec<Rgb565>, Vec<u8>) {
    let mut c = Vec::new();
    let mut a = Vec::new();
    for k in 0..N * N {
        let (x, y) = (f64::from(k % N) / 31.5 - 1.0, f64::from(k / N) / 31.5 - 1.0);
        let r = (1.0 - x.hypot(y)).max(0.0);
        c.push(rgb(1.0, 0.75, 0.35));
        a.push((r * r * 255.0) as u8);
    }
    (c, a)
}

/// The demo checker of side `n` with its full mip chain.
fn checker_chain(n: u32) -> Result<Vec<Rgb565>, Error> {
    let levels = full_levels(n, n);
    let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(n, n, levels)];
    demo::checker_texture(n, n, &mut chain[..(n * n) as usize])?;
    generate_mips(&mut chain, n, n, levels)?;
    Ok(chain)
}

/// A 2 x 2 quad (uv 0..1, white) under `model`, as alpha-shader vertices.
fn quad(model: &Mat4, scale: f64) -> Vec<[Vertex<3>; 3]> {
    let cam = demo::camera(200);
    let mvp = cam.projection.mul(&cam.view).mul(model);
    let v = |x: f64, y: f64, u: i32, t: i32| {
        let c = mvp
            .transform_point(Vec3::from_num(x * scale, y * scale, 0))
            .expect("in range");
        Vertex::new([c.x, c.y, c.z, c.w], [u << 16, t << 16, 256 << 16])
    };
    let (a, b, c, d) = (
        v(-1.0, -1.0, 0, 1),
        v(1.0, -1.0, 1, 1),
        v(1.0, 1.0, 1, 0),
        v(-1.0, 1.0, 0, 0),
    );
    vec![[a, b, c], [a, c, d]]
}

fn main() -> Result<(), Error> {
    let vp = Viewport::new(0, 0, W, H)?;
    let (mut color, mut depth) = (
        vec![Rgb565::new(0, 0, 0); (W * H) as usize],
        vec![0u16; (W * H) as usize],
    );
    let mut frame = Frame::new(&mut color, W, H)?.with_depth(&mut depth)?;
    frame.clear(Rgb565::new(14, 30, 22));
    // Opaque: the floor and the cube, trilinear (the floor is minified many times towards
    // the horizon: without mipmaps its far checks sparkle).
    let (t64, t128) = (checker_chain(64)?, checker_chain(128)?);
    let mode = DrawMode {
        projection: Projection::Exact,
        filter: Filter::Bilinear,
        mip: MipFilter::Linear,
        depth: DepthTest::Less,
        cull: Cull::Back,
        ..DrawMode::default()
    };
    let floor = demo::floor();
    draw_mesh(
        &Draw::dynamic_mip(
            mode,
            Some(MipTexture::new(&t64, 64, 64, full_levels(64, 64))?),
            vp,
        )?,
        &floor.mesh()?,
        &Mat4::IDENTITY,
        &demo::camera(200),
        None,
        &mut frame,
    )?;
    let cube = demo::cube();
    let cube_model = Mat4::translation(Vec3::from_num(0.8, 0, -9))
        * Mat4::rotation_y(Angle::from_degrees(Fx::from_num(30)));
    draw_mesh(
        &Draw::dynamic_mip(
            mode,
            Some(MipTexture::new(&t128, 128, 128, full_levels(128, 128))?),
            vp,
        )?,
        &cube.mesh()?,
        &cube_model,
        &demo::camera(200),
        Some(&DirectionalLight::default()),
        &mut frame,
    )?;
    // The fence: cut-out, writes depth, no sorting.
    let (fc, fa) = fence();
    let ft = Texture::new(&fc, N, N)?;
    let fence_model = Mat4::translation(Vec3::from_num(-2.2, -0.2, -6.5))
        * Mat4::rotation_y(Angle::from_degrees(Fx::from_num(35)));
    ShadedDraw::<_, Exact, DepthLess>::new(
        AlphaTest::new(ft, AlphaSource::Plane(&fa), 128, Nearest)?,
        vp,
        Cull::None,
    )?
    .clip_triangles(&quad(&fence_model, 0.9), &mut frame)?;
    // The translucent quads, back to front: the window, then the glow in front of it.
    let (gc, ga) = glass();
    let gt = Texture::new(&gc, N, N)?;
    let (lc, la) = glow();
    let lt = Texture::new(&lc, N, N)?;
    // The window covers the cube's silhouette with its frame: placed 0.1 further right,
    // its left edge fell within a pixel of the cube's left corner, and a one-pixel sliver
    // of the cube's grazing side face (the floor's checker) showed down the window's left
    // edge against the sky.
    let window = Mat4::translation(Vec3::from_num(0.5, 0.1, -6))
        * Mat4::rotation_y(Angle::from_degrees(Fx::from_num(-20)));
    let light = Mat4::translation(Vec3::from_num(-0.4, 0.9, -5));
    let mut win = quad(&window, 1.0);
    let mut glo = quad(&light, 0.7);
    sort_back_to_front(&mut win);
    sort_back_to_front(&mut glo);
    ShadedDraw::<_, Exact, DepthLess>::new(
        AlphaBlend::new(gt, AlphaSource::Plane(&ga), 255, BlendMode::Over, Bilinear)?,
        vp,
        Cull::None,
    )?
    .clip_triangles(&win, &mut frame)?;
    ShadedDraw::<_, Exact, DepthLess>::new(
        AlphaBlend::new(lt, AlphaSource::Plane(&la), 255, BlendMode::Add, Bilinear)?,
        vp,
        Cull::None,
    )?
    .clip_triangles(&glo, &mut frame)?;
    let path = common::out_dir().join("transparency.png");
    common::write_png(&path, W, H, &color);
    println!("wrote {}", path.display());
    Ok(())
}
