//! Scene `sphere`, frame 0, as `whole_sphere` (one whole 320x240 frame, a prepared vertex per
//! mesh vertex) in the adaptive projection: per triangle affine when a bound on the affine
//! error is within a quarter texel, exact otherwise (the report's balanced mode for the
//! sphere: 44.6 dB against the ideal image, exact 45.3). Whole-frame memory layout.
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
    report("whole_sphere_adaptive", |pause, resume| {
        scenes::sphere_as::<scenes::LitSphereAdaptive, 0, 0, 0>(
            WholeTarget::Whole(&mut buf),
            data::T256X128,
            &mesh,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
