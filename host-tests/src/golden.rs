//! Golden-image checks: a rendered RGB565 frame must equal, bit for bit,
//! `host-tests/golden/{name}.png`. On mismatch the actual, expected and an
//! amplified diff image are written to `target/golden-diff/` and the test
//! panics with their paths and the number of differing pixels. With
//! `FIXEL_BLESS=1` in the environment the golden is (re)written instead, and
//! whether it was new, changed (how many pixels) or unchanged is printed.
//! `target` is `$CARGO_TARGET_DIR` when set, else the workspace's `target/`.

use crate::metrics::error_image_rgb565;
use crate::png_io::{read_png_rgb565, write_png_rgb565, write_png_rgb8};
use std::path::{Path, PathBuf};

/// Where goldens are read from and diffs written to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GoldenDirs {
    /// Directory of the committed golden PNGs.
    pub golden: PathBuf,
    /// Directory receiving `.actual.png`, `.expected.png`, `.diff.png`.
    pub diff: PathBuf,
}

impl Default for GoldenDirs {
    /// `host-tests/golden` and `<target>/golden-diff`.
    fn default() -> Self {
        let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
        let target = std::env::var_os("CARGO_TARGET_DIR")
            .map(PathBuf::from)
            .unwrap_or_else(|| manifest.join("..").join("target"));
        GoldenDirs {
            golden: manifest.join("golden"),
            diff: target.join("golden-diff"),
        }
    }
}

/// What blessing did to a golden.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlessOutcome {
    /// There was no golden; it was written.
    New,
    /// The golden differed in this many pixels (all, if the size changed);
    /// it was rewritten.
    Changed(usize),
    /// The golden already matched; it was left alone.
    Unchanged,
}

/// Number of pixels that differ between two equally sized frames.
pub fn count_differences(a: &[u16], b: &[u16]) -> usize {
    a.iter().zip(b).filter(|(x, y)| x != y).count()
}

/// Whether `FIXEL_BLESS=1` is set.
pub fn blessing() -> bool {
    std::env::var("FIXEL_BLESS").is_ok_and(|v| v == "1")
}

/// Blesses (writes if new or changed) the golden `name`.
pub fn bless_golden(
    dirs: &GoldenDirs,
    name: &str,
    w: u32,
    h: u32,
    pixels: &[u16],
) -> std::io::Result<BlessOutcome> {
    let path = dirs.golden.join(format!("{name}.png"));
    let outcome = match read_png_rgb565(&path) {
        Err(_) if !path.exists() => BlessOutcome::New,
        Err(e) => return Err(e),
        Ok((gw, gh, _)) if (gw, gh) != (w, h) => BlessOutcome::Changed(pixels.len()),
        Ok((_, _, old)) => match count_differences(&old, pixels) {
            0 => BlessOutcome::Unchanged,
            n => BlessOutcome::Changed(n),
        },
    };
    if outcome != BlessOutcome::Unchanged {
        write_png_rgb565(&path, w, h, pixels)?;
    }
    Ok(outcome)
}

/// Checks `pixels` against the golden `name`. `Err` carries the message to
/// panic with (missing golden, or mismatch with the paths of the written
/// actual/expected/diff images and the count of differing pixels).
pub fn check_golden(
    dirs: &GoldenDirs,
    name: &str,
    w: u32,
    h: u32,
    pixels: &[u16],
) -> Result<(), String> {
    let path = dirs.golden.join(format!("{name}.png"));
    if !path.exists() {
        return Err(format!(
            "golden image {} is missing: run `cargo xtask bless` (or set FIXEL_BLESS=1) \
             to create it, then review and commit it",
            path.display()
        ));
    }
    let (gw, gh, expected) =
        read_png_rgb565(&path).map_err(|e| format!("reading {}: {e}", path.display()))?;
    let same_size = (gw, gh) == (w, h);
    let differing = if same_size {
        count_differences(&expected, pixels)
    } else {
        pixels.len()
    };
    if differing == 0 {
        return Ok(());
    }
    let out = |suffix: &str| dirs.diff.join(format!("{name}.{suffix}.png"));
    let io = |e: std::io::Error| format!("writing golden diff files: {e}");
    write_png_rgb565(out("actual"), w, h, pixels).map_err(io)?;
    write_png_rgb565(out("expected"), gw, gh, &expected).map_err(io)?;
    let mut msg = format!(
        "golden {name} mismatch: {differing} of {} pixels differ{}\n  actual:   {}\n  expected: {}",
        pixels.len(),
        if same_size {
            String::new()
        } else {
            format!(" (size {w}x{h}, golden {gw}x{gh})")
        },
        out("actual").display(),
        out("expected").display(),
    );
    if same_size {
        let all = vec![true; pixels.len()];
        let diff = error_image_rgb565(pixels, &all, &expected, &all);
        write_png_rgb8(out("diff"), w, h, &diff).map_err(io)?;
        msg += &format!("\n  diff:     {}", out("diff").display());
    }
    msg += "\n  if the change is intended: cargo xtask bless";
    Err(msg)
}

/// Asserts that `pixels` (`w x h` RGB565, row 0 at the top) equals the
/// golden `host-tests/golden/{name}.png` exactly, or blesses it when
/// `FIXEL_BLESS=1`. `name` may contain `/` for sub-directories.
///
/// # Panics
/// On mismatch or a missing golden (see the module docs).
pub fn assert_golden(name: &str, w: u32, h: u32, pixels: &[u16]) {
    assert_eq!(pixels.len(), (w as usize) * (h as usize), "{name}: size");
    let dirs = GoldenDirs::default();
    if blessing() {
        match bless_golden(&dirs, name, w, h, pixels) {
            Ok(BlessOutcome::New) => println!("golden {name}: new"),
            Ok(BlessOutcome::Changed(n)) => println!("golden {name}: changed ({n} pixels)"),
            Ok(BlessOutcome::Unchanged) => println!("golden {name}: unchanged"),
            Err(e) => panic!("golden {name}: cannot bless: {e}"),
        }
        return;
    }
    if let Err(msg) = check_golden(&dirs, name, w, h, pixels) {
        panic!("{msg}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bless_then_check_then_mismatch() {
        let root = std::env::temp_dir().join(format!("fixel-golden-{}", std::process::id()));
        let dirs = GoldenDirs {
            golden: root.join("golden"),
            diff: root.join("diff"),
        };
        let px: Vec<u16> = (0..6).collect();
        assert!(check_golden(&dirs, "g", 3, 2, &px)
            .unwrap_err()
            .contains("cargo xtask bless"));
        assert_eq!(
            bless_golden(&dirs, "g", 3, 2, &px).unwrap(),
            BlessOutcome::New
        );
        assert_eq!(
            bless_golden(&dirs, "g", 3, 2, &px).unwrap(),
            BlessOutcome::Unchanged
        );
        assert_eq!(check_golden(&dirs, "g", 3, 2, &px), Ok(()));
        let mut bad = px.clone();
        bad[4] = 0xffff;
        let msg = check_golden(&dirs, "g", 3, 2, &bad).unwrap_err();
        assert!(msg.contains("1 of 6 pixels"), "{msg}");
        for s in ["actual", "expected", "diff"] {
            assert!(dirs.diff.join(format!("g.{s}.png")).exists());
        }
        assert_eq!(
            bless_golden(&dirs, "g", 3, 2, &bad).unwrap(),
            BlessOutcome::Changed(1)
        );
        std::fs::remove_dir_all(root).unwrap();
    }
}
