//! `cargo xtask size`: + perspective-correct (exact).
#![no_std]
#![no_main]

#[allow(unused_imports)]
use fixel::pipeline::*;
#[allow(unused_imports)]
use fixel::texture::{Bilinear, Nearest, Repeat};
use fixel_firmware::size;

fn run() -> bool {
    size::typed::<Pipeline<Exact, Nearest, Repeat, Repeat, Replace, NoDepth>, false, false>()
}

fixel_firmware::entry!(run);
