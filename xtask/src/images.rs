//! The commands that write images: `cargo xtask bless` (host-tests' golden images) and
//! `cargo xtask render` (the demo scenes, to target/pictures/).

use std::process::ExitCode;
use std::time::Instant;

use crate::cmd::{cargo, fmt_dur, root, Cmd};

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

pub(crate) fn bless() -> ExitCode {
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

pub(crate) fn render() -> ExitCode {
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
