//! Scene `sphere`, frame 0, as `whole_sphere` (one whole 320x240 frame, a prepared vertex per
//! mesh vertex) in the adaptive projection: per triangle affine when a bound on the affine
//! error is within a quarter texel, exact otherwise (the report's balanced mode for the
//! sphere: 44.6 dB against the ideal image, exact 45.3). Whole-frame memory layout.
#![no_std]
#![no_main]

use fixel_firmware::{data, scenes};

fn run() -> bool {
    fixel_firmware::whole_sphere::<scenes::LitSphereAdaptive>(
        "whole_sphere_adaptive",
        fixel::texture::MipTexture::single(data::T256X128),
    )
}

fixel_firmware::entry!(run);
