//! Host tools for the MCU runs: running commands, installing what is missing (rust
//! targets, llvm-tools, QEMU, gcc, python3), building the icount plugin, tool versions.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use super::{firmware_dir, out_dir, MCUS};
use crate::cmd::root;

/// Runs `cmd`, streaming its output; error text on failure.
pub(super) fn run_visible(cmd: &mut Command, what: &str) -> Result<(), String> {
    eprintln!("xtask: $ {what}");
    match cmd.status() {
        Ok(s) if s.success() => Ok(()),
        Ok(s) => Err(format!("`{what}` failed ({s})")),
        Err(e) => Err(format!("`{what}` could not start: {e}")),
    }
}

/// Runs `cmd` and returns its stdout (stderr passed through).
pub(super) fn output(cmd: &mut Command, what: &str) -> Result<String, String> {
    let out = cmd
        .stderr(Stdio::inherit())
        .output()
        .map_err(|e| format!("`{what}` could not start: {e}"))?;
    if !out.status.success() {
        return Err(format!("`{what}` failed ({})", out.status));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

fn have(program: &str) -> bool {
    Command::new(program)
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok()
}

fn is_root() -> bool {
    Command::new("id")
        .arg("-u")
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim() == "0")
        .unwrap_or(false)
}

/// apt-get install (as root, or through passwordless sudo), after an `apt-get update`;
/// waits up to 5 minutes for another apt-get to release the package database.
pub(crate) fn apt_install(packages: &[&str]) -> Result<(), String> {
    let sudo = !is_root();
    let cmd = |args: &[&str]| {
        let mut c = if sudo {
            let mut c = Command::new("sudo");
            c.args(["-n", "env", "DEBIAN_FRONTEND=noninteractive", "apt-get"]);
            c
        } else {
            let mut c = Command::new("apt-get");
            c.env("DEBIAN_FRONTEND", "noninteractive");
            c
        };
        c.args(args);
        c
    };
    run_visible(&mut cmd(&["update"]), "apt-get update")?;
    let mut args = vec![
        "-o",
        "DPkg::Lock::Timeout=300",
        "install",
        "-y",
        "--no-install-recommends",
    ];
    args.extend_from_slice(packages);
    run_visible(
        &mut cmd(&args),
        &format!(
            "apt-get -o DPkg::Lock::Timeout=300 install -y --no-install-recommends {}",
            packages.join(" ")
        ),
    )
}

/// The `llvm-tools` binaries directory of the active toolchain.
fn llvm_bin() -> Result<PathBuf, String> {
    let sysroot = output(
        Command::new("rustc")
            .args(["--print", "sysroot"])
            .current_dir(root()),
        "rustc --print sysroot",
    )?;
    let vv = output(
        Command::new("rustc").arg("-vV").current_dir(root()),
        "rustc -vV",
    )?;
    let host = vv
        .lines()
        .find_map(|l| l.strip_prefix("host: "))
        .ok_or("rustc -vV printed no host")?;
    Ok(Path::new(sysroot.trim())
        .join("lib/rustlib")
        .join(host.trim())
        .join("bin"))
}

/// Installs what is missing: rust targets, llvm-tools, QEMU, gcc, python3.
pub(super) fn ensure_tools(install: bool) -> Result<PathBuf, String> {
    let installed = output(
        Command::new("rustup")
            .args(["target", "list", "--installed"])
            .current_dir(root()),
        "rustup target list --installed",
    )?;
    let missing: Vec<&str> = MCUS
        .iter()
        .map(|m| m.triple)
        .filter(|t| !installed.lines().any(|l| l.trim() == *t))
        .collect();
    if !missing.is_empty() {
        let mut args = vec!["target", "add"];
        args.extend(&missing);
        run_visible(
            Command::new("rustup").args(&args).current_dir(root()),
            &format!("rustup {}", args.join(" ")),
        )?;
    }
    let llvm = llvm_bin()?;
    if !llvm.join("llvm-size").exists() {
        run_visible(
            Command::new("rustup")
                .args(["component", "add", "llvm-tools"])
                .current_dir(root()),
            "rustup component add llvm-tools",
        )?;
    }
    let mut pkgs = Vec::new();
    for (prog, pkg) in [
        ("qemu-system-arm", "qemu-system-arm"),
        ("qemu-system-riscv32", "qemu-system-misc"),
        ("gcc", "gcc"),
        ("python3", "python3"),
    ] {
        if !have(prog) {
            pkgs.push(pkg);
        }
    }
    if !pkgs.is_empty() {
        if !install {
            return Err(format!(
                "missing: {} (run without --no-install)",
                pkgs.join(" ")
            ));
        }
        apt_install(&pkgs)?;
    }
    Ok(llvm)
}

/// Builds the icount plugin when missing or older than its source.
pub(super) fn build_plugin() -> Result<PathBuf, String> {
    build_plugin_named("icount")
}

/// Builds the plugin `xtask/mcu/NAME.c` into `target/mcu/libNAME.so` when missing or older
/// than its source.
pub(super) fn build_plugin_named(name: &str) -> Result<PathBuf, String> {
    let src = root().join(format!("xtask/mcu/{name}.c"));
    let so = out_dir().join(format!("lib{name}.so"));
    let stale = match (fs::metadata(&src), fs::metadata(&so)) {
        (Ok(s), Ok(o)) => s.modified().ok() > o.modified().ok(),
        _ => true,
    };
    if stale {
        fs::create_dir_all(out_dir()).map_err(|e| e.to_string())?;
        run_visible(
            Command::new("gcc")
                .args([
                    "-O2",
                    "-Wall",
                    "-shared",
                    "-fPIC",
                    "-fvisibility=hidden",
                    "-o",
                ])
                .arg(&so)
                .arg(&src),
            &format!("gcc -O2 -shared -fPIC -o target/mcu/lib{name}.so xtask/mcu/{name}.c"),
        )?;
    }
    Ok(so)
}

pub(super) fn rustc_version() -> String {
    output(
        Command::new("rustc").arg("-V").current_dir(firmware_dir()),
        "rustc -V",
    )
    .map(|s| s.trim().to_string())
    .unwrap_or_default()
}

pub(super) fn qemu_version() -> String {
    output(
        Command::new("qemu-system-arm").arg("--version"),
        "qemu --version",
    )
    .map(|s| s.lines().next().unwrap_or("").to_string())
    .unwrap_or_default()
}
