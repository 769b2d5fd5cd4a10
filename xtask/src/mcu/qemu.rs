//! Firmware runs under QEMU with the icount plugin: one run, a scene's repeated runs
//! (`measure`) and the per-mode counts of a report firmware (`measure_modes`), and the
//! `key=value` parsing of what they print.

use std::fs;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::tools::output;
use super::{out_dir, Mcu};
use crate::cmd::root;

const QEMU_TIMEOUT: Duration = Duration::from_secs(120);

fn symbol(nm: &str, name: &str) -> Option<String> {
    nm.lines().find_map(|l| {
        let f: Vec<&str> = l.split_whitespace().collect();
        (f.len() >= 3 && f[f.len() - 1] == name).then(|| format!("0x{}", f[0]))
    })
}

/// One QEMU run: exit status, stdout, stderr.
pub(super) fn qemu(
    m: &Mcu,
    elf: &Path,
    plugin: Option<String>,
) -> Result<(bool, String, String), String> {
    let dir = out_dir();
    fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let (o, e) = (dir.join("qemu.stdout"), dir.join("qemu.stderr"));
    let mut cmd = Command::new(m.qemu);
    cmd.args(m.machine).args([
        "-nographic",
        "-monitor",
        "none",
        "-serial",
        "none",
        "-semihosting-config",
        "enable=on,target=native",
    ]);
    if let Some(p) = plugin {
        cmd.arg("-plugin").arg(p);
    }
    cmd.arg("-kernel")
        .arg(elf)
        .stdin(Stdio::null())
        .stdout(fs::File::create(&o).map_err(|e| e.to_string())?)
        .stderr(fs::File::create(&e).map_err(|e| e.to_string())?);
    let mut child = cmd
        .spawn()
        .map_err(|err| format!("{} could not start: {err}", m.qemu))?;
    let t0 = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().map_err(|e| e.to_string())? {
            break s;
        }
        if t0.elapsed() > QEMU_TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!(
                "{} timed out after {:?} on {}",
                m.qemu,
                QEMU_TIMEOUT,
                elf.display()
            ));
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let read = |p: &Path| fs::read_to_string(p).unwrap_or_default();
    Ok((status.success(), read(&o), read(&e)))
}

/// `key=value` from text (first occurrence).
pub(super) fn kv<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    let pat = format!("{key}=");
    text.split_whitespace()
        .find_map(|w| w.strip_prefix(pat.as_str()))
}

pub(super) fn num(text: &str, key: &str) -> Option<u64> {
    kv(text, key)?.parse().ok()
}

/// The plugin's report at exit: its stderr without the `icount: mark` lines (which carry
/// the same keys, counted so far).
fn final_report(err: &str) -> String {
    err.lines()
        .filter(|l| !l.starts_with("icount: mark "))
        .collect::<Vec<_>>()
        .join("\n")
}

pub(super) struct Measured {
    pub(super) checksum: String,
    pub(super) pixels: u64,
    pub(super) stack: u64,
    pub(super) net: u64,
    pub(super) total: u64,
    pub(super) est_cycles: f64,
    pub(super) rewalked: bool,
    /// Counted instructions up to the end of the binning pass (`bench_geometry`'s first
    /// hit), when the firmware marks it.
    pub(super) geometry: Option<u64>,
    pub(super) profile: Vec<String>,
    pub(super) mix: String,
}

