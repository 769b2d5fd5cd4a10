//! Time per frame and per drawn pixel of the `docs/scenes.md` benchmark scenes, and of cheaper
//! and dearer modes on the cube and the floor.
//!
//! `cargo bench -p host-tests --bench scenes` (filters work as usual: `... --bench scenes -- floor`).
//!
//! One iteration renders all N frames of a case (clear + transform + draw, 320 x 240 RGB565
//! with a 16-bit depth buffer). Criterion's throughput is in drawn pixels (pixels that passed
//! the depth test, summed over the N frames). After criterion, a Markdown table (scene, mode,
//! pixels per frame, ns per frame, ns per pixel; medians of the timed iterations) is printed
//! and written to `target/bench-summary.md`. Kept short (10 samples, flat sampling) for a
//! small machine; the numbers are for comparison between modes, not a performance test.

#[path = "../../examples/common/bench_scenes.rs"]
mod bench_scenes;

use bench_scenes::{Bench, Case, MODES, SCENES};
use criterion::{black_box, BenchmarkId, Criterion, SamplingMode, Throughput};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// One measured case: drawn pixels per run of N frames and the timed runs (per iteration).
struct Row {
    case: Case,
    pixels: u64,
    times: Vec<Duration>,
}

fn group(c: &mut Criterion, name: &str, cases: &[Case], rows: &mut Vec<Row>) {
    let mut g = c.benchmark_group(name);
    g.sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .warm_up_time(Duration::from_millis(300));
    for &case in cases {
        let frames = case.scene.frames();
        let mut bench = Bench::new(case);
        let t0 = Instant::now();
        let pixels = bench.run(frames);
        // Room for the 10 flat samples of one iteration each (no "unable to complete").
        g.measurement_time((t0.elapsed() * 12).max(Duration::from_secs(1)));
        let mut times = Vec::new();
        g.throughput(Throughput::Elements(pixels));
        g.bench_function(BenchmarkId::new(case.scene.name(), case.mode_name()), |b| {
            b.iter_custom(|iters| {
                let t0 = Instant::now();
                for _ in 0..iters {
                    black_box(bench.run(black_box(frames)));
                }
                let dt = t0.elapsed();
                times.push(dt / iters.max(1) as u32);
                dt
            })
        });
        if !times.is_empty() {
            rows.push(Row {
                case,
                pixels,
                times,
            });
        }
    }
    g.finish();
}

fn median(v: &mut [Duration]) -> Duration {
    v.sort();
    v[v.len() / 2]
}

fn summary(rows: &mut [Row]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "| scene | mode | frames | pixels drawn / frame | ns / frame | ns / pixel |"
    );
    let _ = writeln!(s, "|---|---|---:|---:|---:|---:|");
    for r in rows.iter_mut() {
        let frames = r.case.scene.frames();
        let t = median(&mut r.times).as_nanos() as f64;
        let _ = writeln!(
            s,
            "| {} | {} | {} | {:.0} | {:.0} | {:.2} |",
            r.case.scene.name(),
            r.case.mode_name(),
            frames,
            r.pixels as f64 / f64::from(frames),
            t / f64::from(frames),
            t / r.pixels.max(1) as f64,
        );
    }
    s
}

fn target_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target"))
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    let mut rows = Vec::new();
    group(&mut c, "scenes", &SCENES, &mut rows);
    group(&mut c, "modes", &MODES, &mut rows);
    c.final_summary();
    if rows.is_empty() {
        return;
    }
    let table = format!(
        "# fixel benchmark scenes (x86_64 host, 320 x 240 RGB565, 16-bit depth)\n\n\
         Time per frame includes clear, transform and draw; ns per pixel = time / pixels that \
         passed the depth test. Medians of criterion's timed iterations.\n\n{}",
        summary(&mut rows)
    );
    println!("\n{table}");
    let path = target_dir().join("bench-summary.md");
    match std::fs::write(&path, &table) {
        Ok(()) => println!("written to {}", path.display()),
        Err(e) => eprintln!("could not write {}: {e}", path.display()),
    }
}
