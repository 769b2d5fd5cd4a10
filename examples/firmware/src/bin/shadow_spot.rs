//! Shadow scene, lit pass under the spot light with PCF 2x2 (64 x 64 map), in bands of 4
//! rows; the light pass runs first, outside the counted region.
#![no_std]
#![no_main]

use fixel::geometry::Cull;
use fixel::shading::pcf::Pcf2x2;
use fixel_firmware::shadow::{self, ShadowBuffers};
use fixel_scenes::shadow::{self as scene, SceneLight};

static mut BUF: ShadowBuffers = ShadowBuffers::new();

fn run() -> bool {
    // SAFETY: single-threaded firmware, the only reference to BUF.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    let Ok(space) = scene::spot() else {
        return false;
    };
    shadow::run::<_, Pcf2x2, 7, false>("shadow_spot", &space, SceneLight::Spot, Cull::Back, buf)
}

fixel_firmware::entry!(run);
