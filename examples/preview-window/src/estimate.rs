//! The instruction estimate the window prints for a frame: the measured instructions per
//! drawn pixel of the benchmark's frame 0 on a chip, in the same scene and technique, times
//! the pixels this frame drew. An estimate, not a count: the per-pixel cost of a view
//! differs from frame 0's with the triangles' sizes on screen and the share of set-up work.
//! For exact counts, `cargo xtask mcu` and `cargo xtask report` run the firmwares under QEMU.

use std::fmt;

use crate::scene::SceneKind;

/// A chip the project measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Chip {
    /// Cortex-M0+ (ARMv6-M: no divider, no FPU).
    M0Plus,
    /// Cortex-M4F (ARMv7E-M with the DSP extension).
    M4F,
    /// RV32IMC.
    Rv32,
}

impl Chip {
    /// Every chip, in the order the `c` key steps through them.
    pub const ALL: [Chip; 3] = [Chip::M4F, Chip::M0Plus, Chip::Rv32];

    /// Name on the command line (`--chip`).
    pub fn arg(self) -> &'static str {
        match self {
            Chip::M0Plus => "m0plus",
            Chip::M4F => "m4f",
            Chip::Rv32 => "rv32",
        }
    }

    /// Parses [`Chip::arg`].
    pub fn parse(s: &str) -> Option<Chip> {
        Chip::ALL.into_iter().find(|c| c.arg() == s)
    }

    /// The chip after this one.
    pub fn next(self) -> Chip {
        let i = Chip::ALL.iter().position(|&c| c == self).unwrap_or(0);
        Chip::ALL[(i + 1) % Chip::ALL.len()]
    }

    fn index(self) -> usize {
        match self {
            Chip::M0Plus => 0,
            Chip::M4F => 1,
            Chip::Rv32 => 2,
        }
    }
}

impl fmt::Display for Chip {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Chip::M0Plus => "Cortex-M0+",
            Chip::M4F => "Cortex-M4F",
            Chip::Rv32 => "RV32IMC",
        })
    }
}

/// Where a figure was measured.
const REPORT: &str = "docs/report/report.md (cargo xtask report, commit fdbfd80)";
/// The firmwares' own modes, all three cores.
const MCU: &str = "README, On microcontrollers (cargo xtask mcu, commit fdbfd80)";

/// Executed instructions per drawn pixel, frame 0 of the benchmark scene in 8-row bands
/// under QEMU, `[Cortex-M0+, Cortex-M4F, RV32IMC]` (`None`: not measured), and the source.
type Figures = ([Option<f32>; 3], &'static str);

/// The measured figures, by scene and technique name (the names of `modes.rs`).
const MEASURED: &[(SceneKind, &str, Figures)] = &[
    (
        SceneKind::Cube,
        "facet-bilinear-footprint-quad16",
        ([Some(175.6), Some(102.2), Some(120.5)], MCU),
    ),
    (
        SceneKind::Cube,
        "lit-bilinear-sub64",
        ([Some(182.7), Some(101.5), None], REPORT),
    ),
    (
        SceneKind::Cube,
        "lit-bilinear-exact",
        ([Some(296.2), Some(145.0), None], REPORT),
    ),
    (
        SceneKind::Cube,
        "lit-bilinear-adaptive",
        ([Some(301.3), Some(146.2), None], REPORT),
    ),
    (
        SceneKind::Cube,
        "lit-nearest-affine",
        ([Some(88.9), Some(55.4), None], REPORT),
    ),
    (
        SceneKind::Sphere,
        "lit-bilinear-sub64",
        ([Some(547.7), Some(291.5), Some(357.6)], MCU),
    ),
    (
        SceneKind::Sphere,
        "lit-bilinear-footprint-adaptive",
        ([Some(437.9), Some(223.1), None], REPORT),
    ),
    (
        SceneKind::Sphere,
        "lit-bilinear-exact",
        ([Some(662.8), Some(350.2), None], REPORT),
    ),
    (
        SceneKind::Sphere,
        "lit-bilinear-adaptive",
        ([Some(463.2), Some(255.9), None], REPORT),
    ),
    (
        SceneKind::Teapot,
        "lit-bilinear-sub64",
        ([Some(747.5), Some(384.2), Some(468.7)], MCU),
    ),
];

/// A frame's estimate on one chip.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Estimate {
    /// `per_pixel` measured instructions per pixel times `pixels`.
    Measured {
        /// Instructions per drawn pixel, as measured on the benchmark's frame 0.
        per_pixel: f32,
        /// Pixels this frame drew (that passed the depth test).
        pixels: u32,
        /// Where `per_pixel` comes from.
        source: &'static str,
    },
    /// No figure for this scene, technique and chip.
    Unmeasured,
}

impl Estimate {
    /// The estimate for `pixels` drawn pixels of `scene` in `technique` on `chip`.
    pub fn new(scene: SceneKind, technique: &str, chip: Chip, pixels: u32) -> Estimate {
        MEASURED
            .iter()
            .find(|(s, t, _)| *s == scene && *t == technique)
            .and_then(|(_, _, (figures, source))| {
                figures[chip.index()].map(|per_pixel| Estimate::Measured {
                    per_pixel,
                    pixels,
                    source,
                })
            })
            .unwrap_or(Estimate::Unmeasured)
    }

    /// Estimated instructions for the frame.
    pub fn instructions(&self) -> Option<f64> {
        match *self {
            Estimate::Measured {
                per_pixel, pixels, ..
            } => Some(f64::from(per_pixel) * f64::from(pixels)),
            Estimate::Unmeasured => None,
        }
    }
}

impl fmt::Display for Estimate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Estimate::Measured {
                per_pixel,
                pixels,
                source,
            } => write!(
                f,
                "~{:.2} M instructions (estimate: {per_pixel} instr/px measured on the \
                 benchmark's frame 0 [{source}] x {pixels} px drawn)",
                self.instructions().unwrap_or(0.0) / 1e6
            ),
            Estimate::Unmeasured => f.write_str(
                "no estimate (this scene and technique are not measured on this chip; \
                 `cargo xtask report` and `cargo xtask mcu` measure the modes they list)",
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_firmware_modes_have_figures_on_every_chip() {
        for (scene, technique) in [
            (SceneKind::Cube, "facet-bilinear-footprint-quad16"),
            (SceneKind::Sphere, "lit-bilinear-sub64"),
            (SceneKind::Teapot, "lit-bilinear-sub64"),
        ] {
            for chip in Chip::ALL {
                let e = Estimate::new(scene, technique, chip, 1000);
                assert!(e.instructions().is_some(), "{scene:?} {technique} {chip}");
            }
        }
    }

    #[test]
    fn an_estimate_is_the_figure_times_the_pixels() {
        let e = Estimate::new(SceneKind::Sphere, "lit-bilinear-sub64", Chip::M4F, 1000);
        assert_eq!(e.instructions(), Some(f64::from(291.5f32) * 1000.0));
        let none = Estimate::new(SceneKind::Teapot, "lit-nearest-affine", Chip::M4F, 1000);
        assert_eq!(none, Estimate::Unmeasured);
    }
}
