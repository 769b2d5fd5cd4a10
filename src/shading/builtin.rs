//! The classic shadings (the modes of `Shading`) as built-in shaders, with the same
//! arithmetic and so the same pixels.
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

/// Whether [`ModulateIntensity`] checks a linear piece's intensity once so that its pixels
/// skip the clamp ([`Shader::piece_in_range`]). Not on ARMv6-M, where the second loop
/// costs more than it saves: about 1.5 % more on `whole_sphere_sized` on Cortex-M0+ with
/// 32-bit checks, about 5 % with a 64-bit product (measure with `cargo xtask mcu`).
const CLAMP_FREE_PIECES: bool = !cfg!(all(target_arch = "arm", not(target_has_atomic = "32")));

/// The intensities (Q8.16) whose integer part needs no clamp: `0..256 << 16`.
const INTENSITY_RANGE: core::ops::Range<i64> = 0..(COLOR_ONE as i64) << 16;

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
        #[inline(always)]
        fn pack_triangle(t: &$crate::shading::TexTriangle) -> Option<u32> {
            Some(u32::from(t.shift))
        }
        #[inline(always)]
        fn unpack_triangle(bits: u32) -> Option<$crate::shading::TexTriangle> {
            Some($crate::shading::TexTriangle {
                shift: u8::try_from(bits).ok()?,
            })
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
        self.shade_scaled(f, q8(f.varyings[2]))
    }
    /// The intensity (Q8.16) in `0..256` at both ends, so at every pixel between: its
    /// integer part needs no clamp, and the blend knows it fits 8 bits. The second loop
    /// pays on Cortex-M4F and RV32IMC (about 2 % and 0.5 % of the benchmark sphere drawn
    /// whole, `whole_sphere_sized` in `cargo xtask mcu`); on ARMv6-M it costs more than it
    /// saves, so the single loop is kept there (`CLAMP_FREE_PIECES`).
    #[inline(always)]
    fn piece_in_range(&self, start: &[i32; 3], slope: &[i32; 3], n: u32) -> bool {
        if !CLAMP_FREE_PIECES {
            return false;
        }
        let first = i64::from(start[2]);
        let last = first + i64::from(slope[2]) * i64::from(n.saturating_sub(1));
        INTENSITY_RANGE.contains(&first) && INTENSITY_RANGE.contains(&last)
    }
    /// The intensity: a whole affine triangle in range skips the check of each span (see
    /// `pipeline::in_range`; about 0.5 % of the Cortex-M4F sphere).
    const RANGE_VARYING: Option<usize> = if CLAMP_FREE_PIECES { Some(2) } else { None };
    #[inline(always)]
    fn values_in_range(&self, lo: i64, hi: i64) -> bool {
        CLAMP_FREE_PIECES && INTENSITY_RANGE.contains(&lo) && INTENSITY_RANGE.contains(&hi)
    }
    #[inline(always)]
    fn shade_in_range(&self, f: &Fragment<[i32; 3], TexTriangle>) -> Option<u16> {
        // `q8(i)` for `i` in `0..256 << 16`.
        self.shade_scaled(f, ((f.varyings[2] >> 16) & 0xFF) as u16)
    }
    /// The intensity times `k`, rounded once: `(q8(i) k + 128) >> 8` (both Q8, at most
    /// 256), then one modulation of the texel.
    #[inline(always)]
    fn shade_dimmed(&self, f: &Fragment<[i32; 3], TexTriangle>, k: u16) -> Option<u16> {
        let i = (u32::from(q8(f.varyings[2])) * u32::from(k.min(256)) + 128) >> 8;
        self.shade_scaled(f, i as u16)
    }
    /// The sampler's own loop over a piece ([`TexSampler::lit_span`]), where it has one.
    #[inline(always)]
    fn shade_piece_rgb565(&self, start: &[i32; 3], slope: &[i32; 3], out: &mut [u16]) -> bool {
        self.tex.lit_span(start, slope, out)
    }
    const PIECE_DEPTH_LOOP: bool = TexBinding::<F, WU, WV>::LIT_SPAN_DEPTH;
    /// The sampler's own loop over a piece with the depth test ([`TexSampler::lit_span_depth`]),
    /// where it has one.
    #[inline(always)]
    fn shade_piece_depth_rgb565(
        &self,
        start: &[i32; 3],
        slope: &[i32; 3],
        depth: (i32, i32),
        out: &mut [u16],
        zrow: &mut [u16],
    ) -> Option<u32> {
        self.tex.lit_span_depth(start, slope, depth, out, zrow)
    }
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> ModulateIntensity<'_, F, WU, WV> {
    /// The texel at the fragment's `u, v` times `intensity` (Q8, `0..=256`), taken from the
    /// fragment's third varying by [`Shader::shade`] (clamped) or
    /// [`Shader::shade_in_range`] (known in range).
    #[inline(always)]
    fn shade_scaled(&self, f: &Fragment<[i32; 3], TexTriangle>, intensity: u16) -> Option<u16> {
        let [u, v, _] = f.varyings;
        Some(
            self.tex
                .sample_scaled(f.triangle, u, v, f.lambda, intensity),
        )
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
    fn pack_triangle(_: &()) -> Option<u32> {
        Some(0)
    }
    #[inline(always)]
    fn unpack_triangle(_: u32) -> Option<()> {
        Some(())
    }
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
    fn pack_triangle(_: &()) -> Option<u32> {
        Some(0)
    }
    #[inline(always)]
    fn unpack_triangle(_: u32) -> Option<()> {
        Some(())
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;
    use crate::texture::TexSampler;
    use crate::texture::{footprint_texels, Bilinear, BilinearFootprintSized, MipTexture};
    use crate::texture::{Lod, Repeat, Texture};
    use crate::Rgb565;

    /// Shades the `n` pixels of a piece both ways when `ok` (they must agree and the
    /// intensity must stay in range).
    fn check<F: TexSampler>(
        s: &ModulateIntensity<'_, F, Repeat, Repeat>,
        start: [i32; 3],
        slope: [i32; 3],
        n: u32,
        ok: bool,
    ) {
        let top = i64::from(COLOR_ONE) << 16;
        let mut v = start;
        for k in 0..n {
            let f = Fragment {
                varyings: v,
                x: k as i32,
                y: 0,
                depth: 0,
                lambda: 0,
                triangle: TexTriangle::default(),
            };
            if ok {
                assert_eq!(
                    s.shade_in_range(&f),
                    s.shade(&f),
                    "{start:?} {slope:?} {n} {k}"
                );
                assert!(
                    (0..top).contains(&i64::from(v[2])),
                    "{start:?} {slope:?} {n} {k}"
                );
            }
            for (a, b) in v.iter_mut().zip(slope) {
                *a = a.wrapping_add(b);
            }
        }
    }

    /// Every pixel of a piece `piece_in_range` accepts shades as `shade` shades it, over
    /// pieces whose intensity starts and ends near the clamp's limits; and pieces that
    /// reach 256 or fall below 0 are refused.
    #[test]
    fn clamp_free_pieces_shade_the_same() {
        static RAW: [u16; 16] = {
            let mut t = [0u16; 16];
            let mut i = 0;
            while i < 16 {
                t[i] = (i as u16).wrapping_mul(0x9E37) ^ 0x5A5A;
                i += 1;
            }
            t
        };
        static TEXELS: [Rgb565; 16] = {
            let mut t = [Rgb565::new(0, 0, 0); 16];
            let mut i = 0;
            while i < 16 {
                let c = RAW[i];
                t[i] = Rgb565::new((c >> 11) as u8, ((c >> 5) & 63) as u8, (c & 31) as u8);
                i += 1;
            }
            t
        };
        static FOOTPRINTS: [u64; 16] = footprint_texels(&RAW, 4);
        let tex = Texture::from_static(&TEXELS, 4, 4);
        let chain = MipTexture::single(tex).with_footprints_static(&FOOTPRINTS);
        let sized = ModulateIntensity {
            tex: TexBinding::new(
                &chain,
                BilinearFootprintSized::<2, 2>,
                Repeat,
                Repeat,
                Lod::default(),
            )
            .unwrap(),
        };
        let plain = ModulateIntensity {
            tex: TexBinding::new(&chain, Bilinear, Repeat, Repeat, Lod::default()).unwrap(),
        };
        let top = i32::from(COLOR_ONE) << 16;
        let mut rng = Rng(0x2545_F491_4F6C_DD1D);
        let (mut accepted, mut refused) = (0, 0);
        for _ in 0..20_000 {
            let r = rng.next();
            let n = 1 + (r % 40) as u32;
            let near = [0, top, top / 2][(r >> 8) as usize % 3];
            let first = near.wrapping_add(((r >> 16) as i32) >> 12);
            let slope = [
                ((r >> 40) as i32) << 6,
                ((r >> 20) as i32) >> 2,
                ((r >> 24) as i32) >> 14,
            ];
            let start = [(r >> 3) as i32 >> 8, (r >> 29) as i32 >> 9, first];
            let ok = sized.piece_in_range(&start, &slope, n);
            assert_eq!(ok, plain.piece_in_range(&start, &slope, n));
            if ok {
                accepted += 1;
            } else {
                refused += 1;
            }
            check(&sized, start, slope, n, ok);
            check(&plain, start, slope, n, ok);
        }
        if CLAMP_FREE_PIECES {
            assert!(accepted > 2_000 && refused > 2_000, "{accepted} {refused}");
        }
        // Full intensity at either end, or below zero: the clamped loop.
        for (a, b) in [(top, 0), (0, top), (-1, 0), (0, -4)] {
            let (start, slope) = ([0, 0, a], [0, 0, (b - a) / 4]);
            assert!(!sized.piece_in_range(&start, &slope, 5), "{a} {b}");
        }
    }
}
