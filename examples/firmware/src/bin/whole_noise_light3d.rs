//! Scene `noise_light3d` (the wooden cube lit by the baked 3D light map) drawn as one band
//! holding the whole 320x240 frame: the figure the 8-row bands of `noise_light3d` are
//! compared with (the same checksum). Whole-frame memory layout (`FIXEL_FW_MEMORY=whole`,
//! feature `whole`).
#![no_std]
#![no_main]

#[path = "../light3d_scene.rs"]
#[allow(dead_code, unused_imports)] // the per-vertex baseline and the bake parameters
mod light3d_scene;

use fixel::shading::noise::presets::{WOOD_AMP, WOOD_KEYS, WOOD_RINGS};
use fixel::shading::noise::{BandLimit, LitSolid, Ramp, Wood};
use fixel::texture::LodGranularity;
use fixel_firmware::report;
// `light3d_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;

static mut BUF: light3d_scene::Light3dBuffers<{ light3d_scene::WHOLE }> =
    light3d_scene::Light3dBuffers::sized();

fn run() -> bool {
    // SAFETY: the only reference to BUF, taken once in this single-threaded firmware.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let (Ok(ramp), Ok(light)) = (
        Ramp::from_keys(core::hint::black_box(&WOOD_KEYS)),
        light3d_scene::light_map(),
    ) else {
        return false;
    };
    let shader = LitSolid {
        pattern: Wood {
            ramp: &ramp,
            rings: WOOD_RINGS,
            amp: WOOD_AMP,
        },
        octaves: BandLimit::new(core::hint::black_box(6)),
        light,
        granularity: LodGranularity::Span,
    };
    report("whole_noise_light3d", |pause, resume| {
        light3d_scene::render_light_map(shader, buf, pause, resume)
    })
}

fixel_firmware::entry!(run);
