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
use clap::{error::ErrorKind, CommandFactory, Parser};
use std::process::ExitCode;

/// Command line (`cargo xtask count` runs `--list`, then `<scene>/<mode> [N]`).
#[derive(Parser)]
#[command(
    name = "count_scene",
    about = "Renders one benchmark case for N frames, for counting instructions under callgrind",
    long_about = None
)]
struct Args {
    /// Print every case id (scene/mode), docs/scenes.md cases first, and exit
    #[arg(long)]
    list: bool,
    /// The case to render, `<scene>/<mode>`, e.g. `cube/lit-bilinear-exact`
    #[arg(
        value_name = "SCENE/MODE",
        value_parser = parse_case,
        required_unless_present = "list"
    )]
    case: Option<Case>,
    /// Frames to draw [default: the scene's N]; 0 is the baseline (set-up only)
    #[arg(value_name = "FRAMES")]
    frames: Option<u32>,
}

fn parse_case(s: &str) -> Result<Case, String> {
    Case::parse(s).ok_or_else(|| "not a `<scene>/<mode>` case (see `--list`)".to_string())
}

fn main() -> ExitCode {
    let args = Args::parse();
    if args.list {
        for c in SCENES.iter().chain(MODES.iter()) {
            println!("{}", c.id());
        }
        return ExitCode::SUCCESS;
    }
    let Some(case) = args.case else {
        // Not reached: clap requires the case unless `--list`.
        Args::command()
            .error(
                ErrorKind::MissingRequiredArgument,
                "no `<scene>/<mode>` case",
            )
            .exit()
    };
    let frames = args.frames.unwrap_or_else(|| case.scene.frames());
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
