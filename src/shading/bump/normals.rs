//! Where a bump shader gets its tangent-space normal per pixel: Blinn's perturbation from a
//! height map (precomputed derivatives, or central differences per pixel) or a normal map.
//!
//! Blinn's perturbed normal (SIGGRAPH 1978) is `n' = n + (Bu (n × Pv) − Bv (n × Pu)) / |n|`
//! with `B` the height and `Pu`, `Pv` the surface derivatives. In the orthonormal tangent
//! frame `(t, b, n)` with `Pu = t`, `Pv = b` per texel (the height map is a surface
//! `z = σ h(i, j)` over the texel grid, in texel widths), `n × b = −t` and `n × t = b`, so
//!
//! ```text
//! n' = (−σ ∂h/∂i, −σ ∂h/∂j, 1)            (tangent space, then renormalised)
//! ```
//!
//! with the derivatives in height steps per (level-0) texel and the *strength* `σ` in texel
//! widths per height step (I16F16). All three sources return `n'` unnormalised, `z = 4096`
//! (Q12); the shader renormalises.

use crate::math::Fx;
use crate::shading::{TexBinding, TexTriangle};
use crate::texture::{HeightMap, Nearest, NearestMipmapNearest, TexSampler, WrapMode};
use crate::Error;

/// A tangent-space normal per pixel.
pub trait TangentNormals: Copy {
    /// True when [`TangentNormals::normal`] reads the level of detail.
    const LOD: bool;
    /// The unnormalised tangent-space normal at texel coordinates `(u, v)` (I16F16 texel
    /// units of the shader's colour texture, which has this map's size) with level of
    /// detail `lambda` (Q8.8): each component below `2^24`.
    fn normal(&self, tri: TexTriangle, u: i32, v: i32, lambda: i32) -> [i32; 3];
}

/// Samplers that return a texel's 16 bits unchanged (no filtering): the only ones a packed
/// [`DerivativeMap`] can use.
pub trait TexelFetch: TexSampler {}
impl TexelFetch for Nearest {}
impl TexelFetch for NearestMipmapNearest {}

/// `−σ d` in Q12 for a derivative `d = x · f` with `f` the Q16 factor `σ · scale`: clamped
/// so the normal never exceeds `2^24`.
#[inline(always)]
fn slope(x: i32, f: i32) -> i32 {
    (-(x * f) >> 4).clamp(-(1 << 23), 1 << 23)
}

/// Largest `σ · scale` factor (Q16) a source accepts: steeper than any useful bump.
const MAX_FACTOR: i64 = 1 << 23;

/// Checks and combines the strength with a map's scale into one Q16 factor.
fn factor(strength: Fx, scale: i64) -> Result<i32, Error> {
    let f = (i64::from(strength.to_bits()) * scale) >> 16;
    if !(-MAX_FACTOR..=MAX_FACTOR).contains(&f) {
        return Err(Error::BadMode(
            "bump strength too large: |strength| x scale must stay below 128 per step",
        ));
    }
    Ok(f as i32)
}

/// Precomputed derivatives ([`derivative_map`](super::derivative_map)): a texture whose
/// 16-bit texels hold `(∂h/∂i, ∂h/∂j)` as two `i8` (high byte, low byte) in units of the
/// map's scale, fetched without filtering (nearest, or nearest level of a mip chain).
#[derive(Clone, Copy, Debug)]
pub struct DerivativeMap<'a, F, WU, WV> {
    map: TexBinding<'a, F, WU, WV>,
    /// `σ · scale`, Q16.
    factor: i32,
}

impl<'a, F: TexelFetch, WU: WrapMode, WV: WrapMode> DerivativeMap<'a, F, WU, WV> {
    /// `map` with the `scale` [`derivative_map`](super::derivative_map) returned, at
    /// `strength` σ (texel widths per height step).
    ///
    /// # Errors
    /// [`Error::BadMode`] when `|σ · scale| >= 128`.
    pub fn new(map: TexBinding<'a, F, WU, WV>, scale: Fx, strength: Fx) -> Result<Self, Error> {
        Ok(DerivativeMap {
            map,
            factor: factor(strength, i64::from(scale.to_bits()))?,
        })
    }

