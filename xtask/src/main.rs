//! `cargo xtask`: repository chores for fixel (CI, golden blessing, demo renders).
//!
//! Nearly dependency-free so it builds in seconds: argument parsing is done by
//! hand and every tool is driven through `std::process::Command`; the one
//! dependency is the `png` decoder for `bake`.

mod bake;
mod bake_cube;
mod bake_displaced;
mod bake_obj;
mod light3d;

mod mcu;
mod teapot;

use std::env;
use std::ffi::OsString;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

/// Cross targets the library must build for without `std`.
const CROSS_TARGETS: [&str; 3] = [
    "thumbv6m-none-eabi",
    "thumbv7em-none-eabihf",
    "riscv32imc-unknown-none-elf",
];

/// Rustup components the CI steps need.
const COMPONENTS: [&str; 2] = ["rustfmt", "clippy"];

/// Examples run by `cargo xtask render`.
const RENDER_EXAMPLES: [&str; 13] = [
    "showcase",
    "scenes",
    "preview",
    "shadow",
    "noise",
    "envmap",
    "envmap_filtering",
    "mappings",
    "quads",
    "antialias",
    "transparency",
    "surface_detail",
    "displacement",
];

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
        "ci" => ci(rest),
        "bless" => no_flags("bless", rest).map_or_else(|e| e, |()| bless()),
        "render" => no_flags("render", rest).map_or_else(|e| e, |()| render()),
        "count" => count(rest),
        "mcu" => mcu::mcu(rest),
        "size" => mcu::size(rest),
        "report" => report(rest),
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

// ---------------------------------------------------------------------------
// Command helpers
// ---------------------------------------------------------------------------

/// Workspace root (parent of this crate's manifest dir).
pub(crate) fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives one level below the workspace root")
        .to_path_buf()
}

/// A command plus a human-readable rendering of it for headers and errors.
struct Cmd {
    cmd: Command,
    shown: String,
}

impl Cmd {
    fn new(program: impl Into<OsString>, shown_program: &str, args: &[&str]) -> Self {
        let mut cmd = Command::new(program.into());
        cmd.args(args).current_dir(root()).stdin(Stdio::null());
        let mut shown = shown_program.to_string();
        for a in args {
            shown.push(' ');
            shown.push_str(a);
        }
        Cmd { cmd, shown }
    }

    fn env(mut self, key: &str, val: impl Into<OsString>) -> Self {
        let val = val.into();
        self.shown = format!("{key}={} {}", val.to_string_lossy(), self.shown);
        self.cmd.env(key, val);
        self
    }

    /// Runs with inherited stdout/stderr; Err carries a readable message.
    fn run(mut self) -> Result<(), String> {
        match self.cmd.status() {
            Ok(s) if s.success() => Ok(()),
            Ok(s) => Err(format!("`{}` failed ({s})", self.shown)),
            Err(e) => Err(format!("could not start `{}`: {e}", self.shown)),
        }
    }

    /// Runs capturing stdout (stderr passes through).
    fn output(mut self) -> Result<String, String> {
        self.cmd.stderr(Stdio::inherit());
        match self.cmd.output() {
            Ok(o) if o.status.success() => Ok(String::from_utf8_lossy(&o.stdout).into_owned()),
            Ok(o) => Err(format!("`{}` failed ({})", self.shown, o.status)),
            Err(e) => Err(format!("could not start `{}`: {e}", self.shown)),
        }
    }
}

/// `cargo <args>`, using the same cargo that launched us when known.
fn cargo(args: &[&str]) -> Cmd {
    let program = env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    Cmd::new(program, "cargo", args)
}

fn rustup(args: &[&str]) -> Cmd {
    Cmd::new("rustup", "rustup", args)
}

fn fmt_dur(d: Duration) -> String {
    let s = d.as_secs_f64();
    if s < 60.0 {
        format!("{s:.1}s")
    } else {
        format!("{}m{:04.1}s", (s / 60.0).floor(), s % 60.0)
    }
}

// ---------------------------------------------------------------------------
// ci
// ---------------------------------------------------------------------------

