//! `water_displace`: only the displacement of the `water` scene's frame 3 (positions, then
//! normals, of 169 vertices and 288 triangles), for its cost per vertex: the report's
//! `pixels` is the vertex count, so `/work/tools/m4 water_displace` prints instructions per
//! vertex. Not a `cargo xtask mcu` scene (it draws nothing).
#![no_std]
#![no_main]

#[path = "../water_scene.rs"]
#[allow(dead_code)]
mod water_scene;

use fixel::math::Vec3;
use fixel::scene::Mesh;
use fixel::surface::BandStats;
use fixel_firmware::report;
// `water_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes::{self, FrameResult};
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
    let Ok(mesh) = Mesh::new(
        core::hint::black_box(&base::WATER_POSITIONS),
        Some(&base::WATER_NORMALS),
        &base::WATER_UVS,
        &base::WATER_INDICES,
    ) else {
        return false;
    };
    let frame = core::hint::black_box(3);
    report("water_displace", |pause, resume| {
        water_scene::water_displace_only(&mesh, &base::WATER_HEIGHTS, positions, normals, frame)?;
        pause();
        // FNV-1a of the positions' and normals' bits.
        let mut sum = 0x811c_9dc5u32;
        for v in positions.iter().chain(normals.iter()) {
            for c in [v.x, v.y, v.z] {
                for b in c.to_bits().to_le_bytes() {
                    sum = (sum ^ u32::from(b)).wrapping_mul(16_777_619);
                }
            }
        }
        resume();
        Ok(FrameResult {
            checksum: sum,
            stats: BandStats {
                pixels: WATER_VERTICES as u32,
                ..BandStats::default()
            },
        })
    })
}

fixel_firmware::entry!(run);
