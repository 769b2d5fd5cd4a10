//! Scene `bump`, frame 0: the brick sphere bump-mapped from a precomputed derivative map and
//! lit per pixel by a point light (`bump_scene.rs`), 320 x 240 in 8-row bands; the mesh and
//! brick maps in flash.
#![no_std]
#![no_main]

#[path = "../bump_scene.rs"]
#[allow(dead_code)] // each binary draws one of the two frames
mod bump_scene;

use fixel_firmware::report;
// `bump_scene.rs` names the shared scene helpers and tables `crate::scenes`,
// `crate::open_frame` and `crate::data`.
use fixel_firmware::{data, open_frame, scenes};

static mut BUF: bump_scene::BumpBuffers = bump_scene::BumpBuffers::new();

fn run() -> bool {
    // SAFETY: single-threaded firmware, the only reference to BUF.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let a = bump_scene::BumpAssets::flash();
    let frame = core::hint::black_box(0);
    report("bump", |pause, resume| {
        bump_scene::bump(&a, buf, frame, pause, resume)
    })
}

fixel_firmware::entry!(run);
