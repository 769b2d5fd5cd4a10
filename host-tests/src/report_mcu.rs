//! The firmware counts of `cargo xtask report` (`mcu.tsv`: scene, mode, target,
//! instructions, pixels, checksum) for the host report binaries.

use std::path::Path;

/// One firmware mode on one target: `(mode, target, instructions per pixel, checksum)`.
pub type McuRow = (String, String, f64, String);

/// The rows of `scene` in `path` (none when the file is missing).
pub fn read(path: &Path, scene: &str) -> Vec<McuRow> {
    let Ok(text) = std::fs::read_to_string(path) else {
        return Vec::new();
    };
    text.lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            if f.len() < 6 || f[0] != scene {
                return None;
            }
            let insns: f64 = f[3].parse().ok()?;
            let px: f64 = f[4].parse().ok()?;
            Some((
                f[1].to_string(),
                f[2].to_string(),
                insns / px.max(1.0),
                f[5].to_string(),
            ))
        })
        .collect()
}

/// `(Cortex-M0+, Cortex-M4F)` instructions per pixel of `mode`, when both were measured.
/// Panics when a firmware's checksum differs from the host's `checksum` (the report must
/// not print figures of a different frame).
pub fn of(rows: &[McuRow], mode: &str, checksum: u32) -> Option<(f64, f64)> {
    let get = |t: &str| {
        rows.iter().find(|r| r.0 == mode && r.1 == t).map(|r| {
            assert_eq!(
                r.3,
                format!("0x{checksum:08x}"),
                "{mode} on {t}: firmware checksum differs from the host's"
            );
            r.2
        })
    };
    Some((get("Cortex-M0+")?, get("Cortex-M4F")?))
}
