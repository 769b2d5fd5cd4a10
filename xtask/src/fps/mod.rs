//! `cargo xtask fps`: frames per second on real boards, modelled from measured work.
//!
//! Each benchmark scene's frame is counted band by band under QEMU (`mcu::band_counts`:
//! exact instructions of the binning pass and of each band, the cycle estimate of the
//! static model), then [`crate::frame_model::frame_times`] turns the cycles and a display link into
//! frame times: one core serial (draw a band, send it), one core overlapped (two band
//! buffers, DMA), two cores overlapped. `--docs` writes the table to `docs/fps.md`.

use std::fmt::Write as _;
use std::fs;
use std::process::ExitCode;

use clap::Args;

use crate::cmd::root;
use crate::frame_model::chips::CHIPS;
use crate::frame_model::{frame_times, Work};
use crate::mcu::{band_counts, BandCounts};

/// The scenes modelled: the benchmark cube, sphere and teapot.
const SCENES: [&str; 3] = ["cube", "sphere", "teapot"];

/// The firmware's frame: 320 x 240 in bands of 8 rows.
const WIDTH: u64 = 320;
const HEIGHT: u64 = 240;
const ROWS: u64 = 8;

/// What the table assumes, printed beside it.
pub const ASSUMPTIONS: &str = "\
This is a model, not a board measurement. The work is measured: exact instruction counts \
of each scene's frame 0 under QEMU (`cargo xtask mcu`'s firmware, 320 x 240 RGB565 in 30 \
bands of 8 rows), split into the binning pass and each band; cycles are those counts times \
the frame's cycles per instruction from the static model of `xtask/mcu/cycles.py` \
(zero-wait-state memory: no flash wait states or cache misses, no bus contention between \
the cores or with the DMA). The RP2350's Cortex-M33 is counted with the Cortex-M4F build \
(the same Thumb-2 code) and its cycle model.

