//! Scene `flame_plain`: the flame quad of `noise_flame` (80 x 96, four frames) as a plain
//! textured draw (`T(64, 64)`, bilinear, repeat, `Replace`, one texel per pixel) in 8-row
//! bands: the draw `noise_flame_baked` is compared with.
#![no_std]
#![no_main]

use fixel_firmware::{data, flame_baked_scene, noise, report};

static mut COLOR: [embedded_graphics_core::pixelcolor::Rgb565; noise::FLAME_BAND_PIXELS] =
    [embedded_graphics_core::pixelcolor::Rgb565::new(0, 0, 0); noise::FLAME_BAND_PIXELS];

fn run() -> bool {
    // SAFETY: the only reference to COLOR, taken once in this single-threaded firmware.
    let color = unsafe { &mut *core::ptr::addr_of_mut!(COLOR) };
    let frames = core::hint::black_box(4);
    report("flame_plain", |pause, resume| {
        flame_baked_scene::flame_plain_bands(color, data::T64, frames, pause, resume)
    })
}

fixel_firmware::entry!(run);
