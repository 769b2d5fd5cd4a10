//! Triplanar mapping (`fixel::shading::triplanar`) against the f64 reference
//! (`host_tests::reference::triplanar`) on the demo sphere and cube: every pixel within
//! the error budget, for the default and the widest blend.

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Fx, Mat4};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::scene::DirectionalLight;
use fixel::shading::triplanar::{Triplanar, TriplanarMesh};
use fixel::surface::Frame;
use fixel::texture::{Bilinear, Texture};
use fixel::Rgb565;
use fixel_scenes as demo;
use host_tests::adapter;
use host_tests::metrics::compare;
use host_tests::reference::{triplanar, RefFilter};
use host_tests::scenes::procedural_texture;

const W: u32 = 320;
const H: u32 = 240;

fn tris<const V: usize, const T: usize>(
    m: &demo::MeshData<V, T>,
    model: &Mat4,
) -> Vec<[Vertex<7>; 3]> {
    let mesh = TriplanarMesh {
        positions: &m.positions,
        normals: &m.normals,
        indices: &m.indices,
        texels_per_unit: Fx::from_num(40),
    };
    let mut out = Vec::new();
    mesh.triangles(
        model,
        &demo::camera(20),
        Some(&DirectionalLight::default()),
        |t| out.push(*t),
    );
    out
}

fn check(name: &str, tris: &[[Vertex<7>; 3]], k: u8) {
    let rt = procedural_texture(64, 64);
    let texels = adapter::texels(&rt);
    let tex = Texture::new(&texels, 64, 64).unwrap();
    let shader = Triplanar::new(tex, Bilinear).sharpness(k);
    let draw = ShadedDraw::<_, Exact, DepthLess>::new(
        shader,
        Viewport::new(0, 0, W, H).unwrap(),
        Cull::Back,
    )
    .unwrap();
    let n = (W * H) as usize;
    let (mut px, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut px, W, H)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    draw.clip_triangles(tris, &mut frame).unwrap();
    let covered: Vec<bool> = depth.iter().map(|&d| d != u16::MAX).collect();
    let raw: Vec<u16> = px.iter().map(|&c| RawU16::from(c).into_inner()).collect();
    let reference = triplanar::render(tris, &rt, RefFilter::Bilinear, f64::from(k) / 256.0, W, H);
    let rep = compare(&raw, &covered, &reference);
    println!("triplanar {name} k={k}: {rep}");
    // Measured: max 1 LSB, p99 1 on both meshes and both blends.
    assert!(rep.max <= 2 && rep.p99 <= 1, "{name}: {rep}");
    let miss = rep.only_candidate + rep.only_reference;
    assert!(miss * 500 <= rep.both_covered, "{name}: {rep}");
}

#[test]
fn triplanar_matches_the_reference() {
    let sphere = tris(&demo::sphere(), &demo::sphere_model(10));
    let cube = tris(&demo::cube(), &demo::cube_model(20));
    for k in [128, 0] {
        check("sphere", &sphere, k);
        check("cube", &cube, k);
    }
}
