//! Shaders that read a palette texture ([`PaletteTexture`]: 8- or 4-bit indices into an
//! RGB565 palette): [`PaletteReplace`] (the texel) and [`PaletteModulateIntensity`] (texel
//! times one interpolated intensity), the palette twins of
//! [`Replace`](super::Replace) and [`ModulateIntensity`](super::ModulateIntensity), with the
//! same varyings, texel-coordinate set-up and arithmetic: the same pixels as those shaders
//! on the RGB565 texture the palette expands to.
//!
//! ```
//! use fixel::geometry::{Cull, Viewport};
//! use fixel::pipeline::{DepthLess, ShadedDraw, Subdivided};
//! use fixel::shading::{PaletteBinding, PaletteReplace};
//! use fixel::texture::{Bilinear, Index4, PaletteTexture, Repeat};
//! use fixel::Rgb565;
//!
//! let palette = [Rgb565::new(31, 0, 0); 16];
//! let indices = [0u8; 8 * 8 / 2];
//! let tex = PaletteTexture::<Index4>::new(&indices, &palette, 8, 8)?;
//! let shader = PaletteReplace {
//!     tex: PaletteBinding::new(tex, Bilinear, Repeat, Repeat),
//! };
//! let draw = ShadedDraw::<_, Subdivided, DepthLess>::new(shader, Viewport::new(0, 0, 32, 32)?, Cull::None)?;
//! # let _ = draw;
//! # Ok::<(), fixel::Error>(())
//! ```

use super::builtin::q8;
use super::texcoord::texel_triangle;
use super::{Fragment, Shader, TexTriangle, Varyings};
use crate::texture::{IndexFormat, PaletteFilter, PaletteTexture, WrapMode};

/// A palette texture bound for sampling by a shader: the level, filter `F` and wraps.
#[derive(Debug)]
pub struct PaletteBinding<'a, I: IndexFormat, F, WU, WV> {
    tex: PaletteTexture<'a, I>,
    filter: F,
    wu: WU,
    wv: WV,
}

impl<I: IndexFormat, F: Copy, WU: Copy, WV: Copy> Clone for PaletteBinding<'_, I, F, WU, WV> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<I: IndexFormat, F: Copy, WU: Copy, WV: Copy> Copy for PaletteBinding<'_, I, F, WU, WV> {}

impl<'a, I: IndexFormat, F: PaletteFilter, WU: WrapMode, WV: WrapMode>
    PaletteBinding<'a, I, F, WU, WV>
{
    /// Binds `tex` with filter `filter` and wraps `wu` (columns), `wv` (rows).
    pub fn new(tex: PaletteTexture<'a, I>, filter: F, wu: WU, wv: WV) -> Self {
        PaletteBinding {
            tex,
            filter,
            wu,
            wv,
        }
    }

    /// The texture.
    pub fn texture(&self) -> &PaletteTexture<'a, I> {
        &self.tex
    }

    /// Per triangle: normalized I16F16 coordinates in varyings `pair` to texel units, as
    /// [`TexBinding::triangle`](super::TexBinding::triangle) does.
    pub fn triangle<V: Varyings>(&self, vary: &mut [V; 3], pair: (usize, usize)) -> TexTriangle {
        let get = |v: &V, k: usize| v.as_slice().get(k).copied().unwrap_or(0);
        let (u, v) = (
            vary.each_ref().map(|v| get(v, pair.0)),
            vary.each_ref().map(|v| get(v, pair.1)),
        );
        let _ = self.filter;
        texel_triangle(
            vary,
            pair,
            (u, v),
            (self.tex.log2_width(), self.tex.log2_height()),
            (self.wu.mode(), self.wv.mode()),
        )
    }

    /// The filtered colour at texel coordinates `(u, v)` (I16F16 texel units), raw RGB565.
    #[inline(always)]
    pub fn sample(&self, u: i32, v: i32) -> u16 {
        F::sample_palette(&self.tex, self.wu, self.wv, u, v)
    }

    /// [`PaletteBinding::sample`] times intensity `i` (Q8, `0..=256`).
    #[inline(always)]
    pub fn sample_scaled(&self, u: i32, v: i32, i: u16) -> u16 {
        F::sample_palette_scaled(&self.tex, self.wu, self.wv, u, v, i)
    }
}

/// The [`Shader`] items both palette shaders share (texture pair at varyings 0 and 1).
macro_rules! palette_common {
    () => {
        type Triangle = TexTriangle;
        const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));
        const SMALL: bool = WU::DYNAMIC || WV::DYNAMIC;
        #[inline(always)]
        fn coord_shift(t: &TexTriangle) -> u32 {
            u32::from(t.shift)
        }
        #[inline]
        fn triangle(&self, v: &mut [Self::Varyings; 3]) -> TexTriangle {
            self.tex.triangle(v, (0, 1))
        }
    };
}

/// The palette texel as it is (`GL_REPLACE`). Varyings: `u, v` (normalized I16F16).
#[derive(Debug)]
pub struct PaletteReplace<'a, I: IndexFormat, F, WU, WV> {
    /// The texture.
    pub tex: PaletteBinding<'a, I, F, WU, WV>,
}

impl<I: IndexFormat, F: Copy, WU: Copy, WV: Copy> Clone for PaletteReplace<'_, I, F, WU, WV> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<I: IndexFormat, F: Copy, WU: Copy, WV: Copy> Copy for PaletteReplace<'_, I, F, WU, WV> {}

impl<I: IndexFormat, F: PaletteFilter, WU: WrapMode, WV: WrapMode> Shader
    for PaletteReplace<'_, I, F, WU, WV>
{
    type Varyings = [i32; 2];
    palette_common!();
    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 2], TexTriangle>) -> Option<u16> {
        Some(self.tex.sample(f.varyings[0], f.varyings[1]))
    }
}

/// The palette texel times one intensity (lit textures). Varyings: `u, v`, intensity Q8.16.
#[derive(Debug)]
pub struct PaletteModulateIntensity<'a, I: IndexFormat, F, WU, WV> {
    /// The texture.
    pub tex: PaletteBinding<'a, I, F, WU, WV>,
}

impl<I: IndexFormat, F: Copy, WU: Copy, WV: Copy> Clone
    for PaletteModulateIntensity<'_, I, F, WU, WV>
{
    fn clone(&self) -> Self {
        *self
    }
}

impl<I: IndexFormat, F: Copy, WU: Copy, WV: Copy> Copy
    for PaletteModulateIntensity<'_, I, F, WU, WV>
{
}

impl<I: IndexFormat, F: PaletteFilter, WU: WrapMode, WV: WrapMode> Shader
    for PaletteModulateIntensity<'_, I, F, WU, WV>
{
    type Varyings = [i32; 3];
    palette_common!();
    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 3], TexTriangle>) -> Option<u16> {
        let [u, v, i] = f.varyings;
        Some(self.tex.sample_scaled(u, v, q8(i)))
    }
}
