//! Renders one benchmark case for N frames, for counting instructions under callgrind
//! (`cargo xtask count` drives it; no timing, no output files).
//!
//! ```text
//! count_scene --list                 # every case id: scene/mode, docs/scenes.md cases first
//! count_scene <scene>/<mode> [N]     # N frames (default: the scene's N); N = 0 is the
//!                                    # baseline (texture, mesh and draw set-up only)
//! ```
//!
//! Prints `frames <N>` and `pixels <drawn pixels summed over the frames>` on stdout. Modes are
//! those of `examples/firmware/src/modes.rs`:
//! `{lit|unlit}-{nearest|bilinear|nearest-mip-nearest|trilinear|trilinear-span}-`
//! `{affine|sub4|sub8|sub16|sub32|exact|adaptive}`, for example `cube/lit-bilinear-exact` or
//! `floor/unlit-nearest-sub16`; `--list` prints the benchmark's cases, any mode can be named.

#[path = "common/bench_scenes.rs"]
mod bench_scenes;

use bench_scenes::{Bench, Case, MODES, SCENES};
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--list") {
        for c in SCENES.iter().chain(MODES.iter()) {
            println!("{}", c.id());
        }
        return ExitCode::SUCCESS;
    }
    let Some(case) = args.first().and_then(|s| Case::parse(s)) else {
        eprintln!("usage: count_scene --list | count_scene <scene>/<mode> [frames]");
        return ExitCode::from(2);
    };
    let frames = match args.get(1).map(|s| s.parse::<u32>()) {
        None => case.scene.frames(),
        Some(Ok(n)) => n,
        Some(Err(e)) => {
            eprintln!("count_scene: bad frame count: {e}");
            return ExitCode::from(2);
        }
    };
    let mut bench = Bench::new(case);
    let pixels = bench.run(frames);
    // Keep the frame observable so nothing is optimised away.
    let checksum = bench.pixels().iter().fold(0u32, |h, p| {
        h.rotate_left(5)
            ^ u32::from(embedded_graphics_core::pixelcolor::IntoStorage::into_storage(*p))
    });
    println!("frames {frames}");
    println!("pixels {pixels}");
    println!("checksum {checksum:08x}");
    ExitCode::SUCCESS
}
