//! `cargo xtask mcu` and `cargo xtask size`: fixel on microcontroller instruction sets,
//! under QEMU, with exact instruction counts (a TCG plugin), a cycle estimate, flash and RAM.
//!
//! Everything is driven through `std::process::Command`: rustup, apt-get, cargo, gcc (the
//! plugin, `xtask/mcu/icount.c`), qemu-system-{arm,riscv32}, llvm-nm/llvm-size (rustup's
//! `llvm-tools`) and python3 (the cycle model, `xtask/mcu/cycles.py`).
//!
//! This module holds what the parts share: the MCU profiles, the scene lists, the paths and
//! the flags (clap `Args`). `scenes` is `cargo xtask mcu`, `size` is `cargo xtask size`, `report` the
//! microcontroller part of `cargo xtask report`; `tools`, `firmware` and `qemu` build and
//! run.

mod band_counts;
mod bands;
mod choose;
mod cores;
mod firmware;
mod qemu;
mod report;
mod scenes;
mod size;
mod tools;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Args;

use crate::cmd::root;

pub use band_counts::{band_counts, BandCounts};
pub(crate) use bands::write_region;
pub use cores::cores;
pub use report::report_mcu;
pub use scenes::mcu;
pub use size::size;
pub(crate) use tools::apt_install;

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
const SCENES: [&str; 39] = [
    "cube",
    // The cube with silhouette anti-aliasing from depth on each band: beside the cube it is
    // compared with.
    "aa_edge",
    "sphere",
    // The sphere as a mirror through per-vertex sphere-map coordinates: a plain textured
    // draw, beside the sphere it is compared with.
    "env_matcap",
    // The sphere as a mirror through a cube-map face per triangle and face coordinates per
    // vertex: a plain textured draw of that face, beside the sphere as well.
    "env_cube_vertex",
    // The marble, wood and granite baked into the sphere's texture (at build time): the same
    // draw as `sphere`.
    "noise_baked",
    "noise_baked_wood",
    "noise_baked_granite",
    // The brick sphere's bump lighting resolved into its texture (light fixed in object
    // space): the same draw as `sphere`, unlit.
    "bump_fast",
    // The Utah teapot baked from OBJ into flash (`cargo xtask bake-obj`).
    "teapot",
    "floor",
    "floor_bilinear",
    // Shadow maps (bands of 4 rows, 64x64 map): light pass per map texel, the lit pass's
    // no-shadow baseline, lit passes.
    "shadow_light",
    "shadow_none",
    "shadow_single",
    // The single tap with light coordinates from the texture coordinates (`ShadowedUv`).
    "shadow_single_uv",
    "shadow_pcf2x2",
    "shadow_pcf3x3",
    "shadow_spot",
    // The grazing light, front faces culled in the light pass.
    "shadow_grazing",
    // Solid textures: the marble sphere, the flame and the wooden cube lit by the baked 3D
    // light map.
    "noise",
    "noise_flame",
    // The flame from two baked layers, beside the same quad as a plain textured draw.
    "noise_flame_baked",
    "flame_plain",
    "noise_light3d",
    // Environment maps: the sphere as a mirror, r per pixel and per vertex.
    "env_pixel",
    "env_vertex",
    // Anti-aliasing (rotated grid through bands) and transparency.
    "aa_cube",
    "transparency",
    // Run-time displacement: a subdivided grid displaced by a moving swell each frame.
    "water",
    // Per-pixel lighting of a bump-mapped sphere (mesh and brick maps in flash).
    "bump",
    // The glTF sample models baked by `cargo xtask bake-gltf`, static pose, 240x320 in
    // 240x8 bands (`model_scene.rs`).
    "fox",
    "cesium_man",
    // Palette textures (`cargo xtask bake-palette`, 8- and 4-bit indices) on the floor and
    // the cube, and their RGB565 twins, through the same open-stage path.
    "floor_rgb565",
    "floor_palette8",
    "floor_palette4",
    "cube_rgb565",
    "cube_palette8",
    "cube_palette4",
];

