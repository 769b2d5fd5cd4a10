//! The open fragment stage: shaders as types, over any number of varyings.
//!
//! A draw interpolates the `N` varyings of its vertices (`[i32; N]`, raw fixed-point bits
//! in formats the shader chooses) across each triangle in the draw's projection mode
//! (affine, exact, subdivided or adaptive) and asks its [`Shader`] for the colour of every
//! covered pixel that passes the depth test. The span loop is monomorphised per shader and
//! projection, so a varying a shader does not declare is never interpolated, and a shader
//! that does not read a [`Fragment`] field costs nothing for it.
//!
//! * [`Shader`]: the trait a user implements: a per-triangle hook (rescale or rebase
//!   varyings, keep per-triangle data) and the per-pixel [`Shader::shade`].
//! * [`TexBinding`]: a texture with its filter and wrap modes, as a shader uses it: texel
//!   coordinate set-up per triangle and monomorphised sampling per pixel.
//! * the classic shadings ([`Replace`], [`ModulateIntensity`], [`Modulate`],
//!   [`Gouraud`], [`Flat`]) as ordinary shaders.
//!
//! # Writing a shader
//!
//! ```
//! use fixel::shading::{Fragment, Shader};
//!
//! /// Vertical stripes from an object-space x passed as varying 0 (I16F16 bits).
//! #[derive(Clone, Copy, Debug)]
//! struct Stripes;
//!
//! impl Shader for Stripes {
//!     type Varyings = [i32; 1];
//!     type Triangle = ();
//!     fn triangle(&self, _: &mut [[i32; 1]; 3]) {}
//!     fn shade(&self, f: &Fragment<[i32; 1], ()>) -> Option<u16> {
//!         // Bit 14 of x flips every 1/4 unit: white and red stripes (raw RGB565).
//!         Some(if f.varyings[0] & (1 << 14) != 0 { 0xFFFF } else { 0xF800 })
//!     }
//! }
//! ```
//!
//! See [`crate::pipeline::ShadedDraw`] for drawing with it, and the crate docs for a
//! two-texture light-mapped shader.

pub(crate) mod builtin;
pub mod facet;
mod light;
mod palette;
mod texcoord;

pub use builtin::{q8, Classic, Flat, Gouraud, Modulate, ModulateIntensity, Replace};
pub use facet::ModulateFacet;
pub use light::DirectionalLight;
pub use palette::{PaletteBinding, PaletteModulateIntensity, PaletteReplace};
pub use texcoord::{check_footprints_bound, TexBinding, TexTriangle};

/// The most varyings a shader may declare. The set-up keeps one plane per varying (12 bytes)
/// and the span loop one running value and one step each, sized by the shader's own count,
/// so the limit costs nothing to a shader that declares fewer; 11 covers a normal, an eye
/// vector, texture coordinates and a colour ([`env::Tinted`] around [`env::EnvLit`]). The
/// band renderer's bins hold triangles of at most
/// [`BINNED_VARYINGS`](crate::surface::BINNED_VARYINGS) (8).
pub const MAX_VARYINGS: usize = 11;

/// A shader's interpolated attributes: `[i32; N]` with `N <= MAX_VARYINGS`.
///
/// Implemented for arrays only. Declaring more than [`MAX_VARYINGS`] fails to compile when
/// the draw is instantiated:
///
/// ```compile_fail
/// use fixel::shading::Varyings;
/// const TOO_MANY: usize = <[i32; 12] as Varyings>::N;
/// ```
pub trait Varyings: Copy + core::fmt::Debug + 'static {
    /// The number of varyings, at most [`MAX_VARYINGS`].
    const N: usize;
    /// All zero.
    fn zero() -> Self;
    /// The values as a slice.
    fn as_slice(&self) -> &[i32];
    /// The values as a mutable slice.
    fn as_mut_slice(&mut self) -> &mut [i32];
}

impl<const N: usize> Varyings for [i32; N] {
    const N: usize = {
        assert!(
            N <= MAX_VARYINGS,
            "a shader declares more varyings than fixel's set-up supports (MAX_VARYINGS = 11)"
        );
        N
    };
    #[inline(always)]
    fn zero() -> Self {
        [0; N]
    }
    #[inline(always)]
    fn as_slice(&self) -> &[i32] {
        self
    }
    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [i32] {
        self
    }
}

