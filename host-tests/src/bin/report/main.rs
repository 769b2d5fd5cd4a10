//! Speed against error for every benchmark scene and mode. Run by
//! `cargo xtask report` (which first counts instructions on microcontrollers under QEMU and
//! hands them over with `--mcu`):
//!
//! ```text
//! report --out DIR [--runs N] [--mcu mcu.tsv]
//! ```
//!
//! * Modes: `examples/firmware/src/modes.rs` (shared with the report firmwares): projection
//!   Affine / Subdivided N=8, 16 / Exact / Adaptive (1/4 texel), filter Nearest / Bilinear
//!   (floor also nearest-mipmap-nearest and trilinear with LOD per pixel and per span), lit
//!   and unlit on the lit scenes; typed pipelines, repeat wrap, 16-bit depth, back-face cull.
//! * Host speed: all N frames of the scene (`docs/scenes.md`: clear + transform + draw,
//!   320 x 240, fixel's own fixed-point scene path, as `benches/scenes.rs` does), `N` runs
//!   after a warm-up; ns per pixel that passed the depth test: median, min, max.
//! * Microcontrollers: exact instructions per pixel of frame 0 (from `mcu.tsv`), checked
//!   against the checksum this program computes through the same band code.
//! * Error: the same typed draw fed the reference's clip-space triangles
//!   (`host_tests::adapter`), against the f64 reference with the mode's filter and lighting
//!   and exact perspective (implementation + projection error; PSNR, max, p99 in RGB565
//!   LSBs, coverage disagreement), and against the scene's ideal image (the bilinear
//!   reference on the cube and sphere, the 8 x 8 supersampled reference on the floor).
//! * Pareto: a mode is dominated when another with the same lighting is at most as slow and
//!   at least as accurate (PSNR against the ideal), one of them strictly.

#[path = "../../../../examples/firmware/src/modes.rs"]
#[allow(dead_code)]
mod modes;
#[path = "../../../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

mod bench_scenes;
mod markdown;
mod measure;
mod plot;
mod rows;

use std::collections::BTreeMap;
use std::time::Instant;

use clap::Parser;
use fixel_scenes as demo;
use host_tests::metrics::compare_rgb565;
use host_tests::report_args::{parse_with_runs, ReportArgs};
use indicatif::{ProgressBar, ProgressStyle};
use modes::Filt;

use bench_scenes::{mode_name, Meshes, Scene, Tex};
use markdown::markdown;
use measure::{band_checksum, time_mode, ErrFrame};
use plot::{plot, plot_file};
use rows::{median_min_max, pareto, read_mcu, Row};

const W: u32 = demo::WIDTH;
const H: u32 = demo::HEIGHT;
/// Supersampling of the floor's ideal reference.
const SS: u32 = 8;
/// Speed targets, in table order.
const TARGETS: [&str; 3] = ["host", "Cortex-M0+", "Cortex-M4F"];

/// A reference to render: error frame index, and (lighting, filter) or `None` for the
/// supersampled one.
type Job = (usize, Option<(bool, Filt)>);
/// RGB565 pixels and coverage.
type Image = (Vec<u16>, Vec<bool>);

/// Command line (the flags `cargo xtask report` passes).
#[derive(Parser)]
#[command(
    name = "report",
    about = "Speed against error for every benchmark scene and mode (run by `cargo xtask report`)",
    long_about = None
)]
struct Args {
    #[command(flatten)]
    common: ReportArgs,
    /// Only this scene: cube, sphere or floor
    #[arg(long, value_name = "NAME")]
    scene: Option<String>,
}