type StepFn = Box<dyn FnOnce() -> Result<(), String>>;

struct Step {
    name: String,
    run: Option<StepFn>, // None = skipped
    skip_reason: &'static str,
}

fn step(name: impl Into<String>, f: impl FnOnce() -> Result<(), String> + 'static) -> Step {
    Step {
        name: name.into(),
        run: Some(Box::new(f)),
        skip_reason: "",
    }
}

fn skipped(name: impl Into<String>, reason: &'static str) -> Step {
    Step {
        name: name.into(),
        run: None,
        skip_reason: reason,
    }
}

fn ci(flags: &[String]) -> ExitCode {
    let mut quick = false;
    let mut no_cross = false;
    for f in flags {
        match f.as_str() {
            "--quick" => quick = true,
            "--no-cross" => no_cross = true,
            other => return usage_error(&format!("unknown flag for `ci`: `{other}`")),
        }
    }

    let mut steps = vec![
        step("toolchain", ensure_toolchain),
        step("fmt", || cargo(&["fmt", "--all", "--", "--check"]).run()),
        step("clippy", || {
            cargo(&[
                "clippy",
                "--workspace",
                "--all-targets",
                "--",
                "-D",
                "warnings",
            ])
            .run()
        }),
        step("test (debug)", || cargo(&["test", "--workspace"]).run()),
    ];
    steps.push(if quick {
        skipped("test (release)", "--quick")
    } else {
        step("test (release)", || {
            cargo(&["test", "--workspace", "--release"]).run()
        })
    });
    steps.push(step("doc", || {
        let mut flags = env::var("RUSTDOCFLAGS").unwrap_or_default();
        if !flags.is_empty() {
            flags.push(' ');
        }
        flags.push_str("-D warnings");
        cargo(&["doc", "-p", "fixel", "--no-deps"])
            .env("RUSTDOCFLAGS", flags)
            .run()
    }));
    for t in CROSS_TARGETS {
        let name = format!("build {t}");
        steps.push(if no_cross {
            skipped(name, "--no-cross")
        } else {
            step(name, move || {
                cargo(&["build", "-p", "fixel", "--release", "--target", t]).run()
            })
        });
    }

    // Firmware under QEMU: checksums must equal the host's (and the report is printed).
    steps.push(if no_cross {
        skipped("mcu (QEMU)", "--no-cross")
    } else {
        step("mcu (QEMU)", || {
            if mcu::mcu(&[]) == ExitCode::SUCCESS {
                Ok(())
            } else {
                Err("cargo xtask mcu failed (see above)".to_string())
            }
        })
    });

    let total = steps.len();
    let started = Instant::now();
    let mut results: Vec<(String, String, Option<Duration>)> = Vec::new();
    let mut failure: Option<(String, String)> = None;

    for (i, s) in steps.into_iter().enumerate() {
        let n = i + 1;
        if failure.is_some() {
            results.push((s.name, "not run".into(), None));
            continue;
        }
        let Some(f) = s.run else {
            println!(
                "\n==> [{n}/{total}] {}: skipped ({})",
                s.name, s.skip_reason
            );
            results.push((s.name, format!("skipped ({})", s.skip_reason), None));
            continue;
        };
        println!("\n==> [{n}/{total}] {}", s.name);
        let t0 = Instant::now();
        let r = f();
        let dt = t0.elapsed();
        match r {
            Ok(()) => {
                println!("==> [{n}/{total}] {}: ok in {}", s.name, fmt_dur(dt));
                results.push((s.name, "ok".into(), Some(dt)));
            }
            Err(msg) => {
                println!("==> [{n}/{total}] {}: FAILED after {}", s.name, fmt_dur(dt));
                results.push((s.name.clone(), "FAILED".into(), Some(dt)));
                failure = Some((s.name, msg));
            }
        }
    }

    print_summary(&results, started.elapsed());
    match failure {
        None => {
            println!("\nci: all steps passed");
            ExitCode::SUCCESS
        }
        Some((name, msg)) => {
            eprintln!("\nci: FAILED at step `{name}`: {msg}");
            ExitCode::FAILURE
        }
    }
}

