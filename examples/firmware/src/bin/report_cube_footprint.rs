//! `cargo xtask report`: scene `cube`, frame 0, the first five modes of
//! `modes::CUBE_FOOTPRINT_MODES` (`CUBE_FOOTPRINT_MODES_A`: `report_cube_facet`'s modes
//! reading the texture's bilinear footprints, `data::T128_FP`, 128 KiB in flash beside the
//! 32 KiB texture).
//! The other five are `report_cube_footprint_b`'s: all ten do not fit 256 KiB of flash on
//! Cortex-M0+ (every firmware also links in the default layout).
#![no_std]
#![no_main]

use fixel_firmware::{data, modes};

fn run() -> bool {
    fixel_firmware::report_cube!(
        modes::CUBE_FOOTPRINT_MODES_A,
        [0 1 2 3 4],
        data::T128_FP
    )
}

fixel_firmware::entry!(run);
