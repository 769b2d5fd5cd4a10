//! `cargo xtask report`: scene `sphere`, frame 0, once per mode of `modes::SPHERE_MCU_MODES`.
//! The two footprint modes read `data::T256X128_FP` (256 KiB of footprints beside the 64 KiB
//! texture): in the report memory layout only (the 256K default one runs the other three).
#![no_std]
#![no_main]

use fixel::scene::Mesh;
use fixel::texture::MipTexture;
use fixel_firmware::data;
use fixel_firmware::modes::{Filt, Mode, SPHERE_MCU_MODES};
use fixel_firmware::scenes::{self, Buffers, FrameResult};

/// The modes this build runs.
#[cfg(fixel_fw_report)]
const MODES: [Mode; 5] = SPHERE_MCU_MODES;
#[cfg(not(fixel_fw_report))]
const MODES: [Mode; 3] = [
    SPHERE_MCU_MODES[2],
    SPHERE_MCU_MODES[3],
    SPHERE_MCU_MODES[4],
];

/// The sphere's texture for mode `m`.
#[inline(always)]
fn texture(m: &Mode) -> MipTexture<'static> {
    #[cfg(fixel_fw_report)]
    if m.filter == Filt::BilinearFootprint {
        return data::T256X128_FP;
    }
    let _ = m.filter == Filt::BilinearFootprint;
    MipTexture::single(data::T256X128)
}

/// Frame 0 in mode `m` (inlined, so each call links only its mode's span loop).
#[inline(always)]
fn frame(
    m: &Mode,
    buf: &mut Buffers,
    mesh: &Mesh<'_>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, fixel::Error> {
    let draw = m.draw(texture(m), scenes::viewport()?)?;
    let i = core::hint::black_box(0);
    scenes::sphere_with(
        scenes::Target::Bands(buf),
        &draw,
        mesh,
        m.lit,
        i,
        pause,
        resume,
    )
}

fn run() -> bool {
    let mut buf = Buffers::new();
    let Ok(mesh) = core::hint::black_box(&data::SPHERE).mesh() else {
        return false;
    };
    #[cfg(fixel_fw_report)]
    return fixel_firmware::report_modes!("sphere", MODES, [0 1 2 3 4], |m, pause, resume| {
        frame(m, &mut buf, &mesh, pause, resume)
    });
    #[cfg(not(fixel_fw_report))]
    fixel_firmware::report_modes!("sphere", MODES, [0 1 2], |m, pause, resume| {
        frame(m, &mut buf, &mesh, pause, resume)
    })
}

fixel_firmware::entry!(run);