fn print_summary(results: &[(String, String, Option<Duration>)], total: Duration) {
    let w = results.iter().map(|r| r.0.len()).max().unwrap_or(4).max(5);
    let mut out = String::new();
    let _ = writeln!(out, "\n==> ci summary");
    let _ = writeln!(out, "  {:<w$}  {:<20}  {:>9}", "step", "status", "time");
    let _ = writeln!(
        out,
        "  {}  {}  {}",
        "-".repeat(w),
        "-".repeat(20),
        "-".repeat(9)
    );
    for (name, status, dt) in results {
        let t = dt.map(fmt_dur).unwrap_or_else(|| "-".into());
        let _ = writeln!(out, "  {name:<w$}  {status:<20}  {t:>9}");
    }
    let _ = writeln!(
        out,
        "  {}  {}  {}",
        "-".repeat(w),
        "-".repeat(20),
        "-".repeat(9)
    );
    let _ = writeln!(out, "  {:<w$}  {:<20}  {:>9}", "total", "", fmt_dur(total));
    print!("{out}");
}

/// Step 1: make sure the cross targets and rustfmt/clippy are installed for
/// the active (pinned) toolchain.
fn ensure_toolchain() -> Result<(), String> {
    if Command::new("rustup")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_err()
    {
        println!(
            "warning: `rustup` not found; cannot check targets/components \
             (the fmt/clippy/cross steps will fail if they are missing)"
        );
        return Ok(());
    }

    let installed = rustup(&["target", "list", "--installed"]).output()?;
    let missing: Vec<&str> = CROSS_TARGETS
        .iter()
        .copied()
        .filter(|t| !installed.lines().any(|l| l.trim() == *t))
        .collect();
    if missing.is_empty() {
        println!("targets: all installed ({})", CROSS_TARGETS.join(", "));
    } else {
        println!("targets: installing {}", missing.join(", "));
        let mut args = vec!["target", "add"];
        args.extend(&missing);
        rustup(&args).run()?;
    }

    let installed = rustup(&["component", "list", "--installed"]).output()?;
    let missing: Vec<&str> = COMPONENTS
        .iter()
        .copied()
        .filter(|c| {
            !installed.lines().any(|l| {
                let l = l.trim();
                l == *c || l.strip_prefix(c).is_some_and(|r| r.starts_with('-'))
            })
        })
        .collect();
    if missing.is_empty() {
        println!("components: all installed ({})", COMPONENTS.join(", "));
    } else {
        println!("components: installing {}", missing.join(", "));
        let mut args = vec!["component", "add"];
        args.extend(&missing);
        rustup(&args).run()?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// bless
// ---------------------------------------------------------------------------

fn bless() -> ExitCode {
    println!("==> FIXEL_BLESS=1 cargo test -p host-tests (golden images will be rewritten)");
    let test = cargo(&["test", "-p", "host-tests"])
        .env("FIXEL_BLESS", "1")
        .run();
    if let Err(msg) = &test {
        eprintln!("\nbless: {msg}\n(goldens may still have been rewritten; see below)");
    }

    println!("\n==> git status --short --untracked-files=all host-tests/golden");
    match Cmd::new(
        "git",
        "git",
        &[
            "status",
            "--short",
            "--untracked-files=all",
            "--",
            "host-tests/golden",
        ],
    )
    .output()
    {
        Ok(s) if s.trim().is_empty() => println!("(no golden images changed)"),
        Ok(s) => {
            print!("{s}");
            println!(
                "\nReview every changed golden against the float reference \
                 (e.g. `git diff --stat host-tests/golden`, open the images) \
                 BEFORE committing them."
            );
        }
        Err(msg) => eprintln!("bless: could not list changed goldens: {msg}"),
    }

    if test.is_ok() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}

// ---------------------------------------------------------------------------
// render
// ---------------------------------------------------------------------------

/// Whether the root package has an example named `name` (auto-discovered file
/// or an explicit `[[example]]` entry).
fn example_exists(name: &str) -> bool {
    let root = root();
    let ex = root.join("examples");
    if ex.join(format!("{name}.rs")).is_file() || ex.join(name).join("main.rs").is_file() {
        return true;
    }
    let manifest = std::fs::read_to_string(root.join("Cargo.toml")).unwrap_or_default();
    let mut in_example = false;
    for line in manifest.lines().map(str::trim) {
        if line.starts_with('[') {
            in_example = line == "[[example]]";
        } else if in_example {
            let compact: String = line.chars().filter(|c| !c.is_whitespace()).collect();
            if compact == format!("name=\"{name}\"") {
                return true;
            }
        }
    }
    false
}

fn render() -> ExitCode {
    let mut ok = true;
    for name in RENDER_EXAMPLES {
        println!("\n==> cargo run --release -p fixel --example {name}");
        if !example_exists(name) {
            eprintln!(
                "render: example `{name}` does not exist yet \
                 (expected examples/{name}.rs in the fixel package); skipping"
            );
            ok = false;
            continue;
        }
        let t0 = Instant::now();
        match cargo(&["run", "--release", "-p", "fixel", "--example", name]).run() {
            Ok(()) => println!("==> {name}: ok in {}", fmt_dur(t0.elapsed())),
            Err(msg) => {
                eprintln!("render: {msg}");
                ok = false;
            }
        }
    }
    if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}

// ---------------------------------------------------------------------------
// count
// ---------------------------------------------------------------------------

/// Cargo's target directory (`CARGO_TARGET_DIR` or `<root>/target`).
fn target_dir() -> PathBuf {
    match env::var_os("CARGO_TARGET_DIR") {
        Some(d) if !d.is_empty() => {
            let d = PathBuf::from(d);
            if d.is_absolute() {
                d
            } else {
                root().join(d)
            }
        }
        _ => root().join("target"),
    }
}

/// One case's result: drawn pixels and instructions, both net of the baseline.
struct Counted {
    id: String,
    frames: u32,
    pixels: u64,
    instructions: u64,
}

/// The `key N` line printed by `count_scene` (`frames`, `pixels`).
fn parse_line(stdout: &str, key: &str) -> Option<u64> {
    stdout
        .lines()
        .find_map(|l| l.strip_prefix(key)?.strip_prefix(' '))
        .and_then(|n| n.trim().parse().ok())
}

/// Total `Ir` from a callgrind output file: its `totals:` line, else `summary:`.
fn parse_ir(file: &Path) -> Result<u64, String> {
    let text = std::fs::read_to_string(file)
        .map_err(|e| format!("could not read {}: {e}", file.display()))?;
    let find = |key: &str| {
        text.lines()
            .find_map(|l| l.strip_prefix(key))
            .and_then(|v| v.split_whitespace().next())
            .and_then(|v| v.parse::<u64>().ok())
    };
    find("totals:")
        .or_else(|| find("summary:"))
        .ok_or_else(|| format!("no `totals:`/`summary:` line in {}", file.display()))
}

/// Runs `count_scene <id> [frames]` under callgrind (no frame count: the scene's N);
/// returns (frames, pixels, Ir).
fn callgrind(
    bin: &Path,
    out_dir: &Path,
    id: &str,
    frames: Option<u32>,
) -> Result<(u32, u64, u64), String> {
    let tag = frames.map_or_else(|| "n".to_string(), |n| n.to_string());
    let out = out_dir.join(format!("{}-{tag}.out", id.replace('/', "-")));
    let out_arg = format!("--callgrind-out-file={}", out.display());
    let bin_arg = bin.to_string_lossy();
    let mut args = vec!["--tool=callgrind", "--quiet", &out_arg, &bin_arg, id];
    let frames_arg = frames.map(|n| n.to_string());
    args.extend(frames_arg.as_deref());
    let stdout = Cmd::new("valgrind", "valgrind", &args).output()?;
    let missing = |key: &str| format!("count_scene {id}: no `{key}` line in its output");
    let n = parse_line(&stdout, "frames").ok_or_else(|| missing("frames"))?;
    let pixels = parse_line(&stdout, "pixels").ok_or_else(|| missing("pixels"))?;
    Ok((n as u32, pixels, parse_ir(&out)?))
}

fn count_table(rows: &[Counted]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "| scene | mode | frames | pixels drawn / frame | instructions / frame | instructions / pixel |"
    );
    let _ = writeln!(s, "|---|---|---:|---:|---:|---:|");
    for r in rows {
        let (scene, mode) = r.id.split_once('/').unwrap_or((&r.id, ""));
        let f = f64::from(r.frames.max(1));
        let _ = writeln!(
            s,
            "| {scene} | {mode} | {} | {:.0} | {:.0} | {:.1} |",
            r.frames,
            r.pixels as f64 / f,
            r.instructions as f64 / f,
            r.instructions as f64 / r.pixels.max(1) as f64,
        );
    }
    s
}

fn count(flags: &[String]) -> ExitCode {
    let mut frames: Option<u32> = None;
    let mut filters: Vec<&str> = Vec::new();
    let mut it = flags.iter();
    while let Some(f) = it.next() {
        match f.as_str() {
            "--frames" => match it.next().map(|n| n.parse::<u32>()) {
                Some(Ok(n)) if n > 0 => frames = Some(n),
                _ => return usage_error("`--frames` needs a positive number"),
            },
            other if other.starts_with('-') => {
                return usage_error(&format!("unknown flag for `count`: `{other}`"))
            }
            other => filters.push(other),
        }
    }
    if Command::new("valgrind")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_err()
    {
        eprintln!("count: `valgrind` not found (apt-get install valgrind)");
        return ExitCode::FAILURE;
    }

    println!("==> cargo build --release -p fixel --example count_scene");
    if let Err(msg) = cargo(&[
        "build",
        "--release",
        "-p",
        "fixel",
        "--example",
        "count_scene",
    ])
    .run()
    {
        eprintln!("count: {msg}");
        return ExitCode::FAILURE;
    }
    let target = target_dir();
    let bin = target.join("release").join("examples").join("count_scene");
    let out_dir = target.join("callgrind");
    if let Err(e) = std::fs::create_dir_all(&out_dir) {
        eprintln!("count: could not create {}: {e}", out_dir.display());
        return ExitCode::FAILURE;
    }
    let list = match Cmd::new(&bin, "count_scene", &["--list"]).output() {
        Ok(l) => l,
        Err(msg) => {
            eprintln!("count: {msg}");
            return ExitCode::FAILURE;
        }
    };
    let cases: Vec<&str> = list
        .lines()
        .map(str::trim)
        .filter(|id| !id.is_empty())
        .filter(|id| filters.is_empty() || filters.iter().any(|f| id.contains(f)))
        .collect();
    if cases.is_empty() {
        return usage_error("no case matches the filter (see `count_scene --list`)");
    }

    let mut rows = Vec::new();
    for id in cases {
        let t0 = Instant::now();
        let run = callgrind(&bin, &out_dir, id, Some(0)).and_then(|(_, _, base)| {
            callgrind(&bin, &out_dir, id, frames)
                .map(|(n, pixels, ir)| (n, pixels, ir.saturating_sub(base)))
        });
        match run {
            Ok((n, pixels, instructions)) => {
                println!(
                    "==> {id}: {n} frames, {pixels} pixels, {instructions} instructions \
                     ({:.1} / pixel) in {}",
                    instructions as f64 / pixels.max(1) as f64,
                    fmt_dur(t0.elapsed())
                );
                rows.push(Counted {
                    id: id.to_string(),
                    frames: n,
                    pixels,
                    instructions,
                });
            }
            Err(msg) => {
                eprintln!("count: {msg}");
                return ExitCode::FAILURE;
            }
        }
    }

    let report = format!(
        "# fixel: x86_64 instructions per drawn pixel (callgrind `Ir`)\n\n\
         320 x 240 RGB565, 16-bit depth; release build of `examples/count_scene.rs`. \
         Instructions for all frames (clear, transform, set-up, spans) minus a 0-frame \
         baseline (process start, texture, mesh, draw set-up); pixels are those that \
         passed the depth test.\n\n{}",
        count_table(&rows)
    );
    println!("\n{report}");
    let path = target.join("instructions-x86.md");
    match std::fs::write(&path, &report) {
        Ok(()) => {
            println!("written to {}", path.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("count: could not write {}: {e}", path.display());
            ExitCode::FAILURE
        }
    }
}

// ---------------------------------------------------------------------------
// report
// ---------------------------------------------------------------------------

fn report(flags: &[String]) -> ExitCode {
    let (mut runs, mut mcu_on, mut install, mut docs) = (7u32, true, true, false);
    let mut it = flags.iter();
    while let Some(f) = it.next() {
        match f.as_str() {
            "--runs" => match it.next().map(|n| n.parse::<u32>()) {
                Some(Ok(n)) if n > 0 => runs = n,
                _ => return usage_error("`--runs` needs a positive number"),
            },
            "--no-mcu" => mcu_on = false,
            "--no-install" => install = false,
            "--docs" => docs = true,
            other => return usage_error(&format!("unknown flag for `report`: `{other}`")),
        }
    }
    let t0 = Instant::now();
    let out = target_dir().join("report");
    if let Err(e) = std::fs::create_dir_all(&out) {
        eprintln!("report: could not create {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    let tsv = out.join("mcu.tsv");
    let _ = std::fs::remove_file(&tsv);
    if mcu_on {
        println!("==> report 1/2: microcontrollers (QEMU)");
        let mut step = |s: &str| println!("==> {s} ({})", fmt_dur(t0.elapsed()));
        match mcu::report_mcu(install, &tsv, &mut step) {
            Ok(v) => println!(
                "==> {} mode counts written to {} ({})",
                v.len(),
                tsv.display(),
                fmt_dur(t0.elapsed())
            ),
            Err(e) => {
                eprintln!("report: {e}");
                return ExitCode::FAILURE;
            }
        }
    }
    println!("==> report 2/2: host (timing, errors, plots)");
    let out_s = out.to_string_lossy().into_owned();
    let tsv_s = tsv.to_string_lossy().into_owned();
    let runs_s = runs.to_string();
    let mut args = vec![
        "run",
        "--release",
        "-q",
        "-p",
        "host-tests",
        "--bin",
        "report",
        "--",
        "--out",
        &out_s,
        "--runs",
        &runs_s,
    ];
    if mcu_on {
        args.extend(["--mcu", &tsv_s]);
    }
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Shadow maps: their rows in shadow.md (host-tests/src/bin/shadow_report.rs).
    let shadow = [
        "run",
        "--release",
        "-q",
        "-p",
        "host-tests",
        "--bin",
        "shadow_report",
    ];
    let shadow_mcu: &[&str] = if mcu_on { &["--mcu", &tsv_s] } else { &[] };
    if let Err(e) = cargo(&[&shadow[..], &["--", "--out", &out_s], shadow_mcu].concat()).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Solid textures: their own report, same output directory and MCU counts.
    args[6] = "noise_report";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Environment mapping rows: same flags, written to env.md.
    args[6] = "report_env";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Texture-coordinate generation rows: same flags, written to mapping.md.
    args[6] = "mapping_report";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Anti-aliasing rows: same flags, written to aa.md.
    args[6] = "aa_report";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Surface-detail rows (per-pixel lighting, bump, normal maps): surface.md.
    args[6] = "surface_report";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    if docs {
        let dst = root().join("docs").join("report");
        let copied = std::fs::create_dir_all(&dst).and_then(|()| {
            for e in std::fs::read_dir(&out)? {
                let p = e?.path();
                let ext = p.extension().and_then(|x| x.to_str());
                if matches!(ext, Some("md" | "png")) {
                    std::fs::copy(&p, dst.join(p.file_name().unwrap_or_default()))?;
                }
            }
            Ok(())
        });
        match copied {
            Ok(()) => println!("==> copied report.md and the plots to {}", dst.display()),
            Err(e) => {
                eprintln!("report: could not copy to {}: {e}", dst.display());
                return ExitCode::FAILURE;
            }
        }
    }
    println!(
        "==> report done in {}: {} and the plots {}/*.png",
        fmt_dur(t0.elapsed()),
        out.join("report.md").display(),
        out.display()
    );
    ExitCode::SUCCESS
}
