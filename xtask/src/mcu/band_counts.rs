//! Per-band instruction counts of the banded scene firmwares (the input of `cargo xtask
//! fps`): each scene on each MCU under QEMU, once as `cargo xtask mcu` runs it (checksum,
//! pixels, cycle estimate, the binning pass) and once with the plugin's mark on
//! `bench_end`, which the harness calls as each band is flushed (its checksum is left out
//! of the count): the running region sum at each band's end, so each band's count is a
//! difference.

use std::path::Path;
use std::process::Command;

use super::firmware::{build_firmware, elf};
use super::qemu::{measure, num, qemu};
use super::tools::{build_plugin, ensure_tools, output};
use super::{firmware_dir, Mcu, MCUS};

/// One scene's frame on one MCU, split as the band renderer does it.
#[derive(Clone, Debug)]
pub struct BandCounts {
    /// Scene firmware.
    pub scene: String,
    /// MCU label (`Cortex-M4F`, `Cortex-M0+`, `RV32IMC`).
    pub target: &'static str,
    /// Instructions up to the end of the binning pass (walk, transform, clip, project,
    /// bin), before the first band.
    pub geometry: u64,
    /// Instructions of each band, top to bottom (clear, set-ups, spans, re-projection),
    /// the geometry taken out of band 0; they sum, with `geometry`, to the frame's count.
    pub bands: Vec<u64>,
    /// Estimated cycles per instruction over the frame (the static model of `cycles.py`).
    pub cycles_per_insn: f64,
    /// Pixels written.
    pub pixels: u64,
    /// The frame's checksum (the host's, when `cargo xtask mcu` passes).
    pub checksum: String,
}

fn symbol(nm: &str, name: &str) -> Option<String> {
    nm.lines().find_map(|l| {
        let f: Vec<&str> = l.split_whitespace().collect();
        (f.len() >= 3 && f[f.len() - 1] == name).then(|| format!("0x{}", f[0]))
    })
}

/// The running region sums at each hit of `bench_end`, and the marker pair's overhead.
fn band_marks(llvm: &Path, plugin: &Path, m: &Mcu, e: &Path) -> Result<(Vec<u64>, u64), String> {
    let nm = output(Command::new(llvm.join("llvm-nm")).arg(e), "llvm-nm")?;
    let (Some(start), Some(end)) = (symbol(&nm, "bench_start"), symbol(&nm, "bench_end")) else {
        return Err(format!("{}: no bench_start/bench_end", e.display()));
    };
    let arg = format!("{},start={start},end={end},mark={end}", plugin.display());
    let (ok, out, err) = qemu(m, e, Some(arg))?;
    if !ok {
        return Err(format!(
            "{} on {} failed:\n{out}{err}",
            e.display(),
            m.label
        ));
    }
    let mut first = 0;
    let sums = err
        .lines()
        .filter(|l| l.starts_with("icount: mark "))
        .map(|l| {
            first = num(l, "first_pair").unwrap_or(0);
            num(l, "region_sum").unwrap_or(0)
        })
        .collect();
    Ok((sums, first))
}

/// Builds the scene firmwares `scenes` and counts each one's bands on every MCU.
pub fn band_counts(scenes: &[&str], install: bool) -> Result<Vec<BandCounts>, String> {
    let llvm = ensure_tools(install)?;
    let plugin = build_plugin()?;
    build_firmware(&[], None, Some(scenes))?;
    let td = firmware_dir().join("target");
    let mut all = Vec::new();
    for scene in scenes {
        for m in &MCUS {
            eprintln!("xtask: {scene} on {} (bands)", m.label);
            let e = elf(&td, m, scene);
            let (r, _) = measure(&llvm, &plugin, m, &e, 1)?;
            let geometry = r
                .geometry
                .ok_or_else(|| format!("{scene}: the firmware marks no binning pass"))?;
            let (sums, first) = band_marks(&llvm, &plugin, m, &e)?;
            // Marks: pair 0 (empty), the end of each band, the end of the frame.
            if sums.len() < 3 {
                return Err(format!("{scene} on {}: {} marks", m.label, sums.len()));
            }
            let mut bands: Vec<u64> = sums
                .windows(2)
                .map(|w| w[1].saturating_sub(w[0]).saturating_sub(first))
                .collect();
            // The frame's tail (after the last band's flush) goes with the last band.
            let tail = bands.pop().unwrap_or(0);
            if let Some(last) = bands.last_mut() {
                *last += tail;
            }
            if let Some(b0) = bands.first_mut() {
                *b0 = b0.saturating_sub(geometry);
            }
            let total = geometry + bands.iter().sum::<u64>();
            if total != r.net {
                return Err(format!(
                    "{scene} on {}: bands and geometry sum to {total}, the frame counts {}",
                    m.label, r.net
                ));
            }
            all.push(BandCounts {
                scene: scene.to_string(),
                target: m.label,
                geometry,
                bands,
                cycles_per_insn: r.est_cycles / r.net.max(1) as f64,
                pixels: r.pixels,
                checksum: r.checksum,
            });
        }
    }
    Ok(all)
}