/// Runs one firmware `runs` times with the plugin; errors if the runs disagree.
pub(super) fn measure(
    llvm: &Path,
    plugin: &Path,
    m: &Mcu,
    elf: &Path,
    runs: u32,
) -> Result<(Measured, Vec<(u64, u64)>), String> {
    let nm = output(Command::new(llvm.join("llvm-nm")).arg(elf), "llvm-nm")?;
    let (start, end) = match (symbol(&nm, "bench_start"), symbol(&nm, "bench_end")) {
        (Some(s), Some(e)) => (s, e),
        _ => return Err(format!("{}: no bench_start/bench_end", elf.display())),
    };
    // The end of a banded frame's binning pass, where the scene marks it.
    let geometry_mark = symbol(&nm, "bench_geometry");
    let hist = out_dir().join(format!("hist-{}.tsv", m.core));
    let mut seen = Vec::new();
    let mut first: Option<(String, String)> = None;
    for i in 0..runs.max(1) {
        let mut arg = format!("{},start={start},end={end}", plugin.display());
        if let Some(g) = &geometry_mark {
            arg.push_str(&format!(",mark={g}"));
        }
        if i == 0 {
            arg.push_str(&format!(",hist={}", hist.display()));
        }
        let (ok, out, err) = qemu(m, elf, Some(arg))?;
        if !ok {
            return Err(format!(
                "{} on {} failed:\n{out}{err}",
                elf.display(),
                m.label
            ));
        }
        let report = final_report(&err);
        let total = num(&report, "total").ok_or("plugin printed no total")?;
        let region = num(&report, "region_sum").ok_or("no region_sum")?;
        let pairs = num(&report, "pairs").ok_or("no pairs")?;
        let fp = num(&report, "first_pair").ok_or("no first_pair")?;
        seen.push((total, region - pairs * fp));
        if first.is_none() {
            first = Some((out, err));
        }
    }
    let (out, err) = first.unwrap_or_default();
    let line = out
        .lines()
        .find(|l| l.starts_with("scene="))
        .ok_or_else(|| format!("no result line from {}:\n{out}{err}", elf.display()))?;
    let pixels = num(line, "pixels").unwrap_or(0);
    let region = num(&final_report(&err), "region_sum").unwrap_or(1).max(1);
    let (total, net) = seen[0];
    // The first mark: the region sum so far, less the marker pairs' overhead.
    let geometry = err
        .lines()
        .find(|l| l.starts_with("icount: mark "))
        .and_then(|l| {
            let (s, p, f) = (
                num(l, "region_sum")?,
                num(l, "pairs")?,
                num(l, "first_pair")?,
            );
            Some(s.saturating_sub(p * f))
        });

    let nm_file = out_dir().join(format!("nm-{}.txt", m.core));
    let nm_sorted = output(
        Command::new(llvm.join("llvm-nm"))
            .args(["-n", "-S", "-C"])
            .arg(elf),
        "llvm-nm -n -S -C",
    )?;
    fs::write(&nm_file, nm_sorted).map_err(|e| e.to_string())?;
    let cyc = output(
        Command::new("python3")
            .arg(root().join("xtask/mcu/cycles.py"))
            .arg(&hist)
            .arg(m.core)
            .arg(pixels.max(1).to_string())
            .arg(&nm_file),
        "python3 xtask/mcu/cycles.py",
    )?;
    let est = num(&cyc, "est_cycles").unwrap_or(0) as f64;
    let hist_sum = num(&cyc, "insns").unwrap_or(region).max(1);
    if hist_sum != region {
        return Err(format!(
            "histogram sums to {hist_sum}, the region to {region}: plugin out of step"
        ));
    }
    Ok((
        Measured {
            checksum: kv(line, "checksum").unwrap_or("?").to_string(),
            pixels,
            stack: num(&out, "stack").unwrap_or(0),
            net,
            total,
            // The marker overhead (pairs x first pair) is taken out in proportion.
            est_cycles: est * net as f64 / region as f64,
            rewalked: kv(line, "rewalked") == Some("true"),
            geometry,
            profile: cyc
                .lines()
                .filter(|l| l.trim_start().starts_with("profile:"))
                .map(|l| l.trim().to_string())
                .collect(),
            mix: cyc
                .lines()
                .find(|l| l.starts_with("mix:"))
                .unwrap_or("")
                .to_string(),
        },
        seen,
    ))
}

/// One mode of one report firmware on one MCU.
pub struct ModeCount {
    pub scene: String,
    pub mode: String,
    pub target: &'static str,
    pub instructions: u64,
    pub pixels: u64,
    pub checksum: String,
}

/// Runs one report firmware once with the plugin's `mark=`; per-mode counts are the
/// differences of the running region sum between marks, less the marker overhead.
pub(super) fn measure_modes(
    llvm: &Path,
    plugin: &Path,
    m: &Mcu,
    elf: &Path,
) -> Result<Vec<ModeCount>, String> {
    let nm = output(Command::new(llvm.join("llvm-nm")).arg(elf), "llvm-nm")?;
    let sym = |s: &str| symbol(&nm, s).ok_or_else(|| format!("{}: no {s}", elf.display()));
    let arg = format!(
        "{},start={},end={},mark={}",
        plugin.display(),
        sym("bench_start")?,
        sym("bench_end")?,
        sym("bench_mark")?
    );
    let (ok, out, err) = qemu(m, elf, Some(arg))?;
    if !ok {
        return Err(format!(
            "{} on {} failed:\n{out}{err}",
            elf.display(),
            m.label
        ));
    }
    let marks: Vec<(u64, u64, u64)> = err
        .lines()
        .filter(|l| l.starts_with("icount: mark "))
        .map(|l| {
            (
                num(l, "region_sum").unwrap_or(0),
                num(l, "pairs").unwrap_or(0),
                num(l, "first_pair").unwrap_or(0),
            )
        })
        .collect();
    let lines: Vec<&str> = out.lines().filter(|l| l.starts_with("mode ")).collect();
    if marks.len() != lines.len() + 1 {
        return Err(format!(
            "{} on {}: {} marks for {} modes",
            elf.display(),
            m.label,
            marks.len(),
            lines.len()
        ));
    }
    let mut v = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        if kv(l, "error").is_some() {
            return Err(format!("{} on {}: {l}", elf.display(), m.label));
        }
        let (a, b) = (marks[i], marks[i + 1]);
        let overhead = (b.1 - a.1) * b.2;
        v.push(ModeCount {
            scene: kv(l, "scene").unwrap_or("?").to_string(),
            mode: kv(l, "mode").unwrap_or("?").to_string(),
            target: m.label,
            instructions: (b.0 - a.0).saturating_sub(overhead),
            pixels: num(l, "pixels").unwrap_or(0),
            checksum: kv(l, "checksum").unwrap_or("?").to_string(),
        });
    }
    Ok(v)
}
