//! `cargo xtask mcu`: every scene firmware on every MCU under QEMU, each frame checksum
//! checked against the host's, and the tables (instructions and cycles per pixel, flash,
//! RAM, bands against whole frame, geometry, repeatability).

use std::collections::BTreeMap;
use std::fs;
use std::path::Path;
use std::process::{Command, ExitCode};
use std::time::Instant;

use super::bands::{self, Figures};
use super::firmware::{build_firmware, build_whole, elf, sizes};
use super::qemu::{kv, measure, measure_modes, num, qemu};
use super::tools::{build_plugin, ensure_tools, output, qemu_version, run_visible, rustc_version};
use super::{
    fail, firmware_dir, out_dir, McuArgs, DSP_CHECK, GEOMETRY, MCUS, SCENES, WHOLE_MCUS,
    WHOLE_SCENES,
};
use crate::cmd::root;
use crate::cmd::without_target_env;
use crate::progress::Progress;

/// The [`DSP_CHECK`] firmware on each MCU: its line per MCU, or what failed. It must exit
/// with success, report no mismatch, and run the assembly loop exactly on Cortex-M4F (the
/// one ARMv7E-M core here). One `progress` step per MCU.
fn dsp_check(td: &Path, progress: &mut Progress) -> Result<String, String> {
    let mut lines = String::new();
    for m in &WHOLE_MCUS {
        progress.start(&format!("{DSP_CHECK} on {}", m.label));
        let run = qemu(m, &elf(td, m, DSP_CHECK), None);
        let verdict = run.and_then(|(ok, out, _)| {
            let line = out
                .lines()
                .find(|l| l.starts_with(DSP_CHECK))
                .ok_or_else(|| format!("no `{DSP_CHECK}` line in its output"))?;
            let want = if m.triple.starts_with("thumbv7em") {
                "asm"
            } else {
                "none"
            };
            if !ok || num(line, "mismatches") != Some(0) || kv(line, "loop") != Some(want) {
                return Err(format!(
                    "expected success, loop={want} and no mismatch: {line}"
                ));
            }
            Ok(line.to_string())
        });
        progress.done(verdict.is_ok());
        let line = verdict.map_err(|e| format!("{DSP_CHECK} on {}: {e}", m.label))?;
        lines.push_str(&format!("- {}: `{line}`\n", m.label));
    }
    Ok(lines)
}

/// The geometry firmware on each MCU: a table of instructions per item and stage. One
/// `progress` step per MCU.
fn geometry_table(
    llvm: &Path,
    plugin: &Path,
    td: &Path,
    progress: &mut Progress,
) -> Result<String, String> {
    let mut per: BTreeMap<(String, String), Vec<String>> = BTreeMap::new();
    let mut order: Vec<(String, String)> = Vec::new();
    let mut items: BTreeMap<(String, String), u64> = BTreeMap::new();
    for m in &WHOLE_MCUS {
        progress.start(&format!("geometry on {}", m.label));
        let v = measure_modes(llvm, plugin, m, &elf(td, m, "geometry"));
        progress.done(v.is_ok());
        for c in v? {
            let key = (c.scene.clone(), c.mode.clone());
            if !order.contains(&key) {
                order.push(key.clone());
            }
            items.insert(key.clone(), c.pixels);
            per.entry(key).or_default().push(format!(
                "{:.1}",
                c.instructions as f64 / c.pixels.max(1) as f64
            ));
        }
    }
    let mut t = String::from(
        "| mesh | stage | per | items | Cortex-M4F | Cortex-M0+ | RV32IMC |\n|---|---|---|---:|---:|---:|---:|\n",
    );
    for key in &order {
        let unit = match key.1.as_str() {
            "transform" | "lighting" | "project" => "vertex",
            "face" | "cull" | "walk" | "face_baked" | "walk_baked" => "mesh triangle",
            "clip" => "crossing triangle",
            _ => "kept triangle",
        };
        let v = per.get(key).cloned().unwrap_or_default();
        t.push_str(&format!(
            "| {} | {} | {unit} | {} | {} |\n",
            key.0,
            key.1,
            items.get(key).copied().unwrap_or(0),
            v.join(" | ")
        ));
    }
    Ok(t)
}

