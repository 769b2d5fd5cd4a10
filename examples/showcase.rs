//! The showcase: four perspective quads with uv running from -1 to 2, one per wrap mode
//! (repeat, mirrored repeat, clamp to edge, clamp to border), a lit bilinear cube, and a
//! Gouraud-shaded untextured triangle, drawn band by band (16 rows at a time) through the
//! embedded-graphics adapter into an in-memory display, then saved as a PNG.
//!
//! `cargo run --release --example showcase`

#[path = "common/mod.rs"]
mod common;

use core::convert::Infallible;
use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Size};
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::Pixel;
use fixel::geometry::ClipVertex;
use fixel::prelude::*;
use fixel::scene::{mesh_triangles, DirectionalLight};
use fixel::surface::DrawTargetFlush;
use fixel::surface::{BandDraw, Binned};
use fixel_scenes as demo;

/// A display in RAM: what `embedded-graphics-simulator` would be, without a window.
struct Display {
    w: u32,
    h: u32,
    pixels: Vec<Rgb565>,
}

impl OriginDimensions for Display {
    fn size(&self) -> Size {
        Size::new(self.w, self.h)
    }
}

impl DrawTarget for Display {
    type Color = Rgb565;
    type Error = Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            if p.x >= 0 && p.y >= 0 && (p.x as u32) < self.w && (p.y as u32) < self.h {
                self.pixels[(p.y as u32 * self.w + p.x as u32) as usize] = c;
            }
        }
        Ok(())
    }
}

/// A quad on the floor-like plane, left edge `x0`, tilted away from the camera, with uv
/// from -1 to 2 so the wrap mode shows outside the texture.
fn quad(x0: f32) -> [[ClipVertex; 3]; 2] {
    let camera = demo::camera(20);
    let p = |x: f32, y: f32, z: f32, u: f32, v: f32| {
        let c = camera.projection.transform_point(Vec3::new(
            Fx::from_num(x),
            Fx::from_num(y),
            Fx::from_num(z),
        ));
        let c = c.unwrap_or(fixel::math::Vec4::ZERO);
        ClipVertex::new([c.x, c.y, c.z, c.w], [Fx::from_num(u), Fx::from_num(v)])
    };
    let (x1, y0, y1) = (x0 + 0.95, -1.1, -0.4);
    let a = p(x0, y0, -4.0, -1.0, 2.0);
    let b = p(x1, y0, -4.0, 2.0, 2.0);
    let c = p(x1, y1, -7.0, 2.0, -1.0);
    let d = p(x0, y1, -7.0, -1.0, -1.0);
    [[a, b, c], [a, c, d]]
}

fn main() -> Result<(), Error> {
    let (w, h) = (demo::WIDTH, demo::HEIGHT);
    let vp = Viewport::new(0, 0, w, h)?;

    let mut t64 = vec![Rgb565::new(0, 0, 0); 64 * 64];
    demo::checker_texture(64, 64, &mut t64)?;
    let tex = Texture::new(&t64, 64, 64)?.with_border(Rgb565::new(31, 0, 31));
    let mut t128 = vec![Rgb565::new(0, 0, 0); 128 * 128];
    demo::checker_texture(128, 128, &mut t128)?;
    let cube_tex = Texture::new(&t128, 128, 128)?;

    let wraps = [
        Wrap::Repeat,
        Wrap::MirroredRepeat,
        Wrap::ClampToEdge,
        Wrap::ClampToBorder,
    ];
    let quad_draws: Vec<Draw<'_, Rgb565>> = wraps
        .iter()
        .map(|&wr| {
            let mode = DrawMode {
                projection: Projection::Exact,
                filter: Filter::Bilinear,
                wrap: [wr, wr],
                shading: Shading::Replace,
                depth: DepthTest::Less,
                cull: Cull::None,
                ..DrawMode::default()
            };
            Draw::dynamic(mode, Some(tex), vp)
        })
        .collect::<Result<_, _>>()?;
    let cube_mode = DrawMode {
        filter: Filter::Bilinear,
        depth: DepthTest::Less,
        ..DrawMode::default()
    };
    let cube_draw = Draw::dynamic(cube_mode, Some(cube_tex), vp)?;
    let gouraud = Draw::dynamic(
        DrawMode {
            shading: Shading::Gouraud,
            cull: Cull::None,
            ..DrawMode::default()
        },
        None,
        vp,
    )?;

    let mut draws: Vec<&Draw<'_, Rgb565>> = quad_draws.iter().collect();
    draws.push(&cube_draw);
    draws.push(&gouraud);

    let cube = demo::cube();
    let cube_mesh = cube.mesh()?;
    // The benchmark cube's rotation (its model without the translation), smaller, up right.
    let rotation = Mat4::translation(Vec3::from_num(0, 0, 4)) * demo::cube_model(0);
    let cube_model = Mat4::translation(Vec3::from_num(0.9, 0.5, -4.0))
        * rotation
        * Mat4::scaling(Vec3::from_num(0.45, 0.45, 0.45));
    let camera = demo::camera(20);
    let light = DirectionalLight::default();
    let tri = [
        ClipVertex::new(
            [Fx::from_num(-0.95), Fx::from_num(0.95), Fx::ZERO, Fx::ONE],
            [Fx::ZERO; 2],
        )
        .with_rgb8(255, 0, 0),
        ClipVertex::new(
            [Fx::from_num(-0.95), Fx::from_num(0.25), Fx::ZERO, Fx::ONE],
            [Fx::ZERO; 2],
        )
        .with_rgb8(0, 255, 0),
        ClipVertex::new(
            [Fx::from_num(-0.35), Fx::from_num(0.6), Fx::ZERO, Fx::ONE],
            [Fx::ZERO; 2],
        )
        .with_rgb8(0, 0, 255),
    ];
    let quads: Vec<_> = (0..4).map(|k| quad(-2.05 + 1.05 * k as f32)).collect();

    let mut display = Display {
        w,
        h,
        pixels: vec![Rgb565::new(0, 0, 0); (w * h) as usize],
    };
    let mut band = vec![Rgb565::new(0, 0, 0); (w * 16) as usize];
    let mut depth = vec![0u16; (w * 16) as usize];
    let mut bins = vec![Binned::default(); 64];
    let mut renderer = BandRenderer::new(&mut band, w, 16, h)?.with_depth(&mut depth)?;
    let mut flush = DrawTargetFlush(&mut display);
    let stats = renderer.render(
        &draws
            .iter()
            .map(|d| *d as &dyn BandDraw<Rgb565>)
            .collect::<Vec<_>>(),
        &mut bins,
        Rgb565::new(2, 4, 6),
        |sink| {
            for (k, q) in quads.iter().enumerate() {
                for t in q {
                    draws[k].project(t, &mut |s| sink.push(k as u8, s));
                }
            }
            mesh_triangles(&cube_mesh, &cube_model, &camera, Some(&light), |t| {
                cube_draw.project(t, &mut |s| sink.push(4, s));
            });
            gouraud.project(&tri, &mut |s| sink.push(5, s));
        },
        |b| flush.flush(b),
    )?;
    let path = common::out_dir().join("showcase.png");
    common::write_png(&path, w, h, &display.pixels);
    println!(
        "showcase: {} bands, {} triangles binned, {} pixels drawn -> {}",
        stats.bands,
        stats.triangles,
        stats.pixels,
        path.display()
    );
    Ok(())
}
