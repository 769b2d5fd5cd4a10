//! `cargo xtask size`: the minimal textured unlit firmware through the open stage
//! (`ShadedDraw` + `Replace`, `u, v` from the firmware's own vertex function), clipped.
#![no_std]
#![no_main]

fn run() -> bool {
    fixel_firmware::size::open::<true>()
}

fixel_firmware::entry!(run);
