//! Measuring one variant: the mesh's vertices (reflection per pixel or per vertex), timed
//! whole-frame draws, the f64 references and the error against them, the firmware's band
//! frame checksum and the `env` rows of `mcu.tsv`.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ProjectionStage, ShadedDraw};
use fixel::shading::env::EnvVertices;
use fixel::shading::Shader;
use fixel::surface::{Frame, DEPTH_CLEAR};
use host_tests::metrics::{compare_rgb565, Report};
use host_tests::reference::env::{cube_sample, reflect, render_varyings};
use host_tests::reference::{RefFilter, RefTexture};

use crate::{env, H, W};

pub struct Mesh {
    pub pixel: Vec<[Vertex<6>; 3]>,
    pub vertex: Vec<[Vertex<3>; 3]>,
}

pub fn mesh<const V: usize, const T: usize>(
    m: &fixel_scenes::MeshData<V, T>,
    model: &Mat4,
) -> Mesh {
    let cam = fixel_scenes::camera(20);
    let s = EnvVertices::new(model, &cam.projection.mul(&cam.view), Vec3::ZERO);
    let pn = |i: u16| (m.positions[usize::from(i)], m.normals[usize::from(i)]);
    Mesh {
        pixel: m
            .indices
            .iter()
            .map(|t| t.map(|i| s.per_pixel(pn(i).0, pn(i).1).expect("vertex")))
            .collect(),
        vertex: m
            .indices
            .iter()
            .map(|t| t.map(|i| s.per_vertex(pn(i).0, pn(i).1).expect("vertex")))
            .collect(),
    }
}

pub type Image = (Vec<u16>, Vec<bool>);

fn draw<S: Shader<Varyings = [i32; N]>, P: ProjectionStage, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> u32 {
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    let d = ShadedDraw::<_, P, DepthLess>::new(shader, vp, Cull::Back).expect("draw");
    let mut f = Frame::new(color, W, H)
        .expect("frame")
        .with_depth(depth)
        .expect("depth");
    f.clear(Rgb565::new(0, 0, 0));
    d.clip_triangles(tris, &mut f).expect("draw")
}

/// The frame, and the median ns per pixel over `runs` draws (exact perspective).
pub fn run<S: Shader<Varyings = [i32; N]>, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
    runs: u32,
) -> (Image, f64) {
    run_in::<S, Exact, N>(shader, tris, runs)
}

/// [`run`] under projection stage `P`.
pub fn run_in<S: Shader<Varyings = [i32; N]>, P: ProjectionStage, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
    runs: u32,
) -> (Image, f64) {
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
    let mut ns = Vec::new();
    let mut px = 0;
    for _ in 0..runs {
        let t = Instant::now();
        px = draw::<S, P, N>(shader, tris, &mut color, &mut depth);
        ns.push(t.elapsed().as_nanos() as f64 / f64::from(px.max(1)));
    }
    ns.sort_by(f64::total_cmp);
    let img = (
        color.iter().map(|c| c.into_storage()).collect(),
        depth.iter().map(|&z| z != DEPTH_CLEAR).collect(),
    );
    let _ = px;
    (img, ns[ns.len() / 2])
}

pub fn ref_pixel(m: &Mesh, rf: &[RefTexture; 6], f: RefFilter) -> Image {
    render_varyings(&m.pixel, W, H, |_, _, a| {
        cube_sample(rf, reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]]), f)
    })
}

pub fn ref_vertex(m: &Mesh, rf: &[RefTexture; 6], f: RefFilter) -> Image {
    render_varyings(&m.vertex, W, H, |_, _, a| cube_sample(rf, a, f))
}

pub fn cmp(a: &Image, b: &Image) -> Report {
    compare_rgb565(&a.0, &a.1, &b.0, &b.1)
}

pub fn fmt_err(r: &Report) -> String {
    format!(
        "{:.3} / {} / {:.2} % / {:.1} dB",
        r.mean,
        r.max,
        100.0 * r.share_over_1,
        r.psnr_db
    )
}

/// `scene=env` rows of `mcu.tsv`: mode -> target -> (instructions / pixel, pixels, checksum).
pub fn read_mcu(path: &PathBuf) -> BTreeMap<String, BTreeMap<String, (f64, u64, String)>> {
    let mut m: BTreeMap<String, BTreeMap<String, (f64, u64, String)>> = BTreeMap::new();
    let text = std::fs::read_to_string(path).unwrap_or_default();
    for l in text.lines().skip(1) {
        let f: Vec<&str> = l.split('\t').collect();
        if f.len() < 6 || f[0] != "env" {
            continue;
        }
        let (Ok(ins), Ok(px)) = (f[3].parse::<f64>(), f[4].parse::<u64>()) else {
            continue;
        };
        m.entry(f[1].to_string()).or_default().insert(
            f[2].to_string(),
            (ins / px.max(1) as f64, px, f[5].to_string()),
        );
    }
    m
}

/// The firmware's band frame on the host (its checksum is what the MCU must print).
pub fn band_checksum<S: Shader<Varyings = [i32; N]>, const N: usize>(
    shader: S,
    vertex: impl Fn(&EnvVertices, Vec3, Vec3) -> Option<Vertex<N>>,
) -> (String, u64)
where
    fixel::geometry::ScreenTriangle<N>: fixel::surface::Binnable,
{
    let s = Box::new(fixel_scenes::sphere());
    let mut buf = Box::new(env::EnvBuffers::new());
    let (mut a, mut b) = (|| {}, || {});
    let r = env::env_frame::<_, Exact, N>(
        &mut buf,
        shader,
        &s.positions,
        &s.normals,
        &s.indices,
        vertex,
        &mut a,
        &mut b,
    )
    .expect("band frame");
    (format!("0x{:08x}", r.checksum), u64::from(r.stats.pixels))
}
