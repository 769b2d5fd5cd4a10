//! Transparency on microcontrollers (`report_alpha`, shared with the host report): the
//! benchmark floor drawn opaque into a 240 x 180 frame, then one quad standing on it drawn
//! with an alpha shader: a translucent window (alpha plane, over), a glow (additive), and a
//! fence cut-out (colour key, alpha test). Only the quad's draw is counted.

use crate::scenes::Fnv1a;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{ClipVertex, Cull, Vertex, Viewport};
use fixel::math::{Mat4, Vec3};
use fixel::pipeline::{DepthLess, Draw, Exact, ShadedDraw};
use fixel::scene::mesh_triangles;
use fixel::shading::alpha::{AlphaBlend, AlphaSource, AlphaTest, BlendMode};
use fixel::shading::Shader;
use fixel::surface::Frame;
use fixel::texture::{Bilinear, Nearest, Texture};
use fixel::Error;
use fixel_scenes as demo;

/// Frame width.
pub const W: u32 = 240;
/// Frame height.
pub const H: u32 = 180;
/// Side of the quad's texture and alpha plane.
pub const N: u32 = 8;

/// The variants, by report name.
pub const MODES: [&str; 3] = ["alpha-over", "alpha-add", "alpha-test"];

/// The alpha plane: a diagonal ramp with a clear hole.
pub fn plane() -> [u8; (N * N) as usize] {
    core::array::from_fn(|k| {
        let (x, y) = (k as u32 % N, k as u32 / N);
        if (3..5).contains(&x) && (3..5).contains(&y) {
            0
        } else {
            (64 + (x + y) * 191 / (2 * N - 2)) as u8
        }
    })
}

/// The quad builder of the `transparency` scene (outside the library, compiled here too;
/// only its `quad` is used).
#[allow(dead_code)]
#[path = "alpha_scene.rs"]
mod scene;

/// The quad (2 x 2 at z = -4, facing the camera) as alpha-shader vertices.
fn quad() -> [[Vertex<3>; 3]; 2] {
    scene::quad(&Mat4::translation(Vec3::from_num(0, 0, -4)))
}

/// Draws the floor (`floor_tex`, `T(64, 64)`) opaque into `color`/`depth` (`W x H`).
pub fn floor(floor_tex: Texture<'_>, color: &mut [Rgb565], depth: &mut [u16]) -> Result<(), Error> {
    let mut frame = Frame::new(color, W, H)?.with_depth(depth)?;
    frame.clear(Rgb565::new(0, 0, 0));
    let draw = Draw::new::<crate::scenes::FloorNearest>(
        Some(floor_tex),
        Viewport::new(0, 0, W, H)?,
        Cull::Back,
    )?;
    let m = demo::floor();
    let mesh = m.mesh()?;
    let mut err = Ok(());
    mesh_triangles(
        &mesh,
        &Mat4::IDENTITY,
        &demo::camera(200),
        None,
        |t: &[ClipVertex; 3]| {
            if let Err(e) = draw.clip_triangles(core::slice::from_ref(t), &mut frame) {
                err = Err(e);
            }
        },
    );
    err
}

fn draw_quad<S: Shader<Varyings = [i32; 3]>>(
    shader: S,
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Result<u32, Error> {
    let mut frame = Frame::new(color, W, H)?.with_depth_kept(depth)?;
    ShadedDraw::<_, Exact, DepthLess>::new(shader, Viewport::new(0, 0, W, H)?, Cull::None)?
        .clip_triangles(&quad(), &mut frame)
}

/// Draws mode `k` of [`MODES`] over the floor already in `color`/`depth`; returns the pixels
/// the quad's draw wrote.
pub fn quad_mode(
    k: usize,
    tex: Texture<'_>,
    alpha: &[u8],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Result<u32, Error> {
    match k {
        0 => draw_quad(
            AlphaBlend::new(
                tex,
                AlphaSource::Plane(alpha),
                255,
                BlendMode::Over,
                Bilinear,
            )?,
            color,
            depth,
        ),
        1 => draw_quad(
            AlphaBlend::new(
                tex,
                AlphaSource::Plane(alpha),
                200,
                BlendMode::Add,
                Bilinear,
            )?,
            color,
            depth,
        ),
        _ => draw_quad(
            AlphaTest::new(tex, AlphaSource::Plane(alpha), 128, Nearest)?,
            color,
            depth,
        ),
    }
}

/// FNV-1a of a frame.
pub fn checksum(color: &[Rgb565]) -> u32 {
    let mut f = Fnv1a::default();
    f.pixels(color);
    f.0
}
