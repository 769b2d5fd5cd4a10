//! `cargo xtask report`: scene `floor`, once per mode of `modes::FLOOR_FOOTPRINT_MODES`
//! (bilinear reading the texture's footprints, `data::T64_FP`, every projection).
#![no_std]
#![no_main]

use fixel_firmware::{data, modes};

fn run() -> bool {
    fixel_firmware::report_floor!(
        modes::FLOOR_FOOTPRINT_MODES,
        [0 1 2 3 4 5 6 7 8 9],
        data::T64_FP
    )
}

fixel_firmware::entry!(run);
