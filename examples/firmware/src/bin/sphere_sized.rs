//! Scene `sphere_sized`, frame 0: the benchmark sphere in its fastest mode
//! (`scenes::LitSphereSized`: lit, bilinear footprints of a texture whose size is fixed at
//! compile time), in 320x8 bands: one binning pass stores each triangle's band range
//! (2 B), then each band re-projects only the triangles that meet it. Its texture's
//! footprints (256 KB) need the whole-frame layout's flash (`FIXEL_FW_MEMORY=whole`,
//! feature `whole`); its RAM is the band firmwares'. Compared with `whole_sphere_sized`.
#![no_std]
#![no_main]

use fixel_firmware::{data, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SizedSphereBuffers::with_storage();
    let frame = core::hint::black_box(0);
    let Ok(mesh) = core::hint::black_box(&data::SPHERE)
        .mesh()
        .and_then(|m| m.with_face_planes(&data::SPHERE_FACES))
    else {
        return false;
    };
    report("sphere_sized", |pause, resume| {
        scenes::sphere_mip_as::<scenes::LitSphereSized, _, _, _, _>(
            scenes::Target::Bands(&mut buf),
            data::T256X128_FP,
            &mesh,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
