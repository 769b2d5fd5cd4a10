//! `cargo xtask size`: everything: `Draw::dynamic` (stages chosen at run time, every span loop linked).
#![no_std]
#![no_main]

#[allow(unused_imports)]
use fixel::pipeline::*;
#[allow(unused_imports)]
use fixel::texture::{Bilinear, Nearest, Repeat};
use fixel_firmware::size;

fn run() -> bool {
    size::dynamic(
        DrawMode {
            projection: Projection::Exact,
            filter: fixel::texture::Filter::Bilinear,
            wrap: [fixel::texture::Wrap::Repeat; 2],
            shading: Shading::ModulateIntensity,
            depth: DepthTest::Less,
            cull: fixel::geometry::Cull::Back,
            ..DrawMode::default()
        },
        true,
    )
}

fixel_firmware::entry!(run);
