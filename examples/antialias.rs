//! Anti-aliasing on the benchmark cube and sphere: no anti-aliasing, silhouette
//! anti-aliasing from depth (`fixel::surface::EdgeAa`, the `aa_edge` firmware's pass), 2 x 2
//! regular-grid supersampling (a 2-times frame resolved by `fixel::surface::resolve_box`),
//! 2 x 2 stratified jitter and the 4-sample rotated grid accumulated from jittered frames
//! (`fixel::scene::jittered`, `fixel::surface::Accumulator`), and 4 x 4 supersampling, side
//! by side as 7x zoomed crops of a silhouette. Also `motion_blur.png`: the same accumulation
//! over time, 16 frames of the turning cube.
//!
//! `cargo run --release --example antialias` (picture in `target/pictures/antialias.png`).

#[path = "common/mod.rs"]
mod common;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Viewport};
use fixel::math::{Fx, Mat4};
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection};
use fixel::scene::{draw_mesh, jittered, Camera, DirectionalLight, Mesh, SamplePattern};
use fixel::surface::{resolve_box, Accumulator, EdgeAa, Frame};
use fixel::texture::{Filter, Texture};
use fixel::Error;
use fixel_scenes as demo;

const W: u32 = 320;
const H: u32 = 240;
const ZOOM: u32 = 7;
const CW: u32 = 24;
const CH: u32 = 18;

/// The frame at `k` times the resolution, box-resolved; at `k = 1` with `edge`, smoothed at
/// its depth discontinuities (one band holding the frame).
fn render(
    k: u32,
    edge: bool,
    camera: &Camera,
    mesh: &Mesh<'_>,
    model: &Mat4,
    tex: Texture<'_>,
) -> Result<Vec<Rgb565>, Error> {
    let (w, h) = (W * k, H * k);
    let mode = DrawMode {
        projection: Projection::Exact,
        filter: Filter::Bilinear,
        depth: DepthTest::Less,
        cull: Cull::Back,
        ..DrawMode::default()
    };
    let draw = Draw::dynamic(mode, Some(tex), Viewport::new(0, 0, w, h)?)?;
    let (mut c, mut d) = (
        vec![Rgb565::new(0, 0, 0); (w * h) as usize],
        vec![0u16; (w * h) as usize],
    );
    let mut frame = Frame::new(&mut c, w, h)?.with_depth(&mut d)?;
    frame.clear(Rgb565::new(3, 8, 6));
    draw_mesh(
        &draw,
        mesh,
        model,
        camera,
        Some(&DirectionalLight::default()),
        &mut frame,
    )?;
    if k == 1 && edge {
        let (mut hc, mut hd) = (
            vec![Rgb565::new(0, 0, 0); 2 * W as usize],
            vec![0u16; 2 * W as usize],
        );
        let mut aa = EdgeAa::new(W, 2047, &mut hc, &mut hd)?;
        let mut out = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        aa.band_into(&c, &d, true, &mut out)?;
        return Ok(out);
    }
    if k == 1 {
        return Ok(c);
    }
    let hi = Frame::new(&mut c, w, h)?;
    let mut lo = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    resolve_box(&hi, k, &mut lo)?;
    Ok(lo)
}

fn accumulated(
    p: SamplePattern,
    mesh: &Mesh<'_>,
    model: &Mat4,
    tex: Texture<'_>,
) -> Result<Vec<Rgb565>, Error> {
    let cam = demo::camera(20);
    let vp = Viewport::new(0, 0, W, H)?;
    let mut at = [[Fx::ZERO; 2]; 16];
    let n = p.offsets(&mut at)?;
    let mut sums = vec![[0u16; 3]; (W * H) as usize];
    let mut acc = Accumulator::new(&mut sums)?;
    for o in &at[..n] {
        let c = Camera {
            view: cam.view,
            projection: jittered(&cam.projection, *o, &vp),
        };
        acc.add(&render(1, false, &c, mesh, model, tex)?)?;
    }
    let mut out = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    acc.resolve(&mut out)?;
    Ok(out)
}

/// The crop centre: the rightmost pixel of row `y` that differs from the background.
fn edge(img: &[Rgb565], y: u32) -> u32 {
    let bg = img[0];
    (0..W)
        .rev()
        .find(|&x| img[(y * W + x) as usize] != bg)
        .unwrap_or(W / 2)
}

fn main() -> Result<(), Error> {
    let mut t128 = vec![Rgb565::new(0, 0, 0); 128 * 128];
    demo::checker_texture(128, 128, &mut t128)?;
    let mut t256 = vec![Rgb565::new(0, 0, 0); 256 * 128];
    demo::checker_texture(256, 128, &mut t256)?;
    let (cube, sphere) = (demo::cube(), demo::sphere());
    let objects = [
        (
            cube.mesh()?,
            demo::cube_model(20),
            Texture::new(&t128, 128, 128)?,
            96u32,
        ),
        (
            sphere.mesh()?,
            demo::sphere_model(10),
            Texture::new(&t256, 256, 128)?,
            150u32,
        ),
    ];
    let cols = 6u32;
    let (pw, ph) = (CW * ZOOM, CH * ZOOM);
    let (ow, oh) = (cols * pw + (cols - 1) * 4, 2 * ph + 4);
    let mut out = vec![Rgb565::new(31, 63, 31); (ow * oh) as usize];
    for (row, (mesh, model, tex, y)) in objects.iter().enumerate() {
        let cam = demo::camera(20);
        let images = [
            render(1, false, &cam, mesh, model, *tex)?,
            render(1, true, &cam, mesh, model, *tex)?,
            render(2, false, &cam, mesh, model, *tex)?,
            accumulated(SamplePattern::Jittered { n: 4, seed: 7 }, mesh, model, *tex)?,
            accumulated(SamplePattern::RotatedGrid4, mesh, model, *tex)?,
            render(4, false, &cam, mesh, model, *tex)?,
        ];
        let cx = edge(&images[0], *y).clamp(CW / 2, W - CW / 2);
        let (x0, y0) = (cx - CW / 2, (*y).clamp(CH / 2, H - CH / 2) - CH / 2);
        for (col, img) in images.iter().enumerate() {
            for py in 0..ph {
                for px in 0..pw {
                    let src = img[((y0 + py / ZOOM) * W + x0 + px / ZOOM) as usize];
                    let (ox, oy) = (col as u32 * (pw + 4) + px, row as u32 * (ph + 4) + py);
                    out[(oy * ow + ox) as usize] = src;
                }
            }
        }
    }
    let path = common::out_dir().join("antialias.png");
    common::write_png(&path, ow, oh, &out);
    println!(
        "wrote {} (columns: 1x, 1x + edge AA from depth, 2x2 grid, 2x2 jittered, rotated grid 4, 4x4 grid)",
        path.display()
    );
    motion_blur(&objects[0].0, objects[0].2)
}

/// Accumulation over time: 16 frames of the cube turning (frames 0..32 step 2), averaged.
fn motion_blur(mesh: &Mesh<'_>, tex: Texture<'_>) -> Result<(), Error> {
    let cam = demo::camera(20);
    let mut sums = vec![[0u16; 3]; (W * H) as usize];
    let mut acc = Accumulator::new(&mut sums)?;
    for i in 0..16 {
        acc.add(&render(
            1,
            false,
            &cam,
            mesh,
            &demo::cube_model(2 * i),
            tex,
        )?)?;
    }
    let mut out = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    acc.resolve(&mut out)?;
    let path = common::out_dir().join("motion_blur.png");
    common::write_png(&path, W, H, &out);
    println!("wrote {}", path.display());
    Ok(())
}
