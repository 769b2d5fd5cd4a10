//! Scene `noise_flame` drawn into its whole 80 x 96 frame (15 KB) with the same draw: the
//! figure the banded `noise_flame` is compared with. Whole-frame memory layout
//! (`FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

use fixel_firmware::{noise, report};

static mut COLOR: [embedded_graphics_core::pixelcolor::Rgb565; noise::FLAME_PIXELS] =
    [embedded_graphics_core::pixelcolor::Rgb565::new(0, 0, 0); noise::FLAME_PIXELS];

fn run() -> bool {
    // SAFETY: the only reference to COLOR, taken once in this single-threaded firmware.
    let color = unsafe { &mut *core::ptr::addr_of_mut!(COLOR) };
    let frames = core::hint::black_box(4);
    report("whole_noise_flame", |pause, resume| {
        noise::flame_frames(color, frames, pause, resume)
    })
}

fixel_firmware::entry!(run);
