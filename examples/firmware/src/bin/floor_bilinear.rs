//! Scene `floor`, bilinear filtering, unlit, depth-tested.
#![no_std]
#![no_main]

use fixel_firmware::{data, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SmallBuffers::with_storage();
    report("floor_bilinear", |pause, resume| {
        scenes::floor::<scenes::FloorBilinearFootprint, _, _, _, _>(
            scenes::Target::Bands(&mut buf),
            core::hint::black_box(data::T64_FP),
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
