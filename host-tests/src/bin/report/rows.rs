//! One row of the report per (scene, mode): what was measured, the MCU counts read from
//! `mcu.tsv`, and the comparisons between rows (Pareto dominance, recommended modes).

use std::collections::BTreeMap;
use std::path::Path;

use host_tests::metrics::Report;

use crate::modes::Mode;
use crate::TARGETS;

/// Everything measured for one (scene, mode).
pub struct Row {
    pub mode: Mode,
    pub name: String,
    pub host: Option<(f64, f64, f64)>,
    pub host_pixels: u64,
    /// Instructions per pixel by target label.
    pub mcu: BTreeMap<&'static str, f64>,
    /// (checksum matches the host's band frame) by target label.
    pub mcu_ok: BTreeMap<&'static str, bool>,
    pub err: Report,
    pub ideal: Report,
    /// Targets on which the mode is dominated.
    pub dominated: Vec<&'static str>,
}

impl Row {
    pub fn cost(&self, target: &str) -> Option<f64> {
        if target == "host" {
            self.host.map(|h| h.0)
        } else {
            self.mcu.get(target).copied()
        }
    }
}

pub fn median_min_max(mut v: Vec<f64>) -> (f64, f64, f64) {
    v.sort_by(f64::total_cmp);
    (v[v.len() / 2], v[0], v[v.len() - 1])
}

pub fn read_mcu(path: &Path) -> Vec<(String, String, String, f64, u64, String)> {
    let text = std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("could not read {}: {e}", path.display()));
    text.lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            if f.len() < 6 {
                return None;
            }
            let insns: f64 = f[3].parse().ok()?;
            let px: u64 = f[4].parse().ok()?;
            Some((
                f[0].to_string(),
                f[1].to_string(),
                f[2].to_string(),
                insns / px.max(1) as f64,
                px,
                f[5].to_string(),
            ))
        })
        .collect()
}

pub fn psnr(r: &Report) -> f64 {
    if r.psnr_db.is_finite() {
        r.psnr_db
    } else {
        99.0
    }
}

/// Marks dominated modes per target: same lighting, at most as slow and at least as
/// accurate, one of them strictly.
pub fn pareto(rows: &mut [Row]) {
    for t in TARGETS {
        let pts: Vec<Option<(f64, f64, bool)>> = rows
            .iter()
            .map(|r| r.cost(t).map(|c| (c, psnr(&r.ideal), r.mode.lit)))
            .collect();
        for i in 0..rows.len() {
            let Some((ci, pi, li)) = pts[i] else { continue };
            let dom = pts.iter().enumerate().any(|(j, p)| {
                matches!(*p, Some((cj, pj, lj)) if j != i && lj == li && cj <= ci && pj >= pi
                    && (cj < ci || pj > pi))
            });
            if dom {
                rows[i].dominated.push(t);
            }
        }
    }
}

/// The cheapest mode (with the scene's lighting) within `db` of the best PSNR on `t`.
pub fn pick<'r>(rows: &'r [Row], lit: bool, t: &str, db: f64) -> Option<&'r Row> {
    let cand: Vec<&Row> = rows
        .iter()
        .filter(|r| r.mode.lit == lit && r.cost(t).is_some())
        .collect();
    let best = cand.iter().map(|r| psnr(&r.ideal)).fold(f64::MIN, f64::max);
    cand.into_iter()
        .filter(|r| psnr(&r.ideal) >= best - db)
        .min_by(|a, b| {
            a.cost(t)
                .unwrap_or(0.0)
                .total_cmp(&b.cost(t).unwrap_or(0.0))
        })
}
