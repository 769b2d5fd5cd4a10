//! `cargo xtask report`: scene `cube`, frame 0, once per lit mode of
//! `modes::LIT_SCENE_MODES` (its first half; all 40 span loops do not fit in the 256 KB of
//! the default layout on Cortex-M0+: `report_cube_unlit` has the others).
#![no_std]
#![no_main]

use fixel_firmware::modes;

fn run() -> bool {
    fixel_firmware::report_cube!(
        modes::LIT_SCENE_MODES_LIT,
        [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19]
    )
}

fixel_firmware::entry!(run);
