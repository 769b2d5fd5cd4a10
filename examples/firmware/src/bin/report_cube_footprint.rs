//! `cargo xtask report`: scene `cube`, frame 0, once per mode of
//! `modes::CUBE_FOOTPRINT_MODES` (`report_cube_facet`'s modes reading the texture's bilinear
//! footprints, `data::T128_FP`: 128 KiB of footprints in flash beside the 32 KiB texture).
#![no_std]
#![no_main]

use fixel_firmware::{data, modes};

fn run() -> bool {
    fixel_firmware::report_cube!(
        modes::CUBE_FOOTPRINT_MODES,
        [0 1 2 3 4 5 6 7 8 9],
        data::T128_FP
    )
}

fixel_firmware::entry!(run);