/// What a shader sees of one pixel.
#[derive(Clone, Copy, Debug)]
pub struct Fragment<V, T> {
    /// The interpolated varyings at the pixel centre, in the formats the vertices gave them
    /// (after the shader's [`Shader::triangle`] hook).
    pub varyings: V,
    /// Pixel column (frame coordinates).
    pub x: i32,
    /// Pixel row (frame coordinates, down).
    pub y: i32,
    /// Window depth, `0..=65535` (0 at the near plane). Only computed when read.
    pub depth: u16,
    /// Level of detail of the varying pair [`Shader::TEXCOORDS`]: `log2` of the larger of
    /// the pair's screen derivative lengths (Heckbert), Q8.8 (256 = one level), before any
    /// bias; at the shader's [`Shader::lod_granularity`]. 0 unless [`Shader::LOD`]. For a
    /// shader with [`Shader::LOD_DIRECTION`], the cube-map level of detail of that direction.
    pub lambda: i32,
    /// The per-triangle data returned by [`Shader::triangle`].
    pub triangle: T,
}

/// A fragment shader: the colour of each covered pixel.
///
/// Uniforms (textures, tables, lights) are fields of the shader value, borrowed with no heap;
/// varyings come per pixel in [`Fragment::varyings`]. Implementations should be small `Copy`
/// values: the span loop copies the shader once per span so its fields live in registers.
pub trait Shader: Copy {
    /// The interpolated attributes: `[i32; N]`.
    type Varyings: Varyings;
    /// Per-triangle data the [`Shader::triangle`] hook computes (for example the texel
    /// coordinate shift of [`TexBinding`]); `()` when there is none.
    type Triangle: Copy + core::fmt::Debug;

    /// The varying pair (indices) that holds texel coordinates (I16F16 texel units, as
    /// [`Shader::triangle`] leaves them), if any. The adaptive projection bounds its affine
    /// error in texels on this pair (without one, on every varying against 1/32 of the
    /// Q8.16 colour range), and [`Fragment::lambda`] is this pair's level of detail.
    const TEXCOORDS: Option<(usize, usize)> = None;

    /// True when [`Shader::shade`] may return `None` (alpha-tested cut-outs). A shader that
    /// never discards lets a depth-tested span test and write depth for all its pixels first
    /// and shade only the visible ones; one that does keeps the test and the write fused.
    const DISCARDS: bool = false;

    /// True when the shader blends with what the target already holds (transparency): the
    /// span loop then reads each covered pixel's colour and calls
    /// [`Shader::shade_over`] instead of [`Shader::shade`], and tests depth without writing
    /// it (translucent surfaces do not hide what is drawn after them). Opaque shaders leave
    /// it `false` and pay nothing.
    const BLENDS: bool = false;

    /// True to link the smallest span loops rather than the fastest: one shading loop per
    /// projection (varyings filled into a chunk array, then shaded), where the default also
    /// links loops that step long linear pieces in registers and a branch-free loop for
    /// fully visible chunks. Less flash, a few instructions more per pixel. The run-time
    /// [`Draw::dynamic`](crate::pipeline::Draw::dynamic) path, which links every mode, sets it.
    const SMALL: bool = false;

    /// True when the shader reads [`Fragment::lambda`] (mipmapping): the span loop then
    /// computes it from the [`Shader::TEXCOORDS`] pair.
    const LOD: bool = false;

    /// The first of three varyings holding a direction (any common scale; a cube-map
    /// lookup's), when [`Fragment::lambda`] is to be GL's cube-map level of detail of that
    /// direction rather than the [`Shader::TEXCOORDS`] pair's: `log2` of the larger screen
    /// derivative length of the face coordinates `(sc / ma, tc / ma)` on the face the
    /// pixel's direction selects, in units of half a face (a face of `2^l` texels adds
    /// `l - 1` levels), exact for a perspective-correct direction at every pixel
    /// ([`direction_lambda`](crate::texture::direction_lambda)). Only with
    /// [`Shader::LOD`]. Default `None`.
    const LOD_DIRECTION: Option<usize> = None;

