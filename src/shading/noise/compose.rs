//! A solid texture composed with an image texture through the fragment stage: the texel
//! times the pattern's colour, times the interpolated light ("multiply"). Varyings:
//!
//! | index | name | format |
//! |---|---|---|
//! | 0, 1 | `u, v` | normalized I16F16 texture coordinates (texel units after the hook) |
//! | 2, 3, 4 | `x, y, z` | object-space point, I16F16 lattice units |
//! | 5 | `i` | light intensity, Q8.16 |
//!
//! The span loop's level of detail goes to the solid texture (its footprint pair is
//! [`Shader::TEXCOORDS`], slots 2 and 3 after the per-triangle rotation); the image is
//! sampled at level 0 (bind a single-level texture).

use super::patterns::Pattern;
use super::solid::SolidTriangle;
use super::turbulence::Octaves;
use crate::color::{modulate_rgb, modulate_scalar};
use crate::shading::builtin::q8;
use crate::shading::{Fragment, Shader, TexBinding, TexTriangle};
use crate::texture::{LodGranularity, TexSampler, WrapMode};

/// An image texture times a solid texture, lit (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct SolidTimesTexture<'a, P, O, F, WU, WV> {
    /// The image.
    pub tex: TexBinding<'a, F, WU, WV>,
    /// The pattern.
    pub pattern: P,
    /// The pattern's octave policy.
    pub octaves: O,
    /// Where a band-limited pattern measures the footprint.
    pub granularity: LodGranularity,
}

/// A raw RGB565 colour's channels as Q8 factors (`0..=256`).
#[inline(always)]
fn factors(c: u16) -> (u16, u16, u16) {
    let (r, g, b) = (
        u32::from(c >> 11),
        u32::from((c >> 5) & 63),
        u32::from(c & 31),
    );
    (
        ((r * 256 + 15) / 31) as u16,
        ((g * 256 + 31) / 63) as u16,
        ((b * 256 + 15) / 31) as u16,
    )
}

impl<P: Pattern, O: Octaves, F: TexSampler, WU: WrapMode, WV: WrapMode> Shader
    for SolidTimesTexture<'_, P, O, F, WU, WV>
{
    type Varyings = [i32; 6];
    type Triangle = (TexTriangle, SolidTriangle);
    const TEXCOORDS: Option<(usize, usize)> = Some((2, 3));
    const LOD: bool = O::LOD;

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.granularity
    }

    #[inline(always)]
    fn can_draw(&self) -> bool {
        self.tex.can_draw()
    }

    fn triangle(&self, v: &mut [[i32; 6]; 3]) -> (TexTriangle, SolidTriangle) {
        let tt = self.tex.triangle(v, (0, 1));
        let st = SolidTriangle::of([0, 1, 2].map(|i| [v[i][2], v[i][3], v[i][4]]));
        for c in v.iter_mut() {
            let [a, b, d] = st.rotate([c[2], c[3], c[4]]);
            (c[2], c[3], c[4]) = (a, b, d);
        }
        (tt, st)
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 6], (TexTriangle, SolidTriangle)>) -> Option<u16> {
        let [u, v, a, b, c, i] = f.varyings;
        let (tt, st) = f.triangle;
        // The span loop undoes the shift of the TEXCOORDS pair only: the image's is ours.
        let texel = self.tex.sample(tt, tt.unshift(u), tt.unshift(v), 0);
        let solid = self
            .pattern
            .color(st.unrotate([a, b, c]), &self.octaves, f.lambda);
        let (r, g, bl) = factors(solid);
        Some(modulate_scalar(modulate_rgb(texel, r, g, bl), q8(i)))
    }
}
