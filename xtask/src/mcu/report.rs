//! The microcontroller part of `cargo xtask report`: per-mode instruction counts of the
//! report firmwares on the Cortex-M0+ and Cortex-M4F, written to a TSV file.

use std::fs;
use std::path::Path;
use std::process::Command;
use std::time::Instant;

use super::firmware::elf;
use super::qemu::{measure_modes, ModeCount};
use super::tools::{build_plugin, ensure_tools, run_visible};
use super::{firmware_dir, Mcu};
use crate::cmd::without_target_env;

/// The report's microcontrollers. Both builds run on `mps2-an386` (4 MB of RAM: the
/// report firmwares hold up to 20 span loops and exceed the microbit's 256 KB / 16 KB);
/// instruction counts depend on the instruction stream only, and ARMv6-M code runs
/// unchanged on the M4 model.
const REPORT_MCUS: [Mcu; 2] = [
    Mcu {
        label: "Cortex-M0+",
        triple: "thumbv6m-none-eabi",
        qemu: "qemu-system-arm",
        machine: &["-machine", "mps2-an386"],
        core: "m0plus",
    },
    Mcu {
        label: "Cortex-M4F",
        triple: "thumbv7em-none-eabihf",
        qemu: "qemu-system-arm",
        machine: &["-machine", "mps2-an386"],
        core: "m4",
    },
];

/// The report firmwares (`examples/firmware/src/bin/report_*.rs`).
const REPORT_BINS: [&str; 16] = [
    "report_cube",
    "report_cube_unlit",
    "report_cube_facet",
    "report_cube_footprint",
    "report_cube_footprint_b",
    "report_sphere",
    "report_floor",
    "report_floor_mip",
    "report_floor_footprint",
    "report_noise",
    "report_env",
    "report_mapping",
    "report_aa",
    "report_alpha",
    "report_surface",
    "report_shadow",
];

/// `cargo xtask report`, microcontroller part: builds the report firmwares for the
/// Cortex-M0+ and Cortex-M4F, runs each once under QEMU and writes the per-mode counts to
/// `tsv` (scene, mode, target, instructions, pixels, checksum); only the firmwares in
/// `only` when given (names from [`REPORT_BINS`]). `progress` is told each step.
pub fn report_mcu(
    install: bool,
    tsv: &Path,
    only: Option<&[&str]>,
    progress: &mut dyn FnMut(&str),
) -> Result<Vec<ModeCount>, String> {
    let bins: Vec<&str> = REPORT_BINS
        .into_iter()
        .filter(|b| only.is_none_or(|o| o.contains(b)))
        .collect();
    let llvm = ensure_tools(install)?;
    let plugin = build_plugin()?;
    let td = firmware_dir().join("target").join("report");
    let mut cmd = Command::new("cargo");
    cmd.current_dir(firmware_dir())
        .args(["build", "--release"])
        .arg("--target-dir")
        .arg(&td)
        .env("FIXEL_FW_MEMORY", "report");
    without_target_env(&mut cmd);
    for b in &bins {
        cmd.args(["--bin", b]);
    }
    for m in &REPORT_MCUS {
        cmd.args(["--target", m.triple]);
    }
    progress("building the report firmwares (Cortex-M0+, Cortex-M4F)");
    run_visible(
        &mut cmd,
        "(cd examples/firmware && FIXEL_FW_MEMORY=report cargo build --release \
         --target-dir target/report --bin report_* --target <M0+, M4F>)",
    )?;
    let mut all = Vec::new();
    let total = bins.len() * REPORT_MCUS.len();
    let mut k = 0;
    for bin in bins {
        for m in &REPORT_MCUS {
            k += 1;
            progress(&format!("[{k}/{total}] QEMU: {bin} on {}", m.label));
            let t0 = Instant::now();
            let v = measure_modes(&llvm, &plugin, m, &elf(&td, m, bin))?;
            eprintln!(
                "xtask:   {} modes in {:.1} s",
                v.len(),
                t0.elapsed().as_secs_f64()
            );
            all.extend(v);
        }
    }
    let mut s = String::from("scene\tmode\ttarget\tinstructions\tpixels\tchecksum\n");
    for c in &all {
        s.push_str(&format!(
            "{}\t{}\t{}\t{}\t{}\t{}\n",
            c.scene, c.mode, c.target, c.instructions, c.pixels, c.checksum
        ));
    }
    if let Some(d) = tsv.parent() {
        fs::create_dir_all(d).map_err(|e| e.to_string())?;
    }
    fs::write(tsv, s).map_err(|e| format!("{}: {e}", tsv.display()))?;
    Ok(all)
}
