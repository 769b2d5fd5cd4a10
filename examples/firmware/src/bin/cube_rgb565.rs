//! Scene `cube_rgb565`: the benchmark cube with `T(128, 128)` in RGB565, frame 0, lit per vertex, bilinear, repeat, a parabola every 16 pixels, depth-tested,
//! in 320x8 bands through the open-stage path of the palette scenes (`palette_scene.rs`):
//! the RGB565 row beside `cube_palette8` and `cube_palette4`.
#![no_std]
#![no_main]

use fixel::texture::MipTexture;
use fixel_firmware::{data, palette_scene, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SmallBuffers::with_storage();
    let tex = MipTexture::single(core::hint::black_box(data::T128));
    report("cube_rgb565", |pause, resume| {
        palette_scene::cube_rgb565(&mut buf, &tex, pause, resume)
    })
}

fixel_firmware::entry!(run);
