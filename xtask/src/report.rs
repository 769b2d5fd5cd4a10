//! `cargo xtask report`: speed against error for every benchmark scene and mode: the
//! microcontroller counts (`mcu::report_mcu`), then the host report binaries of host-tests.

use std::process::ExitCode;
use std::time::Instant;

use clap::Args;

use crate::cmd::{cargo, fmt_dur, root, target_dir};
use crate::mcu;

/// Flags of `cargo xtask report`.
#[derive(Args, Clone, Debug)]
pub(crate) struct ReportArgs {
    /// Timed host runs of each scene's frames (ns per pixel: median, min, max)
    #[arg(
        long,
        value_name = "N",
        default_value_t = 7,
        value_parser = clap::value_parser!(u32).range(1..)
    )]
    pub runs: u32,
    /// Host only (no QEMU columns)
    #[arg(long)]
    pub no_mcu: bool,
    /// Do not install missing tools (see `mcu`)
    #[arg(long)]
    pub no_install: bool,
    /// Also copy report.md and the plots to docs/report/
    #[arg(long)]
    pub docs: bool,
    /// Run only this host report binary (repeatable: `--only aa_report`) and only the
    /// report firmwares it reads: its own page (`--docs` copies what it wrote)
    #[arg(long, value_name = "REPORT", value_parser = clap::builder::PossibleValuesParser::new(HOST_REPORTS.map(|r| r.0)))]
    pub only: Vec<String>,
}

/// The host report binaries of host-tests, run in this order, each with `--out` (the
/// report directory) and, with the microcontrollers, `--mcu` (their counts); `true`: the
/// binary also takes `--runs`; then the report firmwares whose counts it reads (`None`:
/// any, so all of them), which `--only` runs.
type HostReport = (&'static str, bool, Option<&'static [&'static str]>);
const HOST_REPORTS: [HostReport; 8] = [
    // Every benchmark scene and mode: report.md and the plots.
    ("report", true, None),
    // Shadow maps: their rows in shadow.md (host-tests/src/bin/shadow_report.rs).
    ("shadow_report", false, Some(&["report_shadow"])),
    // Solid textures: noise.md.
    ("noise_report", true, None),
    // Environment mapping rows: env.md.
    ("report_env", true, None),
    // Texture-coordinate generation rows: mapping.md.
    ("mapping_report", true, Some(&["report_mapping"])),
    // Anti-aliasing rows and the transparency rows: aa.md.
    ("aa_report", true, Some(&["report_aa", "report_alpha"])),
    // Surface-detail rows (per-pixel lighting, bump, normal maps): surface.md.
    ("surface_report", true, Some(&["report_surface"])),
    // Palette textures on the floor and cube against RGB565 (flash, speed, error):
    // palette.md, its instructions from docs/mcu.md.
    ("palette_report", true, None),
];

pub(crate) fn report(args: &ReportArgs) -> ExitCode {
    let (runs, mcu_on, install, docs) = (args.runs, !args.no_mcu, !args.no_install, args.docs);
    let hosts: Vec<HostReport> = HOST_REPORTS
        .into_iter()
        .filter(|r| args.only.is_empty() || args.only.iter().any(|o| o == r.0))
        .collect();
    // The report firmwares to run: those the chosen reports read (`None`: all).
    let firmwares: Option<Vec<&str>> = if args.only.is_empty() {
        None
    } else {
        hosts.iter().try_fold(Vec::new(), |mut all, r| {
            all.extend(r.2?);
            Some(all)
        })
    };
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
        match mcu::report_mcu(install, &tsv, firmwares.as_deref(), &mut step) {
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
    for (bin, timed, _) in hosts {
        let mut args = vec![
            "run",
            "--release",
            "-q",
            "-p",
            "host-tests",
            "--bin",
            bin,
            "--",
            "--out",
            &out_s,
        ];
        if timed {
            args.extend(["--runs", &runs_s]);
        }
        if mcu_on {
            args.extend(["--mcu", &tsv_s]);
        }
        if let Err(e) = cargo(&args).run() {
            eprintln!("report: {e}");
            return ExitCode::FAILURE;
        }
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
