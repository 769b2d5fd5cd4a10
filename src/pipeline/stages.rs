//! The stages a draw can use, as small runtime enums and as zero-sized marker types.
//!
//! A firmware picks its stages as *types* ([`Pipeline`]): the per-pixel loop is then
//! monomorphised for exactly that combination and an unused stage costs no cycles and no
//! flash. Host tools and tests can pick them at run time with [`DrawMode`], which dispatches
//! once per draw to one of the pre-instantiated combinations (and so links them all).

use core::fmt::Debug;
use core::marker::PhantomData;

use crate::geometry::Cull;
use crate::shading::{self, builtin::Classic, TexBinding};
use crate::texture::{
    Bilinear, BilinearFast, BilinearFootprint, BilinearFootprintSized, ClampToBorder, ClampToEdge,
    DynMip, DynWrap, Filter, Lod, MipFilter, Mipmapped, MirroredRepeat, Nearest, Repeat, Sampler,
    TexSampler, Wrap, WrapMode,
};

/// How texture coordinates (and colours) are interpolated across a triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Projection {
    /// Screen-linear: cheapest, wrong under perspective (textures swim and bend).
    Affine,
    /// Exact every `2^log2_n` pixels along a span, affine in between (`log2_n` in `1..=6`).
    Subdivided {
        /// Log2 of the subdivision length N.
        log2_n: u8,
    },
    /// Perspective-correct at every pixel (hyperbolic interpolation of `u/w, v/w, 1/w`).
    #[default]
    Exact,
    /// Exact at the start, middle and end of every `2^log2_n` pixels along a span, a
    /// parabola in between (`log2_n` in `1..=6`): two reciprocals per segment, about the
    /// error of [`Projection::Subdivided`] with a quarter of the length.
    Quadratic {
        /// Log2 of the segment length N.
        log2_n: u8,
    },
    /// Chosen per triangle: affine when a bound on the affine error (see
    /// `affine_error_exceeds` in the set-up) is within `budget` (texels, Q8: 256 = one texel),
    /// exact otherwise. Small or nearly screen-parallel triangles then cost no reciprocal.
    Adaptive {
        /// Largest accepted affine error, 1/256 texel.
        budget: u16,
    },
}

/// What colour a covered pixel gets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Shading {
    /// The texel as it is (GL_REPLACE).
    Replace,
    /// Texel times the interpolated vertex colour, per channel (GL_MODULATE).
    Modulate,
    /// Texel times one interpolated intensity: the vertex colour's red channel (the scene's
    /// lighting sets all three equal). One interpolant instead of three.
    #[default]
    ModulateIntensity,
    /// Texel times one intensity per triangle, the mean of its vertices' (lit textures on
    /// faceted meshes, whose vertices share a face's normal: there the same pixels as
    /// [`Shading::ModulateIntensity`] for one interpolant fewer). Typed draws only:
    /// [`Draw::dynamic`](super::Draw::dynamic) refuses it.
    ModulateFacet,
    /// Untextured: the interpolated vertex colour.
    Gouraud,
    /// Untextured: one constant colour for the whole draw.
    Flat,
}

impl Shading {
    /// True when this shading reads a texture.
    pub const fn textured(self) -> bool {
        matches!(
            self,
            Shading::Replace
                | Shading::Modulate
                | Shading::ModulateIntensity
                | Shading::ModulateFacet
        )
    }
}

/// Depth testing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DepthTest {
    /// No test and no depth writes: later triangles overwrite earlier ones.
    #[default]
    Off,
    /// GL_LESS against a 16-bit depth buffer, writing depth of pixels that pass.
    Less,
}