    /// The map's size in texels (it must equal the colour texture's).
    pub fn size(&self) -> (u32, u32) {
        (self.map.base().width(), self.map.base().height())
    }
}

impl<F: TexelFetch, WU: WrapMode, WV: WrapMode> TangentNormals for DerivativeMap<'_, F, WU, WV> {
    const LOD: bool = F::LOD;
    #[inline(always)]
    fn normal(&self, tri: TexTriangle, u: i32, v: i32, lambda: i32) -> [i32; 3] {
        let t = self.map.sample(tri, u, v, lambda);
        let (du, dv) = (i32::from((t >> 8) as u8 as i8), i32::from(t as u8 as i8));
        [slope(du, self.factor), slope(dv, self.factor), 1 << 12]
    }
}

/// Central differences of a [`HeightMap`] at every pixel: four height fetches at the
/// nearest texel of the nearest mip level (GL's `NEAREST_MIPMAP_NEAREST` level rule),
/// `∂h/∂i = (h(i+1, j) − h(i−1, j)) / 2^(k+1)` at level `k`. The map repeats.
#[derive(Clone, Copy, Debug)]
pub struct HeightDifferences<'a> {
    map: HeightMap<'a>,
    /// σ, Q16 (I16F16 bits).
    strength: i32,
}

impl<'a> HeightDifferences<'a> {
    /// `map` at `strength` σ (texel widths per height step).
    ///
    /// # Errors
    /// [`Error::BadMode`] when `|σ| >= 32` (a difference of 255 steps times σ must fit).
    pub fn new(map: HeightMap<'a>, strength: Fx) -> Result<Self, Error> {
        if strength.to_bits().unsigned_abs() >= 1 << 21 {
            return Err(Error::BadMode(
                "bump strength too large: |strength| must stay below 32 per step",
            ));
        }
        Ok(HeightDifferences {
            map,
            strength: strength.to_bits(),
        })
    }

    /// The map's size in texels (it must equal the colour texture's).
    pub fn size(&self) -> (u32, u32) {
        (self.map.width(), self.map.height_texels())
    }
}

impl TangentNormals for HeightDifferences<'_> {
    const LOD: bool = true;
    #[inline(always)]
    fn normal(&self, _tri: TexTriangle, u: i32, v: i32, lambda: i32) -> [i32; 3] {
        // GL: level 0 up to lambda = 1/2, else ceil(lambda + 1/2) - 1.
        let k = if lambda <= 128 {
            0
        } else {
            // In u32 (lambda > 128 here): no overflow for any clamp a `Lod` holds.
            (((lambda as u32 + 383) >> 8) - 1).min(self.map.levels().saturating_sub(1))
        };
        let (i, j) = (u >> (16 + k), v >> (16 + k));
        let h = |di: i32, dj: i32| i32::from(self.map.height(k, i + di, j + dj));
        let dx = h(1, 0) - h(-1, 0);
        let dy = h(0, 1) - h(0, -1);
        // d = dx / 2^(k+1): fold the shift into the Q12 result.
        let s = |d: i32| (-(d * self.strength) >> (5 + k)).clamp(-(1 << 23), 1 << 23);
        [s(dx), s(dy), 1 << 12]
    }
}

/// A tangent-space normal map: RGB565 texels `((n + 1) / 2)` per channel, filtered with any
/// sampler (bilinear and trilinear blends are renormalised by the shader).
#[derive(Clone, Copy, Debug)]
pub struct NormalMap<'a, F, WU, WV> {
    /// The map.
    pub map: TexBinding<'a, F, WU, WV>,
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> TangentNormals for NormalMap<'_, F, WU, WV> {
    const LOD: bool = F::LOD;
    #[inline(always)]
    fn normal(&self, tri: TexTriangle, u: i32, v: i32, lambda: i32) -> [i32; 3] {
        let c = i32::from(self.map.sample(tri, u, v, lambda));
        // 2 c / max - 1 on a common denominator (2 * 31 * 63).
        [
            (2 * (c >> 11) - 31) * 126,
            (2 * ((c >> 5) & 63) - 63) * 62,
            (2 * (c & 31) - 31) * 126,
        ]
    }
}
