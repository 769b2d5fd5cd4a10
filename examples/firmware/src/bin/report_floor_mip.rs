//! `cargo xtask report`: scene `floor`, once per mode of `modes::FLOOR_MODES` (`T(64, 64)`
//! with its mip chain in flash). All 25 span loops do not fit in 256 KB of flash: this one
//! has the mipmapped filters, `report_floor` the others.
#![no_std]
#![no_main]

use fixel_firmware::{data, modes};

fn run() -> bool {
    fixel_firmware::report_floor!(
        modes::FLOOR_MIP_MODES,
        [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29],
        data::t64_mips()
    )
}

fixel_firmware::entry!(run);
