//! Shadow scene, light pass only: the cube and floor drawn depth-only into a 64 x 64 map
//! from the high directional light. `pixels=` is the map's texel count (4096), so the
//! instruction count per "pixel" is per map texel.
#![no_std]
#![no_main]

use fixel_firmware::shadow::{self, ShadowBuffers, MAP_TEXELS};
use fixel_firmware::{bench_end, bench_start, outln};
use fixel_scenes::shadow::{self as scene, SceneLight};

static mut BUF: ShadowBuffers = ShadowBuffers::new();

fn run() -> bool {
    // SAFETY: single-threaded firmware, the only reference to BUF.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let Ok(space) = scene::directional(SceneLight::High) else {
        return false;
    };
    bench_start();
    bench_end();
    bench_start();
    let r = shadow::light_pass(&space, core::hint::black_box(&mut buf.map));
    bench_end();
    let sum = buf
        .map
        .iter()
        .fold(0u32, |h, &t| (h ^ u32::from(t)).wrapping_mul(16_777_619));
    match r {
        Ok(w) => {
            outln!(
                "scene=shadow_light checksum=0x{:08x} pixels={} written={}",
                sum,
                MAP_TEXELS,
                w
            );
            true
        }
        Err(e) => {
            outln!("scene=shadow_light error={:?}", e);
            false
        }
    }
}

fixel_firmware::entry!(run);