const CYCLE_MODEL: &str = "\
est. cycles = static model over the exact per-PC histogram of the counted region
(xtask/mcu/cycles.py), zero-wait-state memory, no bus contention:
  Cortex-M4F: ALU/MUL/MLA 1, load/store 2 (1 when following another), LDM/STM/PUSH/POP 1+N,
              taken branch 1+P (P=2), VFP 1 (VMLA 3, VDIV 14), SDIV/UDIV 7 (worst 12)
  Cortex-M0+: ALU 1, single-cycle MULS (RP2040/STM32G0 class), load/store 2, taken branch 2,
              BL 3, PUSH/POP 1+N (+2 with PC); QEMU runs the ARMv6-M code on mps2-an386
  RV32IMC:    generic single-issue in-order (SiFive E31-like): ALU/MUL 1, load 2, store 1,
              DIV/REM 33, taken branch/jump 3, not-taken 1
Real parts add flash wait states (hidden by caches on some) and contention: an estimate.";

/// Expected checksums and pixel counts from the host test (same code, same frames).
pub(super) fn host_expected() -> Result<BTreeMap<String, (String, u64)>, String> {
    // The `ci` profile: `cargo xtask ci` has built it already for its test step.
    let what = "cargo test -q --profile ci -p host-tests --test mcu_checksums --test shadow_mcu \
                --test model_mcu --test palette_mcu -- --nocapture";
    eprintln!("xtask: $ {what} (the host's checksums)");
    let out = output(
        Command::new("cargo").current_dir(root()).args([
            "test",
            "-q",
            "--profile",
            "ci",
            "-p",
            "host-tests",
            "--test",
            "mcu_checksums",
            "--test",
            "shadow_mcu",
            "--test",
            "model_mcu",
            "--test",
            "palette_mcu",
            "--",
            "--nocapture",
        ]),
        what,
    )?;
    let mut m = BTreeMap::new();
    // `cargo test -q` prints a `.` per finished test, possibly at the start of another
    // test's line (mcu_checksums runs two tests in parallel).
    let lines = out.lines().map(|l| l.trim_start_matches('.'));
    for l in lines.filter(|l| l.starts_with("mcu-expected ")) {
        if let (Some(s), Some(c), Some(p)) = (kv(l, "scene"), kv(l, "checksum"), num(l, "pixels")) {
            m.insert(s.to_string(), (c.to_string(), p));
        }
    }
    if m.len() != SCENES.len() + WHOLE_SCENES.len() {
        return Err(format!(
            "host test printed {} expected checksums, wanted {}",
            m.len(),
            SCENES.len() + WHOLE_SCENES.len()
        ));
    }
    Ok(m)
}

/// Builds the real-display example (ST7789 via mipidsi) for Cortex-M4F: a compile check.
fn check_display_example() -> Result<(), String> {
    run_visible(
        without_target_env(
            Command::new("cargo")
                .current_dir(root().join("examples").join("display"))
                .args(["build", "--release", "--target", "thumbv7em-none-eabihf"]),
        ),
        "(cd examples/display && cargo build --release --target thumbv7em-none-eabihf)",
    )
}

