//! The environment-mapping firmware frames (`env_pixel`, `env_vertex`, `env_cube_vertex`),
//! rendered on the host
//! through the very same code (`examples/firmware/src/env.rs`), and their checksums: part of
//! the `mcu_checksums` test (its `mcu-expected` lines are what `cargo xtask mcu` compares).
//! The frames are also checked against a whole-frame draw of the same triangles.

#[path = "../../../examples/firmware/src/env.rs"]
#[allow(dead_code)]
mod env;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Vec3;
use fixel::pipeline::{DepthLess, Exact, ProjectionStage, ShadedDraw, SubdividedBy};
use fixel::shading::env::{sky, CubeVertex, EnvVertices, ReflectPerPixel, ReflectPerVertex};
use fixel::shading::Shader;
use fixel::surface::Frame;
use fixel::texture::{Bilinear, Lod, MipTexture, Texture};

use crate::scenes::{Fnv1a, H, W};

fn faces() -> Vec<Vec<Rgb565>> {
    (0..6)
        .map(|f| {
            let mut t = vec![Rgb565::new(0, 0, 0); 64 * 64];
            sky::sky_face(f, 64, &mut t).unwrap();
            t
        })
        .collect()
}

/// The same triangles drawn into one whole frame, hashed the same way.
fn whole<S: Shader<Varyings = [i32; N]>, P: ProjectionStage, const N: usize>(
    shader: S,
    vertex: impl Fn(&EnvVertices, Vec3, Vec3) -> Option<Vertex<N>>,
) -> (u32, u32) {
    let m = fixel_scenes::sphere();
    let cam = fixel_scenes::camera(20);
    let setup = EnvVertices::new(
        &fixel_scenes::sphere_model(0),
        &cam.projection.mul(&cam.view),
        Vec3::ZERO,
    );
    let tris: Vec<[Vertex<N>; 3]> = m
        .indices
        .iter()
        .map(|t| {
            t.map(|i| {
                vertex(
                    &setup,
                    m.positions[usize::from(i)],
                    m.normals[usize::from(i)],
                )
                .unwrap()
            })
        })
        .collect();
    let mut color = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    let mut depth = vec![0u16; (W * H) as usize];
    let mut frame = Frame::new(&mut color, W, H)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    let d =
        ShadedDraw::<_, P, DepthLess>::new(shader, Viewport::new(0, 0, W, H).unwrap(), Cull::Back)
            .unwrap();
    let px = d.clip_triangles(&tris, &mut frame).unwrap();
    let mut h = Fnv1a::default();
    h.pixels(frame.pixels());
    (h.0, px)
}

#[test]
fn env_frames() {
    let f = faces();
    let cube = env::env_cube([&f[0], &f[1], &f[2], &f[3], &f[4], &f[5]]).unwrap();
    let sphere = Box::new(fixel_scenes::sphere());
    let mut buf = Box::new(env::EnvBuffers::new());
    let (mut nop1, mut nop2) = (|| {}, || {});
    let r = env::env_frame::<_, Exact, 6>(
        &mut buf,
        ReflectPerPixel(cube),
        &sphere.positions,
        &sphere.normals,
        &sphere.indices,
        EnvVertices::per_pixel,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    crate::print("env_pixel", &r);
    assert_eq!(
        whole::<_, Exact, 6>(ReflectPerPixel(cube), EnvVertices::per_pixel),
        (r.checksum, r.stats.pixels)
    );
    // The whole-frame firmware's own path.
    let (mut wc, mut wd) = (
        vec![Rgb565::new(0, 0, 0); (W * H) as usize],
        vec![0u16; (W * H) as usize],
    );
    let w = env::env_frame_whole::<_, Exact, 6>(
        &mut wc,
        &mut wd,
        ReflectPerPixel(cube),
        &sphere.positions,
        &sphere.normals,
        &sphere.indices,
        EnvVertices::per_pixel,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    crate::print_whole("env_pixel", &r, &w);
    let r = env::env_frame::<_, Exact, 3>(
        &mut buf,
        ReflectPerVertex(cube),
        &sphere.positions,
        &sphere.normals,
        &sphere.indices,
        EnvVertices::per_vertex,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    crate::print("env_vertex", &r);
    assert_eq!(
        whole::<_, Exact, 3>(ReflectPerVertex(cube), EnvVertices::per_vertex),
        (r.checksum, r.stats.pixels)
    );
    let w = env::env_frame_whole::<_, Exact, 3>(
        &mut wc,
        &mut wd,
        ReflectPerVertex(cube),
        &sphere.positions,
        &sphere.normals,
        &sphere.indices,
        EnvVertices::per_vertex,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    crate::print_whole("env_vertex", &r, &w);
    // The cube map per vertex: a face per triangle, affine in 64-pixel pieces.
    let r = env::cube_vertex_frame(
        &mut buf,
        [&f[0], &f[1], &f[2], &f[3], &f[4], &f[5]],
        &sphere.positions,
        &sphere.normals,
        &sphere.indices,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    crate::print("env_cube_vertex", &r);
    let chains: [MipTexture<'_>; 6] =
        core::array::from_fn(|k| MipTexture::single(Texture::new(&f[k], 64, 64).unwrap()));
    let cv = CubeVertex::new(&chains, Bilinear, Lod::default()).unwrap();
    assert_eq!(
        whole::<_, SubdividedBy<6>, 3>(cv, EnvVertices::per_vertex),
        (r.checksum, r.stats.pixels)
    );
}
