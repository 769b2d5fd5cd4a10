//! Running tools: the workspace root and target directory, the `Cmd` runner (a command
//! with a readable rendering for headers and errors), `cargo`/`rustup` and `fmt_dur`.

use std::env;
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;

/// Workspace root (parent of this crate's manifest dir).
pub(crate) fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives one level below the workspace root")
        .to_path_buf()
}

/// A command plus a human-readable rendering of it for headers and errors.
pub(crate) struct Cmd {
    cmd: Command,
    shown: String,
}

impl Cmd {
    pub(crate) fn new(program: impl Into<OsString>, shown_program: &str, args: &[&str]) -> Self {
        let mut cmd = Command::new(program.into());
        cmd.args(args).current_dir(root()).stdin(Stdio::null());
        let mut shown = shown_program.to_string();
        for a in args {
            shown.push(' ');
            shown.push_str(a);
        }
        Cmd { cmd, shown }
    }

    pub(crate) fn env(mut self, key: &str, val: impl Into<OsString>) -> Self {
        let val = val.into();
        self.shown = format!("{key}={} {}", val.to_string_lossy(), self.shown);
        self.cmd.env(key, val);
        self
    }

    /// Runs in `dir`, relative to the workspace root (a crate outside the workspace, such as
    /// the firmware's), with the caller's target settings removed.
    pub(crate) fn in_dir(mut self, dir: &str) -> Self {
        self.shown = format!("(cd {dir} && {})", self.shown);
        without_target_env(self.cmd.current_dir(root().join(dir)));
        self
    }

    /// Runs with inherited stdout/stderr; Err carries a readable message.
    pub(crate) fn run(mut self) -> Result<(), String> {
        match self.cmd.status() {
            Ok(s) if s.success() => Ok(()),
            Ok(s) => Err(format!("`{}` failed ({s})", self.shown)),
            Err(e) => Err(format!("could not start `{}`: {e}", self.shown)),
        }
    }

    /// Runs capturing stdout (stderr passes through).
    pub(crate) fn output(mut self) -> Result<String, String> {
        self.cmd.stderr(Stdio::inherit());
        match self.cmd.output() {
            Ok(o) if o.status.success() => Ok(String::from_utf8_lossy(&o.stdout).into_owned()),
            Ok(o) => Err(format!("`{}` failed ({})", self.shown, o.status)),
            Err(e) => Err(format!("could not start `{}`: {e}", self.shown)),
        }
    }
}

/// `cmd` without the caller's flags, target and target directory: a crate built for the
/// MCU targets (the firmware's, the display example's) sets its own.
pub(crate) fn without_target_env(cmd: &mut Command) -> &mut Command {
    cmd.env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("CARGO_BUILD_TARGET")
        .env_remove("CARGO_TARGET_DIR")
}

/// `cargo <args>`, using the same cargo that launched us when known.
pub(crate) fn cargo(args: &[&str]) -> Cmd {
    let program = env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    Cmd::new(program, "cargo", args)
}

pub(crate) fn rustup(args: &[&str]) -> Cmd {
    Cmd::new("rustup", "rustup", args)
}

pub(crate) fn fmt_dur(d: Duration) -> String {
    let s = d.as_secs_f64();
    if s < 60.0 {
        format!("{s:.1}s")
    } else {
        format!("{}m{:04.1}s", (s / 60.0).floor(), s % 60.0)
    }
}

/// Cargo's target directory (`CARGO_TARGET_DIR` or `<root>/target`).
pub(crate) fn target_dir() -> PathBuf {
    match env::var_os("CARGO_TARGET_DIR") {
        Some(d) if !d.is_empty() => {
            let d = PathBuf::from(d);
            if d.is_absolute() {
                d
            } else {
                root().join(d)
            }
        }
        _ => root().join("target"),
    }
}
