//! `cargo xtask preview`: the desktop preview window (`examples/preview-window`, its own
//! workspace so that SDL2 stays out of the root's), run for a person, or checked as a
//! person would check it (`--check`, a step of `cargo xtask ci`).
//!
//! The check starts a virtual X server (Xvfb), runs the window, presses keys in it with
//! xdotool (orbit, technique, scene, quit), takes a screenshot of the window after each
//! frame (ImageMagick's `import`) and compares its pixels with the PNG the window wrote
//! for that frame: they must be equal, and each key must change the picture. A second run
//! checks the non-interactive mode (`--frames 1 --hold`). Missing packages (SDL2's
//! headers, Xvfb, ImageMagick, xdotool) are installed with apt-get.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, ExitCode, Stdio};
use std::sync::mpsc::{self, Receiver};
use std::thread;
use std::time::Duration;

use clap::Args;

use crate::bake::read_rgb8;
use crate::cmd::{cargo, root, target_dir};
use crate::mcu::apt_install;

/// The crate's directory, relative to the workspace root.
const DIR: &str = "examples/preview-window";
/// The window's title (`TITLE` in the crate's `main.rs`).
const TITLE: &str = "fixel preview";
/// How long a frame may take to appear (a debug X server on a busy machine is slow; this
/// bounds a hang, it is not a speed requirement).
const FRAME_WAIT: Duration = Duration::from_secs(120);
/// Keys pressed by the check, each with what it must do: every one draws a new frame.
const KEYS: [&str; 5] = ["Right", "t", "s", "Up", "s"];

/// Flags of `cargo xtask preview`.
#[derive(Args, Clone, Debug, Default)]
pub(crate) struct PreviewArgs {
    /// Scene: cube, sphere or teapot
    #[arg(long)]
    pub scene: Option<String>,
    /// Technique (`lit-bilinear-sub64`, ...; `h` in the window lists them)
    #[arg(long)]
    pub technique: Option<String>,
    /// Chip of the instruction estimate: m4f, m0plus or rv32
    #[arg(long)]
    pub chip: Option<String>,
    /// Check the window under Xvfb: keys pressed, screenshots equal to the frames' PNGs
    #[arg(long)]
    pub check: bool,
}

