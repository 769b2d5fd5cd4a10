//! Scene `sphere`, frame 0, as `whole_sphere_adaptive` (one whole 320x240 frame, the
//! adaptive projection), reading the texture's bilinear footprints (`BilinearFootprint`: the
//! same pixels, one 64-bit word per sample; 256 KiB of footprints in flash beside the 64 KiB
//! texture). The report's balanced mode for the sphere. Whole-frame memory layout.
#![no_std]
#![no_main]

use fixel_firmware::scenes::{self, WholeTarget};
use fixel_firmware::{data, report};

fn run() -> bool {
    let mut buf = scenes::Whole::new();
    let frame = core::hint::black_box(0);
    let Ok(mesh) = core::hint::black_box(&data::SPHERE).mesh() else {
        return false;
    };
    report("whole_sphere_footprint", |pause, resume| {
        scenes::sphere_mip_as::<scenes::LitSphereFootprint, 0, 0, 0>(
            WholeTarget::Whole(&mut buf),
            data::T256X128_FP,
            &mesh,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