/// Every run-time choice of one draw.
///
/// `DrawMode::default()` is GL's defaults where GL has one, and the benchmark's lit textured
/// mode otherwise:
///
/// | field | default | meaning |
/// |---|---|---|
/// | `projection` | [`Projection::Exact`] | perspective-correct at every pixel |
/// | `filter` | [`Filter::Nearest`] | `GL_NEAREST` |
/// | `mag_filter` | `None` | the same as `filter` |
/// | `mip` | [`MipFilter::None`] | no mipmapping: level 0 only |
/// | `lod` | [`Lod::default()`] | bias 0, no clamps, computed per pixel |
/// | `wrap` | `[Wrap::Repeat; 2]` | `GL_REPEAT` on s and t |
/// | `shading` | [`Shading::ModulateIntensity`] | texel times the lit intensity (needs a texture) |
/// | `depth` | [`DepthTest::Off`] | no depth test, no depth buffer needed |
/// | `cull` | [`Cull::Back`] | back faces (clockwise in NDC) skipped |
///
/// ```
/// use fixel::pipeline::{DepthTest, DrawMode, Projection, Shading};
/// use fixel::texture::{Filter, Wrap};
/// use fixel::geometry::Cull;
/// let m = DrawMode::default();
/// assert_eq!((m.projection, m.filter, m.wrap), (Projection::Exact, Filter::Nearest, [Wrap::Repeat; 2]));
/// assert_eq!((m.shading, m.depth, m.cull), (Shading::ModulateIntensity, DepthTest::Off, Cull::Back));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawMode {
    /// Interpolation of texture coordinates and colours.
    pub projection: Projection,
    /// Minification filter within a mip level (and the magnification filter unless
    /// `mag_filter` says otherwise).
    pub filter: Filter,
    /// Magnification filter when it differs from `filter` (GL sets the two separately).
    pub mag_filter: Option<Filter>,
    /// Filtering between mip levels (`None`: no mipmapping, level 0 only).
    pub mip: MipFilter,
    /// Level-of-detail bias, clamps and granularity (used when `mip` is not `None`).
    pub lod: Lod,
    /// Wrap modes for s and t.
    pub wrap: [Wrap; 2],
    /// Pixel colour.
    pub shading: Shading,
    /// Depth test.
    pub depth: DepthTest,
    /// Face culling (costs nothing per pixel).
    pub cull: Cull,
}

/// Marker for the projection stage.
pub trait ProjectionStage: Copy + Default + Debug {
    /// Which interpolation this marker selects.
    const KIND: ProjKind;
    /// Log2 of the subdivision length a draw of this marker starts with (subdivided only;
    /// the draw's `with_subdivision` changes it).
    const LOG2_N: u8 = 3;
}
/// Projection kind without parameters (for markers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProjKind {
    /// See [`Projection::Affine`].
    Affine,
    /// See [`Projection::Subdivided`].
    Subdivided,
    /// See [`Projection::Quadratic`].
    Quadratic,
    /// See [`Projection::Exact`].
    Exact,
    /// See [`Projection::Adaptive`].
    Adaptive,
    /// Chosen per draw at run time (the [`DynProjection`] marker of
    /// [`Draw::dynamic`](super::Draw::dynamic)): one span loop serves every projection.
    Dynamic,
}
/// Marker for the shading stage of the classic API: names a built-in shader.
pub trait ShadingStage: Copy + Default + Debug {
    /// Which shading this marker selects.
    const KIND: Shading;
    /// The built-in shader (see [`crate::shading::Classic`]) for a texture bound with
    /// filter `F` and wraps `WU`, `WV`.
    type Shader<'a, F: TexSampler + 'a, WU: WrapMode + 'a, WV: WrapMode + 'a>: Classic;
    /// That shader, from the draw's texture binding and flat colour (raw RGB565).
    fn shader<'a, F: TexSampler + 'a, WU: WrapMode + 'a, WV: WrapMode + 'a>(
        tex: TexBinding<'a, F, WU, WV>,
        flat: u16,
    ) -> Self::Shader<'a, F, WU, WV>;
}
/// Marker for the depth stage.
pub trait DepthStage: Copy + Default + Debug {
    /// Whether the depth test runs.
    const TEST: bool;
}

/// Affine projection marker.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Affine;
impl ProjectionStage for Affine {
    const KIND: ProjKind = ProjKind::Affine;
}
/// Subdivided projection marker (N comes from the draw, default 8).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Subdivided;
impl ProjectionStage for Subdivided {
    const KIND: ProjKind = ProjKind::Subdivided;
}
/// A segment length's log2 from a marker's const parameter, clamped into `1..=6`.
const fn segment_log2(n: u8) -> u8 {
    if n < 1 {
        1
    } else if n > 6 {
        6
    } else {
        n
    }
}