The link: an ST7789-class display over SPI, 2 bytes per pixel, 11 command bytes (a window: \
CASET, RASET, RAMWR) and 2 us of chip select, data/command pin and DMA start per band. SPI \
clocks: RP2040 and RP2350 62.5 MHz (clk_peri 125 MHz / 2, the ST7789's rated 16 ns write \
cycle), STM32F4 42 MHz (SPI1, APB2 84 MHz / 2), ESP32-C3 40 MHz (GPSPI2, 80 MHz APB / 2). \
A whole frame is 153,600 bytes: 19.7 ms at 62.5 MHz.

serial: one core draws a band, sends it and waits, then draws the next (one band buffer). \
overlapped: one core, two band buffers, DMA sends band k while band k + 1 is drawn. two \
cores: the binning pass split in half between the cores, then the bands interleaved (core 0 \
the even ones, core 1 the odd ones, each with two band buffers), sent in order on the one \
link; band work as measured on one core (the set-ups a band keeps for the next one are then \
built by both cores: the two-core figure is a little optimistic for the sphere and teapot; \
`cargo xtask cores` measures the split itself on two RISC-V harts: 0.3 to 0.4 % more \
instructions than one core, the busier hart 50.0 to 50.9 %). One frame on \
its own: the next frame's binning pass does not overlap the last band's transfer. hidden = \
the share of the link time the best way hides behind drawing. busier core = the larger \
core's share of the band work with two cores.";

/// Flags of `cargo xtask fps`.
#[derive(Args, Clone, Debug)]
pub struct FpsArgs {
    /// Write the table and its assumptions to docs/fps.md
    #[arg(long)]
    pub docs: bool,
    /// Do not install missing tools (rust targets, llvm-tools, apt-get packages)
    #[arg(long)]
    pub no_install: bool,
}

/// The work of one scene's frame on one part.
fn work(c: &BandCounts) -> Work {
    let cpi = c.cycles_per_insn;
    let band_pixels = (0..c.bands.len() as u64)
        .map(|k| WIDTH * ROWS.min(HEIGHT.saturating_sub(k * ROWS)))
        .collect();
    Work {
        geometry: c.geometry as f64 * cpi,
        bands: c.bands.iter().map(|&n| n as f64 * cpi).collect(),
        band_pixels,
    }
}

fn ms_fps(t: f64) -> String {
    format!("{:.1} ms ({:.1} fps)", t * 1e3, 1.0 / t)
}

/// The fps table of `counts` (Markdown).
pub fn table(counts: &[BandCounts]) -> String {
    let mut t = String::from(
        "| scene | part | render, 1 core | link | serial, 1 core | overlapped, 1 core | \
         overlapped, 2 cores | best / serial | link hidden | busier core |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for scene in SCENES {
        for chip in &CHIPS {
            let Some(c) = counts
                .iter()
                .find(|c| c.scene == scene && c.target == chip.counts_from)
            else {
                continue;
            };
            let f = frame_times(chip, &work(c));
            let _ = writeln!(
                t,
                "| {scene} | {} ({}) | {:.1} ms | {:.1} ms | {} | {} | {} | {:.2}x | {:.0} % | {} |",
                chip.name,
                chip.core,
                f.render * 1e3,
                f.link * 1e3,
                ms_fps(f.serial),
                ms_fps(f.overlapped),
                f.two_cores.map_or("- (one core)".into(), ms_fps),
                f.serial / f.best(),
                100.0 * f.hidden,
                f.balance.map_or("-".into(), |b| format!("{:.1} %", 100.0 * b)),
            );
        }
    }
    t
}

/// The README's form: the cube on each part, serial against the best overlapped way.
pub fn compact(counts: &[BandCounts]) -> String {
    let mut t = String::from(
        "| part | serial, 1 core (today's loop) | overlapped, 1 core | overlapped, 2 cores | best / serial |\n\
         |---|---:|---:|---:|---:|\n",
    );
    for chip in &CHIPS {
        let Some(c) = counts
            .iter()
            .find(|c| c.scene == "cube" && c.target == chip.counts_from)
        else {
            continue;
        };
        let f = frame_times(chip, &work(c));
        let _ = writeln!(
            t,
            "| {} ({}) | {} | {} | {} | {:.2}x |",
            chip.name,
            chip.core,
            ms_fps(f.serial),
            ms_fps(f.overlapped),
            f.two_cores.map_or("- (one core)".into(), ms_fps),
            f.serial / f.best(),
        );
    }
    t
}

/// The measured input, per scene and instruction set (Markdown).
fn counts_table(counts: &[BandCounts]) -> String {
    let mut t = String::from(
        "| scene | counted as | pixels | binning pass, insns | bands, insns (min / max per band) | est. cycles / insn | checksum |\n\
         |---|---|---:|---:|---:|---:|---|\n",
    );
    for c in counts {
        let sum: u64 = c.bands.iter().sum();
        let _ = writeln!(
            t,
            "| {} | {} | {} | {} | {} ({} / {}) | {:.3} | {} |",
            c.scene,
            c.target,
            c.pixels,
            c.geometry,
            sum,
            c.bands.iter().min().unwrap_or(&0),
            c.bands.iter().max().unwrap_or(&0),
            c.cycles_per_insn,
            c.checksum
        );
    }
    t
}

/// `cargo xtask fps`.
pub fn fps(flags: &FpsArgs) -> ExitCode {
    let counts = match band_counts(&SCENES, !flags.no_install) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("xtask: fps: {e}");
            return ExitCode::FAILURE;
        }
    };
    let doc = format!(
        "# Frames per second on real boards (a model)\n\n\
         Written by `cargo xtask fps --docs` from the firmware's measured instruction counts; \
         do not edit by hand.\n\n{}\n{ASSUMPTIONS}\n\n## The measured work\n\n{}",
        table(&counts),
        counts_table(&counts)
    );
    println!("{doc}");
    if flags.docs {
        let path = root().join("docs").join("fps.md");
        if let Err(e) = fs::write(&path, &doc) {
            eprintln!("xtask: fps: {}: {e}", path.display());
            return ExitCode::FAILURE;
        }
        println!("fps: wrote {}", path.display());
        let readme = root().join("README.md");
        if let Err(e) = crate::mcu::write_region(&readme, "fps", &compact(&counts)) {
            eprintln!("xtask: fps: {e}");
            return ExitCode::FAILURE;
        }
        println!("fps: wrote the fps region of {}", readme.display());
    }
    ExitCode::SUCCESS
}
