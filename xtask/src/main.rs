//! `cargo xtask`: repository chores for fixel (CI, golden blessing, demo renders).
//!
//! Deliberately dependency-free so it builds in a second: argument parsing is
//! done by hand and every tool is driven through `std::process::Command`.

mod mcu;

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
const RENDER_EXAMPLES: [&str; 2] = ["showcase", "scenes"];

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
                  riscv32imc-unknown-none-elf.
                  --quick     skip the release-mode test run
                  --no-cross  skip the cross-target builds
    bless       Re-run host-tests with FIXEL_BLESS=1 (rewrites golden images),
                then show which goldens changed (git status host-tests/golden)
    render      Render the demo scenes (examples `showcase` and `scenes`, release)
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
    report      Generate the quality/perf report    [not implemented yet, issue 6]
    bake        Bake textures/meshes into Rust data [not implemented yet, issue 4]
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
        "mcu" => mcu::mcu(rest),
        "size" => mcu::size(rest),
        "report" => stub(cmd, 6),
        "bake" => stub(cmd, 4),
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

fn stub(cmd: &str, issue: u32) -> ExitCode {
    eprintln!("cargo xtask {cmd}: not implemented yet (issue {issue})");
    ExitCode::from(2)
}

// ---------------------------------------------------------------------------
// Command helpers
// ---------------------------------------------------------------------------

/// Workspace root (parent of this crate's manifest dir).
fn root() -> PathBuf {
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
