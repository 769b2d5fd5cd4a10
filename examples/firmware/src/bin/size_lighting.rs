//! `cargo xtask size`: + per-vertex lighting (ModulateIntensity, light in the geometry).
#![no_std]
#![no_main]

#[allow(unused_imports)]
use fixel::pipeline::*;
#[allow(unused_imports)]
use fixel::texture::{Bilinear, Nearest, Repeat};
use fixel_firmware::size;

fn run() -> bool {
    size::typed::<Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, NoDepth>, true, false>(
    )
}

fixel_firmware::entry!(run);
