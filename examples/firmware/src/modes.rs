//! The mode matrix of `cargo xtask report`: every projection x filter x lighting
//! combination measured on each benchmark scene, as typed pipelines (the way a firmware
//! builds them: one monomorphised span loop per mode).
//!
//! Shared word for word by the report firmwares (`src/bin/report_*.rs`) and the host report
//! (`host-tests/src/bin/report/`, included there with `#[path]`), so the mode a
//! microcontroller counts and the mode the host times and measures are the same code.
//! Only `fixel` and `core` are used here.

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::pipeline::{
    Adaptive, Affine, DepthLess, Draw, Exact, ModulateFacet, ModulateIntensity, Pipeline,
    Quadratic, Replace, Subdivided,
};
use fixel::prelude::{Cull, Error, Viewport};
use fixel::texture::{
    Bilinear, BilinearFootprint, Lod, LodGranularity, MipTexture, Nearest, NearestMipmapNearest,
    Repeat, Trilinear,
};

/// Projection of a mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Proj {
    /// Screen-linear (`Affine`).
    Affine,
    /// Exact every 4 pixels (`Subdivided`, `log2_n = 2`).
    Sub4,
    /// Exact every 8 pixels (`Subdivided`, `log2_n = 3`).
    Sub8,
    /// Exact every 16 pixels (`Subdivided`, `log2_n = 4`).
    Sub16,
    /// Exact every 32 pixels (`Subdivided`, `log2_n = 5`).
    Sub32,
    /// Exact every 64 pixels (`Subdivided`, `log2_n = 6`).
    Sub64,
    /// Exact at the start, middle and end of every 16 pixels, a parabola in between
    /// (`Quadratic`, `log2_n = 4`).
    Quad16,
    /// The same every 32 pixels (`Quadratic`, `log2_n = 5`).
    Quad32,
    /// Exact at every pixel (`Exact`).
    Exact,
    /// Affine or exact per triangle from an error budget of 1/4 texel
    /// (`Projection::Adaptive { budget: 64 }`, the default of the `Adaptive` marker).
    Adaptive,
}

/// Texture filter of a mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filt {
    /// `Nearest`, level 0.
    Nearest,
    /// `Bilinear`, level 0.
    Bilinear,
    /// `BilinearFootprint`, level 0: `Bilinear`'s pixels from the texture's bilinear
    /// footprints (the texture handed to [`Mode::draw`] must have them,
    /// `MipTexture::with_footprints`).
    BilinearFootprint,
    /// `NearestMipmapNearest`, LOD per pixel.
    NearestMip,
    /// `Trilinear`, LOD per pixel.
    Trilinear,
    /// `Trilinear`, LOD once per span.
    TrilinearSpan,
}

impl Filt {
    /// True when the filter reads a mip chain.
    pub const fn mipmapped(self) -> bool {
        matches!(
            self,
            Filt::NearestMip | Filt::Trilinear | Filt::TrilinearSpan
        )
    }
}

/// How a scene is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mode {
    /// Per-vertex light modulated into the texel (`ModulateIntensity`), else `Replace`.
    pub lit: bool,
    /// With `lit`: the light read once per triangle (`ModulateFacet`: the same light on a
    /// mesh with per-face normals, one interpolant fewer), named `facet`.
    pub facet: bool,
    /// Texture filter.
    pub filter: Filt,
    /// Projection.
    pub proj: Proj,
}

