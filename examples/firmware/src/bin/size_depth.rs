//! `cargo xtask size`: + 16-bit depth buffer (DepthLess): the cube's pipeline.
#![no_std]
#![no_main]

#[allow(unused_imports)]
use fixel::pipeline::*;
#[allow(unused_imports)]
use fixel::texture::{Bilinear, Nearest, Repeat};
use fixel_firmware::size;

fn run() -> bool {
    size::typed::<Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>, true, true>(
    )
}

fixel_firmware::entry!(run);
