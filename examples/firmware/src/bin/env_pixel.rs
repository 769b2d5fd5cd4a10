//! Scene `env_pixel`: the benchmark sphere (frame 0) as a mirror in the 64-texel sky cube
//! map, bilinear, the reflection computed per pixel (interpolated n and v), exact perspective, 320x240
//! in 8-row bands.
#![no_std]
#![no_main]

use fixel::pipeline::Exact;
use fixel::shading::env::{EnvVertices, ReflectPerPixel};
use fixel_firmware::{data, env, report};

fn run() -> bool {
    let mut buf = env::EnvBuffers::new();
    let sphere = core::hint::black_box(&data::SPHERE);
    let faces = core::hint::black_box(&data::SKY64);
    report("env_pixel", |pause, resume| {
        let cube = env::env_cube([
            &faces[0], &faces[1], &faces[2], &faces[3], &faces[4], &faces[5],
        ])?;
        env::env_frame::<_, Exact, _>(
            &mut buf,
            ReflectPerPixel(cube),
            &sphere.positions,
            &sphere.normals,
            &sphere.indices,
            EnvVertices::per_pixel,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
