//! `cargo xtask report`: shadow maps (`shadow_modes.rs`): every light, map size and filter
//! of the report's rows, light pass and lit pass as separate modes, 320 x 240 whole frame
//! (report memory layout only; in the default one this binary only has to link).
#![no_std]
#![no_main]

#[cfg(fixel_fw_report)]
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel_firmware::report_begin;
#[cfg(fixel_fw_report)]
use fixel_firmware::shadow_modes as sm;
#[cfg(fixel_fw_report)]
use fixel_firmware::{bench_end, bench_mark, bench_start, data, outln};

#[cfg(fixel_fw_report)]
const PX: usize = (sm::W * sm::H) as usize;
#[cfg(fixel_fw_report)]
static mut COLOR: [Rgb565; PX] = [Rgb565::new(0, 0, 0); PX];
#[cfg(fixel_fw_report)]
static mut DEPTH: [u16; PX] = [0; PX];
#[cfg(fixel_fw_report)]
static mut MAP: [u16; sm::MAP_TEXELS] = [0; sm::MAP_TEXELS];

fn run() -> bool {
    report_begin();
    #[cfg(fixel_fw_report)]
    {
        // SAFETY: the only references to these statics, taken once in this single-threaded
        // firmware.
        let (color, depth, map) = unsafe {
            (
                &mut *core::ptr::addr_of_mut!(COLOR),
                &mut *core::ptr::addr_of_mut!(DEPTH),
                &mut *core::ptr::addr_of_mut!(MAP),
            )
        };
        let mut ok = true;
        for (l, light) in sm::LIGHTS.iter().enumerate() {
            for size in sm::SIZES {
                bench_start();
                let r = sm::light_pass(core::hint::black_box(l), size, map);
                bench_end();
                bench_mark();
                let n = (size * size) as usize;
                match r {
                    Ok(_) => outln!(
                        "mode scene=shadow mode={}-{}-light checksum=0x{:08x} pixels={} rewalked=false",
                        light,
                        size,
                        sm::map_checksum(&map[..n]),
                        n
                    ),
                    Err(e) => {
                        outln!("mode scene=shadow mode={}-{}-light error={:?}", light, size, e);
                        ok = false;
                    }
                }
                for (f, filter) in sm::FILTERS.iter().enumerate() {
                    bench_start();
                    let r = sm::lit_pass(
                        core::hint::black_box(l),
                        f,
                        size,
                        map,
                        [data::T128, data::T64],
                        color,
                        depth,
                    );
                    bench_end();
                    bench_mark();
                    match r {
                        Ok(px) => outln!(
                            "mode scene=shadow mode={}-{}-{} checksum=0x{:08x} pixels={} rewalked=false",
                            light,
                            size,
                            filter,
                            sm::checksum(color),
                            px
                        ),
                        Err(e) => {
                            outln!("mode scene=shadow mode={}-{}-{} error={:?}", light, size, filter, e);
                            ok = false;
                        }
                    }
                }
            }
        }
        ok
    }
    #[cfg(not(fixel_fw_report))]
    true
}

fixel_firmware::entry!(run);
