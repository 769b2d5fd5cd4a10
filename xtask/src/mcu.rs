//! `cargo xtask mcu` and `cargo xtask size`: fixel on microcontroller instruction sets,
//! under QEMU, with exact instruction counts (a TCG plugin), a cycle estimate, flash and RAM.
//!
//! Everything is driven through `std::process::Command`: rustup, apt-get, cargo, gcc (the
//! plugin, `xtask/mcu/icount.c`), qemu-system-{arm,riscv32}, llvm-nm/llvm-size (rustup's
//! `llvm-tools`) and python3 (the cycle model, `xtask/mcu/cycles.py`).

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

use crate::root;

/// One MCU profile: Rust target, QEMU machine, cycle model.
struct Mcu {
    label: &'static str,
    triple: &'static str,
    qemu: &'static str,
    machine: &'static [&'static str],
    /// Core name for `cycles.py`.
    core: &'static str,
}

const MCUS: [Mcu; 3] = [
    Mcu {
        label: "Cortex-M4F",
        triple: "thumbv7em-none-eabihf",
        qemu: "qemu-system-arm",
        machine: &["-machine", "mps2-an386"],
        core: "m4",
    },
    // mps2-an386 rather than the microbit (nRF51: 16K of RAM, below the 24K band bar);
    // ARMv6-M code runs unchanged on the M4 model and counts depend on the instructions only.
    Mcu {
        label: "Cortex-M0+",
        triple: "thumbv6m-none-eabi",
        qemu: "qemu-system-arm",
        machine: &["-machine", "mps2-an386"],
        core: "m0plus",
    },
    Mcu {
        label: "RV32IMC",
        triple: "riscv32imc-unknown-none-elf",
        qemu: "qemu-system-riscv32",
        machine: &["-machine", "virt", "-bios", "none"],
        core: "rv32",
    },
];

/// Scene firmwares (binaries of `examples/firmware`), frame 0 each.
const SCENES: [&str; 20] = [
    "cube",
    "sphere",
    // The Utah teapot baked from OBJ into flash (`cargo xtask bake-obj`).
    "teapot",
    "floor",
    "floor_bilinear",
    // Shadow maps (bands of 4 rows, 64x64 map): light pass per map texel, the lit pass's
    // no-shadow baseline, lit passes.
    "shadow_light",
    "shadow_none",
    "shadow_single",
    "shadow_pcf2x2",
    "shadow_pcf3x3",
    "shadow_spot",
    // The grazing light, front faces culled in the light pass.
    "shadow_grazing",
    // Solid textures: the marble sphere, the flame and the wooden cube lit by the baked 3D
    // light map.
    "noise",
    "noise_flame",
    "noise_light3d",
    // Environment maps: the sphere as a mirror, r per pixel and per vertex.
    "env_pixel",
    "env_vertex",
    // Anti-aliasing (rotated grid through bands) and transparency.
    "aa_cube",
    "transparency",
    // Run-time displacement: a subdivided grid displaced by a moving swell each frame.
    "water",
];

/// The same scenes drawn into one whole 320x240 frame (feature `whole`, memory layout
/// `FIXEL_FW_MEMORY=whole`): the figures to compare with whole-frame renderers; and `bump`
/// (per-pixel lit, bump-mapped sphere), whose per-pixel shader has no band path yet.
const WHOLE_SCENES: [&str; 7] = [
    "whole_cube",
    "whole_sphere",
    "whole_sphere_adaptive",
    "whole_sphere_footprint",
    "whole_floor",
    "whole_floor_bilinear",
    "bump",
];

/// The whole-frame firmwares' machines: `mps2-an386` (4M + 4M SSRAM) for both Arm builds
/// (ARMv6-M code runs unchanged on the M4 model; counts depend on the instruction stream
/// only) and RV32 `virt` (128 MB).
const WHOLE_MCUS: [Mcu; 3] = [
    Mcu {
        label: "Cortex-M4F",
        triple: "thumbv7em-none-eabihf",
        qemu: "qemu-system-arm",
        machine: &["-machine", "mps2-an386"],
        core: "m4",
    },
    Mcu {
        label: "Cortex-M0+",
        triple: "thumbv6m-none-eabi",
        qemu: "qemu-system-arm",
        machine: &["-machine", "mps2-an386"],
        core: "m0plus",
    },
    Mcu {
        label: "RV32IMC",
        triple: "riscv32imc-unknown-none-elf",
        qemu: "qemu-system-riscv32",
        machine: &["-machine", "virt", "-bios", "none"],
        core: "rv32",
    },
];