/// Subdivided projection marker with the subdivision length in the type:
/// `SubdividedBy<4>` is exact every 16 pixels (`LOG2_N` in `1..=6`; other values are
/// clamped into that range).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SubdividedBy<const LOG2_N: u8>;
impl<const LOG2_N: u8> ProjectionStage for SubdividedBy<LOG2_N> {
    const KIND: ProjKind = ProjKind::Subdivided;
    const LOG2_N: u8 = segment_log2(LOG2_N);
}
/// Quadratic projection marker (N comes from the draw, default 16).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Quadratic;
impl ProjectionStage for Quadratic {
    const KIND: ProjKind = ProjKind::Quadratic;
    const LOG2_N: u8 = 4;
}
/// Quadratic projection marker with the segment length in the type: `QuadraticBy<5>` is
/// exact at the start, middle and end of every 32 pixels (`LOG2_N` in `1..=6`; other values
/// are clamped into that range).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QuadraticBy<const LOG2_N: u8>;
impl<const LOG2_N: u8> ProjectionStage for QuadraticBy<LOG2_N> {
    const KIND: ProjKind = ProjKind::Quadratic;
    const LOG2_N: u8 = segment_log2(LOG2_N);
}
/// Adaptive projection marker (affine or exact per triangle; budget from the draw,
/// default 1/4 texel).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Adaptive;
impl ProjectionStage for Adaptive {
    const KIND: ProjKind = ProjKind::Adaptive;
}
/// Projection chosen at run time from the draw's [`Projection`] (host tools: one span loop
/// for all four modes, at the cost of a branch per span).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DynProjection;
impl ProjectionStage for DynProjection {
    const KIND: ProjKind = ProjKind::Dynamic;
}
/// Exact perspective marker.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Exact;
impl ProjectionStage for Exact {
    const KIND: ProjKind = ProjKind::Exact;
}

/// A textured classic shading: its marker type and the built-in shader it names.
macro_rules! textured_stage {
    ($(#[$doc:meta] $name:ident),* $(,)?) => {$(
        #[$doc]
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
        pub struct $name;
        impl ShadingStage for $name {
            const KIND: Shading = Shading::$name;
            type Shader<'a, F: TexSampler + 'a, WU: WrapMode + 'a, WV: WrapMode + 'a> =
                shading::$name<'a, F, WU, WV>;
            #[inline(always)]
            fn shader<'a, F: TexSampler + 'a, WU: WrapMode + 'a, WV: WrapMode + 'a>(
                tex: TexBinding<'a, F, WU, WV>,
                _: u16,
            ) -> Self::Shader<'a, F, WU, WV> {
                shading::$name { tex }
            }
        }
    )*};
}
textured_stage!(
    /// Replace-shading marker.
    Replace,
    /// Modulate-by-colour marker.
    Modulate,
    /// Modulate-by-intensity marker (lit textures).
    ModulateIntensity,
    /// Modulate-by-one-intensity-per-triangle marker (lit textures on faceted meshes).
    ModulateFacet,
);
/// Untextured Gouraud marker.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Gouraud;
impl ShadingStage for Gouraud {
    const KIND: Shading = Shading::Gouraud;
    type Shader<'a, F: TexSampler + 'a, WU: WrapMode + 'a, WV: WrapMode + 'a> = shading::Gouraud;
    #[inline(always)]
    fn shader<'a, F: TexSampler + 'a, WU: WrapMode + 'a, WV: WrapMode + 'a>(
        _: TexBinding<'a, F, WU, WV>,
        _: u16,
    ) -> shading::Gouraud {
        shading::Gouraud
    }
}
/// Untextured flat marker.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Flat;
impl ShadingStage for Flat {
    const KIND: Shading = Shading::Flat;
    type Shader<'a, F: TexSampler + 'a, WU: WrapMode + 'a, WV: WrapMode + 'a> = shading::Flat;
    #[inline(always)]
    fn shader<'a, F: TexSampler + 'a, WU: WrapMode + 'a, WV: WrapMode + 'a>(
        _: TexBinding<'a, F, WU, WV>,
        flat: u16,
    ) -> shading::Flat {
        shading::Flat(flat)
    }
}

