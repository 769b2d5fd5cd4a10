//! `cargo xtask report`: texture-coordinate generation on the Utah teapot baked
//! from OBJ: each per-vertex generator of `mapping::GENERATORS` over its 860 vertices
//! (`pixels` = vertices, so the figure is instructions per vertex), then the triplanar
//! teapot frame and the teapot with cylindrical coordinates per pixel (240 x 180, per pixel; in the report memory layout only: the frame does not
//! fit the default 16K of RAM, where this binary only has to link).
#![no_std]
#![no_main]

#[cfg(fixel_fw_report)]
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::math::Fx;
use fixel_firmware::data::teapot;
use fixel_firmware::{bench_end, bench_mark, bench_start, mapping, outln, report_begin};

const N: usize = teapot::TEAPOT_POSITIONS.len();
static mut UVS: [[Fx; 2]; N] = [[Fx::ZERO; 2]; N];
#[cfg(fixel_fw_report)]
static mut COLOR: [Rgb565; (mapping::W * mapping::H) as usize] =
    [Rgb565::new(0, 0, 0); (mapping::W * mapping::H) as usize];
#[cfg(fixel_fw_report)]
static mut DEPTH: [u16; (mapping::W * mapping::H) as usize] =
    [0; (mapping::W * mapping::H) as usize];

fn run() -> bool {
    // SAFETY: the only reference to UVS, taken once in this single-threaded firmware.
    let uvs = unsafe { &mut *core::ptr::addr_of_mut!(UVS) };
    let p = core::hint::black_box(&teapot::TEAPOT_POSITIONS[..]);
    let n = &teapot::TEAPOT_NORMALS[..];
    report_begin();
    let mut ok = true;
    for (k, name) in mapping::GENERATORS.iter().enumerate() {
        bench_start();
        let r = mapping::generate(core::hint::black_box(k), p, n, uvs);
        bench_end();
        bench_mark();
        match r {
            Ok(()) => outln!(
                "mode scene=mapping mode={} checksum=0x{:08x} pixels={} rewalked=false",
                name,
                mapping::checksum(uvs),
                N
            ),
            Err(e) => {
                outln!("mode scene=mapping mode={} error={:?}", name, e);
                ok = false;
            }
        }
    }
    #[cfg(fixel_fw_report)]
    {
        ok &= per_pixel(mapping::PerPixel::Triplanar, "triplanar", p, n);
        ok &= per_pixel(
            mapping::PerPixel::Cylindrical,
            "uv-per-pixel-cylindrical",
            p,
            n,
        );
    }
    ok
}

/// A per-pixel teapot frame, counted, then a mark.
#[cfg(fixel_fw_report)]
fn per_pixel(
    kind: mapping::PerPixel,
    name: &str,
    p: &[fixel::math::Vec3],
    n: &[fixel::math::Vec3],
) -> bool {
    // SAFETY: the only references to these statics, taken once in this single-threaded
    // firmware.
    let (color, depth) = unsafe {
        (
            &mut *core::ptr::addr_of_mut!(COLOR),
            &mut *core::ptr::addr_of_mut!(DEPTH),
        )
    };
    bench_start();
    let r = mapping::triplanar_frame(
        kind,
        fixel_firmware::data::T64,
        p,
        n,
        &teapot::TEAPOT_INDICES,
        color,
        depth,
        &mut || bench_end(),
        &mut || bench_start(),
    );
    bench_end();
    bench_mark();
    match r {
        Ok((sum, px)) => {
            outln!(
                "mode scene=mapping mode={} checksum=0x{:08x} pixels={} rewalked=false",
                name,
                sum,
                px
            );
            true
        }
        Err(e) => {
            outln!("mode scene=mapping mode={} error={:?}", name, e);
            false
        }
    }
}

fixel_firmware::entry!(run);
