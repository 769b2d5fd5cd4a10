//! `cargo xtask size`: one textured triangle: affine, nearest, unlit, no depth buffer.
#![no_std]
#![no_main]

#[allow(unused_imports)]
use fixel::pipeline::*;
#[allow(unused_imports)]
use fixel::texture::{Bilinear, Nearest, Repeat};
use fixel_firmware::size;

fn run() -> bool {
    size::typed::<Pipeline<Affine, Nearest, Repeat, Repeat, Replace, NoDepth>, false, false>()
}

fixel_firmware::entry!(run);
