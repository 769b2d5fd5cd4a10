//! Scene `noise_baked_granite`, frame 0: the benchmark sphere in the granite solid texture baked
//! into a 256 x 128 texture for the sphere's own (object-space, latitude-longitude) texture
//! coordinates by `build.rs` (`fixel::shading::noise::bake`, band-limited turbulence of at
//! most 6 octaves): the `sphere` scene's draw (lit, bilinear, exact every 64 pixels, 320 x 8
//! bands) with that texture, as `noise_baked` draws the marble.
#![no_std]
#![no_main]

use fixel_firmware::{data, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SphereBuffers::with_storage();
    let frame = core::hint::black_box(0);
    let Ok(mesh) = core::hint::black_box(&data::SPHERE)
        .mesh()
        .and_then(|m| m.with_face_planes(&data::SPHERE_FACES))
    else {
        return false;
    };
    report("noise_baked_granite", |pause, resume| {
        scenes::sphere(
            scenes::Target::Bands(&mut buf),
            data::GRANITE256X128,
            &mesh,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
