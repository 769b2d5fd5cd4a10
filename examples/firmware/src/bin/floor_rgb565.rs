//! Scene `floor_rgb565`: the benchmark floor with `T(64, 64)` in RGB565, unlit, nearest, repeat, exact every 64 pixels, depth-tested,
//! in 320x8 bands through the open-stage path of the palette scenes (`palette_scene.rs`):
//! the RGB565 row beside `floor_palette8` and `floor_palette4`.
#![no_std]
#![no_main]

use fixel::texture::MipTexture;
use fixel_firmware::{data, palette_scene, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SmallBuffers::with_storage();
    let tex = MipTexture::single(core::hint::black_box(data::T64));
    report("floor_rgb565", |pause, resume| {
        palette_scene::floor_rgb565(&mut buf, &tex, pause, resume)
    })
}

fixel_firmware::entry!(run);
