//! `cargo xtask report`: the solid-texture scene of `noise.rs` once per variant: marble
//! with 0 to 6 fixed octaves, marble band-limited (at most 6 octaves, footprint per span
//! and per pixel), and wood and granite band-limited on the same sphere; the wooden cube of
//! `light3d_scene.rs` lit per vertex and by the baked 3D light map; the flame of
//! `noise_flame` (4 frames of 80 x 96) with 1, 3 and 5 octaves and from two baked layers
//! (`noise_flame_baked`, the layers in flash) (these two in the report
//! memory layout only: their buffers do not fit the default 16 KB beside the sphere's; in
//! the default layout this binary only has to link); granite with marble selected by a
//! third noise (`Select`) on the sphere.
#![no_std]
#![no_main]

#[cfg(fixel_fw_report)]
#[path = "../light3d_scene.rs"]
#[allow(dead_code, unused_imports)] // the bake parameters
mod light3d_scene;

use fixel::pipeline::{Exact, ProjectionStage, SubdividedBy};
use fixel::shading::noise::{
    BandLimit, Fixed, Octaves, Pattern, Ramps, Select, SolidShader, SELECT_OFFSET,
};
use fixel::texture::LodGranularity;
use fixel_firmware::scenes::FrameResult;
use fixel_firmware::{bench_end, bench_mark, bench_start, noise, outln, report_begin};
// `light3d_scene.rs` names the shared scene helpers `crate::scenes`.
#[cfg(fixel_fw_report)]
use fixel_firmware::scenes;

static mut BUF: noise::NoiseBuffers = noise::NoiseBuffers::new();
#[cfg(fixel_fw_report)]
static mut CUBE: light3d_scene::Light3dBuffers = light3d_scene::Light3dBuffers::new();
#[cfg(fixel_fw_report)]
static mut FLAME: [embedded_graphics_core::pixelcolor::Rgb565; noise::FLAME_PIXELS] =
    [embedded_graphics_core::pixelcolor::Rgb565::new(0, 0, 0); noise::FLAME_PIXELS];
#[cfg(fixel_fw_report)]
static mut FLAME_BAND: [embedded_graphics_core::pixelcolor::Rgb565; noise::FLAME_BAND_PIXELS] =
    [embedded_graphics_core::pixelcolor::Rgb565::new(0, 0, 0); noise::FLAME_BAND_PIXELS];

#[inline(never)]
fn mode<P: Pattern, O: Octaves>(
    name: &str,
    shader: SolidShader<P, O>,
    buf: &mut noise::NoiseBuffers,
) -> bool {
    mode_in::<P, O, Exact>(name, shader, buf)
}

#[inline(never)]
fn mode_in<P: Pattern, O: Octaves, J: ProjectionStage>(
    name: &str,
    shader: SolidShader<P, O>,
    buf: &mut noise::NoiseBuffers,
) -> bool {
    bench_start();
    let r = noise::render_in::<_, J>(shader, buf, &mut || bench_end(), &mut || bench_start());
    bench_end();
    bench_mark();
    line(name, r)
}

/// One counted frame and its `mode` line (scene `noise` for every variant).
#[cfg(fixel_fw_report)]
#[inline(never)]
fn counted(
    name: &str,
    frame: impl FnOnce(&mut dyn FnMut(), &mut dyn FnMut()) -> Result<FrameResult, fixel::Error>,
) -> bool {
    bench_start();
    let r = frame(&mut || bench_end(), &mut || bench_start());
    bench_end();
    bench_mark();
    line(name, r)
}

/// Prints the `mode` line of a frame (scene `noise` for every variant); returns success.
fn line(name: &str, r: Result<FrameResult, fixel::Error>) -> bool {
    match r {
        Ok(r) => {
            outln!(
                "mode scene=noise mode={} checksum=0x{:08x} pixels={} rewalked=false",
                name,
                r.checksum,
                r.stats.pixels
            );
            true
        }
        Err(e) => {
            outln!("mode scene=noise mode={} error={:?}", name, e);
            false
        }
    }
}

