//! Scene `aa_cube`, frame 0: the cube with the rotated grid of 4 samples accumulated
//! through 320 x 4 bands (12.5 KB of band buffers; `aa_scene.rs`).
#![no_std]
#![no_main]

#[path = "../aa_scene.rs"]
#[allow(dead_code)] // the other size (bands or whole frame)
mod aa_scene;

use fixel_firmware::{data, report};
// `aa_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;

static mut BUF: aa_scene::AaCubeBuffers = aa_scene::AaCubeBuffers::new();

fn run() -> bool {
    // SAFETY: the only reference to BUF, taken once in this single-threaded firmware.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let frame = core::hint::black_box(0);
    report("aa_cube", |pause, resume| {
        aa_scene::aa_cube(data::T128, frame, buf, pause, resume)
    })
}

fixel_firmware::entry!(run);
