//! The environment-mapping test scene shared by the env tests and the env report: the
//! procedural sky as cube-map faces and mip chains (fixel's and the reference's copies of
//! the same texels), the benchmark sphere and cube as per-pixel-reflection vertices, a
//! depth-tested 320 x 240 draw, the reference render with `r` per pixel, and the direction
//! set the lookup tests sweep.

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::env::{sky, CubeMap, EnvVertices};
use fixel::shading::Shader;
use fixel::surface::{Frame, DEPTH_CLEAR};
use fixel::texture::{Sampler, Texture};

use crate::reference::env::{reflect, render_varyings};
use crate::reference::mip::RefMipChain;
use crate::reference::RefTexture;
use fixel::texture::{chain_len, full_levels, generate_mips, level_side};

/// Frame width.
pub const W: u32 = 320;
/// Frame height.
pub const H: u32 = 240;

/// An RGB565 frame (raw) and its coverage (depth written).
pub type Image = (Vec<u16>, Vec<bool>);

/// The six sky faces of side `size` (GL order).
pub fn faces(size: u32) -> Vec<Vec<Rgb565>> {
    (0..6)
        .map(|f| {
            let mut t = vec![Rgb565::new(0, 0, 0); (size * size) as usize];
            sky::sky_face(f, size, &mut t).expect("sky face");
            t
        })
        .collect()
}

/// The reference's copy of `faces`.
pub fn ref_faces(f: &[Vec<Rgb565>], size: u32) -> [RefTexture; 6] {
    core::array::from_fn(|i| RefTexture {
        width: size,
        height: size,
        texels: f[i].iter().map(|&c| c.into_storage()).collect(),
        border: 0,
    })
}

/// fixel's cube map over `faces`.
pub fn cube<F: Sampler>(f: &[Vec<Rgb565>], size: u32, filter: F) -> CubeMap<'_, F> {
    CubeMap::new(
        core::array::from_fn(|i| Texture::new(&f[i], size, size).expect("face")),
        filter,
    )
    .expect("cube map")
}

/// The triangles of `m` (with `model`, the benchmark camera of frame 20) as vertices of
/// `vertex` (for example [`EnvVertices::per_pixel`]).
pub fn triangles<const V: usize, const T: usize, const N: usize>(
    m: &fixel_scenes::MeshData<V, T>,
    model: &Mat4,
    vertex: impl Fn(&EnvVertices, Vec3, Vec3) -> Option<Vertex<N>>,
) -> Vec<[Vertex<N>; 3]> {
    let cam = fixel_scenes::camera(20);
    let s = EnvVertices::new(model, &cam.projection.mul(&cam.view), Vec3::ZERO);
    m.indices
        .iter()
        .map(|t| {
            t.map(|i| {
                let i = usize::from(i);
                vertex(&s, m.positions[i], m.normals[i]).expect("vertex")
            })
        })
        .collect()
}

/// The benchmark sphere (frame 0) with per-pixel-reflection vertices.
pub fn sphere_pixel() -> Vec<[Vertex<6>; 3]> {
    triangles(
        &fixel_scenes::sphere(),
        &fixel_scenes::sphere_model(0),
        EnvVertices::per_pixel,
    )
}

/// Draws `tris` with `shader` into a fresh `W x H` frame (exact perspective, depth less,
/// back faces culled).
pub fn draw<S: Shader<Varyings = [i32; N]>, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
) -> Image {
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    let d = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).expect("draw");
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, W, H)
        .expect("frame")
        .with_depth(&mut depth)
        .expect("depth");
    d.clip_triangles(tris, &mut frame).expect("drawn");
    let cov = frame
        .depth()
        .expect("depth")
        .iter()
        .map(|&z| z != DEPTH_CLEAR)
        .collect();
    (
        frame.pixels().iter().map(|&c| c.into_storage()).collect(),
        cov,
    )
}

