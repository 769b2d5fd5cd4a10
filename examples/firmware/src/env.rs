//! The environment-mapping frame, band by band: the benchmark sphere (frame 0,
//! radius 1.5 at z = -5) as a mirror in the procedural sky cube map
//! (`fixel::shading::env::sky`, 64-texel faces), bilinear within a face, per-pixel or
//! per-vertex reflection. Shared word for word by the firmware (`env_*` bins) and the host
//! test `host-tests/tests/env_mcu/mod.rs` (included with `#[path]`), so both checksums come
//! from the same code.
//!
//! Drawn through fixel's band renderer (`BandRenderer::render_spans`): one binning pass
//! projects every triangle once and keeps the band range it covers (2 B per triangle); each
//! 320 x 8 band then re-projects only the triangles that meet it
//! (`fixel::scene::triangles_to_sink`).

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Vec3;
use fixel::pipeline::{DepthLess, ProjectionStage, ShadedDraw};
use fixel::shading::env::EnvVertices;
use fixel::shading::Shader;
use fixel::surface::{BandRange, Binnable};
use fixel::texture::{Bilinear, Texture};
use fixel::Error;
use fixel_scenes as demo;

use crate::scenes::{FrameResult, BAND_PIXELS, H, W};

/// Side of each cube-map face (6 x 64 x 64 x 2 B = 48 KB of flash).
pub const ENV_SIZE: u32 = 64;
/// Triangles of the benchmark sphere.
pub const ENV_TRIS: usize = demo::SPHERE_TRIANGLES;

/// The cube map the scene reads.
pub type EnvCube<'a> = fixel::shading::env::CubeMap<'a, Bilinear>;

/// Band buffers and one band range per triangle (2 B each): 10 KiB + 4.4 KB.
pub struct EnvBuffers {
    /// Colour band.
    pub color: [Rgb565; BAND_PIXELS],
    /// Depth band.
    pub depth: [u16; BAND_PIXELS],
    /// Band range per triangle.
    pub ranges: [BandRange; ENV_TRIS],
}

impl EnvBuffers {
    /// Zeroed buffers.
    pub fn new() -> Self {
        EnvBuffers {
            color: [Rgb565::new(0, 0, 0); BAND_PIXELS],
            depth: [0; BAND_PIXELS],
            ranges: [BandRange::EMPTY; ENV_TRIS],
        }
    }
}

impl Default for EnvBuffers {
    fn default() -> Self {
        Self::new()
    }
}

/// The cube map from six face texel slices (GL order).
pub fn env_cube<'a>(faces: [&'a [Rgb565]; 6]) -> Result<EnvCube<'a>, Error> {
    let mut t = [Texture::new(faces[0], ENV_SIZE, ENV_SIZE)?; 6];
    for (k, f) in faces.iter().enumerate() {
        t[k] = Texture::new(f, ENV_SIZE, ENV_SIZE)?;
    }
    fixel::shading::env::CubeMap::new(t, Bilinear)
}

