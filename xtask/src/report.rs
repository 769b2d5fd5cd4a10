//! `cargo xtask report`: speed against error for every benchmark scene and mode: the
//! microcontroller counts (`mcu::report_mcu`), then the host report binaries of host-tests.

use std::process::ExitCode;
use std::time::Instant;

use crate::cmd::{cargo, fmt_dur, root, target_dir};
use crate::{mcu, usage_error};

pub(crate) fn report(flags: &[String]) -> ExitCode {
    let (mut runs, mut mcu_on, mut install, mut docs) = (7u32, true, true, false);
    let mut it = flags.iter();
    while let Some(f) = it.next() {
        match f.as_str() {
            "--runs" => match it.next().map(|n| n.parse::<u32>()) {
                Some(Ok(n)) if n > 0 => runs = n,
                _ => return usage_error("`--runs` needs a positive number"),
            },
            "--no-mcu" => mcu_on = false,
            "--no-install" => install = false,
            "--docs" => docs = true,
            other => return usage_error(&format!("unknown flag for `report`: `{other}`")),
        }
    }
    let t0 = Instant::now();
    let out = target_dir().join("report");
    if let Err(e) = std::fs::create_dir_all(&out) {
        eprintln!("report: could not create {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    let tsv = out.join("mcu.tsv");
    let _ = std::fs::remove_file(&tsv);
    if mcu_on {
        println!("==> report 1/2: microcontrollers (QEMU)");
        let mut step = |s: &str| println!("==> {s} ({})", fmt_dur(t0.elapsed()));
        match mcu::report_mcu(install, &tsv, &mut step) {
            Ok(v) => println!(
                "==> {} mode counts written to {} ({})",
                v.len(),
                tsv.display(),
                fmt_dur(t0.elapsed())
            ),
            Err(e) => {
                eprintln!("report: {e}");
                return ExitCode::FAILURE;
            }
        }
    }
    println!("==> report 2/2: host (timing, errors, plots)");
    let out_s = out.to_string_lossy().into_owned();
    let tsv_s = tsv.to_string_lossy().into_owned();
    let runs_s = runs.to_string();
    let mut args = vec![
        "run",
        "--release",
        "-q",
        "-p",
        "host-tests",
        "--bin",
        "report",
        "--",
        "--out",
        &out_s,
        "--runs",
        &runs_s,
    ];
    if mcu_on {
        args.extend(["--mcu", &tsv_s]);
    }
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Shadow maps: their rows in shadow.md (host-tests/src/bin/shadow_report.rs).
    let shadow = [
        "run",
        "--release",
        "-q",
        "-p",
        "host-tests",
        "--bin",
        "shadow_report",
    ];
    let shadow_mcu: &[&str] = if mcu_on { &["--mcu", &tsv_s] } else { &[] };
    if let Err(e) = cargo(&[&shadow[..], &["--", "--out", &out_s], shadow_mcu].concat()).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Solid textures: their own report, same output directory and MCU counts.
    args[6] = "noise_report";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Environment mapping rows: same flags, written to env.md.
    args[6] = "report_env";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Texture-coordinate generation rows: same flags, written to mapping.md.
    args[6] = "mapping_report";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Anti-aliasing rows: same flags, written to aa.md.
    args[6] = "aa_report";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    // Surface-detail rows (per-pixel lighting, bump, normal maps): surface.md.
    args[6] = "surface_report";
    if let Err(e) = cargo(&args).run() {
        eprintln!("report: {e}");
        return ExitCode::FAILURE;
    }
    if docs {
        let dst = root().join("docs").join("report");
        let copied = std::fs::create_dir_all(&dst).and_then(|()| {
            for e in std::fs::read_dir(&out)? {
                let p = e?.path();
                let ext = p.extension().and_then(|x| x.to_str());
                if matches!(ext, Some("md" | "png")) {
                    std::fs::copy(&p, dst.join(p.file_name().unwrap_or_default()))?;
                }
            }
            Ok(())
        });
        match copied {
            Ok(()) => println!("==> copied report.md and the plots to {}", dst.display()),
            Err(e) => {
                eprintln!("report: could not copy to {}: {e}", dst.display());
                return ExitCode::FAILURE;
            }
        }
    }
    println!(
        "==> report done in {}: {} and the plots {}/*.png",
        fmt_dur(t0.elapsed()),
        out.join("report.md").display(),
        out.display()
    );
    ExitCode::SUCCESS
}
