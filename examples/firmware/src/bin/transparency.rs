//! Scene `transparency`, frame 0: the floor, a fence cut out by alpha test and a window
//! blended over it, in 320 x 8 bands (`alpha_scene.rs`).
#![no_std]
#![no_main]

#[path = "../alpha_scene.rs"]
#[allow(dead_code)] // the other target (bands or whole frame)
mod alpha_scene;

use fixel_firmware::{data, report};
// `alpha_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;

static mut BUF: alpha_scene::AlphaBuffers = alpha_scene::AlphaBuffers::new();

fn run() -> bool {
    // SAFETY: the only reference to BUF, taken once in this single-threaded firmware.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    report("transparency", |pause, resume| {
        alpha_scene::transparency(
            core::hint::black_box(data::T64),
            data::T8,
            buf,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
