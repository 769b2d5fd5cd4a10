//! Scene `sphere`, frame 0: 2208 triangles (mesh in flash), lit, bilinear, perspective-correct,
//! depth-tested, in 320x8 bands: one binning pass stores each triangle's band range (2 B),
//! then each band re-projects only the triangles that meet it. The mesh's face planes are
//! baked in flash (`fixel::scene::face_planes`).
#![no_std]
#![no_main]

use fixel_firmware::{data, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SphereBuffers::with_storage();
    let frame = core::hint::black_box(0);
    // The face planes baked in flash (53 KB): the model-space back-face test reads one per
    // triangle.
    let Ok(mesh) = core::hint::black_box(&data::SPHERE)
        .mesh()
        .and_then(|m| m.with_face_planes(&data::SPHERE_FACES))
    else {
        return false;
    };
    report("sphere", |pause, resume| {
        scenes::sphere(
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
