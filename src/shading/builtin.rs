//! The classic shadings as built-in shaders: what `Shading` selected before the fragment
//! stage was opened, with the same arithmetic and so the same pixels.
//!
//! | shader | varyings (formats) | colour |
//! |---|---|---|
//! | [`Replace`] | `u, v` (texture coordinates) | the texel (`GL_REPLACE`) |
//! | [`ModulateIntensity`] | `u, v`, intensity Q8.16 | texel times intensity |
//! | [`Modulate`] | `u, v`, `r, g, b` Q8.16 | texel times colour per channel (`GL_MODULATE`) |
//! | [`Gouraud`] | `r, g, b` Q8.16 | the interpolated colour |
//! | [`Flat`] | none | one colour |
//!
//! Texture coordinates enter as normalized I16F16 bits and are texel units after
//! [`Shader::triangle`] (see [`TexBinding`]). Colours are Q8 with 16 more fraction bits
//! (`256 << 16` = 1.0), clamped to `0..=1.0` per pixel.
//!
//! [`Classic`] maps the classic vertex's varyings (`u, v, r, g, b`, see
//! [`ClipVertex::to_vertex`](crate::geometry::ClipVertex::to_vertex)) onto each shader's own,
//! so the classic [`Draw`](crate::pipeline::Draw) API feeds them unchanged.

use super::{Fragment, Shader, TexBinding, TexTriangle};
use crate::color::{modulate_rgb, rgb565};
use crate::geometry::{CLASSIC_VARYINGS, COLOR_ONE};
use crate::texture::{TexSampler, WrapMode};

/// Colour channel (Q8.16) to Q8 in `0..=256`.
#[inline(always)]
pub fn q8(c: i32) -> u16 {
    (c >> 16).clamp(0, i32::from(COLOR_ONE)) as u16
}

/// A shader the classic vertex (`u, v, r, g, b`) can feed.
pub trait Classic: Shader {
    /// This shader's varyings taken from the classic ones.
    fn from_classic(v: &[i32; CLASSIC_VARYINGS]) -> Self::Varyings;
}

/// The [`Shader`] items every shader sampling one [`TexBinding`] at varyings `(0, 1)` (its
/// field `tex`) shares: per-triangle texel coordinates, the level of detail of that pair
/// (`$lod`: the sampler's `F::LOD`, or more when another binding reads it too) and the
/// coordinate shift. `SMALL` when a wrap mode is chosen at run time.
macro_rules! textured_common {
    () => {
        $crate::shading::builtin::textured_common!(F::LOD);
    };
    ($lod:expr) => {
        type Triangle = $crate::shading::TexTriangle;
        const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));
        const LOD: bool = $lod;
        const SMALL: bool = WU::DYNAMIC || WV::DYNAMIC;
        #[inline(always)]
        fn lod_granularity(&self) -> $crate::texture::LodGranularity {
            self.tex.lod().granularity
        }
        #[inline(always)]
        fn can_draw(&self) -> bool {
            self.tex.can_draw()
        }
        #[inline(always)]
        fn coord_shift(t: &$crate::shading::TexTriangle) -> u32 {
            u32::from(t.shift)
        }
        #[inline]
        fn triangle(&self, v: &mut [Self::Varyings; 3]) -> $crate::shading::TexTriangle {
            self.tex.triangle(v, (0, 1))
        }
    };
}
pub(crate) use textured_common;

/// The texel as it is (`GL_REPLACE`). Varyings: `u, v`.
#[derive(Clone, Copy, Debug)]
pub struct Replace<'a, F, WU, WV> {
    /// The texture.
    pub tex: TexBinding<'a, F, WU, WV>,
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> Shader for Replace<'_, F, WU, WV> {
    type Varyings = [i32; 2];
    textured_common!();
    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 2], TexTriangle>) -> Option<u16> {
        let [u, v] = f.varyings;
        Some(self.tex.sample(f.triangle, u, v, f.lambda))
    }
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> Classic for Replace<'_, F, WU, WV> {
    #[inline(always)]
    fn from_classic(v: &[i32; CLASSIC_VARYINGS]) -> [i32; 2] {
        [v[0], v[1]]
    }
}

/// Texel times one intensity (lit textures). Varyings: `u, v`, intensity Q8.16.
#[derive(Clone, Copy, Debug)]
pub struct ModulateIntensity<'a, F, WU, WV> {
    /// The texture.
    pub tex: TexBinding<'a, F, WU, WV>,
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> Shader for ModulateIntensity<'_, F, WU, WV> {
    type Varyings = [i32; 3];
    textured_common!();
    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 3], TexTriangle>) -> Option<u16> {
        let [u, v, i] = f.varyings;
        Some(self.tex.sample_scaled(f.triangle, u, v, f.lambda, q8(i)))
    }
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> Classic for ModulateIntensity<'_, F, WU, WV> {
    #[inline(always)]
    fn from_classic(v: &[i32; CLASSIC_VARYINGS]) -> [i32; 3] {
        [v[0], v[1], v[2]]
    }
}

/// Texel times the colour, per channel (`GL_MODULATE`). Varyings: `u, v`, `r, g, b` Q8.16.
#[derive(Clone, Copy, Debug)]
pub struct Modulate<'a, F, WU, WV> {
    /// The texture.
    pub tex: TexBinding<'a, F, WU, WV>,
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> Shader for Modulate<'_, F, WU, WV> {
    type Varyings = [i32; 5];
    textured_common!();
    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 5], TexTriangle>) -> Option<u16> {
        let [u, v, r, g, b] = f.varyings;
        Some(modulate_rgb(
            self.tex.sample(f.triangle, u, v, f.lambda),
            q8(r),
            q8(g),
            q8(b),
        ))
    }
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> Classic for Modulate<'_, F, WU, WV> {
    #[inline(always)]
    fn from_classic(v: &[i32; CLASSIC_VARYINGS]) -> [i32; 5] {
        *v
    }
}

/// Untextured: the interpolated colour. Varyings: `r, g, b` Q8.16.
#[derive(Clone, Copy, Debug, Default)]
pub struct Gouraud;

impl Shader for Gouraud {
    type Varyings = [i32; 3];
    type Triangle = ();
    #[inline]
    fn triangle(&self, _: &mut [[i32; 3]; 3]) {}
    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 3], ()>) -> Option<u16> {
        let ch = |c: i32, max: u32| ((u32::from(q8(c)) * max + 128) >> 8) as u8;
        let [r, g, b] = f.varyings;
        Some(rgb565(ch(r, 31), ch(g, 63), ch(b, 31)))
    }
}

impl Classic for Gouraud {
    #[inline(always)]
    fn from_classic(v: &[i32; CLASSIC_VARYINGS]) -> [i32; 3] {
        [v[2], v[3], v[4]]
    }
}

/// Untextured: one colour (raw RGB565) for the whole draw. No varyings.
#[derive(Clone, Copy, Debug)]
pub struct Flat(pub u16);

impl Shader for Flat {
    type Varyings = [i32; 0];
    type Triangle = ();
    #[inline]
    fn triangle(&self, _: &mut [[i32; 0]; 3]) {}
    #[inline(always)]
    fn shade(&self, _: &Fragment<[i32; 0], ()>) -> Option<u16> {
        Some(self.0)
    }
}

impl Classic for Flat {
    #[inline(always)]
    fn from_classic(_: &[i32; CLASSIC_VARYINGS]) -> [i32; 0] {
        []
    }
}
