//! Scene `noise_flame_baked`: the four frames of `noise_flame` (t = 0, 1/8, 2/8, 3/8 s) on
//! its 80 x 96 quad, the flame from two baked layers (`fixel::shading::noise::BakedFlame`:
//! two 64 x 64 tiles of partial turbulence in flash, baked by `build.rs`, scrolled per
//! frame; two texel reads per pixel) in 8-row bands. Compared with `flame_plain`.
#![no_std]
#![no_main]

use fixel_firmware::{data, flame_baked_scene, noise, report};

static mut COLOR: [embedded_graphics_core::pixelcolor::Rgb565; noise::FLAME_BAND_PIXELS] =
    [embedded_graphics_core::pixelcolor::Rgb565::new(0, 0, 0); noise::FLAME_BAND_PIXELS];

fn run() -> bool {
    // SAFETY: the only reference to COLOR, taken once in this single-threaded firmware.
    let color = unsafe { &mut *core::ptr::addr_of_mut!(COLOR) };
    let frames = core::hint::black_box(4);
    let layers = core::hint::black_box(&data::FLAME_LAYER_TEXELS);
    report("noise_flame_baked", |pause, resume| {
        flame_baked_scene::flame_baked_bands(color, [&layers[0], &layers[1]], frames, pause, resume)
    })
}

fixel_firmware::entry!(run);
