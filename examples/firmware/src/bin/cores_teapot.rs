//! Scene `teapot`, frame 0, on one core and then on two (hart 0 the even bands, hart 1 the
//! odd ones): `cargo xtask cores`, RISC-V `virt -smp 2`.
#![no_std]
#![no_main]

fn run() -> bool {
    fixel_firmware::cores::run("teapot")
}

fixel_firmware::entry!(run);
