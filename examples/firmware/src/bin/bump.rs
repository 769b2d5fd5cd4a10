//! Scene `bump`, frame 0: the brick sphere bump-mapped from a precomputed derivative map and
//! lit per pixel by a point light (`bump_scene.rs`), in one whole 320 x 240 frame (the
//! whole-frame memory layout, `FIXEL_FW_MEMORY=whole`, feature `whole`).
#![no_std]
#![no_main]

#[path = "../bump_scene.rs"]
mod bump_scene;

use fixel_firmware::report;
// `bump_scene.rs` names the shared scene helpers `crate::scenes`.
use fixel_firmware::scenes;

fn run() -> bool {
    let mut assets = bump_scene::BumpAssets::zeroed();
    if bump_scene::BumpAssets::build(&mut assets).is_err() {
        return false;
    }
    let mut buf = scenes::Whole::new();
    let mut vertices = [fixel::geometry::Vertex::new([fixel::math::Fx::ZERO; 4], [0; 8]);
        fixel::demo::SPHERE_VERTICES];
    let frame = core::hint::black_box(0);
    report("bump", |pause, resume| {
        bump_scene::bump(
            &assets,
            &mut buf.color,
            &mut buf.depth,
            &mut vertices,
            frame,
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
