//! The cost of one `noise4` call (4D gradient noise): 1024 calls at points
//! spread over many cells, counted between the markers; prints `pixels=1024` so the
//! instructions per "pixel" are instructions per call.
#![no_std]
#![no_main]

use fixel::shading::noise::noise4;
use fixel_firmware::{bench_end, bench_start, outln};

fn run() -> bool {
    let mut p = core::hint::black_box([0x1_2345i32, 0x7_89ABi32, -0x3_CDEFi32, 0x2_4680i32]);
    let step = core::hint::black_box([0x0_9E37i32, 0x1_79B9i32, 0x0_7F4Ai32, 0x0_3C6Fi32]);
    let mut acc = 0u32;
    bench_start();
    bench_end();
    bench_start();
    for _ in 0..1024 {
        acc = acc
            .wrapping_mul(31)
            .wrapping_add(noise4(p[0], p[1], p[2], p[3]) as u32);
        p = [
            p[0].wrapping_add(step[0]),
            p[1].wrapping_add(step[1]),
            p[2].wrapping_add(step[2]),
            p[3].wrapping_add(step[3]),
        ];
    }
    bench_end();
    outln!("scene=noise4_cost checksum=0x{:08x} pixels=1024", acc);
    true
}

fixel_firmware::entry!(run);
