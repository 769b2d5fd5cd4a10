//! Scene `water` (frame 3: the flat grid displaced by the moving swell, then drawn lit)
//! drawn into one whole 320x240 frame with the same draw: the figure the banded `water` is
//! compared with. Whole-frame memory layout (`FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

#[path = "../water_scene.rs"]
#[allow(dead_code)] // water_displace_only is for the `water_displace` firmware
mod water_scene;

use fixel::math::Vec3;
use fixel::scene::Mesh;
use fixel_firmware::{data, report};
// `water_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;
use water_scene::WATER_VERTICES;

mod base {
    include!("../../../../assets/displaced/water_base.rs");
}

static mut POSITIONS: [Vec3; WATER_VERTICES] = [Vec3::ZERO; WATER_VERTICES];
static mut NORMALS: [Vec3; WATER_VERTICES] = [Vec3::ZERO; WATER_VERTICES];

fn run() -> bool {
    // SAFETY: the only references to these statics, taken once in this single-threaded
    // firmware.
    let (positions, normals) = unsafe {
        (
            &mut *core::ptr::addr_of_mut!(POSITIONS),
            &mut *core::ptr::addr_of_mut!(NORMALS),
        )
    };
    let mut buf = scenes::Whole::new();
    let Ok(mesh) = Mesh::new(
        core::hint::black_box(&base::WATER_POSITIONS),
        Some(&base::WATER_NORMALS),
        &base::WATER_UVS,
        &base::WATER_INDICES,
    ) else {
        return false;
    };
    let frame = core::hint::black_box(3);
    report("whole_water", |pause, resume| {
        water_scene::water(
            scenes::WholeTarget::Whole(&mut buf),
            data::T64,
            &mesh,
            &base::WATER_HEIGHTS,
            positions,
            normals,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
