//! Scene `aa_edge`, frame 0: the `cube` scene's frame (same draw, 320 x 8 bands) with
//! silhouette anti-aliasing from depth on each finished band (`edge_scene.rs`).
#![no_std]
#![no_main]

#[path = "../edge_scene.rs"]
#[allow(dead_code)] // EDGE_RAM: the host report's
mod edge_scene;

use fixel_firmware::{data, report};
// `edge_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;

static mut EDGE: edge_scene::EdgeBuffers = edge_scene::EdgeBuffers::new();

fn run() -> bool {
    let mut buf = scenes::SmallBuffers::with_storage();
    // SAFETY: the only reference to EDGE, taken once in this single-threaded firmware.
    let edge = unsafe { &mut *core::ptr::addr_of_mut!(EDGE) };
    let frame = core::hint::black_box(0);
    report("aa_edge", |pause, resume| {
        edge_scene::aa_edge(&mut buf, edge, data::T128_FP, frame, None, pause, resume)
    })
}

fixel_firmware::entry!(run);