    /// The first of six varyings holding a normal `n` then an eye vector `v` (any scale
    /// each), when [`Fragment::lambda`] is to be GL's cube-map level of detail of their
    /// reflection `r = 2 (n·v) n − (n·n) v`, from its exact screen derivatives at the pixel
    /// ([`reflection_lambda`](crate::shading::env::reflection_lambda); units as
    /// [`Shader::LOD_DIRECTION`]). Only with [`Shader::LOD`], and not with
    /// [`Shader::LOD_DIRECTION`] (which wins). Default `None`.
    const LOD_REFLECTION: Option<usize> = None;

    /// Where [`Fragment::lambda`] is computed (only when [`Shader::LOD`]).
    #[inline(always)]
    fn lod_granularity(&self) -> crate::texture::LodGranularity {
        crate::texture::LodGranularity::Pixel
    }

    /// Left shift, in bits, that the span loop applies (wrapping) to the
    /// [`Shader::TEXCOORDS`] pair before [`Shader::shade`]: a hook that had to shift huge
    /// texel coordinates right to fit them in `i32` per triangle says so here (see
    /// [`TexBinding`]). Default 0.
    #[inline(always)]
    fn coord_shift(_triangle: &Self::Triangle) -> u32 {
        0
    }

    /// True when [`Shader::shade_in_range`] shades every pixel of a linear piece of `n`
    /// pixels, whose varyings start at `start` and change by `slope` (wrapping) per pixel,
    /// exactly as [`Shader::shade`] does. A shader that clamps a varying at every pixel
    /// checks the piece's two ends here once (a linear varying lies between them) and skips
    /// the clamp in [`Shader::shade_in_range`]. The default, `false`, links no second loop.
    #[inline(always)]
    fn piece_in_range(&self, start: &Self::Varyings, slope: &Self::Varyings, n: u32) -> bool {
        let _ = (start, slope, n);
        false
    }

    /// The varying whose range alone decides [`Shader::piece_in_range`], if there is one
    /// ([`Shader::values_in_range`] then says which values are in range): the rasterizer
    /// bounds it over a whole affine triangle once and, when the bound is in range, skips
    /// the check of each span. Default `None`.
    const RANGE_VARYING: Option<usize> = None;

    /// True when [`Shader::shade_in_range`] shades every fragment whose
    /// [`Shader::RANGE_VARYING`] lies in `lo..=hi` (the other varyings anything) exactly as
    /// [`Shader::shade`] does. Default `false`.
    #[inline(always)]
    fn values_in_range(&self, lo: i64, hi: i64) -> bool {
        let _ = (lo, hi);
        false
    }

    /// [`Shader::shade`] for the fragments of a piece [`Shader::piece_in_range`] accepted
    /// (the same colour, with fewer instructions). The default calls [`Shader::shade`].
    #[inline(always)]
    fn shade_in_range(&self, fragment: &Fragment<Self::Varyings, Self::Triangle>) -> Option<u16> {
        self.shade(fragment)
    }

    /// Shades every pixel of a linear piece that [`Shader::piece_in_range`] accepted, all of
    /// them visible, into `out` as raw RGB565, and returns true; or returns false, writing
    /// nothing, to leave the piece to the span loop's [`Shader::shade_in_range`] per pixel
    /// (the default). `out[k]` must be what [`Shader::shade_in_range`] returns for the
    /// varyings `start + k slope` (wrapping): a shader with a faster loop of its own for
    /// whole pieces (an assembly loop on one target) overrides this. The span loop calls it
    /// only for a target of [`Rgb565`](crate::Rgb565) pixels, on targets that have such a loop.
    #[inline(always)]
    fn shade_piece_rgb565(
        &self,
        start: &Self::Varyings,
        slope: &Self::Varyings,
        out: &mut [u16],
    ) -> bool {
        let _ = (start, slope, out);
        false
    }

    /// True when [`Shader::shade_piece_depth_rgb565`] has a loop: the span stage then hands
    /// it whole spans of any length, instead of a depth pass and a mask first. Default false.
    const PIECE_DEPTH_LOOP: bool = false;

