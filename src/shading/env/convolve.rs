//! Diffuse and glossy environment maps (Greene, "Environment Mapping and Other Applications
//! of World Projections", IEEE CG&A 1986), baked from a cube map, and the shader that
//! combines them with a base texture.
//!
//! * The **irradiance** map, indexed by the normal `n`: the cosine-weighted average of the
//!   environment, `E(n) = (1/π) ∫ L(ω) max(0, n·ω) dω` (1 for a uniform white sky).
//! * The **glossy** map, indexed by the reflection vector `r`: the Phong-lobe-weighted
//!   average `G(r) = ((e + 1) / 2π) ∫ L(ω) max(0, r·ω)^e dω` for an exponent `e`.
//!
//! Both are baked by brute force over every texel of the source cube map (each weighted by
//! its solid angle `(2/S)² / (1 + sc² + tc²)^(3/2)`), in `f32` on the host or in a build
//! script ([`convolve_face`]); the results are small cube maps (16 x 16 per face is plenty:
//! both are smooth) that [`EnvLit`] reads per pixel:
//!
//! ```text
//! colour = base × E(n) + ks G(r)   per channel, clamped
//! ```
//!
//! In fixed point: `E(n)` per channel to Q8 (`0..=256`, `c5 · 2114 >> 8` and
//! `c6 · 1040 >> 8`), the base texel modulated by it (`modulate_rgb`, one rounding), then
//! the glossy texel times `ks` (Q8, `modulate_rgb` again unless `ks` = 1) added per
//! channel with saturation.

use embedded_graphics_core::pixelcolor::Rgb565;
use micromath::F32Ext;

use super::cube::EnvLookup;
use super::reflect::{fit_group, reflect_fit, FIT_BITS, VARYING_BITS};
use super::sky::texel_direction;
use crate::color::modulate_rgb;
use crate::shading::{Fragment, Shader, TexBinding, TexTriangle};
use crate::texture::{LodGranularity, TexSampler, WrapMode};
use crate::Error;

/// The lobe a map is convolved with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lobe {
    /// `max(0, n·ω) / π`: the irradiance (diffuse) map.
    Cosine,
    /// `(e + 1) / 2π · max(0, r·ω)^e`: the glossy map of Phong exponent `e` (1..=1000).
    Phong(u16),
}

/// `sqrt` to f32 precision: micromath's estimate and two Newton steps.
fn sqrt(x: f32) -> f32 {
    if x <= 0.0 {
        return 0.0;
    }
    let mut y = F32Ext::sqrt(x);
    for _ in 0..2 {
        y = 0.5 * (y + x / y);
    }
    y
}

fn unpack(c: u16) -> [f32; 3] {
    [
        f32::from(c >> 11) / 31.0,
        f32::from((c >> 5) & 63) / 63.0,
        f32::from(c & 31) / 31.0,
    ]
}

/// Fills `out` (`out_size²` texels, row 0 first) with face `face` (GL order) of the map
/// convolved from the cube map `src` (six faces of `src_size²` raw RGB565 texels, GL order)
/// with `lobe`, each output texel evaluated at its centre's direction.
///
/// Cost: `6 out_size² · 6 src_size²` lobe evaluations (16² outputs from 32² sources: 9.4
/// million, a fraction of a second on a PC): meant for build scripts and host tools.
///
/// # Errors
/// [`Error::WrongLength`] if a slice does not have its declared size, [`Error::BadCubeMap`]
/// if `face > 5`, [`Error::BadMode`] for a Phong exponent of 0 or above 1000.
pub fn convolve_face(
    src: [&[u16]; 6],
    src_size: u32,
    lobe: Lobe,
    face: usize,
    out_size: u32,
    out: &mut [Rgb565],
) -> Result<(), Error> {
    let (n_src, n_out) = (
        src_size as usize * src_size as usize,
        out_size as usize * out_size as usize,
    );
    for s in src {
        if s.len() != n_src {
            return Err(Error::WrongLength {
                expected: n_src,
                actual: s.len(),
            });
        }
    }
    if out.len() != n_out {
        return Err(Error::WrongLength {
            expected: n_out,
            actual: out.len(),
        });
    }
    if face > 5 {
        return Err(Error::BadCubeMap {
            face: face as u8,
            width: out_size,
            height: out_size,
        });
    }
    if let Lobe::Phong(e) = lobe {
        if e == 0 || e > 1000 {
            return Err(Error::BadMode("Phong exponent must be in 1..=1000"));
        }
    }
    let texel = 4.0 / (src_size as f32 * src_size as f32);
    for (k, px) in out.iter_mut().enumerate() {
        let (i, j) = ((k as u32) % out_size, (k as u32) / out_size);
        let d = texel_direction(face, i, j, out_size);
        let l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        let n = d.map(|c| c / l);
        let (mut acc, mut wsum) = ([0.0f32; 3], 0.0f32);
        for (f, texels) in src.iter().enumerate() {
            for (t, &c) in texels.iter().enumerate() {
                let (si, sj) = ((t as u32) % src_size, (t as u32) / src_size);
                let w = texel_direction(f, si, sj, src_size);
                let l2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
                let lw = sqrt(l2);
                // Solid angle of the texel: (2/S)² / |w|³ (|w|² = 1 + sc² + tc²).
                let dw = texel / (l2 * lw);
                let cos = (n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / lw;
                if cos <= 0.0 {
                    continue;
                }
                let weight = match lobe {
                    Lobe::Cosine => cos,
                    Lobe::Phong(e) => {
                        let (mut p, mut b, mut e) = (1.0f32, cos, e);
                        while e > 0 {
                            if e & 1 == 1 {
                                p *= b;
                            }
                            b *= b;
                            e >>= 1;
                        }
                        p
                    }
                } * dw;
                let rgb = unpack(c);
                for ch in 0..3 {
                    acc[ch] += rgb[ch] * weight;
                }
                wsum += weight;
            }
        }
        // Normalising by the summed weights makes a uniform sky come out exactly uniform
        // (the analytic factors 1/π and (e + 1)/2π are what the weights sum to).
        let norm = if wsum > 0.0 { 1.0 / wsum } else { 0.0 };
        let q = |c: f32, max: f32| ((c * norm).clamp(0.0, 1.0) * max + 0.5) as u8;
        *px = Rgb565::new(q(acc[0], 31.0), q(acc[1], 63.0), q(acc[2], 31.0));
    }
    Ok(())
}

/// Base texture × diffuse environment + `ks` × glossy environment, the reflection per
/// pixel.
///
/// Varyings: `nx, ny, nz, vx, vy, vz` (as [`ReflectPerPixel`](super::ReflectPerPixel)),
/// then the base texture's `u, v` (normalized I16F16, see [`TexBinding`]).
#[derive(Clone, Copy, Debug)]
pub struct EnvLit<'a, D, G, F, WU, WV> {
    /// The base texture.
    pub base: TexBinding<'a, F, WU, WV>,
    /// The irradiance map, indexed by `n`.
    pub diffuse: D,
    /// The glossy map, indexed by `r`.
    pub glossy: G,
    /// The glossy map's weight `ks`, Q8 (`256` = 1.0; larger is 1.0).
    pub specular: u16,
}

