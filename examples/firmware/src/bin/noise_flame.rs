//! Scene `noise_flame`: four frames (t = 0, 1/8, 2/8, 3/8 s) of the turbulent flame
//! (`fixel::shading::noise::FlameShader`, 5 octaves of table-based Perlin noise per pixel)
//! on an 80 x 96 quad, in 8-row bands (1.25 KB of colour). Compared with
//! `whole_noise_flame`.
#![no_std]
#![no_main]

use fixel_firmware::{noise, report};

static mut COLOR: [embedded_graphics_core::pixelcolor::Rgb565; noise::FLAME_BAND_PIXELS] =
    [embedded_graphics_core::pixelcolor::Rgb565::new(0, 0, 0); noise::FLAME_BAND_PIXELS];

fn run() -> bool {
    // SAFETY: the only reference to COLOR, taken once in this single-threaded firmware.
    let color = unsafe { &mut *core::ptr::addr_of_mut!(COLOR) };
    let frames = core::hint::black_box(4);
    report("noise_flame", |pause, resume| {
        noise::flame_bands(color, frames, pause, resume)
    })
}

fixel_firmware::entry!(run);
