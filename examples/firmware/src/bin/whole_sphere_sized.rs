//! Scene `sphere`, frame 0, as `whole_sphere_footprint` (one whole 320x240 frame, the
//! adaptive projection, the texture's bilinear footprints) with the texture's size fixed at
//! compile time (`BilinearFootprintSized<8, 7>`: the same pixels, the footprint's index from
//! immediates). Whole-frame memory layout.
#![no_std]
#![no_main]

use fixel_firmware::{data, scenes};

fn run() -> bool {
    fixel_firmware::whole_sphere::<scenes::LitSphereSized>("whole_sphere_sized", data::T256X128_FP)
}

fixel_firmware::entry!(run);
