//! Scene `water`, frame 3: run-time displacement of a subdivided grid by a moving swell
//! (`water_scene.rs`), normals recomputed, drawn lit in bands; the displacement is inside
//! the counted region, so instructions per pixel include it.
#![no_std]
#![no_main]

#[path = "../water_scene.rs"]
#[allow(dead_code)] // water_displace_only is for the `water_displace` firmware
mod water_scene;

// `water_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;

fn run() -> bool {
    let mut buf = water_scene::WaterBuffers::with_storage();
    water_scene::run_firmware("water", scenes::Target::Bands(&mut buf))
}

fixel_firmware::entry!(run);
