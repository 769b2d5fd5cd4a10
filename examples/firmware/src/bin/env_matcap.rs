//! Scene `env_matcap`, frame 0: the benchmark sphere as a mirror of the sky through a
//! 128 x 128 sphere map (32 KB of flash), its coordinates computed per vertex from the
//! view-space reflection, then a plain textured draw in the `sphere` scene's bands (see
//! `matcap_scene`): the real-time environment map, to set beside `sphere`.
#![no_std]
#![no_main]

use fixel::texture::Texture;
use fixel_firmware::{data, matcap_scene, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SphereBuffers::with_storage();
    let frame = core::hint::black_box(0);
    let Ok(mesh) = core::hint::black_box(&data::SPHERE)
        .mesh()
        .and_then(|m| m.with_face_planes(&data::SPHERE_FACES))
    else {
        return false;
    };
    let Ok(map) = Texture::new(core::hint::black_box(&data::SKY_SPHERE128), 128, 128) else {
        return false;
    };
    report("env_matcap", |pause, resume| {
        matcap_scene::env_matcap(
            scenes::Target::Bands(&mut buf),
            map,
            &mesh,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
