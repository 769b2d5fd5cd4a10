//! `cargo xtask report`: scene `cube`, frame 0, once per mode of `modes::CUBE_FACET_MODES`
//! (the light read once per triangle, bilinear, every projection).
#![no_std]
#![no_main]

use fixel_firmware::modes;

fn run() -> bool {
    fixel_firmware::report_cube!(modes::CUBE_FACET_MODES, [0 1 2 3 4 5 6 7 8 9])
}

fixel_firmware::entry!(run);
