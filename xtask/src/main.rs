//! `cargo xtask`: repository chores for fixel (CI, golden blessing, demo renders).
//!
//! Nearly dependency-free so it builds in seconds: argument parsing is done by
//! hand and every tool is driven through `std::process::Command`; the one
//! dependency is the `png` decoder for `bake`.

mod bake;
mod bake_cube;
mod bake_displaced;
mod bake_obj;
mod ci;
mod cmd;
mod count;
mod images;
mod light3d;
mod mcu;
mod report;
mod teapot;

use std::env;
use std::process::ExitCode;

const HELP: &str = "\
cargo xtask: repository chores for fixel

USAGE:
    cargo xtask <COMMAND> [FLAGS]

COMMANDS:
    ci [--quick] [--no-cross]
                Run the full check suite, failing fast:
                  toolchain targets/components, fmt, clippy, test (debug),
                  test (release), docs (-D warnings), no_std cross builds for
                  thumbv6m-none-eabi, thumbv7em-none-eabihf,
                  riscv32imc-unknown-none-elf, then `mcu` (firmware under QEMU:
                  checksums must equal the host's; prints the report).
                  --quick     skip the release-mode test run
                  --no-cross  skip the cross-target builds and `mcu`
    bless       Re-run host-tests with FIXEL_BLESS=1 (rewrites golden images),
                then show which goldens changed (git status host-tests/golden)
    render      Render the demo scenes (examples `showcase`, `scenes`, `preview` and
                `shadow`, `noise` and `envmap`, release) to target/pictures/*.png
    count [--frames N] [FILTER...]
                Exact x86_64 instructions per drawn pixel of the benchmark
                scenes and modes: builds the `count_scene` example (release),
                runs each case under `valgrind --tool=callgrind`, subtracts a
                0-frame baseline (texture, mesh, draw set-up) and prints a
                Markdown table, also saved to target/instructions-x86.md.
                Callgrind files stay in target/callgrind/ (for
                `callgrind_annotate --auto=yes`).
                  --frames N  frames per case (default: the scene's N)
                  FILTER      only cases whose `scene/mode` id contains it
    mcu [--runs N] [--profile] [--opt-s] [--no-install]
                Build the firmware examples (examples/firmware) for Cortex-M4F,
                Cortex-M0+ and RV32IMC, run each scene under QEMU with an
                instruction-counting plugin (N runs, default 2, must agree),
                check each frame checksum against the host's, and print
                instructions/pixel, estimated cycles/pixel, flash and RAM.
                Installs missing rust targets, llvm-tools and (apt-get)
                qemu-system-arm/qemu-system-misc/gcc/python3.
                  --profile  where the instructions go, per function
                  --opt-s    also report flash at opt-level s
    size [--opt-s] [--no-install]
                Flash and RAM of a minimal firmware per feature set
    report [--runs N] [--no-mcu] [--no-install] [--docs]
                Speed against error for every benchmark scene and mode:
                builds and runs the report firmwares under QEMU (exact instructions
                per pixel on Cortex-M0+ and Cortex-M4F, target/report/mcu.tsv), then
                the host report (`host-tests` binary `report`, release): host ns per
                pixel (median, min, max of N runs of the scene's frames, default 7),
                errors against the f64 reference and the 8x8 supersampled reference,
                Pareto fronts, recommendations. Writes target/report/report.md and one
                PNG plot per scene and target (target/report/*.png).
                  --no-mcu      host only (no QEMU columns)
                  --no-install  do not install missing tools (see `mcu`)
                  --docs        also copy report.md and the plots to docs/report/
    bake <input.png> <output.rs> [--name NAME] [--levels N|full] [--rgb565 PATH]
                Bake a power-of-two PNG into a Rust source file: RGB565 texels
                (rounded to nearest) and their mip chain (2x2 box filter, the
                same as fixel's generate_mips) as `pub static NAME_TEXELS`,
                with NAME_WIDTH, NAME_HEIGHT, NAME_LEVELS. NAME defaults to the
                file stem in upper case; --levels defaults to full (down to
                1x1); --rgb565 is the path of the colour type in the output
                (default embedded_graphics_core::pixelcolor::Rgb565)
    bake-light3d <output.rs> [--side N] [--origin X,Y,Z] [--texel LOG2] [--ambient A]
                 --light X,Y,Z,P [--light ...] [--name NAME]
                Bake a 3D light map (fixel::shading::noise::LightMap3d) from point
                lights with inverse-square falloff (see xtask/src/light3d.rs)
    bake-cube <input.png> <output.rs> [--name NAME] [--rgb565 PATH] [--mips]
              [--irradiance SIZE] [--glossy EXPONENT[:SIZE]]
                Six cube-map faces from a 4:3 cross or a 6:1 strip (GL order)
                as `pub static NAME_FACES` and NAME_SIZE (fixel::shading::env);
                --mips adds NAME_MIPS (full chains, MipCubeMap), --irradiance and
                --glossy the convolved maps NAME_IRRADIANCE / NAME_GLOSSY (EnvLit)
    bake-obj <input.obj> <output.rs> [--name NAME] [--uv keep|spherical|cylindrical|planar]
                 [--axis x|y|z] [--normals keep|smooth] [--tangents] [--scale S]
                A Wavefront OBJ model as static arrays in fixel's formats (positions,
                normals, uvs, u16 triangles, tangent frames); prints the flash per array
    teapot      Tessellates Newell's teapot patches (assets/teapot/newell.txt) into
                assets/teapot/teapot.obj
    bake-displaced <output.rs> [--sphere coarse|fine] [--levels N] [--scale S]
                 [--bias B] [--name NAME]
                A displaced mesh as static arrays (the bake-obj format): the demo
                sphere (coarse 12 x 24 or fine 24 x 48) subdivided N times (default 1)
                and displaced by the rock height map with fixel::scene::displace
                (scale default 0.45, bias 0.5)
    help        Print this help

Exit status: 0 on success, 1 when a step fails, 2 on usage errors and for
commands that are not implemented yet.
";

fn main() -> ExitCode {
    let args: Vec<String> = env::args().skip(1).collect();
    let (cmd, rest) = match args.split_first() {
        Some((c, r)) => (c.as_str(), r),
        None => {
            eprint!("{HELP}");
            return ExitCode::from(2);
        }
    };
    if rest.iter().any(|a| a == "-h" || a == "--help") {
        print!("{HELP}");
        return ExitCode::SUCCESS;
    }
    match cmd {
        "help" | "-h" | "--help" => {
            print!("{HELP}");
            ExitCode::SUCCESS
        }
        "ci" => ci::ci(rest),
        "bless" => no_flags("bless", rest).map_or_else(|e| e, |()| images::bless()),
        "render" => no_flags("render", rest).map_or_else(|e| e, |()| images::render()),
        "count" => count::count(rest),
        "mcu" => mcu::mcu(rest),
        "size" => mcu::size(rest),
        "report" => report::report(rest),
        "bake-light3d" => match light3d::run(rest) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("cargo xtask bake-light3d: {e}");
                ExitCode::from(1)
            }
        },
        "bake" => match bake::run(rest) {
            Ok(()) => ExitCode::SUCCESS,
            Err(bake::BakeError::Usage(e)) => usage_error(&format!("bake: {e}")),
            Err(bake::BakeError::Failed(e)) => {
                eprintln!("cargo xtask bake: {e}");
                ExitCode::from(1)
            }
        },
        "bake-obj" => match bake_obj::run(rest) {
            Ok(()) => ExitCode::SUCCESS,
            Err(bake::BakeError::Usage(e)) => usage_error(&format!("bake-obj: {e}")),
            Err(bake::BakeError::Failed(e)) => {
                eprintln!("bake-obj: {e}");
                ExitCode::FAILURE
            }
        },
        "bake-displaced" => match bake_displaced::run(rest) {
            Ok(()) => ExitCode::SUCCESS,
            Err(bake::BakeError::Usage(e)) => usage_error(&format!("bake-displaced: {e}")),
            Err(bake::BakeError::Failed(e)) => {
                eprintln!("bake-displaced: {e}");
                ExitCode::FAILURE
            }
        },
        "teapot" => match teapot::run(rest) {
            Ok(()) => ExitCode::SUCCESS,
            Err(bake::BakeError::Usage(e)) => usage_error(&format!("teapot: {e}")),
            Err(bake::BakeError::Failed(e)) => {
                eprintln!("teapot: {e}");
                ExitCode::FAILURE
            }
        },
        "bake-cube" => match bake_cube::run(rest) {
            Ok(()) => ExitCode::SUCCESS,
            Err(bake::BakeError::Usage(e)) => usage_error(&format!("bake-cube: {e}")),
            Err(bake::BakeError::Failed(e)) => {
                eprintln!("cargo xtask bake-cube: {e}");
                ExitCode::from(1)
            }
        },
        other => usage_error(&format!("unknown command `{other}`")),
    }
}

fn usage_error(msg: &str) -> ExitCode {
    eprintln!("error: {msg}\n\nRun `cargo xtask help` for the list of commands.");
    ExitCode::from(2)
}

fn no_flags(cmd: &str, rest: &[String]) -> Result<(), ExitCode> {
    match rest.first() {
        None => Ok(()),
        Some(a) => Err(usage_error(&format!(
            "`{cmd}` takes no arguments (got `{a}`)"
        ))),
    }
}
