//! Scene `aa_cube` (the cube, rotated grid of 4 accumulated) drawn as one band holding the
//! whole 320x240 frame (colour, depth and sums: 750 KB): the figure the 4-row bands of
//! `aa_cube` are compared with (the same checksum). Whole-frame memory layout
//! (`FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

#[path = "../aa_scene.rs"]
#[allow(dead_code)] // the other size (bands or whole frame)
mod aa_scene;

use fixel_firmware::{data, report};
// `aa_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;

static mut BUF: aa_scene::AaCubeBuffers<{ aa_scene::WHOLE }> = aa_scene::AaCubeBuffers::sized();

fn run() -> bool {
    // SAFETY: the only reference to BUF, taken once in this single-threaded firmware.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let frame = core::hint::black_box(0);
    report("whole_aa_cube", |pause, resume| {
        aa_scene::aa_cube(data::T128, frame, buf, pause, resume)
    })
}

fixel_firmware::entry!(run);
