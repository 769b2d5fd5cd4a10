//! `cargo xtask report`: scene `sphere`, frame 0, once per mode of `modes::SPHERE_MCU_MODES`.
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
    let Ok(mesh) = core::hint::black_box(&data::SPHERE).mesh() else {
        return false;
    };
    fixel_firmware::report_modes!(
        "sphere",
        modes::SPHERE_MCU_MODES,
        [0 1 2],
        |m, pause, resume| {
            let draw = m.draw(MipTexture::single(data::T256X128), vp)?;
            scenes::sphere_with(scenes::Target::Bands(&mut buf), &draw, &mesh, m.lit, frame, pause, resume)
        }
    )
}

fixel_firmware::entry!(run);
