//! Scene `water` (frame 3: the flat grid displaced by the moving swell, then drawn lit)
//! drawn into one whole 320x240 frame with the same draw: the figure the banded `water` is
//! compared with. Whole-frame memory layout (`FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

#[path = "../water_scene.rs"]
#[allow(dead_code)] // water_displace_only is for the `water_displace` firmware
mod water_scene;

// `water_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;

fn run() -> bool {
    let mut buf = scenes::Whole::new();
    water_scene::run_firmware("whole_water", scenes::WholeTarget::Whole(&mut buf))
}

fixel_firmware::entry!(run);
