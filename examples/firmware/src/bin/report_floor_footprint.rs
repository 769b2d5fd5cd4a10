//! `cargo xtask report`: scene `floor`, once per mode of `modes::FLOOR_FOOTPRINT_MODES`
//! (bilinear reading the texture's footprints, `data::T64_FP`, every projection).
#![no_std]
#![no_main]

use fixel_firmware::{data, modes, scenes};

fn run() -> bool {
    let mut buf = scenes::Buffers::new();
    let Ok(vp) = scenes::viewport() else {
        return false;
    };
    fixel_firmware::report_modes!(
        "floor",
        modes::FLOOR_FOOTPRINT_MODES,
        [0 1 2 3 4 5 6 7 8 9],
        |m, pause, resume| {
            let draw = m.draw(core::hint::black_box(data::T64_FP), vp)?;
            scenes::floor_with(scenes::Target::Bands(&mut buf), &draw, pause, resume)
        }
    )
}

fixel_firmware::entry!(run);
