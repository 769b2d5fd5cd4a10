//! The commands that write images: `cargo xtask bless` (host-tests' golden images) and
//! `cargo xtask render` (the demo scenes, to target/pictures/).

use std::process::ExitCode;
use std::time::Instant;

use crate::cmd::{cargo, fmt_dur, root, Cmd};

/// Examples run by `cargo xtask render`.
const RENDER_EXAMPLES: [&str; 16] = [
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
    "models",
    // The real-time modes beside the accurate ones.
    "realtime",
    // Last: composes the README's gallery from the pictures above.
    "gallery",
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

/// Flags of `cargo xtask render`.
#[derive(clap::Args, Clone, Debug)]
pub(crate) struct RenderArgs {
    /// Then copy into docs/images every picture there whose pixels changed
    #[arg(long, conflicts_with = "check")]
    pub docs: bool,
    /// Then fail if a picture in docs/images differs from what the code draws now
    #[arg(long)]
    pub check: bool,
    /// Cargo profile of the examples (CI renders with `ci`, whose build the tests share:
    /// the pixels are the same in every profile)
    #[arg(long, default_value = "release")]
    pub profile: String,
}

pub(crate) fn render(args: &RenderArgs) -> ExitCode {
    let t0 = Instant::now();
    let names: Vec<&str> = RENDER_EXAMPLES
        .iter()
        .copied()
        .filter(|name| {
            let there = example_exists(name);
            if !there {
                eprintln!("render: example `{name}` does not exist (examples/{name}.rs); skipped");
            }
            there
        })
        .collect();
    // One build of every example first, with cargo's own progress (the first build of a
    // fresh checkout takes a minute or two), then each run in turn.
    println!(
        "==> [build] the {} demo examples, profile {} (cargo's progress follows)",
        names.len(),
        args.profile
    );
    let mut build = vec!["build", "--profile", &args.profile, "-p", "fixel"];
    for name in &names {
        build.extend(["--example", name]);
    }
    if let Err(msg) = cargo(&build).run() {
        eprintln!("render: {msg}");
        return ExitCode::FAILURE;
    }
    println!("==> [build] done in {}", fmt_dur(t0.elapsed()));
    let mut ok = names.len() == RENDER_EXAMPLES.len();
    for (k, name) in names.iter().enumerate() {
        println!("\n==> [{}/{}] {name}", k + 1, names.len());
        let t = Instant::now();
        let run = [
            "run",
            "-q",
            "--profile",
            &args.profile,
            "-p",
            "fixel",
            "--example",
            name,
        ];
        match cargo(&run).run() {
            Ok(()) => println!("==> {name}: ok in {}", fmt_dur(t.elapsed())),
            Err(msg) => {
                eprintln!("render: {msg}");
                ok = false;
            }
        }
    }
    println!("\n==> rendered in {}", fmt_dur(t0.elapsed()));
    if ok && (args.docs || args.check) {
        println!("\n==> docs/images against the fresh render (decoded pixels)");
        match crate::pictures::check_docs(args.docs) {
            Ok(changed) if changed.is_empty() => println!("docs/images: every picture is current"),
            Ok(changed) if args.docs => println!(
                "docs/images: {} updated ({}); review them before committing",
                changed.len(),
                changed.join(", ")
            ),
            Ok(changed) => {
                eprintln!(
                    "render --check: {} picture(s) in docs/images differ from what the code \
                     draws: {}. Run `cargo xtask render --docs`, look at them, commit them.",
                    changed.len(),
                    changed.join(", ")
                );
                ok = false;
            }
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
