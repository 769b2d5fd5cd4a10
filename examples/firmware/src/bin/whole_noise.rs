//! Scene `noise` (the marble sphere) drawn into one whole 320x240 frame with the same draw:
//! the figure the banded `noise` is compared with. Whole-frame memory layout
//! (`FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

use fixel::shading::noise::presets::{MARBLE_AMP, MARBLE_FREQ, MARBLE_KEYS};
use fixel::shading::noise::Marble;
use fixel::shading::noise::{BandLimit, Ramp, SolidShader};
use fixel_firmware::{noise, report, scenes};

fn run() -> bool {
    let mut buf = scenes::Whole::new();
    let mut verts = [None; noise::VERTS];
    let Ok(ramp) = Ramp::sine(core::hint::black_box(&MARBLE_KEYS)) else {
        return false;
    };
    let marble = Marble {
        ramp: &ramp,
        freq: MARBLE_FREQ,
        amp: MARBLE_AMP,
    };
    let shader = SolidShader::new(marble, BandLimit::new(core::hint::black_box(6)));
    report("whole_noise", |pause, resume| {
        noise::render_whole(shader, &mut buf.color, &mut verts, pause, resume)
    })
}

fixel_firmware::entry!(run);
