//! Scene `teapot`, frame 0: the Utah teapot baked from OBJ into flash by `cargo xtask
//! bake-obj` (1560 triangles), lit, bilinear, perspective-correct, depth-tested, in 320x8
//! bands through the sphere's band ranges and vertex cache.
#![no_std]
#![no_main]

use fixel::scene::Mesh;
use fixel_firmware::data::{self, teapot};
use fixel_firmware::{report, scenes};

fn run() -> bool {
    let mut buf = scenes::SphereBuffers::with_storage();
    let frame = core::hint::black_box(0);
    let Ok(mesh) = Mesh::new(
        core::hint::black_box(&teapot::TEAPOT_POSITIONS),
        Some(&teapot::TEAPOT_NORMALS),
        &teapot::TEAPOT_UVS,
        &teapot::TEAPOT_INDICES,
    ) else {
        return false;
    };
    report("teapot", |pause, resume| {
        scenes::teapot(
            scenes::Target::Bands(&mut buf),
            data::T256X128,
            &mesh,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
