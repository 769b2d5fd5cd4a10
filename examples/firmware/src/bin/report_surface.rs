//! `cargo xtask report`: per-pixel lighting, bump and normal mapping (`surface.rs`): the
//! brick sphere in a 160 x 160 frame, one mode per lighting variant, vertices included
//! (report memory layout only; in the default one this binary only has to link).
#![no_std]
#![no_main]

#[cfg(fixel_fw_report)]
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel_firmware::report_begin;
#[cfg(fixel_fw_report)]
use fixel_firmware::surface;
#[cfg(fixel_fw_report)]
use fixel_firmware::{bench_end, bench_mark, bench_start, outln};

#[cfg(fixel_fw_report)]
const PX: usize = (surface::W * surface::H) as usize;
#[cfg(fixel_fw_report)]
static mut COLOR: [Rgb565; PX] = [Rgb565::new(0, 0, 0); PX];
#[cfg(fixel_fw_report)]
static mut DEPTH: [u16; PX] = [0; PX];
#[cfg(fixel_fw_report)]
static mut ASSETS: surface::SurfaceAssets = surface::SurfaceAssets::zeroed();

fn run() -> bool {
    report_begin();
    #[cfg(fixel_fw_report)]
    {
        // SAFETY: the only references to these statics, taken once in this single-threaded
        // firmware.
        let (color, depth, assets) = unsafe {
            (
                &mut *core::ptr::addr_of_mut!(COLOR),
                &mut *core::ptr::addr_of_mut!(DEPTH),
                &mut *core::ptr::addr_of_mut!(ASSETS),
            )
        };
        if assets.build().is_err() {
            return false;
        }
        let mut ok = true;
        for (k, name) in surface::VARIANTS.iter().enumerate() {
            bench_start();
            let r = surface::render(core::hint::black_box(k), assets, color, depth);
            bench_end();
            bench_mark();
            match r {
                Ok(px) => outln!(
                    "mode scene=surface mode={} checksum=0x{:08x} pixels={} rewalked=false",
                    name,
                    surface::checksum(color),
                    px
                ),
                Err(e) => {
                    outln!("mode scene=surface mode={} error={:?}", name, e);
                    ok = false;
                }
            }
        }
        ok
    }
    #[cfg(not(fixel_fw_report))]
    true
}

fixel_firmware::entry!(run);
