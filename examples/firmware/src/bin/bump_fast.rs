//! Scene `bump_fast`, frame 0: the benchmark sphere with the brick tile's bump-mapped
//! lighting resolved into a 256 x 128 texture for a light fixed in object space
//! (`fixel::shading::bump::resolve_sphere`, by `build.rs`), then drawn as a plain unlit
//! textured mesh in the `sphere` scene's bands (bilinear, exact every 64 pixels): the
//! real-time form of the `bump` scene's per-pixel lighting, to set beside `sphere`.
#![no_std]
#![no_main]

use fixel::texture::MipTexture;
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
    report("bump_fast", |pause, resume| {
        scenes::render::<
            scenes::FloorBilinear,
            { scenes::RANGES },
            { scenes::CACHE },
            0,
            { scenes::SETUPS },
        >(
            scenes::Target::Bands(&mut buf),
            MipTexture::single(data::BRICKS_LIT256X128),
            &mesh,
            &fixel_scenes::sphere_model(frame),
            20,
            false,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
