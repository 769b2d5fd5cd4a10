//! Shadow scene, lit pass with SingleTap (64 x 64 map, high directional light), in bands of 4
//! rows; the light pass runs first, outside the counted region.
#![no_std]
#![no_main]

use fixel::geometry::Cull;
use fixel::shading::pcf::SingleTap;
use fixel_firmware::shadow::{self, ShadowBuffers};
use fixel_scenes::shadow::SceneLight;

static mut BUF: ShadowBuffers = ShadowBuffers::new();

fn run() -> bool {
    // SAFETY: single-threaded firmware, the only reference to BUF.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    shadow::run_directional::<SingleTap, false>("shadow_single", SceneLight::High, Cull::Back, buf)
}

fixel_firmware::entry!(run);