/// The reference with the reflection per pixel (from the interpolated `n`, `v` of the
/// first six varyings), coloured by `lookup` of the unnormalised `r`.
pub fn reference_per_pixel<const N: usize>(
    tris: &[[Vertex<N>; 3]],
    lookup: impl Fn([f64; 3]) -> [f64; 3],
) -> Image {
    render_varyings(tris, W, H, |_, _, a| {
        lookup(reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]]))
    })
}

/// The six sky faces of side `size` with full mip chains (fixel's `generate_mips`), one buffer
/// per face.
pub fn sky_chains(size: u32) -> Vec<Vec<Rgb565>> {
    let levels = full_levels(size, size);
    faces(size)
        .into_iter()
        .map(|base| {
            let mut c = vec![Rgb565::new(0, 0, 0); chain_len(size, size, levels)];
            c[..base.len()].copy_from_slice(&base);
            generate_mips(&mut c, size, size, levels).expect("mips");
            c
        })
        .collect()
}

/// The reference's copy of full chains of side `size` (data shared, nothing else).
pub fn ref_chains(c: &[Vec<Rgb565>], size: u32) -> [RefMipChain; 6] {
    let levels = full_levels(size, size);
    core::array::from_fn(|f| {
        let mut off = 0;
        RefMipChain {
            levels: (0..levels)
                .map(|k| {
                    let s = level_side(size, k);
                    let n = (s * s) as usize;
                    let t = RefTexture {
                        width: s,
                        height: s,
                        texels: c[f][off..off + n]
                            .iter()
                            .map(|p| p.into_storage())
                            .collect(),
                        border: 0,
                    };
                    off += n;
                    t
                })
                .collect(),
        }
    })
}

/// A deterministic spread of `n` directions: a Fibonacci sphere at four scales (from 3e3 to
/// 1e9 per unit), as `i32` components.
pub fn directions(n: usize) -> Vec<[i32; 3]> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let y = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - y * y).sqrt();
            let a = golden * i as f64;
            let scale = [3.0e3, 1.0e5, 2.0e7, 1.0e9][i % 4];
            [r * a.cos(), y, r * a.sin()].map(|c| (c * scale).round() as i32)
        })
        .collect()
}

/// Six plain face colours (GL order) for the edge and corner tests: every channel of each
/// is 0 or near full, so blends of two or three faces are told apart.
pub const PLAIN_FACES: [Rgb565; 6] = [
    Rgb565::new(30, 0, 0),
    Rgb565::new(0, 60, 0),
    Rgb565::new(0, 0, 30),
    Rgb565::new(30, 60, 0),
    Rgb565::new(0, 60, 30),
    Rgb565::new(30, 0, 30),
];

/// True when raw `got` is, per channel, within 2/3 LSB of the mean of the
/// [`PLAIN_FACES`] colours of `faces` (a seamless blend of those faces).
pub fn is_plain_blend(got: u16, faces: &[usize]) -> bool {
    let ch = |v: u16| {
        [
            f64::from(v >> 11),
            f64::from((v >> 5) & 63),
            f64::from(v & 31),
        ]
    };
    let g = ch(got);
    (0..3).all(|k| {
        let m = faces
            .iter()
            .map(|&f| ch(PLAIN_FACES[f].into_storage())[k])
            .sum::<f64>()
            / faces.len() as f64;
        (g[k] - m).abs() <= 0.67
    })
}

/// The 64-texel sky cube map baked into an `n x n` sphere map (bilinear lookups,
/// `fixel::shading::env::bake_sphere_map`): the `env_matcap` scene's texture for `n = 128`.
pub fn sky_sphere_map(n: u32) -> Vec<Rgb565> {
    let f = faces(64);
    let c = cube(&f, 64, fixel::texture::Bilinear);
    let mut t = vec![Rgb565::new(0, 0, 0); (n * n) as usize];
    fixel::shading::env::bake_sphere_map(&c, n, &mut t).expect("sphere map");
    t
}