/// Builds the whole-frame firmwares and the geometry firmware (whole layout, own target
/// directory so the default build's artefacts stay).
fn build_whole(td: &Path) -> Result<(), String> {
    let mut cmd = Command::new("cargo");
    cmd.current_dir(firmware_dir())
        .args(["build", "--release", "--features", "whole"])
        .arg("--target-dir")
        .arg(td)
        .env("FIXEL_FW_MEMORY", "whole")
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("CARGO_BUILD_TARGET")
        .env_remove("CARGO_TARGET_DIR");
    for b in WHOLE_SCENES.iter().chain(&["geometry"]) {
        cmd.args(["--bin", b]);
    }
    for m in &WHOLE_MCUS {
        cmd.args(["--target", m.triple]);
    }
    run_visible(
        &mut cmd,
        "(cd examples/firmware && FIXEL_FW_MEMORY=whole cargo build --release --features whole \
         --target-dir target/whole --bin whole_* --bin bump --bin geometry --target <3 MCU targets>)",
    )
}

/// The geometry firmware on each MCU: a table of instructions per item and stage.
fn geometry_table(llvm: &Path, plugin: &Path, td: &Path) -> Result<String, String> {
    let mut per: BTreeMap<(String, String), Vec<String>> = BTreeMap::new();
    let mut order: Vec<(String, String)> = Vec::new();
    let mut items: BTreeMap<(String, String), u64> = BTreeMap::new();
    for m in &WHOLE_MCUS {
        let v = measure_modes(llvm, plugin, m, &elf(td, m, "geometry"))?;
        for c in v {
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
            "cull" | "walk" => "mesh triangle",
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

/// Size firmwares, in the order of the table.
const SIZES: [(&str, &str); 11] = [
    ("size_base", "harness only (no fixel)"),
    ("size_affine", "textured affine nearest unlit triangle"),
    (
        "size_affine_unclipped",
        "the same, no clipper (Draw::project_unclipped: geometry stays in view)",
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

const QEMU_TIMEOUT: Duration = Duration::from_secs(120);

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

fn fail(msg: impl AsRef<str>) -> ExitCode {
    eprintln!("xtask: {}", msg.as_ref());
    ExitCode::FAILURE
}

fn firmware_dir() -> PathBuf {
    root().join("examples").join("firmware")
}

fn out_dir() -> PathBuf {
    root().join("target").join("mcu")
}

/// Runs `cmd`, streaming its output; error text on failure.
fn run_visible(cmd: &mut Command, what: &str) -> Result<(), String> {
    eprintln!("xtask: $ {what}");
    match cmd.status() {
        Ok(s) if s.success() => Ok(()),
        Ok(s) => Err(format!("`{what}` failed ({s})")),
        Err(e) => Err(format!("`{what}` could not start: {e}")),
    }
}

/// Runs `cmd` and returns its stdout (stderr passed through).
fn output(cmd: &mut Command, what: &str) -> Result<String, String> {
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

/// apt-get install (as root, or through passwordless sudo), after an `apt-get update`.
fn apt_install(packages: &[&str]) -> Result<(), String> {
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
    let mut args = vec!["install", "-y", "--no-install-recommends"];
    args.extend_from_slice(packages);
    run_visible(
        &mut cmd(&args),
        &format!(
            "apt-get install -y --no-install-recommends {}",
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
fn ensure_tools(install: bool) -> Result<PathBuf, String> {
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
fn build_plugin() -> Result<PathBuf, String> {
    let src = root().join("xtask/mcu/icount.c");
    let so = out_dir().join("libicount.so");
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
            "gcc -O2 -shared -fPIC -o target/mcu/libicount.so xtask/mcu/icount.c",
        )?;
    }
    Ok(so)
}

/// Builds every firmware binary for every MCU target (one cargo invocation).
fn build_firmware(extra_env: &[(&str, &str)], target_dir: Option<&Path>) -> Result<(), String> {
    let mut cmd = Command::new("cargo");
    cmd.current_dir(firmware_dir())
        .args(["build", "--release", "--bins"])
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("CARGO_BUILD_TARGET")
        .env_remove("CARGO_TARGET_DIR");
    for m in &MCUS {
        cmd.args(["--target", m.triple]);
    }
    if let Some(d) = target_dir {
        cmd.arg("--target-dir").arg(d);
    }
    for (k, v) in extra_env {
        cmd.env(k, v);
    }
    run_visible(
        &mut cmd,
        "(cd examples/firmware && cargo build --release --bins --target <3 MCU targets>)",
    )
}

fn elf(target_dir: &Path, m: &Mcu, bin: &str) -> PathBuf {
    target_dir.join(m.triple).join("release").join(bin)
}

/// Section sizes (`llvm-size -A`): (flash = vector table + text + rodata + data,
/// static RAM = data + bss + uninit).
fn sizes(llvm: &Path, elf: &Path) -> Result<(u64, u64), String> {
    let out = output(
        Command::new(llvm.join("llvm-size")).arg("-A").arg(elf),
        "llvm-size -A",
    )?;
    let mut s: BTreeMap<String, u64> = BTreeMap::new();
    for l in out.lines() {
        let f: Vec<&str> = l.split_whitespace().collect();
        if f.len() >= 2 {
            if let Ok(n) = f[1].parse() {
                s.insert(f[0].to_string(), n);
            }
        }
    }
    let g = |k: &str| s.get(k).copied().unwrap_or(0);
    Ok((
        g(".vector_table") + g(".text") + g(".rodata") + g(".data"),
        g(".data") + g(".bss") + g(".uninit"),
    ))
}

fn symbol(nm: &str, name: &str) -> Option<String> {
    nm.lines().find_map(|l| {
        let f: Vec<&str> = l.split_whitespace().collect();
        (f.len() >= 3 && f[f.len() - 1] == name).then(|| format!("0x{}", f[0]))
    })
}

/// One QEMU run: exit status, stdout, stderr.
fn qemu(m: &Mcu, elf: &Path, plugin: Option<String>) -> Result<(bool, String, String), String> {
    let dir = out_dir();
    fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let (o, e) = (dir.join("qemu.stdout"), dir.join("qemu.stderr"));
    let mut cmd = Command::new(m.qemu);
    cmd.args(m.machine).args([
        "-nographic",
        "-monitor",
        "none",
        "-serial",
        "none",
        "-semihosting-config",
        "enable=on,target=native",
    ]);
    if let Some(p) = plugin {
        cmd.arg("-plugin").arg(p);
    }
    cmd.arg("-kernel")
        .arg(elf)
        .stdin(Stdio::null())
        .stdout(fs::File::create(&o).map_err(|e| e.to_string())?)
        .stderr(fs::File::create(&e).map_err(|e| e.to_string())?);
    let mut child = cmd
        .spawn()
        .map_err(|err| format!("{} could not start: {err}", m.qemu))?;
    let t0 = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().map_err(|e| e.to_string())? {
            break s;
        }
        if t0.elapsed() > QEMU_TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!(
                "{} timed out after {:?} on {}",
                m.qemu,
                QEMU_TIMEOUT,
                elf.display()
            ));
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let read = |p: &Path| fs::read_to_string(p).unwrap_or_default();
    Ok((status.success(), read(&o), read(&e)))
}

/// `key=value` from text (first occurrence).
fn kv<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    let pat = format!("{key}=");
    text.split_whitespace()
        .find_map(|w| w.strip_prefix(pat.as_str()))
}

fn num(text: &str, key: &str) -> Option<u64> {
    kv(text, key)?.parse().ok()
}

/// Expected checksums and pixel counts from the host test (same code, same frames).
fn host_expected() -> Result<BTreeMap<String, (String, u64)>, String> {
    let out = output(
        Command::new("cargo").current_dir(root()).args([
            "test",
            "-q",
            "-p",
            "host-tests",
            "--test",
            "mcu_checksums",
            "--test",
            "shadow_mcu",
            "--",
            "--nocapture",
        ]),
        "cargo test -p host-tests --test mcu_checksums --test shadow_mcu -- --nocapture",
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

struct Measured {
    checksum: String,
    pixels: u64,
    stack: u64,
    net: u64,
    total: u64,
    est_cycles: f64,
    rewalked: bool,
    profile: Vec<String>,
    mix: String,
}

/// Runs one firmware `runs` times with the plugin; errors if the runs disagree.
fn measure(
    llvm: &Path,
    plugin: &Path,
    m: &Mcu,
    elf: &Path,
    runs: u32,
) -> Result<(Measured, Vec<(u64, u64)>), String> {
    let nm = output(Command::new(llvm.join("llvm-nm")).arg(elf), "llvm-nm")?;
    let (start, end) = match (symbol(&nm, "bench_start"), symbol(&nm, "bench_end")) {
        (Some(s), Some(e)) => (s, e),
        _ => return Err(format!("{}: no bench_start/bench_end", elf.display())),
    };
    let hist = out_dir().join(format!("hist-{}.tsv", m.core));
    let mut seen = Vec::new();
    let mut first: Option<(String, String)> = None;
    for i in 0..runs.max(1) {
        let mut arg = format!("{},start={start},end={end}", plugin.display());
        if i == 0 {
            arg.push_str(&format!(",hist={}", hist.display()));
        }
        let (ok, out, err) = qemu(m, elf, Some(arg))?;
        if !ok {
            return Err(format!(
                "{} on {} failed:\n{out}{err}",
                elf.display(),
                m.label
            ));
        }
        let total = num(&err, "total").ok_or("plugin printed no total")?;
        let region = num(&err, "region_sum").ok_or("no region_sum")?;
        let pairs = num(&err, "pairs").ok_or("no pairs")?;
        let fp = num(&err, "first_pair").ok_or("no first_pair")?;
        seen.push((total, region - pairs * fp));
        if first.is_none() {
            first = Some((out, err));
        }
    }
    let (out, err) = first.unwrap_or_default();
    let line = out
        .lines()
        .find(|l| l.starts_with("scene="))
        .ok_or_else(|| format!("no result line from {}:\n{out}{err}", elf.display()))?;
    let pixels = num(line, "pixels").unwrap_or(0);
    let region = num(&err, "region_sum").unwrap_or(1).max(1);
    let (total, net) = seen[0];

    let nm_file = out_dir().join(format!("nm-{}.txt", m.core));
    let nm_sorted = output(
        Command::new(llvm.join("llvm-nm"))
            .args(["-n", "-S", "-C"])
            .arg(elf),
        "llvm-nm -n -S -C",
    )?;
    fs::write(&nm_file, nm_sorted).map_err(|e| e.to_string())?;
    let cyc = output(
        Command::new("python3")
            .arg(root().join("xtask/mcu/cycles.py"))
            .arg(&hist)
            .arg(m.core)
            .arg(pixels.max(1).to_string())
            .arg(&nm_file),
        "python3 xtask/mcu/cycles.py",
    )?;
    let est = num(&cyc, "est_cycles").unwrap_or(0) as f64;
    let hist_sum = num(&cyc, "insns").unwrap_or(region).max(1);
    if hist_sum != region {
        return Err(format!(
            "histogram sums to {hist_sum}, the region to {region}: plugin out of step"
        ));
    }
    Ok((
        Measured {
            checksum: kv(line, "checksum").unwrap_or("?").to_string(),
            pixels,
            stack: num(&out, "stack").unwrap_or(0),
            net,
            total,
            // The marker overhead (pairs x first pair) is taken out in proportion.
            est_cycles: est * net as f64 / region as f64,
            rewalked: kv(line, "rewalked") == Some("true"),
            profile: cyc
                .lines()
                .filter(|l| l.trim_start().starts_with("profile:"))
                .map(|l| l.trim().to_string())
                .collect(),
            mix: cyc
                .lines()
                .find(|l| l.starts_with("mix:"))
                .unwrap_or("")
                .to_string(),
        },
        seen,
    ))
}

fn rustc_version() -> String {
    output(
        Command::new("rustc").arg("-V").current_dir(firmware_dir()),
        "rustc -V",
    )
    .map(|s| s.trim().to_string())
    .unwrap_or_default()
}

fn qemu_version() -> String {
    output(
        Command::new("qemu-system-arm").arg("--version"),
        "qemu --version",
    )
    .map(|s| s.lines().next().unwrap_or("").to_string())
    .unwrap_or_default()
}

/// Flags shared by `mcu` and `size`.
struct Flags {
    runs: u32,
    profile: bool,
    opt_s: bool,
    install: bool,
}

fn parse_flags(cmd: &str, rest: &[String]) -> Result<Flags, ExitCode> {
    let mut f = Flags {
        runs: 2,
        profile: false,
        opt_s: false,
        install: true,
    };
    let mut it = rest.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--profile" if cmd == "mcu" => f.profile = true,
            "--opt-s" => f.opt_s = true,
            "--no-install" => f.install = false,
            "--runs" if cmd == "mcu" => {
                f.runs = match it.next().and_then(|n| n.parse().ok()) {
                    Some(n) if n >= 1 => n,
                    _ => return Err(crate::usage_error("--runs needs a number >= 1")),
                }
            }
            other => {
                return Err(crate::usage_error(&format!(
                    "{cmd}: unknown flag `{other}`"
                )))
            }
        }
    }
    Ok(f)
}

/// `cargo xtask mcu`.
pub fn mcu(rest: &[String]) -> ExitCode {
    let flags = match parse_flags("mcu", rest) {
        Ok(f) => f,
        Err(e) => return e,
    };
    let t0 = Instant::now();
    let llvm = match ensure_tools(flags.install) {
        Ok(l) => l,
        Err(e) => return fail(e),
    };
    let plugin = match build_plugin() {
        Ok(p) => p,
        Err(e) => return fail(e),
    };
    if let Err(e) = build_firmware(&[], None) {
        return fail(e);
    }
    // The real-display example (ST7789 via mipidsi): compile check only.
    if let Err(e) = run_visible(
        Command::new("cargo")
            .current_dir(root().join("examples").join("display"))
            .args(["build", "--release", "--target", "thumbv7em-none-eabihf"])
            .env_remove("RUSTFLAGS")
            .env_remove("CARGO_ENCODED_RUSTFLAGS")
            .env_remove("CARGO_TARGET_DIR"),
        "(cd examples/display && cargo build --release --target thumbv7em-none-eabihf)",
    ) {
        return fail(e);
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
        ) {
            return fail(e);
        }
    }
    let td = firmware_dir().join("target");
    let td_whole = firmware_dir().join("target").join("whole");
    if let Err(e) = build_whole(&td_whole) {
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
    let mut per_px: BTreeMap<(String, &'static str), f64> = BTreeMap::new();
    let sets = SCENES
        .iter()
        .map(|s| (*s, &MCUS, &td))
        .chain(WHOLE_SCENES.iter().map(|s| (*s, &WHOLE_MCUS, &td_whole)));
    for (scene, mcus, td) in sets {
        for m in mcus.iter() {
            let e = elf(td, m, scene);
            let (r, seen) = match measure(&llvm, &plugin, m, &e, flags.runs) {
                Ok(x) => x,
                Err(err) => {
                    problems.push(format!("{scene} on {}: {err}", m.label));
                    continue;
                }
            };
            let (flash, ram) = match sizes(&llvm, &e) {
                Ok(x) => x,
                Err(err) => return fail(err),
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
            per_px.insert((scene.to_string(), m.label), r.net as f64 / px);
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
        }
    }
    println!(
        "\n## cargo xtask mcu: {}, {}\n",
        rustc_version(),
        qemu_version()
    );
    println!(
        "Frame 0 of each scene, 320x240 RGB565 in bands of 8 rows (colour + 16-bit depth band; \
         16 triangle bins for the cube and floor, a 2-byte band range per triangle for the \
         sphere; 24 KB of RAM), one frame per run (QEMU is deterministic: one frame is enough).\n\
         insns/px = instructions executed by the renderer (geometry, binning, band clears, \
         raster) / pixels that passed the depth test; the harness's checksum of each band is \
         outside the counted region. (rewalk) = storage overflowed, some geometry ran once per band.\n\
         flash = vector table + text + rodata + data (textures and the sphere mesh are in \
         flash); RAM = data + bss + measured stack high-water mark (band buffers are on the stack).\n"
    );
    print!("{report}");
    // Kept for reports that quote these counts (host-tests' shadow_report reads it).
    let _ = fs::write(out_dir().join("scenes.md"), &report);
    println!(
        "\nwhole_* = the same frame drawn into one 320x240 frame (colour + 16-bit depth, \
         300 KiB) with one prepared vertex per mesh vertex, on mps2-an386 (both Arm builds) \
         and RV32 virt: the figures to set beside whole-frame renderers.\n"
    );
    println!("| scene | target | bands insns/px | whole insns/px | bands / whole |\n|---|---|---:|---:|---:|");
    for scene in SCENES {
        for m in &MCUS {
            let b = per_px.get(&(scene.to_string(), m.label));
            let w = per_px.get(&(format!("whole_{scene}"), m.label));
            if let (Some(b), Some(w)) = (b, w) {
                println!("| {scene} | {} | {b:.2} | {w:.2} | {:.3} |", m.label, b / w);
            }
        }
    }
    match geometry_table(&llvm, &plugin, &td_whole) {
        Ok(t) => println!(
            "\nGeometry on its own (`geometry` firmware, sphere camera, frame 0): instructions \
             per item and stage\n\n{t}"
        ),
        Err(e) => problems.push(format!("geometry firmware: {e}")),
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

/// `cargo xtask size`.
pub fn size(rest: &[String]) -> ExitCode {
    let flags = match parse_flags("size", rest) {
        Ok(f) => f,
        Err(e) => return e,
    };
    let llvm = match ensure_tools(flags.install) {
        Ok(l) => l,
        Err(e) => return fail(e),
    };
    if let Err(e) = build_firmware(&[], None) {
        return fail(e);
    }
    let opt_s_dir = firmware_dir().join("target").join("opt-s");
    if flags.opt_s {
        if let Err(e) = build_firmware(
            &[("CARGO_PROFILE_RELEASE_OPT_LEVEL", "s")],
            Some(&opt_s_dir),
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

// ---------------------------------------------------------------------------
// report: per-mode instruction counts of the report firmwares
// ---------------------------------------------------------------------------

/// The report's microcontrollers. Both builds run on `mps2-an386` (4 MB of RAM: the
/// report firmwares hold up to 20 span loops and exceed the microbit's 256 KB / 16 KB);
/// instruction counts depend on the instruction stream only, and ARMv6-M code runs
/// unchanged on the M4 model.
const REPORT_MCUS: [Mcu; 2] = [
    Mcu {
        label: "Cortex-M0+",
        triple: "thumbv6m-none-eabi",
        qemu: "qemu-system-arm",
        machine: &["-machine", "mps2-an386"],
        core: "m0plus",
    },
    Mcu {
        label: "Cortex-M4F",
        triple: "thumbv7em-none-eabihf",
        qemu: "qemu-system-arm",
        machine: &["-machine", "mps2-an386"],
        core: "m4",
    },
];

/// The report firmwares (`examples/firmware/src/bin/report_*.rs`).
const REPORT_BINS: [&str; 16] = [
    "report_cube",
    "report_cube_unlit",
    "report_cube_facet",
    "report_cube_footprint",
    "report_cube_footprint_b",
    "report_sphere",
    "report_floor",
    "report_floor_mip",
    "report_floor_footprint",
    "report_noise",
    "report_env",
    "report_mapping",
    "report_aa",
    "report_alpha",
    "report_surface",
    "report_shadow",
];

/// One mode of one report firmware on one MCU.
pub struct ModeCount {
    pub scene: String,
    pub mode: String,
    pub target: &'static str,
    pub instructions: u64,
    pub pixels: u64,
    pub checksum: String,
}

/// Runs one report firmware once with the plugin's `mark=`; per-mode counts are the
/// differences of the running region sum between marks, less the marker overhead.
fn measure_modes(
    llvm: &Path,
    plugin: &Path,
    m: &Mcu,
    elf: &Path,
) -> Result<Vec<ModeCount>, String> {
    let nm = output(Command::new(llvm.join("llvm-nm")).arg(elf), "llvm-nm")?;
    let sym = |s: &str| symbol(&nm, s).ok_or_else(|| format!("{}: no {s}", elf.display()));
    let arg = format!(
        "{},start={},end={},mark={}",
        plugin.display(),
        sym("bench_start")?,
        sym("bench_end")?,
        sym("bench_mark")?
    );
    let (ok, out, err) = qemu(m, elf, Some(arg))?;
    if !ok {
        return Err(format!(
            "{} on {} failed:\n{out}{err}",
            elf.display(),
            m.label
        ));
    }
    let marks: Vec<(u64, u64, u64)> = err
        .lines()
        .filter(|l| l.starts_with("icount: mark "))
        .map(|l| {
            (
                num(l, "region_sum").unwrap_or(0),
                num(l, "pairs").unwrap_or(0),
                num(l, "first_pair").unwrap_or(0),
            )
        })
        .collect();
    let lines: Vec<&str> = out.lines().filter(|l| l.starts_with("mode ")).collect();
    if marks.len() != lines.len() + 1 {
        return Err(format!(
            "{} on {}: {} marks for {} modes",
            elf.display(),
            m.label,
            marks.len(),
            lines.len()
        ));
    }
    let mut v = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        if kv(l, "error").is_some() {
            return Err(format!("{} on {}: {l}", elf.display(), m.label));
        }
        let (a, b) = (marks[i], marks[i + 1]);
        let overhead = (b.1 - a.1) * b.2;
        v.push(ModeCount {
            scene: kv(l, "scene").unwrap_or("?").to_string(),
            mode: kv(l, "mode").unwrap_or("?").to_string(),
            target: m.label,
            instructions: (b.0 - a.0).saturating_sub(overhead),
            pixels: num(l, "pixels").unwrap_or(0),
            checksum: kv(l, "checksum").unwrap_or("?").to_string(),
        });
    }
    Ok(v)
}

/// `cargo xtask report`, microcontroller part: builds the report firmwares for the
/// Cortex-M0+ and Cortex-M4F, runs each once under QEMU and writes the per-mode counts to
/// `tsv` (scene, mode, target, instructions, pixels, checksum). `progress` is told each step.
pub fn report_mcu(
    install: bool,
    tsv: &Path,
    progress: &mut dyn FnMut(&str),
) -> Result<Vec<ModeCount>, String> {
    let llvm = ensure_tools(install)?;
    let plugin = build_plugin()?;
    let td = firmware_dir().join("target").join("report");
    let mut cmd = Command::new("cargo");
    cmd.current_dir(firmware_dir())
        .args(["build", "--release"])
        .arg("--target-dir")
        .arg(&td)
        .env("FIXEL_FW_MEMORY", "report")
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("CARGO_BUILD_TARGET")
        .env_remove("CARGO_TARGET_DIR");
    for b in REPORT_BINS {
        cmd.args(["--bin", b]);
    }
    for m in &REPORT_MCUS {
        cmd.args(["--target", m.triple]);
    }
    progress("building the report firmwares (Cortex-M0+, Cortex-M4F)");
    run_visible(
        &mut cmd,
        "(cd examples/firmware && FIXEL_FW_MEMORY=report cargo build --release \
         --target-dir target/report --bin report_* --target <M0+, M4F>)",
    )?;
    let mut all = Vec::new();
    let total = REPORT_BINS.len() * REPORT_MCUS.len();
    let mut k = 0;
    for bin in REPORT_BINS {
        for m in &REPORT_MCUS {
            k += 1;
            progress(&format!("[{k}/{total}] QEMU: {bin} on {}", m.label));
            let t0 = Instant::now();
            let v = measure_modes(&llvm, &plugin, m, &elf(&td, m, bin))?;
            eprintln!(
                "xtask:   {} modes in {:.1} s",
                v.len(),
                t0.elapsed().as_secs_f64()
            );
            all.extend(v);
        }
    }
    let mut s = String::from("scene\tmode\ttarget\tinstructions\tpixels\tchecksum\n");
    for c in &all {
        s.push_str(&format!(
            "{}\t{}\t{}\t{}\t{}\t{}\n",
            c.scene, c.mode, c.target, c.instructions, c.pixels, c.checksum
        ));
    }
    if let Some(d) = tsv.parent() {
        fs::create_dir_all(d).map_err(|e| e.to_string())?;
    }
    fs::write(tsv, s).map_err(|e| format!("{}: {e}", tsv.display()))?;
    Ok(all)
}