impl Mode {
    /// Lighting part of the name: `lit` or `unlit`.
    pub const fn lit_name(&self) -> &'static str {
        if self.lit && self.facet {
            "facet"
        } else if self.lit {
            "lit"
        } else {
            "unlit"
        }
    }

    /// Filter part of the name.
    pub const fn filter_name(&self) -> &'static str {
        match self.filter {
            Filt::Nearest => "nearest",
            Filt::Bilinear => "bilinear",
            Filt::BilinearFootprint => "bilinear-footprint",
            Filt::NearestMip => "nearest-mip-nearest",
            Filt::Trilinear => "trilinear",
            Filt::TrilinearSpan => "trilinear-span",
        }
    }

    /// Projection part of the name.
    pub const fn proj_name(&self) -> &'static str {
        match self.proj {
            Proj::Affine => "affine",
            Proj::Sub4 => "sub4",
            Proj::Sub8 => "sub8",
            Proj::Sub16 => "sub16",
            Proj::Sub32 => "sub32",
            Proj::Sub64 => "sub64",
            Proj::Quad16 => "quad16",
            Proj::Quad32 => "quad32",
            Proj::Exact => "exact",
            Proj::Adaptive => "adaptive",
        }
    }

    /// `lit-bilinear-exact`, `unlit-trilinear-span-sub16`, ...
    pub fn write_name(&self, out: &mut impl core::fmt::Write) -> core::fmt::Result {
        write!(
            out,
            "{}-{}-{}",
            self.lit_name(),
            self.filter_name(),
            self.proj_name()
        )
    }

    /// The typed draw of this mode (`Repeat` wrap, `DepthLess`, back faces culled).
    /// `tex` must hold a full mip chain when the filter is mipmapped. Inlined so that a
    /// constant mode links only its own span loop.
    #[inline(always)]
    pub fn draw<'a>(&self, tex: MipTexture<'a>, vp: Viewport) -> Result<Draw<'a, Rgb565>, Error> {
        macro_rules! typed {
            ($p:ty, $f:ty) => {
                if self.lit && self.facet {
                    Draw::new_mip::<Pipeline<$p, $f, Repeat, Repeat, ModulateFacet, DepthLess>>(
                        Some(tex),
                        vp,
                        Cull::Back,
                    )
                } else if self.lit {
                    Draw::new_mip::<Pipeline<$p, $f, Repeat, Repeat, ModulateIntensity, DepthLess>>(
                        Some(tex),
                        vp,
                        Cull::Back,
                    )
                } else {
                    Draw::new_mip::<Pipeline<$p, $f, Repeat, Repeat, Replace, DepthLess>>(
                        Some(tex),
                        vp,
                        Cull::Back,
                    )
                }
            };
        }
        macro_rules! by_filter {
            ($p:ty) => {
                match self.filter {
                    Filt::Nearest => typed!($p, Nearest),
                    Filt::Bilinear => typed!($p, Bilinear),
                    Filt::BilinearFootprint => typed!($p, BilinearFootprint),
                    Filt::NearestMip => typed!($p, NearestMipmapNearest),
                    Filt::Trilinear | Filt::TrilinearSpan => typed!($p, Trilinear),
                }
            };
        }
        let draw = match self.proj {
            Proj::Affine => by_filter!(Affine)?,
            Proj::Sub4 => by_filter!(Subdivided)?.with_subdivision(2)?,
            Proj::Sub8 => by_filter!(Subdivided)?.with_subdivision(3)?,
            Proj::Sub16 => by_filter!(Subdivided)?.with_subdivision(4)?,
            Proj::Sub32 => by_filter!(Subdivided)?.with_subdivision(5)?,
            Proj::Sub64 => by_filter!(Subdivided)?.with_subdivision(6)?,
            Proj::Quad16 => by_filter!(Quadratic)?.with_subdivision(4)?,
            Proj::Quad32 => by_filter!(Quadratic)?.with_subdivision(5)?,
            Proj::Exact => by_filter!(Exact)?,
            Proj::Adaptive => by_filter!(Adaptive)?.with_adaptive_budget(64),
        };
        Ok(if self.filter == Filt::TrilinearSpan {
            draw.with_lod(Lod {
                granularity: LodGranularity::Span,
                ..Lod::default()
            })
        } else {
            draw
        })
    }
}

/// Every projection of the report, in the order of its matrices and legends.
pub const PROJS: [Proj; 10] = [
    Proj::Affine,
    Proj::Sub4,
    Proj::Sub8,
    Proj::Sub16,
    Proj::Sub32,
    Proj::Sub64,
    Proj::Quad16,
    Proj::Quad32,
    Proj::Exact,
    Proj::Adaptive,
];

/// `lit` x `filters` x every projection, lit first.
const fn matrix<const N: usize>(lights: &[bool], filters: &[Filt]) -> [Mode; N] {
    assert!(N == lights.len() * filters.len() * PROJS.len());
    let mut out = [Mode {
        lit: false,
        facet: false,
        filter: Filt::Nearest,
        proj: Proj::Affine,
    }; N];
    let mut k = 0;
    let mut l = 0;
    while l < lights.len() {
        let mut f = 0;
        while f < filters.len() {
            let mut p = 0;
            while p < PROJS.len() {
                out[k] = Mode {
                    lit: lights[l],
                    facet: false,
                    filter: filters[f],
                    proj: PROJS[p],
                };
                k += 1;
                p += 1;
            }
            f += 1;
        }
        l += 1;
    }
    out
}

/// Modes of the lit scenes (cube, sphere): lit and unlit, nearest and bilinear, every
/// projection.
pub const LIT_SCENE_MODES: [Mode; 40] = matrix(&[true, false], &[Filt::Nearest, Filt::Bilinear]);

/// The lit half of [`LIT_SCENE_MODES`] (firmware `report_cube`).
pub const LIT_SCENE_MODES_LIT: [Mode; 20] = matrix(&[true], &[Filt::Nearest, Filt::Bilinear]);

/// The unlit half of [`LIT_SCENE_MODES`] (firmware `report_cube_unlit`).
pub const LIT_SCENE_MODES_UNLIT: [Mode; 20] = matrix(&[false], &[Filt::Nearest, Filt::Bilinear]);

/// The cube's modes with the light read once per triangle (`facet`: its faces have per-face
/// normals), bilinear, every projection (firmware `report_cube_facet`).
pub const CUBE_FACET_MODES: [Mode; 10] = {
    let mut out: [Mode; 10] = matrix(&[true], &[Filt::Bilinear]);
    let mut k = 0;
    while k < out.len() {
        out[k].facet = true;
        k += 1;
    }
    out
};

