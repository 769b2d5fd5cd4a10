//! The `publish (dry run)` step of `cargo xtask ci` (and `cargo xtask package`): what
//! crates.io would get.
//!
//! `cargo publish --dry-run -p fixel` packages the library and builds the package as a
//! user's download would be built; then the package's file list must hold only the library
//! (`src/`, `build.rs`), the README, the changelog, the licence texts and the files cargo
//! adds, and the `.crate` (`cargo package --no-verify`) must stay within
//! [`MAX_CRATE_BYTES`]. Last, the documentation is built for `thumbv7em-none-eabihf` with
//! warnings denied, as docs.rs builds it from `[package.metadata.docs.rs]`.

use std::env;
use std::fs;

use crate::cmd::{cargo, target_dir};

/// The largest `.crate` accepted (compressed), in bytes.
const MAX_CRATE_BYTES: u64 = 1024 * 1024;

/// Files the package must hold.
const REQUIRED: [&str; 5] = [
    "README.md",
    "CHANGELOG.md",
    "LICENSE-MIT",
    "LICENSE-APACHE",
    "src/lib.rs",
];

/// Files cargo writes into every package besides the `include` list.
const CARGO_FILES: [&str; 4] = [
    "Cargo.toml",
    "Cargo.toml.orig",
    "Cargo.lock",
    ".cargo_vcs_info.json",
];

/// Whether `path` (as `cargo package --list` prints it) belongs in the package.
fn allowed(path: &str) -> bool {
    path.starts_with("src/")
        || path == "build.rs"
        || REQUIRED.contains(&path)
        || CARGO_FILES.contains(&path)
}

/// The docs.rs target besides the host's (`[package.metadata.docs.rs]` in `Cargo.toml`).
const DOCS_TARGET: &str = "thumbv7em-none-eabihf";

/// The step: dry-run publish, file list, size, docs.rs build. Err says what is wrong.
pub(crate) fn check() -> Result<(), String> {
    // `--allow-dirty`: a local run may have uncommitted work; CI's clone is clean anyway.
    cargo(&["publish", "--dry-run", "--allow-dirty", "-p", "fixel"]).run()?;

    let list = cargo(&["package", "--list", "--allow-dirty", "-p", "fixel"]).output()?;
    let files: Vec<&str> = list
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    let stray: Vec<&str> = files.iter().copied().filter(|f| !allowed(f)).collect();
    if !stray.is_empty() {
        return Err(format!(
            "the package holds files outside the library: {} (see `include` in Cargo.toml)",
            stray.join(", ")
        ));
    }
    let missing: Vec<&str> = REQUIRED
        .iter()
        .copied()
        .filter(|r| !files.contains(r))
        .collect();
    if !missing.is_empty() {
        return Err(format!("the package lacks {}", missing.join(", ")));
    }

    // `publish --dry-run` leaves no `.crate` behind: package again, unverified (the
    // dry run built it), to weigh it.
    cargo(&["package", "--no-verify", "--allow-dirty", "-p", "fixel"]).run()?;
    let version = cargo_version()?;
    let krate = target_dir()
        .join("package")
        .join(format!("fixel-{version}.crate"));
    let bytes = fs::metadata(&krate)
        .map_err(|e| format!("{}: {e}", krate.display()))?
        .len();
    println!(
        "package: {} files, {} ({:.1} KiB compressed, limit {} KiB)",
        files.len(),
        krate.display(),
        bytes as f64 / 1024.0,
        MAX_CRATE_BYTES / 1024
    );
    if bytes > MAX_CRATE_BYTES {
        return Err(format!(
            "fixel-{version}.crate is {bytes} B, over the {MAX_CRATE_BYTES} B limit"
        ));
    }

    let mut flags = env::var("RUSTDOCFLAGS").unwrap_or_default();
    if !flags.is_empty() {
        flags.push(' ');
    }
    flags.push_str("-D warnings");
    cargo(&["doc", "-p", "fixel", "--no-deps", "--target", DOCS_TARGET])
        .env("RUSTDOCFLAGS", flags)
        .run()
}

/// fixel's version: the `version` line of the root `Cargo.toml`'s `[package]` table.
fn cargo_version() -> Result<String, String> {
    let path = crate::cmd::root().join("Cargo.toml");
    let text = fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut in_package = false;
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            in_package = line == "[package]";
        } else if in_package {
            if let Some(v) = line.strip_prefix("version") {
                let v = v.trim_start().trim_start_matches('=').trim();
                return Ok(v.trim_matches('"').to_string());
            }
        }
    }
    Err("no version in the [package] table of Cargo.toml".into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_library_and_its_texts_are_allowed_and_nothing_else() {
        for f in [
            "src/lib.rs",
            "src/texture/wrap.rs",
            "build.rs",
            "README.md",
            "CHANGELOG.md",
            "LICENSE-MIT",
            "Cargo.toml.orig",
        ] {
            assert!(allowed(f), "{f}");
        }
        for f in [
            "docs/images/sphere.png",
            "assets/teapot/teapot.obj",
            "examples/preview.rs",
            "xtask/src/ci.rs",
            "host-tests/Cargo.toml",
        ] {
            assert!(!allowed(f), "{f}");
        }
    }

    #[test]
    fn the_version_is_read_from_the_package_table() {
        let v = cargo_version().expect("version");
        assert_eq!(v.split('.').count(), 3, "{v}");
        assert!(v.split('.').all(|n| n.parse::<u32>().is_ok()), "{v}");
    }
}