pub(crate) fn preview(args: &PreviewArgs) -> ExitCode {
    let r = if args.check { check() } else { run(args) };
    match r {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("xtask preview: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Whether `program` is an executable file on `PATH`.
fn on_path(program: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|d| d.join(program).is_file()))
}

/// Installs what is missing: SDL2's development files, and for the check Xvfb,
/// ImageMagick and xdotool.
fn ensure_packages(check: bool) -> Result<(), String> {
    let mut wanted = vec![("sdl2-config", "libsdl2-dev")];
    if check {
        wanted.extend([
            ("Xvfb", "xvfb"),
            ("import", "imagemagick"),
            ("xdotool", "xdotool"),
        ]);
    }
    let missing: Vec<&str> = wanted
        .iter()
        .filter(|(prog, _)| !on_path(prog))
        .map(|(_, pkg)| *pkg)
        .collect();
    if missing.is_empty() {
        return Ok(());
    }
    apt_install(&missing)
}

fn preview_target() -> PathBuf {
    target_dir().join("preview")
}

fn binary() -> PathBuf {
    preview_target().join("release").join("preview-window")
}

/// `cargo <args> --release --target-dir target/preview` in the crate's directory.
fn cargo_here(args: &[&str]) -> Result<(), String> {
    let dir = preview_target();
    let dir = dir.to_string_lossy();
    let mut all: Vec<&str> = args.to_vec();
    let tail = all.iter().position(|a| *a == "--").unwrap_or(all.len());
    all.splice(tail..tail, ["--release", "--target-dir", &dir]);
    cargo(&all).in_dir(DIR).run()
}

/// Opens the window for a person.
fn run(args: &PreviewArgs) -> Result<(), String> {
    let has = |var: &str| std::env::var_os(var).is_some_and(|v| !v.is_empty());
    if !has("DISPLAY") && !has("WAYLAND_DISPLAY") {
        return Err("no display to open a window on (DISPLAY is not set); \
                    `cargo xtask preview --check` runs the window under Xvfb"
            .into());
    }
    ensure_packages(false)?;
    cargo_here(&["build"])?;
    let mut cmd = Command::new(binary());
    for (flag, value) in [
        ("--scene", &args.scene),
        ("--technique", &args.technique),
        ("--chip", &args.chip),
    ] {
        if let Some(v) = value {
            cmd.args([flag, v]);
        }
    }
    match cmd.status() {
        Ok(s) if s.success() => Ok(()),
        Ok(s) => Err(format!("preview-window failed ({s})")),
        Err(e) => Err(format!("could not start preview-window: {e}")),
    }
}

/// A virtual X server, stopped when dropped.
struct Xvfb {
    child: Child,
    display: String,
}

impl Xvfb {
    /// Starts one on the first free display from :90 and waits for its socket.
    fn start() -> Result<Xvfb, String> {
        let n = (90..200)
            .find(|n| {
                !Path::new(&format!("/tmp/.X{n}-lock")).exists()
                    && !Path::new(&format!("/tmp/.X11-unix/X{n}")).exists()
            })
            .ok_or("no free X display number in :90..:199")?;
        let display = format!(":{n}");
        let child = Command::new("Xvfb")
            .args([&display, "-screen", "0", "640x480x24", "-nolisten", "tcp"])
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .map_err(|e| format!("could not start Xvfb: {e}"))?;
        let x = Xvfb { child, display };
        let socket = PathBuf::from(format!("/tmp/.X11-unix/X{n}"));
        for _ in 0..200 {
            if socket.exists() {
                return Ok(x);
            }
            thread::sleep(Duration::from_millis(50));
        }
        Err(format!("Xvfb {} did not open its socket", x.display))
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The window process, its output lines and its standard input (closing it ends `--hold`).
struct Running {
    child: Child,
    stdin: Option<ChildStdin>,
    lines: Receiver<String>,
}

impl Running {
    fn start(display: &str, out_dir: &Path, extra: &[&str]) -> Result<Running, String> {
        let mut child = Command::new(binary())
            .arg("--out-dir")
            .arg(out_dir)
            .args(extra)
            .env("DISPLAY", display)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .map_err(|e| format!("could not start preview-window: {e}"))?;
        let stdout = child.stdout.take().ok_or("no stdout")?;
        let (tx, lines) = mpsc::channel();
        thread::spawn(move || {
            for line in BufReader::new(stdout).lines().map_while(Result::ok) {
                println!("  | {line}");
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
        let stdin = child.stdin.take();
        Ok(Running {
            child,
            stdin,
            lines,
        })
    }

    /// Waits for `frame N shown` and returns that line and the estimate line after it.
    fn shown(&self, n: u32) -> Result<(String, String), String> {
        let want = format!("frame {n} shown:");
        loop {
            let line = self
                .lines
                .recv_timeout(FRAME_WAIT)
                .map_err(|_| format!("no `{want}` line from the window"))?;
            if line.starts_with(&want) {
                let estimate = self
                    .lines
                    .recv_timeout(FRAME_WAIT)
                    .map_err(|_| format!("no estimate line after `{want}`"))?;
                return Ok((line, estimate));
            }
        }
    }

    /// Waits for the process to exit by itself, successfully.
    fn finished(mut self) -> Result<(), String> {
        drop(self.stdin.take());
        for _ in 0..(FRAME_WAIT.as_millis() / 50) {
            match self.child.try_wait() {
                Ok(Some(s)) if s.success() => return Ok(()),
                Ok(Some(s)) => return Err(format!("preview-window exited with {s}")),
                Ok(None) => thread::sleep(Duration::from_millis(50)),
                Err(e) => return Err(e.to_string()),
            }
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
        Err("preview-window did not exit".into())
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        if let Ok(None) = self.child.try_wait() {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}

/// Takes screenshots of the window until one equals `png` (the frame may still be on its
/// way to the X server), at most 50 tries; the last one is kept as `shot`.
fn screenshot_equals(display: &str, png: &Path, shot: &Path) -> Result<(), String> {
    let want = read_rgb8(png)?;
    let mut last = String::new();
    for _ in 0..50 {
        let status = Command::new("import")
            .args(["-window", TITLE])
            .arg(format!("PNG24:{}", shot.display()))
            .env("DISPLAY", display)
            .status()
            .map_err(|e| format!("could not start import: {e}"))?;
        if status.success() {
            let got = read_rgb8(shot)?;
            if got == want {
                return Ok(());
            }
            let differ = if (got.0, got.1) == (want.0, want.1) {
                let n = got.2.iter().zip(&want.2).filter(|(a, b)| a != b).count();
                format!("{n} pixels differ")
            } else {
                format!(
                    "{}x{} where the frame is {}x{}",
                    got.0, got.1, want.0, want.1
                )
            };
            last = format!("{}: {differ} from {}", shot.display(), png.display());
        } else {
            last = format!("import -window '{TITLE}' failed ({status})");
        }
        thread::sleep(Duration::from_millis(100));
    }
    Err(last)
}

/// Presses `key` in the window (focused first: there is no window manager to do it).
fn press(display: &str, key: &str) -> Result<(), String> {
    let status = Command::new("xdotool")
        .args(["search", "--sync", "--name", &format!("^{TITLE}$")])
        .args(["windowfocus", "--sync", "key", key])
        .env("DISPLAY", display)
        .status()
        .map_err(|e| format!("could not start xdotool: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("xdotool key {key} failed ({status})"))
    }
}

/// Checks frame `n`: its line names `scene`, its estimate line is there, the screenshot
/// equals its PNG. Returns the PNG's path.
fn frame(
    run: &Running,
    x: &Xvfb,
    dir: &Path,
    n: u32,
    scene: Option<&str>,
) -> Result<PathBuf, String> {
    let (line, estimate) = run.shown(n)?;
    if let Some(s) = scene {
        if !line.contains(&format!(": {s} ")) {
            return Err(format!("frame {n} should show the {s}: `{line}`"));
        }
    }
    if !(estimate.contains("M instructions (estimate:") || estimate.contains("no estimate")) {
        return Err(format!("frame {n}: no instruction estimate: `{estimate}`"));
    }
    let png = dir.join(format!("frame-{n:03}.png"));
    screenshot_equals(&x.display, &png, &dir.join(format!("screen-{n:03}.png")))?;
    Ok(png)
}

/// The check of `cargo xtask ci`.
fn check() -> Result<(), String> {
    ensure_packages(true)?;
    cargo(&["fmt", "--check"]).in_dir(DIR).run()?;
    cargo_here(&["clippy", "--all-targets", "--", "-D", "warnings"])?;
    cargo_here(&["test"])?;
    cargo_here(&["build"])?;
    let x = Xvfb::start()?;
    let out = preview_target().join("check");
    let _ = std::fs::remove_dir_all(&out);

    // A person at the keys: orbit, technique, scene, tilt, scene, quit.
    let keys_dir = out.join("keys");
    let run = Running::start(&x.display, &keys_dir, &["--scene", "cube"])?;
    let mut previous = frame(&run, &x, &keys_dir, 0, Some("cube"))?;
    let scenes = [None, None, Some("sphere"), None, Some("teapot")];
    for (i, (key, scene)) in KEYS.iter().zip(scenes).enumerate() {
        press(&x.display, key)?;
        let n = i as u32 + 1;
        let png = frame(&run, &x, &keys_dir, n, scene)?;
        if read_rgb8(&png)? == read_rgb8(&previous)? {
            return Err(format!(
                "key {key} did not change the picture ({})",
                png.display()
            ));
        }
        previous = png;
    }
    // Escape quits on the key-down: the window may be gone before xdotool sends the
    // key-up, which it reports as an error. The check is that the window exits cleanly.
    let quit = press(&x.display, "Escape");
    run.finished().map_err(|e| match quit {
        Err(q) => format!("{e} ({q})"),
        Ok(()) => e,
    })?;

    // Without a person: one frame, held on screen until standard input closes.
    let frames_dir = out.join("frames");
    let args = ["--scene", "sphere", "--frames", "1", "--hold"];
    let run = Running::start(&x.display, &frames_dir, &args)?;
    frame(&run, &x, &frames_dir, 0, Some("sphere"))?;
    run.finished()?;

    println!(
        "preview: {} screenshots of the window under Xvfb equal the frames' PNGs (keys {} \
         and Escape; --frames 1); in {}",
        KEYS.len() + 2,
        KEYS.join(", "),
        out.strip_prefix(root()).unwrap_or(&out).display()
    );
    Ok(())
}
