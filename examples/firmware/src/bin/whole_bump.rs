//! Scene `bump` drawn into one whole 320 x 240 frame (colour + 16-bit depth) with the same
//! draw: the figure the banded `bump` is compared with. Whole-frame memory layout
//! (`FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

#[path = "../bump_scene.rs"]
#[allow(dead_code)] // each binary draws one of the two frames
mod bump_scene;

use fixel_firmware::report;
// `bump_scene.rs` names the shared scene helpers and tables `crate::scenes`,
// `crate::open_frame` and `crate::data`.
use fixel_firmware::{data, open_frame, scenes};

fn run() -> bool {
    let a = bump_scene::BumpAssets::flash();
    let mut buf = scenes::Whole::new();
    let frame = core::hint::black_box(0);
    report("whole_bump", |pause, resume| {
        bump_scene::bump_whole(&a, &mut buf.color, &mut buf.depth, frame, pause, resume)
    })
}

fixel_firmware::entry!(run);
