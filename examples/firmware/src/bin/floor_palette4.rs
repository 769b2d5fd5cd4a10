//! Scene `floor_palette4`: the benchmark floor with `T(64, 64)` baked to 4-bit
//! palette indices (`cargo xtask bake-palette`, `assets/palette/`), unlit, nearest, repeat, exact every 64 pixels, depth-tested, in 320x8
//! bands (`palette_scene.rs`).
#![no_std]
#![no_main]

use fixel::texture::{Index4, PaletteTexture};
use fixel_firmware::data::palette;
use fixel_firmware::{palette_scene, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SmallBuffers::with_storage();
    let Ok(tex) = PaletteTexture::<Index4>::new(
        core::hint::black_box(&palette::T64_P4_INDICES),
        &palette::T64_P4_PALETTE,
        palette::T64_P4_WIDTH,
        palette::T64_P4_HEIGHT,
    ) else {
        return false;
    };
    report("floor_palette4", |pause, resume| {
        palette_scene::floor_palette(&mut buf, tex, pause, resume)
    })
}

fixel_firmware::entry!(run);
