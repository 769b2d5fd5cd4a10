//! `cargo xtask size`: the textured triangle as a mirror in a cube map (per-pixel
//! reflection, bilinear, exact perspective, depth): what an environment-mapped draw links.
#![no_std]
#![no_main]

use fixel_firmware::size;

fn run() -> bool {
    size::env()
}

fixel_firmware::entry!(run);