    /// [`Shader::shade_piece_rgb565`] with the depth test in the loop, for a shader that
    /// neither discards nor blends: pixel `k`'s depth is `clamp(z_k >> 14, 0, 0xFFFF)` with
    /// `z_k = z + k dz` (wrapping, Q14 above the 16-bit depth); where it is below `zrow[k]`
    /// (`GL_LESS`) it is written there and the pixel to `out[k]`, elsewhere neither. Returns
    /// the pixels that passed, or `None`, writing nothing, to leave the piece to the span
    /// loop (the default).
    #[inline(always)]
    fn shade_piece_depth_rgb565(
        &self,
        start: &Self::Varyings,
        slope: &Self::Varyings,
        depth: (i32, i32),
        out: &mut [u16],
        zrow: &mut [u16],
    ) -> Option<u32> {
        let _ = (start, slope, depth, out, zrow);
        None
    }

    /// False when the shader cannot draw anything (for example a binding to an empty texel
    /// slice, which fixel's constructors never produce). The span loop checks it once per
    /// chunk, so the compiler can drop the per-texel bounds branch of every fetch.
    #[inline(always)]
    fn can_draw(&self) -> bool {
        true
    }

    /// Called once per screen triangle with the varyings of its three vertices, before the
    /// set-up builds their planes: rescale or rebase them here (texture coordinates to texel
    /// units, for example). Every varying and every difference of two vertices' values must
    /// fit `i32` afterwards.
    fn triangle(&self, varyings: &mut [Self::Varyings; 3]) -> Self::Triangle;

    /// How many of the varyings, from the first, the shader reads in [`Shader::shade`]: the
    /// span loops interpolate only those per pixel (the exact projection's, and the affine
    /// and subdivided ones' steps; the quadratic projection steps them all). The others
    /// reach [`Shader::triangle`] at the vertices and are stale in fragments. Default: all.
    const INTERPOLATED: usize = usize::MAX;

    /// [`Shader::triangle`]'s result in 32 bits, for a band renderer that keeps a triangle
    /// from one band for the next and draws it there without its screen triangle (see
    /// [`BandRenderer::with_setup_cache`](crate::surface::BandRenderer::with_setup_cache)).
    /// `None` (the default): such a triangle is projected again in the next band (the same
    /// pixels, more time). An implementation must give back the same value from
    /// [`Shader::unpack_triangle`].
    #[inline(always)]
    fn pack_triangle(triangle: &Self::Triangle) -> Option<u32> {
        let _ = triangle;
        None
    }

    /// The per-triangle data [`Shader::pack_triangle`] packed, or `None` (the default).
    #[inline(always)]
    fn unpack_triangle(bits: u32) -> Option<Self::Triangle> {
        let _ = bits;
        None
    }

    /// The colour of one pixel as raw RGB565, or `None` to discard it (the pixel and its
    /// depth are left as they were; a shader that discards must say so in
    /// [`Shader::DISCARDS`], or the depth is written anyway).
    fn shade(&self, fragment: &Fragment<Self::Varyings, Self::Triangle>) -> Option<u16>;

    /// The colour of one pixel given the colour `dst` (raw RGB565) the target holds there,
    /// for shaders with [`Shader::BLENDS`]; `None` leaves the pixel as it is. The default
    /// ignores `dst`.
    #[inline(always)]
    fn shade_over(
        &self,
        fragment: &Fragment<Self::Varyings, Self::Triangle>,
        dst: u16,
    ) -> Option<u16> {
        let _ = dst;
        self.shade(fragment)
    }

    /// [`Shader::shade`] darkened by `k` (Q8, `0..=256`; 256 leaves the colour as it is):
    /// what a wrapper that dims the light, a shadow ([`shadow::Shadowed`]), asks of the
    /// shader it wraps. The default multiplies the colour
    /// ([`modulate_scalar`](crate::color::modulate_scalar), three multiplies); a shader whose
    /// colour is a light term times a texel scales its light term instead, one multiply and
    /// one rounding ([`ModulateIntensity`]).
    #[inline(always)]
    fn shade_dimmed(
        &self,
        fragment: &Fragment<Self::Varyings, Self::Triangle>,
        k: u16,
    ) -> Option<u16> {
        self.shade(fragment)
            .map(|c| crate::color::modulate_scalar(c, k))
    }
}

pub mod alpha;
pub mod bump;
pub mod env;
pub mod lighting;
pub mod noise;
pub mod pcf;
pub mod shadow;
pub mod triplanar;
pub mod uv_mapping;
pub mod uv_per_pixel;
