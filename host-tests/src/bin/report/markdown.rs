//! `report.md`: the recommended modes and one table per scene, with how and where it was
//! generated.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::time::Instant;

use host_tests::metrics::Report;

use crate::bench_scenes::Scene;
use crate::plot::{cost_unit, plot_file};
use crate::rows::{pick, Row};
use crate::{SS, TARGETS};

pub fn markdown(
    rows: &BTreeMap<Scene, Vec<Row>>,
    runs: u32,
    have_mcu: bool,
    problems: &[String],
    t_start: Instant,
) -> String {
    let mut md = String::new();
    let date = sh("date", &["-u", "+%Y-%m-%d %H:%M UTC"]);
    let rustc = sh("rustc", &["--version"]);
    let commit = sh("git", &["rev-parse", "--short", "HEAD"]);
    let _ = writeln!(
        md,
        "# fixel: speed against error, per scene and mode\n\n\
         Generated {date} by `cargo xtask report` (commit {commit}), {rustc}, on {}. \
         Reproduce: `cargo xtask report` (host + QEMU; `--no-mcu` for the host only, \
         `--docs` to copy the result here).\n",
        machine()
    );
    let _ = writeln!(
        md,
        "**Speed.** *host*: x86-64 ns per pixel that passed the depth test, all N frames of \
         the scene (`docs/scenes.md`; clear + transform + draw, 320 x 240 RGB565, 16-bit depth, \
         fixel's fixed-point scene path), median of {runs} runs after a warm-up, (min-max). \
         *M0+ / M4F*: exact instructions per pixel of frame 0 under QEMU (the report \
         firmwares, 8-row bands, as `cargo xtask mcu`), checked against the host's frame \
         checksum.{}\n\n\
         **Error.** The same typed draw fed the reference's clip-space triangles. *ref*: \
         against the f64 reference with the mode's filter (and mip filter) and lighting and \
         exact perspective: implementation + projection error. PSNR in dB over 8-bit \
         values; max and p99 of the per-pixel largest channel error, in RGB565 LSBs; cov = \
         pixels covered by only one of the two, % of covered. *ideal*: against the scene's \
         ideal image (cube, sphere: the bilinear f64 reference with the mode's lighting; \
         floor: the {SS} x {SS} supersampled reference, i.e. what filtering should give). \
         Errors pooled over frames {} of the cube, {} of the sphere, {} of the floor.\n\n\
         **Pareto.** A mode is *dominated* on a target when another mode with the same \
         lighting is at most as slow there and at least as accurate (PSNR against the \
         ideal), one of them strictly. The column lists the targets where it is.\n",
        if have_mcu {
            ""
        } else {
            " (Not measured in this run: `--no-mcu`.)"
        },
        fmt_frames(Scene::Cube),
        fmt_frames(Scene::Sphere),
        fmt_frames(Scene::Floor),
    );
    // Recommendations.
    let _ = writeln!(
        md,
        "## Recommended modes\n\nPer scene and target, among the modes with the scene's \
         lighting: *best* = the cheapest within 0.5 dB of the most accurate, *balanced* = \
         the cheapest within 3 dB of it, *fastest* = the cheapest. Figures: cost, PSNR \
         against the ideal.\n\n| scene | target | best | balanced | fastest |\n|---|---|---|---|---|"
    );
    for (scene, rs) in rows {
        for t in TARGETS {
            if rs.iter().all(|r| r.cost(t).is_none()) {
                continue;
            }
            let cell = |r: Option<&Row>| {
                r.map_or("-".to_string(), |r| {
                    format!(
                        "`{}` ({:.1} {}, {} dB)",
                        r.name,
                        r.cost(t).unwrap_or(0.0),
                        cost_unit(t),
                        fmt_psnr(&r.ideal)
                    )
                })
            };
            let lit = scene.lit();
            let _ = writeln!(
                md,
                "| {} | {t} | {} | {} | {} |",
                scene.name(),
                cell(pick(rs, lit, t, 0.5)),
                cell(pick(rs, lit, t, 3.0)),
                cell(pick(rs, lit, t, f64::INFINITY)),
            );
        }
    }
    for (scene, rs) in rows {
        let _ = writeln!(
            md,
            "\n## {}\n\nN = {} frames; {:.0} pixels drawn per frame on the host. Ideal: the {}.\n",
            scene.name(),
            scene.frames(),
            rs.first()
                .map_or(0.0, |r| r.host_pixels as f64 / f64::from(scene.frames())),
            scene.ideal()
        );
        let _ = writeln!(
            md,
            "| mode | host ns/px | M0+ insns/px | M4F insns/px | ref PSNR | ref max | ref p99 | cov % | ideal PSNR | ideal p99 | dominated on |\n\
             |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
        );
        for r in rs {
            let mcu = |t: &str| {
                r.mcu.get(t).map_or("-".to_string(), |v| {
                    let ok = r.mcu_ok.get(t).copied().unwrap_or(true);
                    format!("{v:.1}{}", if ok { "" } else { " (**checksum!**)" })
                })
            };
            let cov = 100.0 * (r.err.only_candidate + r.err.only_reference) as f64
                / (r.err.both_covered + r.err.only_reference).max(1) as f64;
            let dom = if r.dominated.is_empty() {
                "-".to_string()
            } else {
                r.dominated
                    .iter()
                    .map(|t| t.replace("Cortex-", ""))
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            let _ = writeln!(
                md,
                "| `{}` | {} | {} | {} | {} | {} | {} | {cov:.2} | {} | {} | {dom} |",
                r.name,
                fmt_host(r.host),
                mcu("Cortex-M0+"),
                mcu("Cortex-M4F"),
                fmt_psnr(&r.err),
                r.err.max,
                r.err.p99,
                fmt_psnr(&r.ideal),
                r.ideal.p99,
            );
        }
        let _ = writeln!(md);
        for t in TARGETS {
            if rs.iter().any(|r| r.cost(t).is_some()) {
                let f = plot_file(*scene, t);
                let _ = writeln!(md, "![{} on {t}]({f})", scene.name());
            }
        }
    }
    if !problems.is_empty() {
        let _ = writeln!(md, "\n## Problems\n");
        for p in problems {
            let _ = writeln!(md, "* {p}");
        }
    }
    let _ = writeln!(
        md,
        "\n(host part of the report: {:.0} s)",
        t_start.elapsed().as_secs_f64()
    );
    md
}

fn fmt_frames(s: Scene) -> String {
    s.error_frames()
        .iter()
        .map(u32::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

fn sh(cmd: &str, args: &[&str]) -> String {
    std::process::Command::new(cmd)
        .args(args)
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_default()
}

fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let n = std::thread::available_parallelism().map_or(0, |n| n.get());
    format!("{cpu}, {n} cores ({})", std::env::consts::ARCH)
}

fn fmt_host(h: Option<(f64, f64, f64)>) -> String {
    h.map_or("-".into(), |(m, a, b)| format!("{m:.2} ({a:.2}-{b:.2})"))
}

fn fmt_psnr(r: &Report) -> String {
    if r.psnr_db.is_finite() {
        format!("{:.1}", r.psnr_db)
    } else {
        "inf".into()
    }
}
