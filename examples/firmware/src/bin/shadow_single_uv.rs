//! Shadow scene, lit pass with SingleTap in its real-time form (`ShadowedUv`: light
//! coordinates from the texture coordinates, none interpolated), 64 x 64 map, high
//! directional light, in bands of 4 rows; the light pass runs first, outside the counted
//! region. Compared with `shadow_single` (the same filter through light varyings) and
//! `shadow_none`.
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
    shadow::run_directional::<SingleTap, true>(
        "shadow_single_uv",
        SceneLight::High,
        Cull::Back,
        buf,
    )
}

fixel_firmware::entry!(run);
