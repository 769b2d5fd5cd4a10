//! Scene `noise_light3d`: the wooden cube lit by the baked 3D
//! light map (`examples/common/light3d_cube.rs`, `cargo xtask bake-light3d`: two point
//! lights with inverse-square falloff in the cube's own space, 16³ texels, 4 KB of flash)
//! instead of a per-vertex light. Band-limited wood (at most 6 octaves, footprint per span),
//! 320x240 in bands of 8 rows, no depth buffer (one convex object, back faces culled).
//!
//! RAM: the band (5 KB), the cube's 12 clip-space triangles, computed once (1.1 KB, plus
//! 0.9 KB for the light-map draw's copy without the intensity), and 16 bins of fixel's band
//! renderer (2.7 KB): the triangles are projected once and binned, each band draws the bins
//! that meet it. Kept out of the firmware
//! library (the bins include it by path) so the other firmwares' code does not move. Shared
//! with the host test `host-tests/tests/mcu_checksums.rs` and the report
//! (`host-tests/src/bin/noise_report/`), which render the same frame.

use crate::scenes::{Fnv1a, FrameResult, H, ROWS, W};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::ScreenTriangle;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
use fixel::scene::DirectionalLight;
use fixel::shading::noise::{LightMap3d, SolidMesh};
use fixel::shading::Shader;
use fixel::surface::{BandRenderer, Binnable, Binned};
use fixel::Error;
use fixel_scenes as demo;
use fixel_scenes::noise::SHOWCASE_SCALE;

#[path = "../../common/light3d_cube.rs"]
#[allow(dead_code)]
mod light3d_cube;
pub use light3d_cube::{
    CUBE_LIGHT_AMBIENT, CUBE_LIGHT_LIGHTS, CUBE_LIGHT_LOG2_TEXEL, CUBE_LIGHT_ORIGIN,
    CUBE_LIGHT_SIDE, CUBE_LIGHT_TEXELS,
};

/// Cube triangles.
pub const TRIS: usize = 12;
/// Bins: the cube's screen triangles (at most 6 face the camera; room for clipped pieces).
pub const BINS: usize = 16;

/// The baked light map of the cube (`light3d_cube.rs`).
///
/// # Errors
/// None for the baked data; [`LightMap3d::new`]'s errors otherwise.
pub fn light_map() -> Result<LightMap3d<'static>, Error> {
    LightMap3d::new(
        &CUBE_LIGHT_TEXELS,
        CUBE_LIGHT_SIDE,
        CUBE_LIGHT_ORIGIN,
        CUBE_LIGHT_LOG2_TEXEL,
    )
}

/// The cube's model matrix: the right-hand cube of the showcase `noise_lightmap.png`,
/// moved to the middle of the frame.
pub fn model() -> Mat4 {
    Mat4::translation(Vec3::new(Fx::ZERO, Fx::ZERO, Fx::from_num(-4.5)))
        * (Mat4::rotation_x(Angle::from_turns(5000)) * Mat4::rotation_y(Angle::from_turns(7000)))
}

/// Pixels of a band.
pub const BAND: usize = (W * ROWS) as usize;
/// Pixels of the whole frame (one band of 240 rows: the whole-frame firmware).
pub const WHOLE: usize = (W * H) as usize;

/// Scratch of the scene: a colour band of `P / 320` rows (8 by default; [`WHOLE`] for one
/// band holding the frame).
pub struct Light3dBuffers<const P: usize = BAND> {
    color: [Rgb565; P],
    lit: [[Vertex<4>; 3]; TRIS],
    point: [[Vertex<3>; 3]; TRIS],
    bins: [Binned; BINS],
}

const V4: Vertex<4> = Vertex::new([Fx::ZERO; 4], [0; 4]);
const V3: Vertex<3> = Vertex::new([Fx::ZERO; 4], [0; 3]);

impl Light3dBuffers {
    /// Zeroed 8-row band.
    pub const fn new() -> Self {
        Self::sized()
    }
}

impl<const P: usize> Light3dBuffers<P> {
    /// Zeroed.
    pub const fn sized() -> Self {
        Light3dBuffers {
            color: [Rgb565::new(0, 0, 0); P],
            lit: [[V4; 3]; TRIS],
            point: [[V3; 3]; TRIS],
            bins: [Binned::EMPTY; BINS],
        }
    }
}

impl Default for Light3dBuffers {
    fn default() -> Self {
        Self::new()
    }
}

/// The cube's clip-space triangles with the object-space point (lattice units) as varyings
/// 0..3 and the per-vertex light intensity as varying 3, into `out`; returns how many.
pub fn triangles(out: &mut [[Vertex<4>; 3]; TRIS]) -> usize {
    let cube = demo::cube();
    let Ok(mesh) = SolidMesh::new(
        &cube.positions,
        Some(&cube.normals),
        &cube.indices,
        SHOWCASE_SCALE,
    ) else {
        return 0;
    };
    let mut n = 0;
    mesh.triangles(
        &model(),
        &demo::camera(20),
        Some(&DirectionalLight::default()),
        |t| {
            if let Some(slot) = out.get_mut(n) {
                *slot = *t;
                n += 1;
            }
        },
    );
    n
}

/// The frame with a light-map shader (varyings `x, y, z`, e.g. `LitSolid`): geometry, then
/// the bands. `pause` / `resume` bracket the harness-only checksum of each band.
pub fn render_light_map<S: Shader<Varyings = [i32; 3]>, const P: usize>(
    shader: S,
    buf: &mut Light3dBuffers<P>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let n = triangles(&mut buf.lit);
    for (p, l) in buf.point.iter_mut().zip(&buf.lit) {
        *p = l.map(|v| Vertex::new(v.position, [v.varyings[0], v.varyings[1], v.varyings[2]]));
    }
    let tris = buf.point.get(..n).unwrap_or(&[]);
    bands(shader, tris, &mut buf.color, &mut buf.bins, pause, resume)
}

/// The same frame lit per vertex (varyings `x, y, z, i`, e.g. `SolidShader`): the baseline
/// the light map is compared with.
pub fn render_vertex_lit<S: Shader<Varyings = [i32; 4]>, const P: usize>(
    shader: S,
    buf: &mut Light3dBuffers<P>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let n = triangles(&mut buf.lit);
    let tris = buf.lit.get(..n).unwrap_or(&[]);
    bands(shader, tris, &mut buf.color, &mut buf.bins, pause, resume)
}

/// The triangles projected and binned once, then band by band the bins that meet the band
/// (`BandRenderer::render`).
fn bands<S: Shader<Varyings = [i32; N]>, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
    color: &mut [Rgb565],
    bins: &mut [Binned; BINS],
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    ScreenTriangle<N>: Binnable,
{
    let draw =
        ShadedDraw::<S, Exact, NoDepth>::new(shader, Viewport::new(0, 0, W, H)?, Cull::Back)?;
    let mut sum = Fnv1a::default();
    let rows = (color.len() as u32 / W).min(H);
    let mut bands = BandRenderer::new(color, W, rows, H)?;
    let stats = bands.render(
        &[&draw],
        bins,
        Rgb565::new(0, 0, 0),
        |sink| {
            for tr in tris {
                draw.project(tr, &mut |s| sink.push(0, s));
            }
            if sink.fresh() {
                crate::scenes::geometry_done();
            }
        },
        sum.band_flush::<core::convert::Infallible>(pause, resume),
    )?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}
