//! `cargo xtask report`: regular-grid supersampling of the benchmark cube in bands
//! (`aa::cube`): 1x, 2 x 2 and 4 x 4, then the rotated grid of 4 and 16 jittered samples
//! accumulated through 8-row bands (`aa::cube_accumulated`), then 1x with post-process
//! edge smoothing (`aa::cube_smoothed`), then the `aa_edge` scene's frame (silhouettes
//! smoothed from depth, `edge_scene.rs`) (report memory layout only: the 4 x 4 band takes
//! 160 KB; in the default layout this binary only has to link).
#![no_std]
#![no_main]

#[cfg(fixel_fw_report)]
use fixel::scene::SamplePattern;
#[cfg(fixel_fw_report)]
use fixel_firmware::aa;
use fixel_firmware::report_begin;
#[cfg(fixel_fw_report)]
use fixel_firmware::{bench_end, bench_mark, bench_start, data, outln};

#[cfg(fixel_fw_report)]
#[path = "../edge_scene.rs"]
#[allow(dead_code)] // EDGE_RAM: the host report's
mod edge_scene;
// `edge_scene.rs` names the shared scene helpers `crate::scenes`.
#[cfg(fixel_fw_report)]
use fixel_firmware::scenes;

#[cfg(fixel_fw_report)]
static mut BUF: aa::AaBuffers = aa::AaBuffers::new();
#[cfg(fixel_fw_report)]
static mut ACC: aa::AccumBuffers = aa::AccumBuffers::new();
#[cfg(fixel_fw_report)]
static mut SMOOTH: aa::SmoothBuffers = aa::SmoothBuffers::new();
#[cfg(fixel_fw_report)]
static mut EDGE: edge_scene::EdgeBuffers = edge_scene::EdgeBuffers::new();

fn run() -> bool {
    report_begin();
    #[cfg(fixel_fw_report)]
    {
        // SAFETY: the only reference to BUF, taken once in this single-threaded firmware.
        let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
        let mut ok = true;
        for k in 1..=aa::K_MAX {
            if k == 3 {
                continue;
            }
            bench_start();
            let r = aa::cube(
                core::hint::black_box(k),
                data::T128,
                0,
                buf,
                None,
                &mut || bench_end(),
                &mut || bench_start(),
            );
            bench_end();
            bench_mark();
            match r {
                Ok(r) => outln!(
                    "mode scene=aa mode=cube-{}x{} checksum=0x{:08x} pixels={} rewalked={}",
                    k,
                    k,
                    r.checksum,
                    // Display pixels: the k-times frame wrote k² per pixel.
                    r.stats.pixels / (k * k),
                    r.stats.rewalked
                ),
                Err(e) => {
                    outln!("mode scene=aa mode=cube-{}x{} error={:?}", k, k, e);
                    ok = false;
                }
            }
        }
        // SAFETY: the only reference to ACC, taken once in this single-threaded firmware.
        let acc = unsafe { &mut *core::ptr::addr_of_mut!(ACC) };
        for (name, p) in [
            ("cube-rgss4-bands", SamplePattern::RotatedGrid4),
            (
                "cube-jitter16-bands",
                SamplePattern::Jittered { n: 16, seed: 1 },
            ),
        ] {
            bench_start();
            let r = aa::cube_accumulated(
                core::hint::black_box(p),
                data::T128,
                0,
                acc,
                None,
                &mut || bench_end(),
                &mut || bench_start(),
            );
            bench_end();
            bench_mark();
            match r {
                Ok(r) => outln!(
                    "mode scene=aa mode={} checksum=0x{:08x} pixels={} rewalked=false",
                    name,
                    r.checksum,
                    r.stats.pixels
                ),
                Err(e) => {
                    outln!("mode scene=aa mode={} error={:?}", name, e);
                    ok = false;
                }
            }
        }
        // SAFETY: the only reference to SMOOTH, taken once in this single-threaded firmware.
        let sm = unsafe { &mut *core::ptr::addr_of_mut!(SMOOTH) };
        bench_start();
        let r = aa::cube_smoothed(data::T128, 0, sm, None, &mut || bench_end(), &mut || {
            bench_start()
        });
        bench_end();
        bench_mark();
        match r {
            Ok(r) => outln!(
                "mode scene=aa mode=cube-smoothed checksum=0x{:08x} pixels={} rewalked=false",
                r.checksum,
                r.stats.pixels
            ),
            Err(e) => {
                outln!("mode scene=aa mode=cube-smoothed error={:?}", e);
                ok = false;
            }
        }
        // SAFETY: the only reference to EDGE, taken once in this single-threaded firmware.
        let edge = unsafe { &mut *core::ptr::addr_of_mut!(EDGE) };
        let mut small = scenes::SmallBuffers::with_storage();
        bench_start();
        let r = edge_scene::aa_edge(
            &mut small,
            edge,
            data::T128_FP,
            core::hint::black_box(0),
            None,
            &mut || bench_end(),
            &mut || bench_start(),
        );
        bench_end();
        bench_mark();
        match r {
            Ok(r) => outln!(
                "mode scene=aa mode=cube-edge checksum=0x{:08x} pixels={} rewalked=false",
                r.checksum,
                r.stats.pixels
            ),
            Err(e) => {
                outln!("mode scene=aa mode=cube-edge error={:?}", e);
                ok = false;
            }
        }
        ok
    }
    #[cfg(not(fixel_fw_report))]
    true
}

fixel_firmware::entry!(run);
