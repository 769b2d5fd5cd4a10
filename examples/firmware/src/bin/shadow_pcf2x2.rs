//! Shadow scene, lit pass with Pcf2x2 (64 x 64 map, high directional light), in bands of 4
//! rows; the light pass runs first, outside the counted region.
#![no_std]
#![no_main]

use fixel::demo::shadow::{self as scene, SceneLight};
use fixel::shading::pcf::Pcf2x2;
use fixel_firmware::shadow::{self, ShadowBuffers};
use fixel_firmware::{data, report};

static mut BUF: ShadowBuffers = ShadowBuffers::new();

fn run() -> bool {
    // SAFETY: single-threaded firmware, the only reference to BUF.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let Ok(space) = scene::directional(SceneLight::High) else {
        return false;
    };
    if shadow::light_pass(&space, &mut buf.map).is_err() {
        return false;
    }
    report("shadow_pcf2x2", |pause, resume| {
        shadow::lit_pass::<_, Pcf2x2, 6>(
            buf,
            &space,
            SceneLight::High,
            core::hint::black_box(data::T128),
            core::hint::black_box(data::T64),
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
