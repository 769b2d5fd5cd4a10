//! `cargo xtask`: repository chores for fixel (CI, golden blessing, demo renders).
//!
//! Few dependencies so it builds quickly: the command line is parsed with `clap` (derive:
//! [`Cli`] here, each command's flags next to its code) and every tool is driven through
//! `std::process::Command`; `png`, `tobj` and `gltf` read the inputs of the bake commands, and
//! `indicatif` shows the progress of the long runs (`cargo xtask mcu`).

mod bake;
mod bake_cube;
mod bake_displaced;
mod bake_gltf;
mod bake_noise;
mod bake_obj;
mod bake_palette;
mod budget;
mod ci;
mod cmd;
mod count;
mod fps;
mod frame_model;
mod fuzz;
mod images;
#[cfg(test)]
mod imports;
#[cfg(test)]
mod layers;
mod light3d;
mod mcu;
mod pictures;
mod preview;
mod progress;
mod publish;
mod report;
mod teapot;

use std::fmt::Display;
use std::process::ExitCode;

use clap::error::ErrorKind;
use clap::{CommandFactory, Parser, Subcommand};

/// `cargo xtask`: the command line (clap derive); each command's flags live with its code.
#[derive(Parser, Debug)]
#[command(
    name = "xtask",
    bin_name = "cargo xtask",
    about = "cargo xtask: repository chores for fixel",
    after_help = "Exit status: 0 on success, 1 when a step fails, 2 on usage errors.",
    long_about = None,
    arg_required_else_help = true,
    args_override_self = true
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run the full check suite, failing fast
    ///
    /// Steps, in order: toolchain targets/components, fmt, clippy, test (the `ci`
    /// profile: optimized, with overflow checks and debug assertions), `fuzz`
    /// (400000 random cases), the pictures of docs/images against a fresh render
    /// (`render --check --profile ci`), docs (-D warnings), `cargo publish
    /// --dry-run` (package at most 1 MiB, docs for thumbv7em), the preview window
    /// under Xvfb (`preview --check`), no_std cross builds for
    /// thumbv6m-none-eabi, thumbv7em-none-eabihf, riscv32imc-unknown-none-elf,
    /// then `mcu` (firmware under QEMU: checksums must equal the host's; prints
    /// the report). Ends with a summary table of the steps and their times.
    #[command(verbatim_doc_comment)]
    Ci(ci::CiArgs),
    /// The benchmark scenes in a desktop window (embedded-graphics-simulator, SDL2)
    ///
    /// Builds and runs examples/preview-window (release): the cube, sphere or
    /// teapot at 320 x 240 RGB565, drawn in 8-row bands through BandRenderer as a
    /// firmware draws them. Keys: arrows orbit, + / - distance, t technique,
    /// s scene, c chip, e instruction estimate, r start view, h help, q quits.
    /// Installs SDL2's development files (apt-get) when missing. --check runs it
    /// under Xvfb, presses keys with xdotool and compares screenshots of the
    /// window with the PNGs of the same frames (a step of `ci`).
    #[command(verbatim_doc_comment)]
    Preview(preview::PreviewArgs),
    /// What crates.io would get: the `publish (dry run)` step of `ci`
    ///
    /// Runs `cargo publish --dry-run -p fixel` (packages the library and builds
    /// the package), checks the package's file list (the library, build.rs,
    /// README, CHANGELOG, licence texts) and its size (at most 1 MiB
    /// compressed), and builds the docs for thumbv7em-none-eabihf with warnings
    /// denied, as docs.rs builds them.
    #[command(verbatim_doc_comment)]
    Package,
    /// Re-run host-tests with FIXEL_BLESS=1 (rewrites golden images), then show which goldens changed
    ///
    /// Re-runs `cargo test -p host-tests` with FIXEL_BLESS=1 (rewrites the golden
    /// images), then shows which goldens changed (git status host-tests/golden).
    #[command(verbatim_doc_comment)]
    Bless,
    /// Render the demo scenes (release) to target/pictures/*.png
    ///
    /// Builds the demo examples (`showcase`, `scenes`, `preview`, `shadow`, `noise`,
    /// `envmap` and the other technique demos, release) and runs each, which write
    /// target/pictures/*.png. With --docs, copies every picture of docs/images whose
    /// pixels changed; with --check, fails when one differs (CI runs it).
    #[command(verbatim_doc_comment)]
    Render(images::RenderArgs),
    /// Exact x86_64 instructions per drawn pixel of the benchmark scenes and modes
    ///
    /// Builds the `count_scene` example (release), runs each case under
    /// `valgrind --tool=callgrind`, subtracts a 0-frame baseline (texture, mesh,
    /// draw set-up) and prints a Markdown table, also saved to
    /// target/instructions-x86.md. Callgrind files stay in target/callgrind/
    /// (for `callgrind_annotate --auto=yes`).
    #[command(verbatim_doc_comment)]
    Count(count::CountArgs),
    /// Firmware examples under QEMU: instructions/pixel, cycles/pixel, flash and RAM
    ///
    /// Builds the firmware examples (examples/firmware) for Cortex-M4F, Cortex-M0+
    /// and RV32IMC, runs each scene under QEMU with an instruction-counting plugin
    /// (N runs, default 2, must agree), checks each frame checksum against the
    /// host's, and prints instructions/pixel, estimated cycles/pixel, flash and RAM.
    /// Installs missing rust targets, llvm-tools and (apt-get)
    /// qemu-system-arm/qemu-system-misc/gcc/python3.
    #[command(verbatim_doc_comment)]
    Mcu(mcu::McuArgs),
    /// Flash and RAM of a minimal firmware per feature set
    ///
    /// Builds the size firmwares (examples/firmware) for Cortex-M4F, Cortex-M0+ and
    /// RV32IMC and prints flash, fixel's share of it and RAM (static + measured
    /// stack) per feature set; each must give the same frame checksum on all three.
    /// Installs missing tools as `mcu` does.
    #[command(verbatim_doc_comment)]
    Size(mcu::SizeArgs),
    /// Frames per second on real boards, modelled from the firmware's per-band counts
    ///
    /// Counts the cube, sphere and teapot firmwares band by band under QEMU (exact
    /// instructions of the binning pass and of each band, cycles from the static
    /// model), then models the frame time and fps on an RP2040, RP2350, STM32F4 and
    /// ESP32-C3 driving an ST7789 over SPI: one core serial, one core overlapped
    /// (two band buffers, DMA), two cores overlapped; with the share of the link time
    /// hidden and the assumptions. --docs writes docs/fps.md.
    #[command(verbatim_doc_comment)]
    Fps(fps::FpsArgs),
    /// Flash, RAM and frame time of a model on a part, before flashing it
    ///
    /// MODEL is a glTF 2.0 file (.glb/.gltf: baked in memory as bake-gltf
    /// --center bakes it, scaled to 3.1 units, drawn on the host as the fox
    /// firmware draws the Fox, to count its pixels, triangles and band pieces) or
    /// a benchmark scene (cube, sphere, teapot, floor, fox, cesium_man). Prints
    /// the model's flash and the firmware's, the RAM, the predicted instructions
    /// (unit costs fitted to docs/mcu.md: per pixel of the draw's mode, per
    /// vertex, per drawn triangle, per band and band piece), the frame times of
    /// the fps frame model, the fit against every benchmark frame (fails above
    /// 15 %) and the assumptions.
    #[command(verbatim_doc_comment)]
    Budget(budget::BudgetArgs),
    /// One frame on two cores under QEMU (RISC-V virt -smp 2): per-hart exact counts
    ///
    /// Builds the cores_cube, cores_sphere and cores_teapot firmwares (RV32IMC) and
    /// runs each on two harts with a per-vCPU instruction-counting plugin: frame 0
    /// on one hart, then binned half on each hart and drawn in interleaved bands.
    /// Prints each hart's instructions and the balance; fails unless both
    /// checksums equal the host's and the busier hart does at most 55 %.
    #[command(verbatim_doc_comment)]
    Cores {
        /// Do not install missing tools (rust targets, llvm-tools, apt-get packages)
        #[arg(long)]
        no_install: bool,
    },
    /// Speed against error for every benchmark scene and mode
    ///
    /// Builds and runs the report firmwares under QEMU (exact instructions per pixel
    /// on Cortex-M0+ and Cortex-M4F, target/report/mcu.tsv), then the host report
    /// (`host-tests` binary `report`, release): host ns per pixel (median, min, max
    /// of N runs of the scene's frames, default 7), errors against the f64
    /// reference and the 8x8 supersampled reference, Pareto fronts,
    /// recommendations. Writes target/report/report.md and one PNG plot per scene
    /// and target (target/report/*.png).
    #[command(verbatim_doc_comment)]
    Report(report::ReportArgs),
    /// Bake a power-of-two PNG into a Rust source file of RGB565 texels and their mip chain
    ///
    /// Bakes a power-of-two PNG (sides up to 4096) into a Rust source file: RGB565
    /// texels (rounded to nearest) and their mip chain (each texel the mean of the
    /// 8-bit pixels it covers, rounded once) as `pub static NAME_TEXELS`, with NAME_WIDTH,
    /// NAME_HEIGHT, NAME_LEVELS.
    #[command(verbatim_doc_comment)]
    Bake(bake::BakeArgs),
    /// Bake a 3D light map (fixel::shading::noise::LightMap3d) from point lights
    ///
    /// Bakes a 3D light map (fixel::shading::noise::LightMap3d) from point lights
    /// with inverse-square falloff (see xtask/src/light3d.rs). Texel (i, j, k)
    /// (x fastest) holds round(255 * min(1, A + sum of P / max(d^2, 1/16))), d the
    /// distance in lattice cells from its centre
    /// origin + (i + 0.5, j + 0.5, k + 0.5) * 2^(LOG2 - 16) to each light. The
    /// output also records the parameters (NAME_LIGHTS, NAME_AMBIENT).
    #[command(name = "bake-light3d", verbatim_doc_comment)]
    BakeLight3d(light3d::Light3dArgs),
    /// Bake a solid texture for a sphere's texture coordinates, or a flame layer, to a .bin
    ///
    /// Bakes the demonstration marble, wood or granite for a UV sphere's own texture
    /// coordinates (fixel::shading::noise::bake_mips: band-limited to each texel, every
    /// mip level from the pattern), or one layer of the flame from baked layers
    /// (bake_flame_layer), into little-endian u16 (RGB565 or Q15 turbulence): the
    /// format the firmware's build.rs writes. See xtask/src/bake_noise.rs.
    #[command(name = "bake-noise", verbatim_doc_comment)]
    BakeNoise(bake_noise::BakeNoiseArgs),
    /// Six cube-map faces from a 4:3 cross or a 6:1 strip (GL order) as Rust statics
    ///
    /// Six cube-map faces from a 4:3 cross or a 6:1 strip (GL order: +X -X +Y -Y
    /// +Z -Z) as `pub static NAME_FACES` and NAME_SIZE (fixel::shading::env);
    /// --mips adds NAME_MIPS (full chains, MipCubeMap), --irradiance and --glossy
    /// the convolved maps NAME_IRRADIANCE / NAME_GLOSSY (EnvLit).
    #[command(verbatim_doc_comment)]
    BakeCube(bake_cube::CubeArgs),
    /// A Wavefront OBJ model as static arrays in fixel's formats
    ///
    /// A Wavefront OBJ model as static arrays in fixel's formats (positions,
    /// normals, uvs, u16 triangles, tangent frames); prints the flash per array.
    /// Missing normals are generated (area-weighted, smooth), missing texture
    /// coordinates with fixel's own mapping (see xtask/src/bake_obj.rs).
    #[command(verbatim_doc_comment)]
    BakeObj(bake_obj::ObjArgs),
    /// A glTF 2.0 model (.glb/.gltf) as static arrays: its meshes and base-colour texture
    ///
    /// A glTF 2.0 model (.glb, or .gltf with its buffers and images) as static
    /// arrays in fixel's formats: every mesh primitive of the default scene,
    /// carried by its node's transform and welded into one mesh (positions,
    /// normals, uvs, u16 triangles, and vertex colours when the model has them),
    /// and the base-colour texture resized to power-of-two sides with its mip
    /// chain (RGB565, as `bake`). Skins and animations are not applied (the bind
    /// pose). Refuses non-triangle primitives, missing attributes, indices out of
    /// range and textures over --max-texture-kib, naming the part of the file
    /// (see xtask/src/bake_gltf.rs).
    #[command(name = "bake-gltf", verbatim_doc_comment)]
    BakeGltf(bake_gltf::GltfArgs),
    /// An RGB565 texture quantised to a 16- or 256-colour palette (4- or 8-bit indices)
    ///
    /// Quantises a power-of-two PNG, or fixel's benchmark texture (checker:WxH),
    /// with its mip chain (the RGB565 chain `bake` makes) to one RGB565 palette of
    /// 16 or 256 colours (median cut, then k-means; --dither for Floyd-Steinberg)
    /// and 4- or 8-bit indices in fixel::texture::PaletteMips's layout, as
    /// `pub static NAME_PALETTE` and `NAME_INDICES`. Prints the flash and the
    /// error against the RGB565 source (PSNR, largest channel error) per level,
    /// beside what a palette per level would reach (see xtask/src/bake_palette.rs).
    #[command(name = "bake-palette", verbatim_doc_comment)]
    BakePalette(bake_palette::PaletteArgs),
    /// Tessellate Newell's teapot patches (assets/teapot/newell.txt) into assets/teapot/teapot.obj
    ///
    /// Tessellates Newell's teapot patches (assets/teapot/newell.txt: 32 bicubic
    /// patches) into a Wavefront OBJ (assets/teapot/teapot.obj), the example model
    /// of `bake-obj`: welded, degenerate triangles dropped, y up, no normals or
    /// texture coordinates.
    #[command(verbatim_doc_comment)]
    Teapot(teapot::TeapotArgs),
    /// A displaced mesh as static arrays (the bake-obj format)
    ///
    /// A displaced mesh as static arrays (the bake-obj format): the demo sphere
    /// (coarse 12 x 24 or fine 24 x 48, radius 1.5) subdivided N times (default 1)
    /// and displaced by the rock height map with fixel::scene::displace (scale
    /// default 0.45, bias 0.5); or `water`, a 6 x 6-quad grid 4.8 units across
    /// displaced by the swell, whose heights the file also holds as NAME_HEIGHTS
    /// (with --scale 0, its default, the flat base of the firmware's `water` scene).
    #[command(verbatim_doc_comment)]
    BakeDisplaced(bake_displaced::DisplacedArgs),
    /// Random draws checked for panics, stray writes, depth-rule breaks and band mismatches
    ///
    /// Runs N random cases (default 400000) from SEED (default 1), built with the
    /// `ci` profile (overflow checks, debug assertions): each draws one random
    /// clip-space triangle with a random DrawMode (every projection, filter, wrap,
    /// shading, depth test, cull, mipmapping and level of detail) into a frame of
    /// random pixels with canaries around its buffers (depth cleared or kept), again
    /// through a random technique shader (typed span loop), in bands against the
    /// whole frame, and one random convex quad. Counts panics, writes outside the buffers
    /// or the viewport, pixels written against GL_LESS, band frames unequal to whole
    /// frames and implausible pictures; fails if any is non-zero and prints the
    /// first failing seed.
    #[command(verbatim_doc_comment)]
    Fuzz(fuzz::FuzzArgs),
}

