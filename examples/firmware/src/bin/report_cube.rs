//! `cargo xtask report`: scene `cube`, frame 0, once per lit mode of
//! `modes::LIT_SCENE_MODES` (its first half; all 40 span loops do not fit in the 256 KB of
//! the default layout on Cortex-M0+: `report_cube_unlit` has the others).
#![no_std]
#![no_main]

use fixel::texture::MipTexture;
use fixel_firmware::{data, modes, scenes};

fn run() -> bool {
    let mut buf = scenes::Buffers::new();
    let frame = core::hint::black_box(0);
    let Ok(vp) = scenes::viewport() else {
        return false;
    };
    fixel_firmware::report_modes!(
        "cube",
        modes::LIT_SCENE_MODES_LIT,
        [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19],
        |m, pause, resume| {
            let draw = m.draw(MipTexture::single(data::T128), vp)?;
            scenes::cube_with(scenes::Target::Bands(&mut buf), &draw, m.lit, frame, pause, resume)
        }
    )
}

fixel_firmware::entry!(run);
