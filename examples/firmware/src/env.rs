//! The environment-mapping frame (issue 11), band by band: the benchmark sphere (frame 0,
//! radius 1.5 at z = -5) as a mirror in the procedural sky cube map
//! (`fixel::shading::env::sky`, 64-texel faces), bilinear within a face, per-pixel or
//! per-vertex reflection. Shared word for word by the firmware (`env_*` bins) and the host
//! test `host-tests/tests/env_mcu/mod.rs` (included with `#[path]`), so both checksums come
//! from the same code.
//!
//! One pass projects every triangle once and keeps the band range it covers (2 B per
//! triangle) and, per band, the run of triangle indices that meets it; each 320 x 8 band
//! then scans its run and re-projects only the triangles that meet it.

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::demo;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Vec3;
use fixel::pipeline::{DepthLess, ProjectionStage, ShadedDraw};
use fixel::shading::env::EnvVertices;
use fixel::shading::Shader;
use fixel::surface::{BandStats, Frame};
use fixel::texture::{Bilinear, Texture};
use fixel::Error;

use crate::scenes::{Fnv1a, FrameResult, BAND_PIXELS, H, ROWS, W};

/// Side of each cube-map face (6 x 64 x 64 x 2 B = 48 KB of flash).
pub const ENV_SIZE: u32 = 64;
/// Triangles of the benchmark sphere.
pub const ENV_TRIS: usize = demo::SPHERE_TRIANGLES;

/// The cube map the scene reads.
pub type EnvCube<'a> = fixel::shading::env::CubeMap<'a, Bilinear>;

/// Band buffers, one band range per triangle (first and last band; `first > last` when
/// the triangle is culled or off screen) and one index run per band: 10 KiB + 4.5 KB.
pub struct EnvBuffers {
    /// Colour band.
    pub color: [Rgb565; BAND_PIXELS],
    /// Depth band.
    pub depth: [u16; BAND_PIXELS],
    /// Band range per triangle.
    pub ranges: [[u8; 2]; ENV_TRIS],
    /// Per band, the first and one past the last triangle index that meets it (a mesh
    /// stored row by row, like the UV sphere, meets each band with a short index run).
    pub runs: [[u16; 2]; (H / ROWS) as usize],
}

impl EnvBuffers {
    /// Zeroed buffers.
    pub fn new() -> Self {
        EnvBuffers {
            color: [Rgb565::new(0, 0, 0); BAND_PIXELS],
            depth: [0; BAND_PIXELS],
            ranges: [[1, 0]; ENV_TRIS],
            runs: [[0, 0]; (H / ROWS) as usize],
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
{
    let v = |s: &EnvVertices, i: usize| vertex(s, *positions.get(i)?, *normals.get(i)?);
    env_frame_indexed::<S, P, N>(buf, shader, positions, indices, v, pause, resume)
}

/// [`env_frame`] with vertices made from their index (for varyings beyond `n` and `v`,
/// such as texture coordinates): `vertex(setup, i)`.
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
{
    let cam = demo::camera(20);
    let setup = EnvVertices::new(
        &demo::sphere_model(0),
        &cam.projection.mul(&cam.view),
        Vec3::ZERO,
    );
    let draw = ShadedDraw::<S, P, DepthLess>::new(shader, Viewport::new(0, 0, W, H)?, Cull::Back)?;
    let tri = |t: &[u16; 3]| -> Option<[Vertex<N>; 3]> {
        let v = |i: u16| vertex(&setup, usize::from(i));
        Some([v(t[0])?, v(t[1])?, v(t[2])?])
    };
    let bands = H / ROWS;
    let mut stats = BandStats {
        bands,
        reprojected: true,
        ..BandStats::default()
    };
    // Pass 1: the band range of every triangle (rows in 1/16 pixel, 4 fraction bits), from
    // clip positions alone (no varyings).
    let clip = |t: &[u16; 3]| -> Option<[Vertex<0>; 3]> {
        let v = |i: u16| {
            let c = setup.mvp.transform_point(*positions.get(usize::from(i))?)?;
            Some(Vertex::new([c.x, c.y, c.z, c.w], []))
        };
        Some([v(t[0])?, v(t[1])?, v(t[2])?])
    };
    buf.runs = [[u16::MAX, 0]; (H / ROWS) as usize];
    for (k, (t, range)) in indices.iter().zip(buf.ranges.iter_mut()).enumerate() {
        *range = [1, 0];
        let Some(v) = clip(t) else { continue };
        let (mut lo, mut hi) = (i32::MAX, i32::MIN);
        draw.project(&v, &mut |s| {
            for p in s {
                lo = lo.min(p.y);
                hi = hi.max(p.y);
            }
        });
        if lo <= hi {
            stats.triangles += 1;
            let band = |y: i32| ((y >> 4).clamp(0, H as i32 - 1) as u32 / ROWS) as u8;
            *range = [band(lo), band(hi + 15)];
            let k = k as u16;
            for run in buf.runs[usize::from(range[0])..=usize::from(range[1])].iter_mut() {
                run[0] = run[0].min(k);
                run[1] = run[1].max(k + 1);
            }
        }
    }
    let mut hash = Fnv1a::default();
    for b in 0..bands {
        let mut frame = Frame::new(&mut buf.color[..], W, ROWS)?
            .at_row(b * ROWS)
            .with_depth(&mut buf.depth[..])?;
        frame.clear(Rgb565::new(0, 0, 0));
        let b8 = b as u8;
        let [first, end] = buf.runs[b as usize];
        let (first, end) = (usize::from(first), usize::from(end).max(usize::from(first)));
        let tris = indices.get(first..end).unwrap_or(&[]);
        let ranges = buf.ranges.get(first..end).unwrap_or(&[]);
        for (t, r) in tris.iter().zip(ranges.iter()) {
            if r[0] > b8 || r[1] < b8 {
                continue;
            }
            let Some(v) = tri(t) else { continue };
            let mut err = Ok(());
            draw.project(&v, &mut |s| match draw.screen_triangle(s, &mut frame) {
                Ok(n) => stats.pixels = stats.pixels.wrapping_add(n),
                Err(e) => err = Err(e),
            });
            err?;
        }
        pause();
        hash.pixels(frame.pixels());
        resume();
    }
    Ok(FrameResult {
        checksum: hash.0,
        stats,
    })
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