/// The same scenes drawn into one whole 320x240 frame (feature `whole`, memory layout
/// `FIXEL_FW_MEMORY=whole`): the figures to compare with whole-frame renderers and with the
/// banded scenes; and `sphere_sized`, the sphere in bands in its fastest mode, whose
/// texture footprints (256 KB) need this layout's flash (its RAM is a band firmware's).
const WHOLE_SCENES: [&str; 22] = [
    "whole_cube",
    "sphere_sized",
    "whole_sphere",
    "whole_sphere_adaptive",
    "whole_sphere_footprint",
    "whole_sphere_sized",
    "whole_teapot",
    "whole_floor",
    "whole_floor_bilinear",
    "whole_shadow_single",
    "whole_shadow_single_uv",
    "whole_noise",
    "whole_noise_flame",
    "whole_noise_light3d",
    "whole_env_pixel",
    "whole_env_vertex",
    "whole_aa_cube",
    "whole_transparency",
    "whole_water",
    "whole_bump",
    // The glTF models into one whole 240x320 frame.
    "whole_fox",
    "whole_cesium_man",
];

/// The whole-frame firmwares' machines: the band firmwares' ones, whose memory suffices
/// (`mps2-an386`: 4M + 4M SSRAM for both Arm builds; RV32 `virt`: 128 MB). The builds
/// differ in their memory layout only (`FIXEL_FW_MEMORY=whole`).
const WHOLE_MCUS: [Mcu; 3] = MCUS;

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

/// QEMU runs per scene of `cargo xtask mcu` unless `--runs` says otherwise.
const DEFAULT_RUNS: u32 = 2;

/// Flags of `cargo xtask mcu` (its defaults are what `cargo xtask ci` runs).
#[derive(Args, Clone, Debug)]
pub struct McuArgs {
    /// QEMU runs per scene; their instruction counts must agree
    #[arg(
        long,
        value_name = "N",
        default_value_t = DEFAULT_RUNS,
        value_parser = clap::value_parser!(u32).range(1..)
    )]
    pub runs: u32,
    /// Where the instructions go, per function
    #[arg(long)]
    pub profile: bool,
    /// Also report flash at opt-level s
    #[arg(long)]
    pub opt_s: bool,
    /// Do not install missing tools (rust targets, llvm-tools, apt-get packages)
    #[arg(long)]
    pub no_install: bool,
    /// Build and run only this firmware (repeatable: `--only whole_sphere_footprint --only
    /// geometry`); every scene and the geometry firmware when not given
    #[arg(long, value_name = "FIRMWARE", value_parser = firmware_name)]
    pub only: Vec<String>,
    /// Write the tables to docs/mcu.md and the bands table into README.md's
    /// `mcu-bands` region (a full run only)
    #[arg(long)]
    pub docs: bool,
}

impl Default for McuArgs {
    fn default() -> Self {
        McuArgs {
            runs: DEFAULT_RUNS,
            profile: false,
            opt_s: false,
            no_install: false,
            only: Vec::new(),
            docs: false,
        }
    }
}

impl McuArgs {
    /// Whether `--only` selects the firmware `name` (all do when it is not given).
    fn runs_firmware(&self, name: &str) -> bool {
        self.only.is_empty() || self.only.iter().any(|o| o == name)
    }
}

/// The firmware measured alone (geometry table) rather than as a scene.
const GEOMETRY: &str = "geometry";

/// The firmware that checks the ARMv7E-M assembly span loops against the generic sampler
/// and depth test, pixel by pixel (pass or fail, no figures): `loop=asm` on Cortex-M4F,
/// `loop=none` where the core has no such loop.
const DSP_CHECK: &str = "dsp_span";

/// Parses `--only`: a scene of [`SCENES`] or [`WHOLE_SCENES`], [`GEOMETRY`] or
/// [`DSP_CHECK`]; an error
/// that lists them otherwise.
fn firmware_name(name: &str) -> Result<String, String> {
    let known = || {
        SCENES
            .iter()
            .chain(WHOLE_SCENES.iter())
            .chain([&GEOMETRY, &DSP_CHECK])
    };
    if known().any(|s| *s == name) {
        Ok(name.to_string())
    } else {
        Err(format!(
            "no firmware `{name}`; the firmwares are {}",
            known().copied().collect::<Vec<_>>().join(", ")
        ))
    }
}

/// Flags of `cargo xtask size`.
#[derive(Args, Clone, Debug)]
pub struct SizeArgs {
    /// Also report fixel's flash at opt-level s
    #[arg(long)]
    pub opt_s: bool,
    /// Do not install missing tools (rust targets, llvm-tools, apt-get packages)
    #[arg(long)]
    pub no_install: bool,
}
