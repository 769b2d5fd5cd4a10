//! Triplanar mapping: a texture projected along the three model axes and blended per pixel
//! by the surface normal, for surfaces with no usable texture coordinates (terrain,
//! scanned or generated objects). The planar projection, three times.
//!
//! For a model-space point `p` (in texels: `p · texels_per_unit`) and normal `n`:
//!
//! ```text
//! projections  X: (u, v) = (p.z, −p.y)   Y: (p.x, p.z)   Z: (p.x, −p.y)
//! weights      a_i = max(0, |n_i| − k · max(|n_x|, |n_y|, |n_z|)),  w_i = a_i / Σ a
//! colour       Σ w_i · texture(projection_i) · intensity
//! ```
//!
//! `k` ([`Triplanar::sharpness`], Q8, default 1/2) narrows the blend to the edges where two
//! projections are both good; `k = 0` blends by `|n|` alone. `v = −y` keeps "up" at the top
//! of the image on the side projections. A projection whose weight is zero is not sampled,
//! so most pixels of a box-like object cost one sample.
//!
//! Varyings (see [`TriplanarMesh`]): `0..3` the point in I16F16 texels; `3..6` the normal,
//! any length up to `2^30` (the mesh writes unit normals in Q24: the span interpolators'
//! last few bits of error are then far below the weights' resolution); `6` the Gouraud
//! intensity in Q8.16. Weights are Q8 through one table reciprocal (no divide); colours are
//! blended per RGB565 channel with one rounding.

use crate::color::modulate_scalar;
use crate::geometry::Camera;
use crate::geometry::{Vertex, COLOR_ONE};
use crate::math::{Fx, Mat4, Vec3};
use crate::shading::env::cube::recip16;
use crate::shading::DirectionalLight;
use crate::shading::{Fragment, Shader};
use crate::texture::{Repeat, Sampler, Texture};

/// Varyings of [`Triplanar`]: point (3, I16F16 texels), normal (3), intensity (Q8.16).
pub type TriplanarVaryings = [i32; 7];

/// The triplanar shader over `tex` (repeating), filtered with `F`.
#[derive(Clone, Copy, Debug)]
pub struct Triplanar<'a, F> {
    tex: Texture<'a>,
    /// Blend threshold `k`, Q8 (`0..=255`).
    sharpness: u8,
    filter: core::marker::PhantomData<F>,
}

impl<'a, F: Sampler> Triplanar<'a, F> {
    /// Triplanar mapping of `tex` with the default sharpness (1/2).
    pub fn new(tex: Texture<'a>, _filter: F) -> Self {
        Triplanar {
            tex,
            sharpness: 128,
            filter: core::marker::PhantomData,
        }
    }

    /// The blend threshold `k` in Q8 (`0` blends by `|n|`; `255` nearly picks the dominant
    /// axis alone).
    pub fn sharpness(mut self, k: u8) -> Self {
        self.sharpness = k;
        self
    }

    /// Q8 weights of the three projections (summing to 256, or all 0 for a zero normal).
    #[inline(always)]
    pub fn weights(&self, n: [i32; 3]) -> [u32; 3] {
        let a = n.map(|c| c.unsigned_abs().min(1 << 30));
        let m = a[0].max(a[1]).max(a[2]);
        if m == 0 {
            return [0; 3];
        }
        // Down to 16 significant bits of the largest, so the products below fit u32.
        let sh = (32 - m.leading_zeros()).saturating_sub(16);
        let (a, m) = (a.map(|c| c >> sh), m >> sh);
        let cut = (m * u32::from(self.sharpness)) >> 8;
        let b = a.map(|c| c.saturating_sub(cut));
        let sum = b[0] + b[1] + b[2]; // <= 3 * 2^16, > 0 (the largest exceeds the cut)
                                      // sum normalised into [2^15, 2^16) for the table reciprocal (2^31 / d, Q1.15).
        let z = sum.leading_zeros();
        let shift = z as i32 - 16; // sum << shift in [2^15, 2^16)
        let d = if shift >= 0 {
            sum << shift
        } else {
            sum >> -shift
        };
        let r = recip16(d); // 2^31 / d, 2^15..2^16
                            // w = 256 b / sum = 256 b 2^shift / d = b r 2^(shift - 23).
        let w = b.map(|c| {
            let p = u64::from(c) * u64::from(r);
            let e = 23 - shift;
            if e >= 0 {
                ((p + (1 << e >> 1)) >> e) as u32
            } else {
                (p << -e) as u32
            }
        });
        // Rounding may leave the sum at 255..257: give the difference to the largest.
        let s = w[0] + w[1] + w[2];
        let big = if w[0] >= w[1] && w[0] >= w[2] {
            0
        } else if w[1] >= w[2] {
            1
        } else {
            2
        };
        let mut w = w;
        w[big] = (w[big] + 256).saturating_sub(s);
        w
    }
}