fn run() -> bool {
    // SAFETY: the only reference to BUF, taken once in this single-threaded firmware.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let Ok(ramps) = Ramps::new() else {
        return false;
    };
    report_begin();
    let mut ok = true;
    const NAMES: [&str; 7] = [
        "marble-fixed0",
        "marble-fixed1",
        "marble-fixed2",
        "marble-fixed3",
        "marble-fixed4",
        "marble-fixed5",
        "marble-fixed6",
    ];
    for (k, name) in NAMES.iter().enumerate() {
        let s = SolidShader::new(ramps.marble(), Fixed(core::hint::black_box(k as u8)));
        ok &= mode(name, s, buf);
    }
    let band = BandLimit::new(core::hint::black_box(6));
    ok &= mode(
        "marble-band6-span",
        SolidShader::new(ramps.marble(), band),
        buf,
    );
    let mut px = SolidShader::new(ramps.marble(), band);
    px.granularity = LodGranularity::Pixel;
    ok &= mode("marble-band6-pixel", px, buf);
    ok &= mode("wood-band6-span", SolidShader::new(ramps.wood(), band), buf);
    ok &= mode_in::<_, _, SubdividedBy<3>>(
        "marble-band6-span-sub8",
        SolidShader::new(ramps.marble(), band),
        buf,
    );
    ok &= mode(
        "granite-band6-span",
        SolidShader::new(ramps.granite(), band),
        buf,
    );
    // Composition by selection: granite, and marble where a third noise passes 0.1.
    let Ok(sel) = Select::new(
        ramps.granite(),
        ramps.marble(),
        core::hint::black_box(3277),
        6554,
        1,
        SELECT_OFFSET,
    ) else {
        return false;
    };
    ok &= mode(
        "select-granite-marble-band6-span",
        SolidShader::new(sel, band),
        buf,
    );
    ok & cube_and_flame(&ramps, band)
}

/// The wooden cube lit per vertex and by the baked 3D light map (`noise_light3d`), and the
/// flame (`noise_flame`: 4 frames; 1, 3 and 5 octaves).
#[cfg(fixel_fw_report)]
fn cube_and_flame(ramps: &Ramps, band: BandLimit) -> bool {
    use fixel::shading::noise::LitSolid;
    // SAFETY: the only reference to CUBE, taken once in this single-threaded firmware.
    let cube = unsafe { &mut *core::ptr::addr_of_mut!(CUBE) };
    let mut ok = counted("cube-wood-vertex-band6-span", |pause, resume| {
        light3d_scene::render_vertex_lit(SolidShader::new(ramps.wood(), band), cube, pause, resume)
    });
    let Ok(light) = light3d_scene::light_map() else {
        return false;
    };
    let lit = LitSolid {
        pattern: ramps.wood(),
        octaves: band,
        light,
        granularity: LodGranularity::Span,
    };
    ok &= counted("cube-wood-light3d-band6-span", |pause, resume| {
        light3d_scene::render_light_map(lit, cube, pause, resume)
    });
    // SAFETY: the only reference to FLAME, taken once in this single-threaded firmware.
    let flame = unsafe { &mut *core::ptr::addr_of_mut!(FLAME) };
    for (name, octaves) in [("flame-oct1", 1u8), ("flame-oct3", 3), ("flame-oct5", 5)] {
        let octaves = core::hint::black_box(octaves);
        ok &= counted(name, |pause, resume| {
            noise::flame_frames_with(flame, 4, octaves, pause, resume)
        });
    }
    // SAFETY: the only reference to FLAME_BAND, taken once in this single-threaded firmware.
    let flame_band = unsafe { &mut *core::ptr::addr_of_mut!(FLAME_BAND) };
    let layers = core::hint::black_box(&fixel_firmware::data::FLAME_LAYER_TEXELS);
    ok &= counted("flame-baked", |pause, resume| {
        fixel_firmware::flame_baked_scene::flame_baked_bands(
            flame_band,
            [&layers[0], &layers[1]],
            4,
            pause,
            resume,
        )
    });
    ok
}

/// Default memory layout: the cube's and the flame's buffers do not fit (see the top).
#[cfg(not(fixel_fw_report))]
fn cube_and_flame(_: &Ramps, _: BandLimit) -> bool {
    true
}

fixel_firmware::entry!(run);