/// `cargo xtask mcu`.
pub fn mcu(flags: &McuArgs) -> ExitCode {
    let t0 = Instant::now();
    let llvm = match ensure_tools(!flags.no_install) {
        Ok(l) => l,
        Err(e) => return fail(e),
    };
    let plugin = match build_plugin() {
        Ok(p) => p,
        Err(e) => return fail(e),
    };
    // The band scenes it runs (all of them, or the `--only` ones).
    let scenes: Vec<&str> = SCENES
        .iter()
        .copied()
        .filter(|s| flags.runs_firmware(s))
        .collect();
    if let Err(e) = build_firmware(&[], None, Some(&scenes)) {
        return fail(e);
    }
    // The real-display example (ST7789 via mipidsi): compile check only (not with `--only`,
    // which measures named firmwares).
    if flags.only.is_empty() {
        if let Err(e) = check_display_example() {
            return fail(e);
        }
    }
    let expected = match host_expected() {
        Ok(x) => x,
        Err(e) => return fail(e),
    };
    let opt_s_dir = firmware_dir().join("target").join("opt-s");
    if flags.opt_s {
        if let Err(e) = build_firmware(
            &[("CARGO_PROFILE_RELEASE_OPT_LEVEL", "s")],
            Some(&opt_s_dir),
            Some(&scenes),
        ) {
            return fail(e);
        }
    }
    let td = firmware_dir().join("target");
    let td_whole = firmware_dir().join("target").join("whole");
    if let Err(e) = build_whole(&td_whole, |b| flags.runs_firmware(b)) {
        return fail(e);
    }

    let mut report = String::new();
    let mut problems = Vec::new();
    let mut profiles = String::new();
    let mut repeat = String::new();
    report.push_str(
        "| scene | target | insns/px (exact) | est. cycles/px | pixels | checksum | = host | flash B | RAM B (static + stack) |",
    );
    if flags.opt_s {
        report.push_str(" flash B (opt s) |");
    }
    report.push_str("\n|---|---|---:|---:|---:|---|---|---:|---:|");
    if flags.opt_s {
        report.push_str("---:|");
    }
    report.push('\n');
    let mut figures = Figures::default();
    let sets: Vec<_> = SCENES
        .iter()
        .map(|s| (*s, &MCUS, &td))
        .chain(WHOLE_SCENES.iter().map(|s| (*s, &WHOLE_MCUS, &td_whole)))
        .filter(|(s, _, _)| flags.runs_firmware(s))
        .collect();
    let with_geometry = flags.runs_firmware(GEOMETRY);
    let with_dsp_check = flags.runs_firmware(DSP_CHECK);
    // One step per QEMU firmware run (scene and MCU), then the geometry firmware's and the
    // check's.
    let steps = sets.iter().map(|(_, m, _)| m.len()).sum::<usize>()
        + (usize::from(with_geometry) + usize::from(with_dsp_check)) * WHOLE_MCUS.len();
    let mut progress = Progress::new("mcu", steps);
    for (scene, mcus, td) in sets {
        for m in mcus.iter() {
            progress.start(&format!("{scene} on {}", m.label));
            let e = elf(td, m, scene);
            let (r, seen) = match measure(&llvm, &plugin, m, &e, flags.runs) {
                Ok(x) => x,
                Err(err) => {
                    progress.done(false);
                    problems.push(format!("{scene} on {}: {err}", m.label));
                    continue;
                }
            };
            let (flash, ram) = match sizes(&llvm, &e) {
                Ok(x) => x,
                Err(err) => {
                    progress.done(false);
                    progress.finish();
                    return fail(err);
                }
            };
            let (want_c, want_p) = expected.get(scene).cloned().unwrap_or_default();
            let matches = r.checksum == want_c && r.pixels == want_p;
            if !matches {
                problems.push(format!(
                    "{scene} on {}: checksum {} pixels {} but the host has {want_c} pixels {want_p}",
                    m.label, r.checksum, r.pixels
                ));
            }
            let same = seen.iter().all(|s| *s == seen[0]);
            if !same {
                problems.push(format!("{scene} on {}: runs differ: {seen:?}", m.label));
            }
            repeat.push_str(&format!(
                "{scene:>14} {:<11} {}\n",
                m.label,
                seen.iter()
                    .map(|(t, n)| format!("total={t} counted={n}"))
                    .collect::<Vec<_>>()
                    .join(" | ")
            ));
            let px = r.pixels.max(1) as f64;
            let key = (scene.to_string(), m.label);
            figures.per_px.insert(key.clone(), r.net as f64 / px);
            figures.ram.insert(key.clone(), ram + r.stack);
            figures.frame.insert(key.clone(), (r.net, r.est_cycles));
            if let Some(g) = r.geometry {
                figures.geometry.insert(key, g as f64 / r.net.max(1) as f64);
            }
            report.push_str(&format!(
                "| {scene}{} | {} | {:.2} | {:.1} | {} | {} | {} | {} | {} ({} + {}) |",
                if r.rewalked { " (rewalk)" } else { "" },
                m.label,
                r.net as f64 / px,
                r.est_cycles / px,
                r.pixels,
                r.checksum,
                if matches { "yes" } else { "**NO**" },
                flash,
                ram + r.stack,
                ram,
                r.stack,
            ));
            if flags.opt_s {
                let f = if *td == td_whole {
                    "-".to_string()
                } else {
                    sizes(&llvm, &elf(&opt_s_dir, m, scene))
                        .map(|(f, _)| f.to_string())
                        .unwrap_or_else(|_| "?".into())
                };
                report.push_str(&format!(" {f} |"));
            }
            report.push('\n');
            if flags.profile {
                profiles.push_str(&format!(
                    "{scene} on {} ({} counted instructions, {} in the whole run):\n  {}\n",
                    m.label, r.net, r.total, r.mix
                ));
                for p in &r.profile {
                    profiles.push_str(&format!("  {p}\n"));
                }
            }
            progress.done(matches && same);
        }
    }
    let geometry = with_geometry.then(|| geometry_table(&llvm, &plugin, &td_whole, &mut progress));
    let dsp = with_dsp_check.then(|| dsp_check(&td_whole, &mut progress));
    progress.finish();
    println!(
        "\n## cargo xtask mcu: {}, {}\n",
        rustc_version(),
        qemu_version()
    );
    println!(
        "Frame 0 of each scene, 320x240 RGB565 (the glTF models fox and cesium_man: 240x320) in \
         bands of 8 rows (colour + 16-bit depth band; \
         16 triangle bins for the cube and floor, a 2-byte band range per triangle for the \
         sphere; 24 KB of RAM), one frame per run (QEMU is deterministic: one frame is enough).\n\
         insns/px = instructions executed by the renderer (geometry, binning, band clears, \
         raster) / pixels that passed the depth test; the harness's checksum of each band is \
         outside the counted region. (rewalk) = storage overflowed, some geometry ran once per band.\n\
         flash = vector table + text + rodata + data (textures and the sphere mesh are in \
         flash); RAM = data + bss + measured stack high-water mark (band buffers are on the stack).\n"
    );
    print!("{report}");
    // Kept for reports that quote these counts (host-tests' shadow_report reads it): only
    // when every scene ran.
    if flags.only.is_empty() {
        let _ = fs::write(out_dir().join("scenes.md"), &report);
    }
    println!(
        "\nwhole_* = the same frame drawn into one 320x240 frame (colour + 16-bit depth, \
         300 KiB) with one prepared vertex per mesh vertex, on mps2-an386 (both Arm builds) \
         and RV32 virt: the figures to set beside whole-frame renderers. geometry = the share \
         of the banded count spent up to the end of the frame's binning pass (walk, transform, \
         clip, project, bin: `bench_geometry` in the scene), the rest in the bands (clears, \
         set-ups, spans, and the triangles a band re-projects).\n"
    );
    let (bands_table, missed) = bands::table(&figures);
    print!("{bands_table}");
    if missed.is_empty() {
        println!(
            "\nEvery banded technique scene is within {}x of its whole frame.",
            bands::BAR
        );
    } else {
        println!("\nBars missed (banded technique scene against its whole frame):");
        for m in &missed {
            println!("  {m}");
        }
    }
    if flags.docs {
        if !flags.only.is_empty() {
            problems.push("--docs writes the tables of a full run: drop --only".into());
        } else {
            let compact = bands::compact(&figures);
            let doc = format!(
                "# Scenes on microcontrollers\n\nWritten by `cargo xtask mcu --docs` ({}, {}). \
                 Frame 0 of each scene, 320 x 240 RGB565; exact instructions per drawn pixel \
                 under QEMU; RAM = static data + measured stack.\n\n## Every scene\n\n{report}\n\
                 ## Bands against the whole frame\n\n{bands_table}\n",
                rustc_version(),
                qemu_version()
            );
            let results = [
                fs::write(root().join("docs").join("mcu.md"), doc).map_err(|e| e.to_string()),
                bands::write_region(&root().join("README.md"), "mcu-bands", &compact),
                bands::write_region(&root().join("README.md"), "tgx", &bands::tgx(&figures)),
                bands::write_region(
                    &root().join("README.md"),
                    "models",
                    &bands::models(&figures),
                ),
                bands::write_region(
                    &root().join("README.md"),
                    "realtime",
                    &bands::realtime(&figures),
                ),
                bands::write_region(
                    &root().join("README.md"),
                    "choose",
                    &super::choose::table(&figures),
                ),
            ];
            for r in results {
                if let Err(e) = r {
                    problems.push(format!("--docs: {e}"));
                }
            }
        }
    }
    match geometry.unwrap_or(Ok(String::new())) {
        Ok(t) if t.is_empty() => {}
        Ok(t) => println!(
            "\nGeometry on its own (`geometry` firmware, sphere camera, frame 0): instructions \
             per item and stage\n\n{t}"
        ),
        Err(e) => problems.push(format!("geometry firmware: {e}")),
    }
    match dsp {
        None => {}
        Some(Ok(lines)) => println!(
            "\nThe ARMv7E-M span loops (`dsp_span` firmware: the assembly loops of \
             `BilinearFootprintSized` and `BilinearFootprint` against the generic sampler and \
             depth test, pixel by pixel, random spans):\n\n{lines}"
        ),
        Some(Err(e)) => problems.push(e),
    }
    println!("\n{CYCLE_MODEL}\n");
    println!(
        "Repeatability ({} runs each, instruction counts):\n{repeat}",
        flags.runs
    );
    if flags.profile {
        println!("Where the instructions go (per function, inlined code included):\n{profiles}");
    }
    println!("mcu: done in {:.1} s", t0.elapsed().as_secs_f64());
    if problems.is_empty() {
        println!("mcu: all checksums equal the host's; all runs identical");
        ExitCode::SUCCESS
    } else {
        for p in &problems {
            eprintln!("mcu: FAIL: {p}");
        }
        ExitCode::FAILURE
    }
}
