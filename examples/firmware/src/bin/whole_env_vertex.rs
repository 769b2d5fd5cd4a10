//! Scene `env_vertex` (the mirror sphere, reflection per vertex) drawn into one whole
//! 320x240 frame (colour + 16-bit depth) with the same draw: the figure the banded
//! `env_vertex` is compared with. Whole-frame memory layout (`FIXEL_FW_MEMORY=whole`,
//! feature `whole`).
#![no_std]
#![no_main]

use fixel::pipeline::Exact;
use fixel::shading::env::{EnvVertices, ReflectPerVertex};
use fixel_firmware::{data, env, report, scenes};

fn run() -> bool {
    let mut buf = scenes::Whole::new();
    let sphere = core::hint::black_box(&data::SPHERE);
    let faces = core::hint::black_box(&data::SKY64);
    report("whole_env_vertex", |pause, resume| {
        let cube = env::env_cube([
            &faces[0], &faces[1], &faces[2], &faces[3], &faces[4], &faces[5],
        ])?;
        env::env_frame_whole::<_, Exact, _>(
            &mut buf.color,
            &mut buf.depth,
            ReflectPerVertex(cube),
            &sphere.positions,
            &sphere.normals,
            &sphere.indices,
            EnvVertices::per_vertex,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
