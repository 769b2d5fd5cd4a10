//! `cargo xtask report`: scene `cube`, frame 0, the last five modes of
//! `modes::CUBE_FOOTPRINT_MODES` (`CUBE_FOOTPRINT_MODES_B`; see `report_cube_footprint`).
#![no_std]
#![no_main]

use fixel_firmware::{data, modes};

fn run() -> bool {
    fixel_firmware::report_cube!(
        modes::CUBE_FOOTPRINT_MODES_B,
        [0 1 2 3 4],
        data::T128_FP
    )
}

fixel_firmware::entry!(run);
