//! `cargo xtask count`: exact x86_64 instructions per drawn pixel of the benchmark
//! scenes, counted with callgrind (net of a 0-frame baseline) and tabulated.

use std::fmt::Write as _;
use std::path::Path;
use std::process::{Command, ExitCode, Stdio};
use std::time::Instant;

use clap::Args;

use crate::cmd::{cargo, fmt_dur, target_dir, Cmd};
use crate::usage_error;

/// Flags of `cargo xtask count`.
#[derive(Args, Clone, Debug)]
pub(crate) struct CountArgs {
    /// Frames per case [default: the scene's N]
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub frames: Option<u32>,
    /// Only cases whose `scene/mode` id contains one of these (`count_scene --list`); a
    /// `scene/mode` id that is not listed is counted as named
    #[arg(value_name = "FILTER")]
    pub filters: Vec<String>,
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

pub(crate) fn count(args: &CountArgs) -> ExitCode {
    let (frames, filters) = (args.frames, &args.filters);
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
    let listed: Vec<&str> = list
        .lines()
        .map(str::trim)
        .filter(|id| !id.is_empty())
        .collect();
    let mut cases: Vec<&str> = listed
        .iter()
        .copied()
        .filter(|id| filters.is_empty() || filters.iter().any(|f| id.contains(f.as_str())))
        .collect();
    // A `scene/mode` filter that matches no listed case names a case of its own (any mode
    // can be counted, for example `sphere/lit-bilinear-footprint-adaptive`); `count_scene`
    // refuses one that is not a case.
    for f in filters {
        if f.contains('/') && !listed.iter().any(|id| id.contains(f.as_str())) {
            cases.push(f);
        }
    }
    if cases.is_empty() {
        return usage_error(
            "count",
            "no case matches the filter (see `count_scene --list`)",
        );
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
