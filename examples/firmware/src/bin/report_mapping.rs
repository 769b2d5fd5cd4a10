//! `cargo xtask report`: texture-coordinate generation (issue 15) on the Utah teapot baked
//! from OBJ: each per-vertex generator of `mapping::GENERATORS` over its 860 vertices
//! (`pixels` = vertices, so the figure is instructions per vertex), then the triplanar
//! teapot frame (240 x 180, per pixel).
#![no_std]
#![no_main]

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::math::Fx;
use fixel_firmware::data::{self, teapot};
use fixel_firmware::{bench_end, bench_mark, bench_start, mapping, outln, report_begin};

const N: usize = teapot::TEAPOT_POSITIONS.len();
static mut UVS: [[Fx; 2]; N] = [[Fx::ZERO; 2]; N];
static mut COLOR: [Rgb565; (mapping::W * mapping::H) as usize] =
    [Rgb565::new(0, 0, 0); (mapping::W * mapping::H) as usize];
static mut DEPTH: [u16; (mapping::W * mapping::H) as usize] =
    [0; (mapping::W * mapping::H) as usize];

fn run() -> bool {
    // SAFETY: the only references to these statics, taken once in this single-threaded
    // firmware.
    let (uvs, color, depth) = unsafe {
        (
            &mut *core::ptr::addr_of_mut!(UVS),
            &mut *core::ptr::addr_of_mut!(COLOR),
            &mut *core::ptr::addr_of_mut!(DEPTH),
        )
    };
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
    bench_start();
    let r = mapping::triplanar_frame(
        data::T64,
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
        Ok((sum, px)) => outln!(
            "mode scene=mapping mode=triplanar checksum=0x{:08x} pixels={} rewalked=false",
            sum,
            px
        ),
        Err(e) => {
            outln!("mode scene=mapping mode=triplanar error={:?}", e);
            ok = false;
        }
    }
    ok
}

fixel_firmware::entry!(run);
