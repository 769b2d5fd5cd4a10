//! `cargo xtask size`: flash and RAM of a minimal firmware per feature set, on every MCU.

use std::collections::BTreeMap;
use std::process::ExitCode;

use super::firmware::{build_firmware, elf, sizes};
use super::qemu::{kv, num, qemu};
use super::tools::{ensure_tools, rustc_version};
use super::{fail, firmware_dir, SizeArgs, MCUS};

/// Size firmwares, in the order of the table.
const SIZES: [(&str, &str); 13] = [
    ("size_base", "harness only (no fixel)"),
    ("size_affine", "textured affine nearest unlit triangle"),
    (
        "size_affine_unclipped",
        "the same, no clipper (Draw::project_unclipped: geometry stays in view)",
    ),
    (
        "size_open",
        "the same triangle through the open stage (ShadedDraw + Replace, u and v from the \
         firmware's own vertex function, bands by Frame::at_row, clipped)",
    ),
    (
        "size_open_unclipped",
        "the same, no clipper (ShadedDraw::project_unclipped)",
    ),
    ("size_perspective", "+ perspective-correct"),
    ("size_bilinear", "+ bilinear"),
    ("size_lighting", "+ lighting"),
    ("size_depth", "+ depth buffer"),
    ("size_everything", "everything (Draw::dynamic)"),
    (
        "size_noise",
        "lit band-limited marble solid texture (ShadedDraw, no texture)",
    ),
    (
        "size_env",
        "depth-tested cube-map mirror (per-pixel r, bilinear, exact)",
    ),
    (
        "size_bump",
        "bump-mapped, per-pixel lit (derivative map, Blinn-Phong, bilinear, exact, depth)",
    ),
];

/// `cargo xtask size`.
pub fn size(flags: &SizeArgs) -> ExitCode {
    let llvm = match ensure_tools(!flags.no_install) {
        Ok(l) => l,
        Err(e) => return fail(e),
    };
    // Only the size firmwares: the others are built (and laid out) by `mcu` and `report`;
    // a report firmware in the band layout's 256 KB of flash is not one that is run.
    let bins: Vec<&str> = SIZES.iter().map(|(b, _)| *b).collect();
    if let Err(e) = build_firmware(&[], None, Some(&bins)) {
        return fail(e);
    }
    let opt_s_dir = firmware_dir().join("target").join("opt-s");
    if flags.opt_s {
        if let Err(e) = build_firmware(
            &[("CARGO_PROFILE_RELEASE_OPT_LEVEL", "s")],
            Some(&opt_s_dir),
            Some(&bins),
        ) {
            return fail(e);
        }
    }
    let td = firmware_dir().join("target");
    let mut problems = Vec::new();
    println!("\n## cargo xtask size: {}\n", rustc_version());
    println!(
        "One textured triangle through the scene path (mesh -> camera -> clip -> 320x240 in \
         8-row bands), 8x8 texture; each row adds one feature to the previous. fixel = flash - \
         flash of `size_base` (same harness: semihosting printing, checksum, no fixel). \
         RAM = data + bss + measured stack (band buffers are on the stack). opt-level 3, LTO.\n"
    );
    let mut head = String::from("| firmware |");
    let mut rule = String::from("|---|");
    for m in &MCUS {
        head.push_str(&format!(" {0} flash | {0} fixel | {0} RAM |", m.label));
        rule.push_str("---:|---:|---:|");
        if flags.opt_s {
            head.push_str(&format!(" {} fixel (opt s) |", m.label));
            rule.push_str("---:|");
        }
    }
    println!("{head}\n{rule}");
    let mut base = [0u64; 3];
    let mut base_s = [0u64; 3];
    let mut checks: BTreeMap<&str, Vec<String>> = BTreeMap::new();
    for (bin, what) in SIZES {
        let mut row = format!("| {what} |");
        for (i, m) in MCUS.iter().enumerate() {
            let e = elf(&td, m, bin);
            let (flash, ram) = match sizes(&llvm, &e) {
                Ok(x) => x,
                Err(err) => return fail(err),
            };
            let stack = match qemu(m, &e, None) {
                Ok((true, out, _)) => {
                    checks
                        .entry(bin)
                        .or_default()
                        .push(kv(&out, "checksum").unwrap_or("?").to_string());
                    num(&out, "stack").unwrap_or(0)
                }
                Ok((false, out, err)) => {
                    problems.push(format!("{bin} on {}: {out}{err}", m.label));
                    0
                }
                Err(err) => {
                    problems.push(err);
                    0
                }
            };
            if bin == "size_base" {
                base[i] = flash;
            }
            row.push_str(&format!(
                " {flash} | {} | {} |",
                if bin == "size_base" {
                    "-".to_string()
                } else {
                    (flash as i64 - base[i] as i64).to_string()
                },
                ram + stack
            ));
            if flags.opt_s {
                let f = sizes(&llvm, &elf(&opt_s_dir, m, bin))
                    .map(|x| x.0)
                    .unwrap_or(0);
                if bin == "size_base" {
                    base_s[i] = f;
                    row.push_str(" - |");
                } else {
                    row.push_str(&format!(" {} |", f as i64 - base_s[i] as i64));
                }
            }
        }
        println!("{row}");
    }
    for (bin, c) in &checks {
        if c.iter().any(|x| x != &c[0]) {
            problems.push(format!("{bin}: targets disagree on the frame: {c:?}"));
        }
    }
    // The minimal firmwares draw one frame, through the classic draw and the open stage.
    for bin in ["size_affine_unclipped", "size_open", "size_open_unclipped"] {
        if checks.get(bin) != checks.get("size_affine") {
            problems.push(format!(
                "{bin} and size_affine draw different frames: {:?} vs {:?}",
                checks.get(bin),
                checks.get("size_affine")
            ));
        }
    }
    if problems.is_empty() {
        println!(
            "\nsize: every firmware ran; each gives the same frame checksum on all three targets"
        );
        ExitCode::SUCCESS
    } else {
        for p in &problems {
            eprintln!("size: FAIL: {p}");
        }
        ExitCode::FAILURE
    }
}
