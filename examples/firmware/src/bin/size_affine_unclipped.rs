//! `cargo xtask size`: `size_affine` (one textured triangle: affine, nearest, unlit, no depth
//! buffer) for geometry that stays in view: triangles go through `Draw::project_unclipped`,
//! so the firmware links no clipper.
#![no_std]
#![no_main]

#[allow(unused_imports)]
use fixel::pipeline::*;
#[allow(unused_imports)]
use fixel::texture::{Bilinear, Nearest, Repeat};
use fixel_firmware::size;

fn run() -> bool {
    size::typed_unclipped::<Pipeline<Affine, Nearest, Repeat, Repeat, Replace, NoDepth>, false, false>(
    )
}

fixel_firmware::entry!(run);