fn main() -> ExitCode {
    match Cli::parse().command {
        Command::Ci(a) => ci::ci(&a),
        Command::Preview(a) => preview::preview(&a),
        Command::Package => match publish::check() {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("xtask package: {e}");
                ExitCode::FAILURE
            }
        },
        Command::Bless => images::bless(),
        Command::Render(a) => images::render(&a),
        Command::Count(a) => count::count(&a),
        Command::Fuzz(a) => fuzz::fuzz(&a),
        Command::Mcu(a) => mcu::mcu(&a),
        Command::Size(a) => mcu::size(&a),
        Command::Fps(a) => fps::fps(&a),
        Command::Budget(a) => budget::budget(&a),
        Command::Cores { no_install } => mcu::cores(!no_install),
        Command::Report(a) => report::report(&a),
        Command::BakeNoise(a) => match bake_noise::run(&a) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("cargo xtask bake-noise: {e}");
                ExitCode::from(1)
            }
        },
        Command::BakeLight3d(a) => match light3d::run(&a) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("cargo xtask bake-light3d: {e}");
                ExitCode::from(1)
            }
        },
        Command::Bake(a) => bake_status("bake", "cargo xtask bake", bake::run(&a)),
        Command::BakeObj(a) => bake_status("bake-obj", "bake-obj", bake_obj::run(&a)),
        Command::BakeGltf(a) => bake_status("bake-gltf", "bake-gltf", bake_gltf::run(&a)),
        Command::BakePalette(a) => {
            bake_status("bake-palette", "bake-palette", bake_palette::run(&a))
        }
        Command::BakeDisplaced(a) => {
            bake_status("bake-displaced", "bake-displaced", bake_displaced::run(&a))
        }
        Command::Teapot(a) => bake_status("teapot", "teapot", teapot::run(&a)),
        Command::BakeCube(a) => {
            bake_status("bake-cube", "cargo xtask bake-cube", bake_cube::run(&a))
        }
    }
}