/// No depth test marker.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoDepth;
impl DepthStage for NoDepth {
    const TEST: bool = false;
}
/// GL_LESS depth test marker.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DepthLess;
impl DepthStage for DepthLess {
    const TEST: bool = true;
}

/// The stages of a draw as types: projection `P`, filter `F`, wraps `WU`/`WV`, shading `S`,
/// depth `D`.
///
/// ```
/// use fixel::pipeline::*;
/// use fixel::texture::{Bilinear, Repeat};
/// // The benchmark cube: lit, bilinear, perspective-correct, depth-tested.
/// type CubePipeline = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
/// ```
pub struct Pipeline<P, F, WU, WV, S, D>(PhantomData<(P, F, WU, WV, S, D)>);

impl<P, F, WU, WV, S, D> Debug for Pipeline<P, F, WU, WV, S, D> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("Pipeline")
    }
}

/// The stage types of a [`Pipeline`].
pub trait Stages {
    /// Projection stage.
    type P: ProjectionStage;
    /// Texture sampler (plain or mipmapped).
    type F: TexSampler + FromMode;
    /// Wrap mode for s.
    type WU: WrapMode + FromWrap;
    /// Wrap mode for t.
    type WV: WrapMode + FromWrap;
    /// Shading.
    type S: ShadingStage;
    /// Depth test.
    type D: DepthStage;
}

impl<P, F, WU, WV, S, D> Stages for Pipeline<P, F, WU, WV, S, D>
where
    P: ProjectionStage,
    F: TexSampler + FromMode,
    WU: WrapMode + FromWrap,
    WV: WrapMode + FromWrap,
    S: ShadingStage,
    D: DepthStage,
{
    type P = P;
    type F = F;
    type WU = WU;
    type WV = WV;
    type S = S;
    type D = D;
}

/// Builds a wrap-mode value from the draw's run-time wrap (markers ignore it).
pub trait FromWrap: WrapMode {
    /// The wrap-mode value for `w`.
    fn from_wrap(w: Wrap) -> Self;
}
macro_rules! from_wrap_marker {
    ($($t:ty),*) => {$(
        impl FromWrap for $t {
            #[inline(always)]
            fn from_wrap(_: Wrap) -> Self {
                <$t>::default()
            }
        }
    )*};
}
from_wrap_marker!(Repeat, MirroredRepeat, ClampToEdge, ClampToBorder);
impl FromWrap for DynWrap {
    #[inline(always)]
    fn from_wrap(w: Wrap) -> Self {
        DynWrap(w)
    }
}

/// Builds a sampler value from the draw's mode (markers ignore it).
pub trait FromMode: TexSampler {
    /// The sampler for `mode`.
    fn from_mode(mode: &DrawMode) -> Self;
}
impl FromMode for Nearest {
    fn from_mode(_: &DrawMode) -> Self {
        Nearest
    }
}
impl FromMode for BilinearFast {
    fn from_mode(_: &DrawMode) -> Self {
        BilinearFast
    }
}
impl FromMode for Bilinear {
    fn from_mode(_: &DrawMode) -> Self {
        Bilinear
    }
}
impl FromMode for BilinearFootprint {
    fn from_mode(_: &DrawMode) -> Self {
        BilinearFootprint
    }
}
impl<const LOG2_W: u32, const LOG2_H: u32> FromMode for BilinearFootprintSized<LOG2_W, LOG2_H> {
    fn from_mode(_: &DrawMode) -> Self {
        BilinearFootprintSized
    }
}
impl<Min: Sampler, Mag: Sampler, const LB: bool> FromMode for Mipmapped<Min, Mag, LB> {
    fn from_mode(_: &DrawMode) -> Self {
        Mipmapped::default()
    }
}
impl FromMode for DynMip {
    fn from_mode(mode: &DrawMode) -> Self {
        DynMip {
            min: mode.filter,
            mag: mode.mag_filter.unwrap_or(mode.filter),
            between: mode.mip,
        }
    }
}
