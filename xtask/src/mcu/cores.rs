//! `cargo xtask cores`: one frame on two cores, measured. The `cores_*` firmwares
//! (features `whole` + `smp`, RV32IMC) run on QEMU RISC-V `virt -smp 2`: each scene's
//! frame 0 on hart 0 alone, then on both harts (each bins half of the triangles, then hart
//! 0 draws the even bands, hart 1 the odd ones). The per-vCPU plugin
//! (`xtask/mcu/icount_smp.c`) counts each hart's instructions exactly; the frame's checksum
//! on one core and on two must equal the host's, and the busier hart may do at most 55 %
//! of the two-core frame's instructions.

use std::process::{Command, ExitCode};

use super::firmware::elf;
use super::qemu::{kv, num};
use super::scenes::host_expected;
use super::tools::{build_plugin_named, ensure_tools, output, run_visible};
use super::{fail, firmware_dir, out_dir, Mcu, MCUS};
use crate::cmd::without_target_env;

/// The two-core firmwares and their scenes.
const SCENES: [&str; 3] = ["cube", "sphere", "teapot"];

/// The busier core's largest share of a two-core frame's instructions.
const BALANCE: f64 = 0.55;

/// One scene's counts: one core; two cores (binning half + even bands, binning half + odd
/// bands).
struct Cores {
    one: u64,
    hart0: u64,
    hart1: u64,
}

/// A vCPU's mark lines: (running region sum, pairs, first pair).
fn marks(err: &str, cpu: u32) -> Vec<(u64, u64, u64)> {
    let tag = cpu.to_string();
    err.lines()
        .filter(|l| l.starts_with("icount: mark ") && kv(l, "cpu") == Some(tag.as_str()))
        .map(|l| {
            (
                num(l, "region_sum").unwrap_or(0),
                num(l, "pairs").unwrap_or(0),
                num(l, "first_pair").unwrap_or(0),
            )
        })
        .collect()
}

/// Instructions between two marks, less the marker pairs' overhead.
fn between(a: (u64, u64, u64), b: (u64, u64, u64)) -> u64 {
    (b.0 - a.0).saturating_sub((b.1 - a.1) * b.2)
}

/// Runs one firmware on two harts; its output line and counts.
fn run(
    m: &Mcu,
    llvm: &std::path::Path,
    plugin: &std::path::Path,
    scene: &str,
) -> Result<(String, Cores), String> {
    let e = elf(
        &firmware_dir().join("target").join("whole"),
        m,
        &format!("cores_{scene}"),
    );
    let nm = output(Command::new(llvm.join("llvm-nm")).arg(&e), "llvm-nm")?;
    let sym = |s: &str| {
        nm.lines()
            .find_map(|l| {
                let f: Vec<&str> = l.split_whitespace().collect();
                (f.len() >= 3 && f[f.len() - 1] == s).then(|| format!("0x{}", f[0]))
            })
            .ok_or_else(|| format!("{}: no {s}", e.display()))
    };
    let arg = format!(
        "{},start={},end={},mark={}",
        plugin.display(),
        sym("bench_start")?,
        sym("bench_end")?,
        sym("bench_mark")?
    );
    let out = Command::new(m.qemu)
        .args(m.machine)
        .args([
            "-smp",
            "2",
            "-accel",
            "tcg,thread=single",
            "-nographic",
            "-monitor",
            "none",
        ])
        .args([
            "-serial",
            "none",
            "-semihosting-config",
            "enable=on,target=native",
        ])
        .arg("-plugin")
        .arg(arg)
        .arg("-kernel")
        .arg(&e)
        .output()
        .map_err(|err| format!("{} could not start: {err}", m.qemu))?;
    let (so, se) = (
        String::from_utf8_lossy(&out.stdout).to_string(),
        String::from_utf8_lossy(&out.stderr).to_string(),
    );
    let line = so
        .lines()
        .find(|l| l.starts_with("scene="))
        .ok_or_else(|| format!("cores_{scene}: no result line:\n{so}{se}"))?
        .to_string();
    if !out.status.success() || kv(&line, "error").is_some() {
        return Err(format!("cores_{scene} failed: {line}\n{se}"));
    }
    // Hart 0: pair 0, then marks after the one-core frame, its binning half and its bands;
    // hart 1: its pair 0, then marks after its binning half and its bands.
    let (h0, h1) = (marks(&se, 0), marks(&se, 1));
    if h0.len() != 3 || h1.len() != 2 {
        return Err(format!(
            "cores_{scene}: {} and {} marks\n{se}",
            h0.len(),
            h1.len()
        ));
    }
    let start0 = (h0[0].2, 1, h0[0].2);
    let start1 = (h1[0].2, 1, h1[0].2);
    Ok((
        line,
        Cores {
            one: between(start0, h0[0]),
            hart0: between(h0[0], h0[2]),
            hart1: between(start1, h1[1]),
        },
    ))
}

