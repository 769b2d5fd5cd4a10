//! Scene `shadow_single` (the lit pass of the shadow-mapped cube on its floor, one shadow
//! tap per pixel) drawn into one whole 320x240 frame from the same 64 x 64 map: the figure
//! the banded `shadow_single` is compared with. Whole-frame memory layout
//! (`FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

use fixel::shading::pcf::SingleTap;
use fixel_firmware::{scenes, shadow};
use fixel_scenes::shadow::SceneLight;

fn run() -> bool {
    let mut map = [0u16; shadow::MAP_TEXELS];
    let mut buf = scenes::Whole::new();
    shadow::run_whole_directional::<SingleTap, false>(
        "whole_shadow_single",
        SceneLight::High,
        &mut map,
        &mut buf.color,
        &mut buf.depth,
    )
}

fixel_firmware::entry!(run);
