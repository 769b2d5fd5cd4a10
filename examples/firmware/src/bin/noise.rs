//! Scene `noise`: the marble sphere of `noise.rs` with band-limited turbulence (at most 6
//! octaves, footprint per span), 320x240 in 8-row bands.
#![no_std]
#![no_main]

use fixel::shading::noise::presets::{MARBLE_AMP, MARBLE_FREQ, MARBLE_KEYS};
use fixel::shading::noise::Marble;
use fixel::shading::noise::{BandLimit, Ramp, SolidShader};
use fixel_firmware::{noise, report};

static mut BUF: noise::NoiseBuffers = noise::NoiseBuffers::new();

fn run() -> bool {
    // SAFETY: the only reference to BUF, taken once in this single-threaded firmware.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let Ok(ramp) = Ramp::sine(core::hint::black_box(&MARBLE_KEYS)) else {
        return false;
    };
    let marble = Marble {
        ramp: &ramp,
        freq: MARBLE_FREQ,
        amp: MARBLE_AMP,
    };
    let shader = SolidShader::new(marble, BandLimit::new(core::hint::black_box(6)));
    report("noise", |pause, resume| {
        noise::render(shader, buf, pause, resume)
    })
}

fixel_firmware::entry!(run);
