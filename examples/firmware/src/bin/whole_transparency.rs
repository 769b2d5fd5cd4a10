//! Scene `transparency` (the floor, the alpha-tested fence, the blended window) drawn into
//! one whole 320x240 frame, draw by draw: the figure the banded `transparency` is compared
//! with. Whole-frame memory layout (`FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

#[path = "../alpha_scene.rs"]
#[allow(dead_code)] // the other target (bands or whole frame)
mod alpha_scene;

use fixel_firmware::{data, report};
// `alpha_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;

fn run() -> bool {
    let mut buf = scenes::Whole::new();
    report("whole_transparency", |pause, resume| {
        alpha_scene::transparency_in(
            core::hint::black_box(data::T64),
            data::T8,
            alpha_scene::AlphaTarget::Whole(&mut buf.color, &mut buf.depth),
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
