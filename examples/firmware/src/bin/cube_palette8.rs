//! Scene `cube_palette8`: the benchmark cube with `T(128, 128)` baked to 8-bit
//! palette indices (`cargo xtask bake-palette`, `assets/palette/`), frame 0, lit per vertex, bilinear, repeat, a parabola every 16 pixels, depth-tested, in 320x8
//! bands (`palette_scene.rs`).
#![no_std]
#![no_main]

use fixel::texture::{Index8, PaletteTexture};
use fixel_firmware::data::palette;
use fixel_firmware::{palette_scene, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SmallBuffers::with_storage();
    let Ok(tex) = PaletteTexture::<Index8>::new(
        core::hint::black_box(&palette::T128_P8_INDICES),
        &palette::T128_P8_PALETTE,
        palette::T128_P8_WIDTH,
        palette::T128_P8_HEIGHT,
    ) else {
        return false;
    };
    report("cube_palette8", |pause, resume| {
        palette_scene::cube_palette(&mut buf, tex, pause, resume)
    })
}

fixel_firmware::entry!(run);
