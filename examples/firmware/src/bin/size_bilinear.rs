//! `cargo xtask size`: + bilinear filtering.
#![no_std]
#![no_main]

#[allow(unused_imports)]
use fixel::pipeline::*;
#[allow(unused_imports)]
use fixel::texture::{Bilinear, Nearest, Repeat};
use fixel_firmware::size;

fn run() -> bool {
    size::typed::<Pipeline<Exact, Bilinear, Repeat, Repeat, Replace, NoDepth>, false, false>()
}

fixel_firmware::entry!(run);