fn main() {
    let Args {
        common: ReportArgs {
            out,
            runs,
            mcu: mcu_path,
        },
        scene: only,
    } = parse_with_runs::<Args>("7");
    std::fs::create_dir_all(&out).expect("output directory");
    if let Err(e) = host_tests::plot_font::register() {
        eprintln!("report: {e}");
        std::process::exit(1)
    }

    let chosen: Vec<Scene> = Scene::ALL
        .into_iter()
        .filter(|s| only.as_deref().is_none_or(|o| o == s.name()))
        .collect();
    if chosen.is_empty() {
        eprintln!("report: no scene named {only:?} (cube, sphere, floor)");
        std::process::exit(2);
    }
    let t_start = Instant::now();
    let mcu = mcu_path.as_deref().map(read_mcu).unwrap_or_default();
    let meshes = Meshes {
        cube: demo::cube(),
        sphere: Box::new(demo::sphere()),
        floor: demo::floor(),
    };
    let texes: BTreeMap<Scene, Tex> = chosen.iter().map(|&s| (s, Tex::new(s))).collect();

    let n_modes: usize = chosen.iter().map(|s| s.modes().len()).sum();
    let n_ref: usize = chosen
        .iter()
        .map(|&s| {
            let filters = if s == Scene::Floor { 4 } else { 2 };
            let lights = if s.lit() { 2 } else { 1 };
            s.error_frames().len() * (filters * lights + usize::from(s == Scene::Floor))
        })
        .sum();
    let style =
        ProgressStyle::with_template("{elapsed_precise} [{bar:40.cyan/blue}] {pos}/{len} {msg}")
            .expect("template")
            .progress_chars("=> ");
    let pb = ProgressBar::new((n_modes * 2 + n_ref) as u64).with_style(style);

    // 1. Host timing first, alone (no other thread of ours running).
    let mut rows: BTreeMap<Scene, Vec<Row>> = BTreeMap::new();
    for &scene in &chosen {
        for m in scene.modes() {
            let name = mode_name(m);
            pb.set_message(format!("timing {}/{name}", scene.name()));
            let (ns, pixels) = time_mode(scene, m, &texes[&scene], &meshes, runs);
            let mut row = Row {
                mode: *m,
                name,
                host: Some(median_min_max(ns)),
                host_pixels: pixels,
                mcu: BTreeMap::new(),
                mcu_ok: BTreeMap::new(),
                err: compare_rgb565(&[], &[], &[], &[]),
                ideal: compare_rgb565(&[], &[], &[], &[]),
                dominated: Vec::new(),
            };
            for (s, mode, target, ipp, px, sum) in &mcu {
                if s == scene.name() && *mode == row.name {
                    let t = TARGETS.iter().copied().find(|t| t == target).unwrap_or("?");
                    row.mcu.insert(t, *ipp);
                    let (want, want_px) = band_checksum(scene, m, &texes[&scene], &meshes);
                    row.mcu_ok.insert(t, *sum == want && *px == want_px);
                }
            }
            rows.entry(scene).or_default().push(row);
            pb.inc(1);
        }
    }

    // 2. Errors: references (two threads), then fixel's frames.
    let mut problems = Vec::new();
    for &scene in &chosen {
        let tex = &texes[&scene];
        let frames: Vec<ErrFrame> = scene
            .error_frames()
            .iter()
            .map(|&i| ErrFrame::new(scene, i))
            .collect();
        let filters: &[Filt] = if scene == Scene::Floor {
            &[
                Filt::Nearest,
                Filt::Bilinear,
                Filt::NearestMip,
                Filt::Trilinear,
            ]
        } else {
            &[Filt::Nearest, Filt::Bilinear]
        };
        let lights: &[bool] = if scene.lit() {
            &[true, false]
        } else {
            &[false]
        };
        // Jobs: (frame, Some((lit, filter)) | None = supersampled).
        let mut jobs: Vec<Job> = Vec::new();
        for k in 0..frames.len() {
            for &l in lights {
                for &f in filters {
                    jobs.push((k, Some((l, f))));
                }
            }
            if scene == Scene::Floor {
                jobs.push((k, None));
            }
        }
        pb.set_message(format!("f64 references of {}", scene.name()));
        let results: Vec<(Job, Image)> = std::thread::scope(|sc| {
            let chunks: Vec<Vec<Job>> = (0..2)
                .map(|t| jobs.iter().copied().skip(t).step_by(2).collect())
                .collect();
            let handles: Vec<_> = chunks
                .into_iter()
                .map(|chunk| {
                    let (frames, pb) = (&frames, &pb);
                    sc.spawn(move || {
                        chunk
                            .into_iter()
                            .map(|(k, j)| {
                                let img = match j {
                                    Some((l, f)) => frames[k].reference(l, f),
                                    None => frames[k].supersampled(),
                                };
                                pb.inc(1);
                                ((k, j), img)
                            })
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            handles
                .into_iter()
                .flat_map(|h| h.join().expect("reference thread"))
                .collect()
        });
        let find = |k: usize, j: Option<(bool, Filt)>| {
            &results.iter().find(|r| r.0 == (k, j)).expect("reference").1
        };
        for row in rows.get_mut(&scene).expect("rows") {
            pb.set_message(format!("errors {}/{}", scene.name(), row.name));
            // Modes that differ only in cost share their filter's reference.
            let f = match row.mode.filter {
                Filt::TrilinearSpan => Filt::Trilinear,
                Filt::BilinearFootprint => Filt::Bilinear,
                f => f,
            };
            let (mut c, mut cc, mut r, mut rc, mut i, mut ic) =
                (vec![], vec![], vec![], vec![], vec![], vec![]);
            for (k, fr) in frames.iter().enumerate() {
                let px = fr.fixel(&row.mode, tex);
                c.extend_from_slice(&px);
                cc.extend_from_slice(&fr.covered);
                let re = find(k, Some((row.mode.lit, f)));
                r.extend_from_slice(&re.0);
                rc.extend_from_slice(&re.1);
                let id = if scene == Scene::Floor {
                    find(k, None)
                } else {
                    find(k, Some((row.mode.lit, Filt::Bilinear)))
                };
                i.extend_from_slice(&id.0);
                ic.extend_from_slice(&id.1);
            }
            row.err = compare_rgb565(&c, &cc, &r, &rc);
            row.ideal = compare_rgb565(&c, &cc, &i, &ic);
            pb.inc(1);
        }
        for row in rows.get(&scene).expect("rows") {
            for (t, ok) in &row.mcu_ok {
                if !ok {
                    problems.push(format!(
                        "{}/{} on {t}: the MCU's frame differs from the host's band frame",
                        scene.name(),
                        row.name
                    ));
                }
            }
        }
    }
    pb.set_message("plots");
    for (scene, rs) in rows.iter_mut() {
        pareto(rs);
        for t in TARGETS {
            let p = out.join(plot_file(*scene, t));
            if let Err(e) = plot(*scene, t, rs, &p) {
                problems.push(format!("plot {}: {e}", p.display()));
            }
        }
    }
    pb.finish_with_message("done");

    let md = markdown(&rows, runs, mcu_path.is_some(), &problems, t_start);
    let path = out.join("report.md");
    std::fs::write(&path, &md).expect("write report.md");
    println!("{md}");
    eprintln!(
        "report: wrote {} and the plots in {}",
        path.display(),
        out.display()
    );
    if !problems.is_empty() {
        for p in &problems {
            eprintln!("report: PROBLEM: {p}");
        }
        std::process::exit(1);
    }
}
