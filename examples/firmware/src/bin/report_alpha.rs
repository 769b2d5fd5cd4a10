//! `cargo xtask report`: transparency (`alpha.rs`): the floor opaque, then a quad with an
//! alpha shader (over, additive, alpha test), only the quad counted; 240 x 180 whole frame
//! (report memory layout only; in the default one this binary only has to link).
#![no_std]
#![no_main]

#[cfg(fixel_fw_report)]
use embedded_graphics_core::pixelcolor::Rgb565;
#[cfg(fixel_fw_report)]
use fixel_firmware::alpha;
use fixel_firmware::report_begin;
#[cfg(fixel_fw_report)]
use fixel_firmware::{bench_end, bench_mark, bench_start, data, outln};

#[cfg(fixel_fw_report)]
const PX: usize = (alpha::W * alpha::H) as usize;
#[cfg(fixel_fw_report)]
static mut COLOR: [Rgb565; PX] = [Rgb565::new(0, 0, 0); PX];
#[cfg(fixel_fw_report)]
static mut DEPTH: [u16; PX] = [0; PX];

fn run() -> bool {
    report_begin();
    #[cfg(fixel_fw_report)]
    {
        // SAFETY: the only references to these statics, taken once in this single-threaded
        // firmware.
        let (color, depth) = unsafe {
            (
                &mut *core::ptr::addr_of_mut!(COLOR),
                &mut *core::ptr::addr_of_mut!(DEPTH),
            )
        };
        let plane = alpha::plane();
        let mut ok = true;
        for (k, name) in alpha::MODES.iter().enumerate() {
            if alpha::floor(data::T64, color, depth).is_err() {
                return false;
            }
            bench_start();
            let r = alpha::quad_mode(core::hint::black_box(k), data::T8, &plane, color, depth);
            bench_end();
            bench_mark();
            match r {
                Ok(px) => outln!(
                    "mode scene=alpha mode={} checksum=0x{:08x} pixels={} rewalked=false",
                    name,
                    alpha::checksum(color),
                    px
                ),
                Err(e) => {
                    outln!("mode scene=alpha mode={} error={:?}", name, e);
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
