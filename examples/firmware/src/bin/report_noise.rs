//! `cargo xtask report`: the solid-texture scene of `noise.rs` once per variant: marble
//! with 0 to 6 fixed octaves, marble band-limited (at most 6 octaves, footprint per span
//! and per pixel), and wood and granite band-limited on the same sphere.
#![no_std]
#![no_main]

use fixel::pipeline::{Exact, ProjectionStage, SubdividedBy};
use fixel::shading::noise::{BandLimit, Fixed, Octaves, Pattern, Ramps, SolidShader};
use fixel::texture::LodGranularity;
use fixel_firmware::{bench_end, bench_mark, bench_start, noise, outln, report_begin};

static mut BUF: noise::NoiseBuffers = noise::NoiseBuffers::new();

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
    ok
}

fixel_firmware::entry!(run);
