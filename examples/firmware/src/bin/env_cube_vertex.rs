//! Scene `env_cube_vertex`, frame 0: the benchmark sphere as a mirror in the 64-texel sky
//! cube map, the reflection computed per vertex, one face per triangle and its face
//! coordinates per vertex (`fixel::shading::env::CubeVertex`), then a plain textured draw of
//! that face, bilinear, clamp-to-edge, affine in 64-pixel pieces, 320x240 in 8-row bands
//! (`env::cube_vertex_frame`): the real-time cube-map environment, to set beside `sphere`
//! and `env_vertex`.
#![no_std]
#![no_main]

use fixel_firmware::{data, env, report};

fn run() -> bool {
    let mut buf = env::EnvBuffers::new();
    let s = core::hint::black_box(&data::SPHERE);
    let f = core::hint::black_box(&data::SKY64);
    report("env_cube_vertex", |pause, resume| {
        env::cube_vertex_frame(
            &mut buf,
            [&f[0], &f[1], &f[2], &f[3], &f[4], &f[5]],
            &s.positions,
            &s.normals,
            &s.indices,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
