//! Scene `floor_bilinear`, frame 0, drawn into one whole 320x240 frame (colour + 16-bit depth, 300 KiB
//! on the stack) with a prepared-vertex cache per mesh vertex: the figure to set beside
//! whole-frame renderers such as TGX. Built with the whole-frame memory layout
//! (`FIXEL_FW_MEMORY=whole`, feature `whole`) for `mps2-an386` and RV32 `virt`.
#![no_std]
#![no_main]

use fixel_firmware::scenes::{self, WholeTarget};
use fixel_firmware::{data, report};

fn run() -> bool {
    let mut buf = scenes::Whole::new();
    let frame = core::hint::black_box(0);
    let _ = frame;
    report("whole_floor_bilinear", |pause, resume| {
        scenes::floor::<scenes::FloorBilinearFootprint, 0, 0, 0, 0>(
            WholeTarget::Whole(&mut buf),
            data::T64_FP,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