/// One frame of the sphere with `shader` under projection `P`, its vertices made by
/// `vertex` (`EnvVertices::per_pixel` or `per_vertex`). `pause`/`resume` bracket each
/// band's checksum (left out of the instruction count).
#[allow(clippy::too_many_arguments)]
pub fn env_frame<S, P, const N: usize>(
    buf: &mut EnvBuffers,
    shader: S,
    positions: &[Vec3],
    normals: &[Vec3],
    indices: &[[u16; 3]],
    vertex: impl Fn(&EnvVertices, Vec3, Vec3) -> Option<Vertex<N>>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
    fixel::geometry::ScreenTriangle<N>: Binnable,
{
    let v = |s: &EnvVertices, i: usize| vertex(s, *positions.get(i)?, *normals.get(i)?);
    env_frame_indexed::<S, P, N>(buf, shader, positions, indices, v, pause, resume)
}

/// [`env_frame`] with vertices made from their index (for varyings beyond `n` and `v`,
/// such as texture coordinates): `vertex(setup, i)`, at `positions[i]` (the binning pass
/// projects the positions alone).
pub fn env_frame_indexed<S, P, const N: usize>(
    buf: &mut EnvBuffers,
    shader: S,
    positions: &[Vec3],
    indices: &[[u16; 3]],
    vertex: impl Fn(&EnvVertices, usize) -> Option<Vertex<N>>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
    fixel::geometry::ScreenTriangle<N>: Binnable,
{
    let cam = demo::camera(20);
    let setup = EnvVertices::new(
        &demo::sphere_model(0),
        &cam.projection.mul(&cam.view),
        Vec3::ZERO,
    );
    let draw = ShadedDraw::<S, P, DepthLess>::new(shader, Viewport::new(0, 0, W, H)?, Cull::Back)?;
    // The binning pass needs the rows only: clip positions, no varyings (the vertex stage
    // of the reflection runs in the bands a triangle meets).
    let tri = |k: usize, attributes: bool| -> Option<[Vertex<N>; 3]> {
        let t = indices.get(k)?;
        let v = |i: u16| {
            if attributes {
                vertex(&setup, usize::from(i))
            } else {
                let c = setup.mvp.transform_point(*positions.get(usize::from(i))?)?;
                Some(Vertex::new([c.x, c.y, c.z, c.w], [0; N]))
            }
        };
        Some([v(t[0])?, v(t[1])?, v(t[2])?])
    };
    crate::open_frame::open_bands::<S, P, N>(
        &mut buf.color,
        &mut buf.depth,
        &mut buf.ranges,
        &draw,
        indices.len(),
        tri,
        Rgb565::new(0, 0, 0),
        pause,
        resume,
    )
}

/// [`env_frame`] drawn into one whole frame (`color`, `depth`: 320 x 240) with the same
/// draw, triangle by triangle: the figure the banded frame is compared with (the same
/// checksum: the hash runs over the frame's pixels in the same order).
#[allow(clippy::too_many_arguments)]
pub fn env_frame_whole<S, P, const N: usize>(
    color: &mut [Rgb565],
    depth: &mut [u16],
    shader: S,
    positions: &[Vec3],
    normals: &[Vec3],
    indices: &[[u16; 3]],
    vertex: impl Fn(&EnvVertices, Vec3, Vec3) -> Option<Vertex<N>>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
{
    let cam = demo::camera(20);
    let setup = EnvVertices::new(
        &demo::sphere_model(0),
        &cam.projection.mul(&cam.view),
        Vec3::ZERO,
    );
    let draw = ShadedDraw::<S, P, DepthLess>::new(shader, Viewport::new(0, 0, W, H)?, Cull::Back)?;
    let tri = |k: usize, _: bool| -> Option<[Vertex<N>; 3]> {
        let t = indices.get(k)?;
        let v = |i: u16| {
            let i = usize::from(i);
            vertex(&setup, *positions.get(i)?, *normals.get(i)?)
        };
        Some([v(t[0])?, v(t[1])?, v(t[2])?])
    };
    crate::open_frame::open_whole::<S, P, N>(
        color,
        depth,
        &draw,
        indices.len(),
        tri,
        Rgb565::new(0, 0, 0),
        pause,
        resume,
    )
}

/// A vertex for `EnvLit`: `n`, `v` as [`EnvVertices::per_pixel`], then the texture
/// coordinates of vertex `i`.
pub fn lit_vertex(
    setup: &EnvVertices,
    positions: &[Vec3],
    normals: &[Vec3],
    uvs: &[[fixel::math::Fx; 2]],
    i: usize,
) -> Option<Vertex<8>> {
    let v = setup.per_pixel(*positions.get(i)?, *normals.get(i)?)?;
    let a = v.varyings;
    let uv = uvs.get(i)?;
    Some(Vertex::new(
        v.position,
        [
            a[0],
            a[1],
            a[2],
            a[3],
            a[4],
            a[5],
            uv[0].to_bits(),
            uv[1].to_bits(),
        ],
    ))
}

/// The `env_cube_vertex` frame: the sphere (`positions`, `normals`, `indices`) as a mirror
/// of the six 64-texel `faces` through one face per triangle and its coordinates per vertex
/// (`CubeVertex`, bilinear, clamp-to-edge), affine in 64-pixel pieces, in the same bands as
/// [`env_frame`].
#[allow(clippy::too_many_arguments)]
pub fn cube_vertex_frame(
    buf: &mut EnvBuffers,
    faces: [&[Rgb565]; 6],
    positions: &[Vec3],
    normals: &[Vec3],
    indices: &[[u16; 3]],
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    use fixel::texture::{Lod, MipTexture};
    let t = |k: usize| Texture::new(faces[k], ENV_SIZE, ENV_SIZE).map(MipTexture::single);
    let chains = [t(0)?, t(1)?, t(2)?, t(3)?, t(4)?, t(5)?];
    let shader = fixel::shading::env::CubeVertex::new(&chains, Bilinear, Lod::default())?;
    env_frame::<_, fixel::pipeline::SubdividedBy<6>, 3>(
        buf,
        shader,
        positions,
        normals,
        indices,
        EnvVertices::per_vertex,
        pause,
        resume,
    )
}
