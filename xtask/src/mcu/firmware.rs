//! Building the firmwares (`examples/firmware`: band, opt-level s and whole-frame builds)
//! and reading their ELF files: paths and flash/RAM section sizes.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use super::tools::{output, run_visible};
use super::{firmware_dir, Mcu, DSP_CHECK, GEOMETRY, MCUS, WHOLE_MCUS, WHOLE_SCENES};
use crate::cmd::without_target_env;

/// Builds the whole-frame firmwares and the geometry firmware (whole layout, own target
/// directory so the default build's artefacts stay), or only those of them `keep` selects
/// (`--only`: a change to fixel rebuilds just the firmwares to be measured).
pub(super) fn build_whole(td: &Path, keep: impl Fn(&str) -> bool) -> Result<(), String> {
    let mut cmd = Command::new("cargo");
    cmd.current_dir(firmware_dir())
        .args(["build", "--release", "--features", "whole"])
        .arg("--target-dir")
        .arg(td)
        .env("FIXEL_FW_MEMORY", "whole");
    without_target_env(&mut cmd);
    let bins: Vec<&str> = WHOLE_SCENES
        .iter()
        .chain(&[GEOMETRY, DSP_CHECK])
        .copied()
        .filter(|b| keep(b))
        .collect();
    if bins.is_empty() {
        return Ok(());
    }
    for b in bins {
        cmd.args(["--bin", b]);
    }
    for m in &WHOLE_MCUS {
        cmd.args(["--target", m.triple]);
    }
    run_visible(
        &mut cmd,
        "(cd examples/firmware && FIXEL_FW_MEMORY=whole cargo build --release --features whole \
         --target-dir target/whole --bin whole_* --bin sphere_sized --bin geometry --bin dsp_span (or the --only ones) \
         --target <3 MCU targets>)",
    )
}

/// Builds firmware binaries for every MCU target (one cargo invocation): every binary
/// (`None`: `cargo xtask size`, whose rows are most of them), or only `bins` (nothing when
/// it is empty). `cargo xtask mcu` builds only the scenes it runs: building every binary
/// there (the `report_*` and `size_*` ones too, 52 in all against its 20) was most of CI's
/// time.
pub(super) fn build_firmware(
    extra_env: &[(&str, &str)],
    target_dir: Option<&Path>,
    bins: Option<&[&str]>,
) -> Result<(), String> {
    let mut cmd = Command::new("cargo");
    cmd.current_dir(firmware_dir()).args(["build", "--release"]);
    match bins {
        None => {
            cmd.arg("--bins");
        }
        Some([]) => return Ok(()),
        Some(bins) => {
            for b in bins {
                cmd.args(["--bin", b]);
            }
        }
    }
    without_target_env(&mut cmd);
    for m in &MCUS {
        cmd.args(["--target", m.triple]);
    }
    if let Some(d) = target_dir {
        cmd.arg("--target-dir").arg(d);
    }
    for (k, v) in extra_env {
        cmd.env(k, v);
    }
    run_visible(
        &mut cmd,
        "(cd examples/firmware && cargo build --release --bin <each scene, or the --only ones; \
         the size ones for size> --target <3 MCU targets>)",
    )
}

pub(super) fn elf(target_dir: &Path, m: &Mcu, bin: &str) -> PathBuf {
    target_dir.join(m.triple).join("release").join(bin)
}

/// Section sizes (`llvm-size -A`): (flash = vector table + text + rodata + data,
/// static RAM = data + bss + uninit).
pub(super) fn sizes(llvm: &Path, elf: &Path) -> Result<(u64, u64), String> {
    let out = output(
        Command::new(llvm.join("llvm-size")).arg("-A").arg(elf),
        "llvm-size -A",
    )?;
    let mut s: BTreeMap<String, u64> = BTreeMap::new();
    for l in out.lines() {
        let f: Vec<&str> = l.split_whitespace().collect();
        if f.len() >= 2 {
            if let Ok(n) = f[1].parse() {
                s.insert(f[0].to_string(), n);
            }
        }
    }
    let g = |k: &str| s.get(k).copied().unwrap_or(0);
    Ok((
        g(".vector_table") + g(".text") + g(".rodata") + g(".data"),
        g(".data") + g(".bss") + g(".uninit"),
    ))
}
