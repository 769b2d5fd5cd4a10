//! Scene `sphere`, frame 0, as `whole_sphere_adaptive` (one whole 320x240 frame, the
//! adaptive projection), reading the texture's bilinear footprints (`BilinearFootprint`: the
//! same pixels, one 64-bit word per sample; 256 KiB of footprints in flash beside the 64 KiB
//! texture). The report's balanced mode for the sphere. Whole-frame memory layout.
#![no_std]
#![no_main]

use fixel_firmware::{data, scenes};

fn run() -> bool {
    fixel_firmware::whole_sphere::<scenes::LitSphereFootprint>(
        "whole_sphere_footprint",
        data::T256X128_FP,
    )
}

fixel_firmware::entry!(run);
