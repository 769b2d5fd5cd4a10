//! `cargo xtask ci`: the check steps (toolchain, fmt, clippy, tests, fuzz, the pictures of
//! docs/images, docs, the dry-run publish, the preview window under Xvfb, cross builds, the
//! board examples' builds, firmware clippy, `mcu`), run fail-fast, and the summary table.

use std::env;
use std::fmt::Write as _;
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

use clap::Args;

use crate::cmd::{cargo, fmt_dur, rustup};
use crate::{images, mcu, preview, publish};

/// Cross targets the library must build for without `std`.
const CROSS_TARGETS: [&str; 3] = [
    "thumbv6m-none-eabi",
    "thumbv7em-none-eabihf",
    "riscv32imc-unknown-none-elf",
];

/// The board examples (crates of their own, outside the workspace) and their targets: built,
/// not run. Each builds its HAL from scratch on a fresh machine (about 3 minutes each).
const BOARDS: [(&str, &str); 2] = [
    ("rp2040", "thumbv6m-none-eabi"),
    ("esp32c3", "riscv32imc-unknown-none-elf"),
];

/// The target the firmware clippy step checks every firmware binary for.
const FIRMWARE_TARGET: &str = "thumbv7em-none-eabihf";

/// Rustup components the CI steps need.
const COMPONENTS: [&str; 2] = ["rustfmt", "clippy"];

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

/// Flags of `cargo xtask ci`.
#[derive(Args, Clone, Debug)]
pub(crate) struct CiArgs {
    /// Skip the cross-target builds and `mcu`
    #[arg(long)]
    pub no_cross: bool,
    /// Skip the preview window's check (Xvfb, SDL2)
    #[arg(long)]
    pub no_preview: bool,
}

pub(crate) fn ci(args: &CiArgs) -> ExitCode {
    let CiArgs {
        no_cross,
        no_preview,
    } = *args;

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
        // One optimized build with a debug build's checks (`[profile.ci]`): CI once built
        // and ran every test twice, in debug and in release.
        step("test (ci profile)", || {
            cargo(&["test", "--workspace", "--profile", "ci"]).run()
        }),
        step("fuzz", || crate::fuzz::run(crate::fuzz::CI_CASES, 1)),
    ];
    // The pictures of docs/images are what the code draws (decoded pixels), rendered with
    // the tests' build.
    steps.push(step("pictures", || {
        let args = images::RenderArgs {
            docs: false,
            check: true,
            profile: "ci".to_string(),
        };
        if images::render(&args) == ExitCode::SUCCESS {
            Ok(())
        } else {
            Err("cargo xtask render --check --profile ci failed (see above)".to_string())
        }
    }));
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
    // What crates.io would get: packaged, built from the package, at most 1 MiB, and its
    // docs built for thumbv7em as docs.rs builds them.
    steps.push(step("publish (dry run)", publish::check));
    // The desktop window under Xvfb: keys pressed, screenshots equal to the frames' PNGs.
    steps.push(if no_preview {
        skipped("preview window (Xvfb)", "--no-preview")
    } else {
        step("preview window (Xvfb)", || {
            let args = preview::PreviewArgs {
                check: true,
                ..preview::PreviewArgs::default()
            };
            if preview::preview(&args) == ExitCode::SUCCESS {
                Ok(())
            } else {
                Err("cargo xtask preview --check failed (see above)".to_string())
            }
        })
    });
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

    // The board examples (RP2040 on two cores, ESP32-C3 with the async frame) build with
    // their pinned HALs.
    for (board, t) in BOARDS {
        let name = format!("build examples/{board}");
        steps.push(if no_cross {
            skipped(name, "--no-cross")
        } else {
            step(name, move || {
                cargo(&["build", "--release", "--target", t])
                    .in_dir(&format!("examples/{board}"))
                    .run()
            })
        });
    }

    // Every firmware binary compiles, lint-clean: `mcu` builds only the ones it runs (the
    // `report_*` and `size_*` ones are built by `cargo xtask report` and `size`).
    steps.push(if no_cross {
        skipped("firmware clippy", "--no-cross")
    } else {
        step("firmware clippy", || {
            let lint = ["clippy", "--release", "--bins", "--target", FIRMWARE_TARGET];
            let deny = ["--", "-D", "warnings"];
            cargo(&[&lint[..], &deny[..]].concat())
                .in_dir("examples/firmware")
                .run()?;
            let whole = ["--features", "whole,smp", "--target-dir", "target/whole"];
            cargo(&[&lint[..], &whole[..], &deny[..]].concat())
                .in_dir("examples/firmware")
                .env("FIXEL_FW_MEMORY", "whole")
                .run()
        })
    });

    // Firmware under QEMU: checksums must equal the host's (and the report is printed).
    steps.push(if no_cross {
        skipped("mcu (QEMU)", "--no-cross")
    } else {
        step("mcu (QEMU)", || {
            if mcu::mcu(&mcu::McuArgs::default()) == ExitCode::SUCCESS {
                Ok(())
            } else {
                Err("cargo xtask mcu failed (see above)".to_string())
            }
        })
    });

    // One frame on two cores (RISC-V virt -smp 2): per-hart counts, checksums, balance.
    steps.push(if no_cross {
        skipped("cores (QEMU, two harts)", "--no-cross")
    } else {
        step("cores (QEMU, two harts)", || {
            if mcu::cores(true) == ExitCode::SUCCESS {
                Ok(())
            } else {
                Err("cargo xtask cores failed (see above)".to_string())
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
