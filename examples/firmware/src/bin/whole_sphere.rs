//! Scene `sphere`, frame 0, drawn into one whole 320x240 frame (colour + 16-bit depth, 300 KiB
//! on the stack) with a prepared-vertex cache per mesh vertex: the figure to set beside
//! whole-frame renderers such as TGX. Built with the whole-frame memory layout
//! (`FIXEL_FW_MEMORY=whole`, feature `whole`) for `mps2-an386` and RV32 `virt`.
#![no_std]
#![no_main]

use fixel_firmware::{data, scenes};

fn run() -> bool {
    fixel_firmware::whole_sphere::<scenes::LitSphere>(
        "whole_sphere",
        fixel::texture::MipTexture::single(data::T256X128),
    )
}

fixel_firmware::entry!(run);
