//! Scene `cube`, frame 0: lit, bilinear, perspective-correct, depth-tested, 320x240 in bands.
#![no_std]
#![no_main]

use fixel_firmware::{data, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SmallBuffers::with_storage();
    let frame = core::hint::black_box(0);
    report("cube", |pause, resume| {
        scenes::cube(
            scenes::Target::Bands(&mut buf),
            data::T128_FP,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