/// `Σ w_i c_i / 256` per RGB565 channel (weights summing to 256), rounded once.
#[inline(always)]
fn blend(c: [u16; 3], w: [u32; 3]) -> u16 {
    let ch = |shift: u32, mask: u32| {
        let s: u32 = (0..3)
            .map(|i| ((u32::from(c[i]) >> shift) & mask) * w[i])
            .sum();
        ((s + 128) >> 8).min(mask) << shift
    };
    (ch(11, 31) | ch(5, 63) | ch(0, 31)) as u16
}

impl<F: Sampler> Shader for Triplanar<'_, F> {
    type Varyings = TriplanarVaryings;
    type Triangle = ();

    fn triangle(&self, _: &mut [TriplanarVaryings; 3]) {}

    #[inline(always)]
    fn shade(&self, f: &Fragment<TriplanarVaryings, ()>) -> Option<u16> {
        let v = f.varyings;
        let w = self.weights([v[3], v[4], v[5]]);
        let (x, y, z) = (v[0], v[1], v[2]);
        let mut c = [0u16; 3];
        let proj = [(z, y.wrapping_neg()), (x, z), (x, y.wrapping_neg())];
        for i in 0..3 {
            if w[i] != 0 {
                c[i] = F::sample(&self.tex, Repeat, Repeat, proj[i].0, proj[i].1);
            }
        }
        let k = ((v[6].saturating_add(1 << 15) >> 16).clamp(0, i32::from(COLOR_ONE))) as u16;
        Some(modulate_scalar(blend(c, w), k))
    }
}

/// A mesh seen by [`Triplanar`]: positions, unit normals, counter-clockwise indices and
/// the texture's scale on the model.
#[derive(Clone, Copy, Debug)]
pub struct TriplanarMesh<'a> {
    /// Model-space positions (I16F16).
    pub positions: &'a [Vec3],
    /// Unit model-space normals, one per position.
    pub normals: &'a [Vec3],
    /// Triangles, counter-clockwise from the front.
    pub indices: &'a [[u16; 3]],
    /// Texels per model unit.
    pub texels_per_unit: Fx,
}

impl TriplanarMesh<'_> {
    /// Calls `emit` with each triangle as [`Triplanar`] vertices: clip position under
    /// `camera · model`, the model-space point in texels, the model-space normal in Q24 and
    /// the Gouraud intensity of `light` (Q8.16; 1.0 without one). Triangles with an index
    /// out of range or a vertex that overflows are skipped.
    pub fn triangles(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: Option<&DirectionalLight>,
        mut emit: impl FnMut(&[Vertex<7>; 3]),
    ) {
        let model_view = camera.view.mul(model);
        let mvp = camera.projection.mul(&model_view);
        let s = i64::from(self.texels_per_unit.to_bits());
        let vertex = |i: u16| -> Option<Vertex<7>> {
            let i = usize::from(i);
            let p = *self.positions.get(i)?;
            let n = *self.normals.get(i)?;
            let c = mvp.transform_point(p)?;
            let intensity = match light {
                Some(l) => {
                    let nv = model_view.transform_vector(n)?;
                    l.intensity(nv.normalize().unwrap_or(Vec3::ZERO))
                }
                None => COLOR_ONE,
            };
            let t = |x: Fx| ((i64::from(x.to_bits()) * s) >> 16).clamp(-(1 << 30), 1 << 30) as i32;
            let q24 = |x: Fx| x.to_bits().clamp(-(1 << 22), 1 << 22) << 8;
            Some(Vertex::new(
                [c.x, c.y, c.z, c.w],
                [
                    t(p.x),
                    t(p.y),
                    t(p.z),
                    q24(n.x),
                    q24(n.y),
                    q24(n.z),
                    i32::from(intensity) << 16,
                ],
            ))
        };
        for tri in self.indices {
            if let (Some(a), Some(b), Some(c)) = (vertex(tri[0]), vertex(tri[1]), vertex(tri[2])) {
                emit(&[a, b, c]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::Nearest;

    #[test]
    fn weights_sum_to_one_and_follow_the_normal() {
        let px = [crate::Rgb565::new(0, 0, 0); 4];
        let t = Triplanar::new(Texture::new(&px, 2, 2).unwrap(), Nearest);
        assert_eq!(t.weights([0, 1 << 24, 0]), [0, 256, 0]);
        assert_eq!(t.weights([0, 0, 0]), [0, 0, 0]);
        let w = t.weights([1 << 24, 1 << 24, 0]);
        assert_eq!(w, [128, 128, 0]);
        for n in [
            [3, -7, 11],
            [1 << 30, -(1 << 29), 5],
            [-9_000_000, 8_000_000, 7_000_000],
        ] {
            let w = t.weights(n);
            assert_eq!(w.iter().sum::<u32>(), 256, "{n:?}: {w:?}");
        }
        let flat = t.sharpness(0);
        let w = flat.weights([1 << 24, 1 << 23, 1 << 23]);
        assert!(
            (w[0] as i32 - 128).abs() <= 1 && (w[1] as i32 - 64).abs() <= 1,
            "{w:?}"
        );
    }
}
