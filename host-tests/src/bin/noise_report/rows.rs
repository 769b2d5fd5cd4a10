//! The table rows: one measured variant, built from its frame, its MCU counts (the
//! `noise` rows of `mcu.tsv`) and its errors, and the thousands separator of the titles.

use host_tests::metrics::{compare_rgb565, Report};
use host_tests::report_mcu::McuRow;

/// One measured variant.
pub struct Row {
    pub name: String,
    pub pixels: usize,
    pub ns_px: f64,
    pub m0: Option<(f64, bool)>,
    pub m4: Option<(f64, bool)>,
    pub vs_ref: Report,
    pub vs_ideal: Report,
}
/// A row from a frame (pixels, coverage, checksum, ns/px), its MCU counts (checksums
/// checked against the frame's) and its errors against the reference and the ideal.
#[allow(clippy::too_many_arguments)]
pub fn row(
    name: &str,
    res: (Vec<u16>, Vec<bool>, u32, f64),
    mcu: &[McuRow],
    r: &[u16],
    rcov: &[bool],
    ideal: &[u16],
    icov: &[bool],
) -> Row {
    let (px, cov, sum, ns) = res;
    let get = |t: &str| {
        mcu.iter()
            .find(|(m, tt, _, _)| m == name && tt == t)
            .map(|(_, _, ipp, c)| (*ipp, *c == format!("0x{sum:08x}")))
    };
    Row {
        name: name.to_string(),
        pixels: cov.iter().filter(|&&c| c).count(),
        ns_px: ns,
        m0: get("Cortex-M0+"),
        m4: get("Cortex-M4F"),
        vs_ref: compare_rgb565(&px, &cov, r, rcov),
        vs_ideal: compare_rgb565(&px, &cov, ideal, icov),
    }
}

/// `28899` as `28,899`.
pub fn thousands(n: usize) -> String {
    let s = n.to_string();
    let mut out = String::new();
    for (i, c) in s.chars().enumerate() {
        if i > 0 && (s.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}
