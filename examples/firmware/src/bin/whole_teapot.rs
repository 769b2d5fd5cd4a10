//! Scene `teapot` drawn into one whole 320x240 frame (colour + 16-bit depth, one prepared
//! vertex per mesh vertex) with the same draw: the figure the banded `teapot` is compared
//! with. Whole-frame memory layout (`FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

use fixel::scene::Mesh;
use fixel_firmware::data::{self, teapot};
use fixel_firmware::{report, scenes};

fn run() -> bool {
    let mut buf = scenes::Whole::new();
    let frame = core::hint::black_box(0);
    let Ok(mesh) = Mesh::new(
        core::hint::black_box(&teapot::TEAPOT_POSITIONS),
        Some(&teapot::TEAPOT_NORMALS),
        &teapot::TEAPOT_UVS,
        &teapot::TEAPOT_INDICES,
    ) else {
        return false;
    };
    report("whole_teapot", |pause, resume| {
        scenes::teapot(
            scenes::WholeTarget::Whole(&mut buf),
            data::T256X128,
            &mesh,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