/// A 5- or 6-bit channel to Q8 (`0..=256`).
#[inline(always)]
fn q8_of(c: u16, six: bool) -> u16 {
    let c = u32::from(c);
    (if six {
        (c * 1040 + 128) >> 8
    } else {
        (c * 2114 + 128) >> 8
    }) as u16
}

impl<D: EnvLookup, G: EnvLookup, F: TexSampler, WU: WrapMode, WV: WrapMode> Shader
    for EnvLit<'_, D, G, F, WU, WV>
{
    type Varyings = [i32; 8];
    type Triangle = TexTriangle;
    const TEXCOORDS: Option<(usize, usize)> = Some((6, 7));
    const LOD: bool = F::LOD;

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.base.lod().granularity
    }

    #[inline(always)]
    fn can_draw(&self) -> bool {
        self.base.can_draw()
    }

    #[inline(always)]
    fn coord_shift(t: &TexTriangle) -> u32 {
        u32::from(t.shift)
    }

    #[inline]
    fn triangle(&self, v: &mut [[i32; 8]; 3]) -> TexTriangle {
        fit_group::<8, VARYING_BITS>(v, 0);
        fit_group::<8, VARYING_BITS>(v, 3);
        self.base.triangle(v, (6, 7))
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 8], TexTriangle>) -> Option<u16> {
        Some(self.lit(f.triangle, &f.varyings, f.lambda, None))
    }
}

impl<D: EnvLookup, G: EnvLookup, F: TexSampler, WU: WrapMode, WV: WrapMode>
    EnvLit<'_, D, G, F, WU, WV>
{
    /// The colour of a pixel from its first eight varyings (`n`, `v` in the fitted
    /// formats of [`EnvLit::triangle`](Shader::triangle), then `u, v`) and `lambda`: the
    /// base texel times `tint` (Q8 per channel, `0..=256`; `None` is white) times the
    /// irradiance, plus `ks` times the glossy texel. The tint and the irradiance multiply
    /// in Q8 first, `min(256, (e · (t + 1)) >> 8)`: `e` itself for `t` = 255 and 256 (an
    /// interpolated white colour comes out one Q8 step below 1.0 where the interpolator
    /// rounds down), within one step of `e · t / 256` otherwise; the base then takes one
    /// rounding either way.
    #[inline(always)]
    pub(crate) fn lit(
        &self,
        tri: TexTriangle,
        a: &[i32; 8],
        lambda: i32,
        tint: Option<[u16; 3]>,
    ) -> u16 {
        const S: u32 = VARYING_BITS - FIT_BITS;
        let n = [a[0] >> S, a[1] >> S, a[2] >> S];
        let e = self.diffuse.lookup(n);
        let g = self
            .glossy
            .lookup(reflect_fit(n, [a[3] >> S, a[4] >> S, a[5] >> S]));
        let ks = self.specular;
        let g = if ks >= 256 {
            g
        } else {
            modulate_rgb(g, ks, ks, ks)
        };
        let base = self.base.sample(tri, a[6], a[7], lambda);
        let mut q = [
            q8_of(e >> 11, false),
            q8_of((e >> 5) & 63, true),
            q8_of(e & 31, false),
        ];
        if let Some(t) = tint {
            for (q, t) in q.iter_mut().zip(t) {
                *q = ((u32::from(*q) * (u32::from(t.min(256)) + 1)) >> 8).min(256) as u16;
            }
        }
        let lit = modulate_rgb(base, q[0], q[1], q[2]);
        let r = ((lit >> 11) + (g >> 11)).min(31);
        let gg = ((lit >> 5) & 63) + ((g >> 5) & 63);
        let b = ((lit & 31) + (g & 31)).min(31);
        (r << 11) | (gg.min(63) << 5) | b
    }
}
