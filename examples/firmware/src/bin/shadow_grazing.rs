//! Shadow scene under the grazing directional light (about 11 degrees above the floor),
//! lit pass with Pcf3x3 (64 x 64 map), in bands of 4 rows; the light pass culls the faces
//! turned to the light (front-face culling against acne: the floor is not in the map) and
//! runs first, outside the counted region.
#![no_std]
#![no_main]

use fixel::geometry::Cull;
use fixel::shading::pcf::Pcf3x3;
use fixel_firmware::shadow::{self, ShadowBuffers};
use fixel_scenes::shadow::SceneLight;

static mut BUF: ShadowBuffers = ShadowBuffers::new();

fn run() -> bool {
    // SAFETY: single-threaded firmware, the only reference to BUF.
    let buf = unsafe { &mut *core::ptr::addr_of_mut!(BUF) };
    shadow::run_directional::<Pcf3x3, false>(
        "shadow_grazing",
        SceneLight::Grazing,
        Cull::Front,
        buf,
    )
}

fixel_firmware::entry!(run);
