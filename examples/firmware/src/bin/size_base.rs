//! `cargo xtask size`: the harness alone (buffers, checksum, semihosting output), no fixel.
#![no_std]
#![no_main]

#[allow(unused_imports)]
use fixel::pipeline::*;
#[allow(unused_imports)]
use fixel::texture::{Bilinear, Nearest, Repeat};
use fixel_firmware::size;

fn run() -> bool {
    size::base()
}

fixel_firmware::entry!(run);