/// [`CUBE_FACET_MODES`] reading the texture's bilinear footprints (`BilinearFootprint`: the
/// same pixels, one 64-bit load per sample; firmware `report_cube_footprint`).
pub const CUBE_FOOTPRINT_MODES: [Mode; 10] = {
    let mut out = CUBE_FACET_MODES;
    let mut k = 0;
    while k < out.len() {
        out[k].filter = Filt::BilinearFootprint;
        k += 1;
    }
    out
};

/// [`CUBE_FOOTPRINT_MODES`] `0..5` (firmware `report_cube_footprint`; all ten do not fit
/// 256 KiB of flash on Cortex-M0+).
pub const CUBE_FOOTPRINT_MODES_A: [Mode; 5] = half(0);

/// [`CUBE_FOOTPRINT_MODES`] `5..10` (firmware `report_cube_footprint_b`).
pub const CUBE_FOOTPRINT_MODES_B: [Mode; 5] = half(5);

/// Five modes of [`CUBE_FOOTPRINT_MODES`] from `from`.
const fn half(from: usize) -> [Mode; 5] {
    let mut out = [CUBE_FOOTPRINT_MODES[0]; 5];
    let mut k = 0;
    while k < 5 {
        out[k] = CUBE_FOOTPRINT_MODES[from + k];
        k += 1;
    }
    out
}

/// Modes of the cube: [`LIT_SCENE_MODES`], [`CUBE_FACET_MODES`] and
/// [`CUBE_FOOTPRINT_MODES`].
pub const CUBE_MODES: [Mode; 60] = {
    let mut out = [LIT_SCENE_MODES[0]; 60];
    let mut k = 0;
    while k < 60 {
        out[k] = if k < 40 {
            LIT_SCENE_MODES[k]
        } else if k < 50 {
            CUBE_FACET_MODES[k - 40]
        } else {
            CUBE_FOOTPRINT_MODES[k - 50]
        };
        k += 1;
    }
    out
};

/// Modes of the floor (unlit, minified): every filter incl. the mipmapped ones and the
/// footprint bilinear, every projection.
pub const FLOOR_MODES: [Mode; 60] = matrix(
    &[false],
    &[
        Filt::Nearest,
        Filt::Bilinear,
        Filt::NearestMip,
        Filt::Trilinear,
        Filt::TrilinearSpan,
        Filt::BilinearFootprint,
    ],
);

/// The floor's unmipmapped modes (firmware `report_floor`).
pub const FLOOR_PLAIN_MODES: [Mode; 20] = matrix(&[false], &[Filt::Nearest, Filt::Bilinear]);

/// The floor's footprint bilinear modes (firmware `report_floor_footprint`).
pub const FLOOR_FOOTPRINT_MODES: [Mode; 10] = matrix(&[false], &[Filt::BilinearFootprint]);

/// The floor's mipmapped modes (firmware `report_floor_mip`).
pub const FLOOR_MIP_MODES: [Mode; 30] = matrix(
    &[false],
    &[Filt::NearestMip, Filt::Trilinear, Filt::TrilinearSpan],
);

/// Modes of the sphere: [`LIT_SCENE_MODES`] and the lit modes reading the texture's
/// bilinear footprints (`BilinearFootprint`: `Bilinear`'s pixels, one 64-bit load per
/// sample; 8 bytes per texel, 256 KiB for the sphere's 256 x 128 texture).
pub const SPHERE_MODES: [Mode; 50] = {
    let lit_footprint: [Mode; 10] = matrix(&[true], &[Filt::BilinearFootprint]);
    let mut out = [LIT_SCENE_MODES[0]; 50];
    let mut k = 0;
    while k < 50 {
        out[k] = if k < 40 {
            LIT_SCENE_MODES[k]
        } else {
            lit_footprint[k - 40]
        };
        k += 1;
    }
    out
};

/// The sphere's modes on microcontrollers (firmware `report_sphere`, 8-row bands; its 2208
/// triangles overflow the bins, so each band re-projects the triangles it meets): unlit
/// nearest affine (the cheapest), lit bilinear adaptive and exact, and the same two
/// reading footprints ([`Mode::draw`] needs `data::T256X128_FP` for those).
pub const SPHERE_MCU_MODES: [Mode; 5] = [
    Mode {
        lit: true,
        facet: false,
        filter: Filt::BilinearFootprint,
        proj: Proj::Adaptive,
    },
    Mode {
        lit: true,
        facet: false,
        filter: Filt::BilinearFootprint,
        proj: Proj::Exact,
    },
    Mode {
        lit: false,
        facet: false,
        filter: Filt::Nearest,
        proj: Proj::Affine,
    },
    Mode {
        lit: true,
        facet: false,
        filter: Filt::Bilinear,
        proj: Proj::Adaptive,
    },
    Mode {
        lit: true,
        facet: false,
        filter: Filt::Bilinear,
        proj: Proj::Exact,
    },
];
