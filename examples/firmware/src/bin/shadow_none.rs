//! Shadow scene without shadows: the lit pass's baseline (same geometry, same bands of 4
//! rows, the textured lit shader alone), so `shadow_* - shadow_none` is what shadowing
//! costs per pixel.
#![no_std]
#![no_main]

use fixel_firmware::shadow::{self, ShadowBuffers};
use fixel_firmware::{data, report};
use fixel_scenes::shadow::{self as scene, SceneLight};

static mut BUF: ShadowBuffers = ShadowBuffers::new();

fn run() -> bool {
    // SAFETY: single-threaded firmware, the only reference to BUF.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let Ok(space) = scene::directional(SceneLight::High) else {
        return false;
    };
    report("shadow_none", |pause, resume| {
        shadow::unshadowed_pass(
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