/// The exit status of a bake command `cmd`: a usage error as clap reports one, a failure
/// as `{prefix}: {message}` (exit status 1).
fn bake_status(cmd: &str, prefix: &str, r: Result<(), bake::BakeError>) -> ExitCode {
    match r {
        Ok(()) => ExitCode::SUCCESS,
        Err(bake::BakeError::Usage(e)) => usage_error(cmd, e),
        Err(bake::BakeError::Failed(e)) => {
            eprintln!("{prefix}: {e}");
            ExitCode::FAILURE
        }
    }
}

/// A usage error found after parsing (it depends on the input, e.g. a PNG's size): printed
/// in clap's format with the usage of the subcommand `cmd`; exit status 2.
fn usage_error(cmd: &str, msg: impl Display) -> ExitCode {
    let mut top = Cli::command();
    top.build();
    let err = match top.find_subcommand_mut(cmd) {
        Some(sub) => sub.error(ErrorKind::ValueValidation, msg),
        None => top.error(ErrorKind::ValueValidation, msg),
    };
    let _ = err.print();
    ExitCode::from(2)
}

/// Parses `cargo xtask <args>` for the tests.
#[cfg(test)]
fn parse(args: &[&str]) -> Result<Command, clap::Error> {
    Cli::try_parse_from(std::iter::once("xtask").chain(args.iter().copied())).map(|c| c.command)
}
