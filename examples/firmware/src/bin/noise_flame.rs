//! Scene `noise_flame`: the animated flame as a firmware loop: 4 frames
//! (t = 0, 1/8, 2/8, 3/8 s) of an 80 x 96 quad, 5 octaves, one checksum over all frames.
#![no_std]
#![no_main]

use fixel_firmware::{noise, report};

static mut COLOR: [embedded_graphics_core::pixelcolor::Rgb565; noise::FLAME_PIXELS] =
    [embedded_graphics_core::pixelcolor::Rgb565::new(0, 0, 0); noise::FLAME_PIXELS];

fn run() -> bool {
    // SAFETY: the only reference to COLOR, taken once in this single-threaded firmware.
    let color = unsafe { &mut *core::ptr::addr_of_mut!(COLOR) };
    let frames = core::hint::black_box(4);
    report("noise_flame", |pause, resume| {
        noise::flame_frames(color, frames, pause, resume)
    })
}

fixel_firmware::entry!(run);