/// `cargo xtask cores`.
pub fn cores(install: bool) -> ExitCode {
    let Some(m) = MCUS.iter().find(|m| m.triple.starts_with("riscv32")) else {
        return fail("no RISC-V profile");
    };
    let llvm = match ensure_tools(install).and_then(|l| Ok((l, build_plugin_named("icount_smp")?)))
    {
        Ok(x) => x,
        Err(e) => return fail(e),
    };
    let mut cmd = Command::new("cargo");
    cmd.current_dir(firmware_dir())
        .args([
            "build",
            "--release",
            "--features",
            "whole,smp",
            "--target",
            m.triple,
        ])
        .args(["--target-dir", "target/whole"])
        .env("FIXEL_FW_MEMORY", "whole");
    for s in SCENES {
        cmd.args(["--bin", &format!("cores_{s}")]);
    }
    without_target_env(&mut cmd);
    if let Err(e) = run_visible(
        &mut cmd,
        "(cd examples/firmware && FIXEL_FW_MEMORY=whole cargo build --release --features whole,smp \
         --target riscv32imc-unknown-none-elf --target-dir target/whole --bin cores_cube --bin cores_sphere --bin cores_teapot)",
    ) {
        return fail(e);
    }
    let expected = match host_expected() {
        Ok(x) => x,
        Err(e) => return fail(e),
    };
    let mut problems = Vec::new();
    let mut table = String::from(
        "| scene | one core | hart 0 (half the binning, even bands) | hart 1 (half the binning, odd bands) | two cores / one | busier hart | longer hart / one core | checksum (one core, two cores, host) |\n\
         |---|---:|---:|---:|---:|---:|---:|---|\n",
    );
    for scene in SCENES {
        let (line, c) = match run(m, &llvm.0, &llvm.1, scene) {
            Ok(x) => x,
            Err(e) => {
                problems.push(e);
                continue;
            }
        };
        let (one_sum, two_sum) = (
            kv(&line, "checksum").unwrap_or("?"),
            kv(&line, "two_checksum").unwrap_or("?"),
        );
        let (host_sum, host_px) = expected.get(scene).cloned().unwrap_or_default();
        let pixels = (num(&line, "pixels"), num(&line, "two_pixels"));
        if one_sum != host_sum || two_sum != host_sum || pixels != (Some(host_px), Some(host_px)) {
            problems.push(format!(
                "{scene}: checksums {one_sum} (one core) {two_sum} (two) pixels {pixels:?}, the host has {host_sum} ({host_px} pixels)"
            ));
        }
        let two = c.hart0 + c.hart1;
        let busier = c.hart0.max(c.hart1) as f64 / two.max(1) as f64;
        if busier > BALANCE {
            problems.push(format!(
                "{scene}: the busier hart does {:.1} % of the frame",
                100.0 * busier
            ));
        }
        table.push_str(&format!(
            "| {scene} | {} | {} | {} | {:.3} | {:.1} % | {:.3} | {one_sum}, {two_sum}, {host_sum} |\n",
            c.one,
            c.hart0,
            c.hart1,
            two as f64 / c.one.max(1) as f64,
            100.0 * busier,
            c.hart0.max(c.hart1) as f64 / c.one.max(1) as f64,
        ));
    }
    println!(
        "\n## cargo xtask cores: frame 0 on RISC-V virt -smp 2 (RV32IMC), exact instructions per hart\n\n\
         Each frame bins its triangles with the walker and draws 30 bands of 8 rows through two \
         band buffers per hart; the two-core frame bins half of the triangles on each hart, then \
         hart 0 draws the even bands and hart 1 the odd ones from the joined bins. Copying each \
         band into the checked whole frame and waiting for the other hart are outside the \
         counts.\n\n{table}"
    );
    let _ = std::fs::write(out_dir().join("cores.md"), &table);
    if problems.is_empty() {
        println!(
            "cores: checksums equal the host's on one core and on two; busier hart at most 55 %"
        );
        ExitCode::SUCCESS
    } else {
        for p in &problems {
            eprintln!("cores: FAIL: {p}");
        }
        ExitCode::FAILURE
    }
}
