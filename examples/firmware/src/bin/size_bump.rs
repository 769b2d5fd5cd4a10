//! `cargo xtask size`: the textured triangle bump-mapped from a derivative map and lit per
//! pixel by a point light (bilinear, exact perspective, depth): what a bump-mapped draw
//! links.
#![no_std]
#![no_main]

use fixel_firmware::size;

fn run() -> bool {
    size::bump()
}

fixel_firmware::entry!(run);
