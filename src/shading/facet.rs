//! Texel times one intensity per triangle: lit textures on faceted meshes.
//!
//! A mesh whose vertices carry per-face normals (a cube, a low-poly model) gives all three
//! vertices of a triangle the same Gouraud intensity, so interpolating it across the
//! triangle only reproduces a constant. [`ModulateFacet`] reads the intensity once, in its
//! [`Shader::triangle`] hook, and interpolates `u, v` alone: one varying fewer to step and
//! store per pixel, and no clamp per pixel.
//!
//! | | varyings (formats) | per triangle | colour |
//! |---|---|---|---|
//! | [`ModulateFacet`] | `u, v` (texture coordinates) | intensity Q8 `0..=256`: the mean of the vertices' Q8.16 intensities, rounded down, clamped | texel times intensity |
//!
//! Where the three intensities are equal (every triangle of a faceted mesh) this is the
//! exact Gouraud intensity, which [`ModulateIntensity`](super::ModulateIntensity) only
//! approaches: its interpolated constant wanders in its low bits and the per-pixel Q8
//! truncation turns that into 1-LSB steps. On the benchmark cube (quadratic N = 32,
//! `host-tests/tests/facet.rs`) the two differ by 1 LSB at 13-21 % of the pixels and this
//! shader is the closer to the f64 reference (PSNR 40.1 / 51.6 / 51.1 / 47.5 dB on frames
//! 0 / 25 / 50 / 75 against 39.5 / 45.9 / 42.2 / 44.8). Where the intensities differ (smooth
//! meshes) the triangle is lit flat, with the mean, which depends neither on the vertex
//! order nor on clipping.
//!
//! ```
//! use embedded_graphics_core::pixelcolor::Rgb565;
//! use fixel::geometry::{Cull, Viewport};
//! use fixel::pipeline::*;
//! use fixel::texture::{Bilinear, Repeat, Texture};
//! static TEXELS: [Rgb565; 16] = [Rgb565::new(31, 63, 31); 16];
//! let tex = Texture::new(&TEXELS, 4, 4)?;
//! let vp = Viewport::new(0, 0, 320, 240)?;
//! // The benchmark cube's faces are flat: its lighting is one intensity per triangle.
//! type Cube = Pipeline<Quadratic, Bilinear, Repeat, Repeat, ModulateFacet, DepthLess>;
//! let draw = Draw::<Rgb565>::new::<Cube>(Some(tex), vp, Cull::Back)?.with_subdivision(5)?;
//! assert_eq!(draw.mode().shading, Shading::ModulateFacet);
//! # Ok::<(), fixel::Error>(())
//! ```

use super::{Classic, Fragment, Shader, TexBinding, TexTriangle, Varyings};
use crate::geometry::CLASSIC_VARYINGS;
use crate::texture::{TexSampler, WrapMode};

/// The varyings of [`ModulateFacet`]: `u, v` interpolated (I16F16 texel-coordinate bits, as
/// [`TexBinding`] takes them) and the vertex's intensity (Q8.16, `256 << 16` = 1.0), which
/// only the triangle hook reads: [`Varyings::N`] is 2, so the set-up, the interpolators and
/// the scratch see `u, v` alone, and per pixel `intensity` is 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FacetVaryings {
    /// `u, v`, interpolated.
    pub uv: [i32; 2],
    /// The vertex's intensity, Q8.16; read per triangle, not interpolated.
    pub intensity: i32,
}

impl Varyings for FacetVaryings {
    const N: usize = 2;
    #[inline(always)]
    fn zero() -> Self {
        FacetVaryings::default()
    }
    #[inline(always)]
    fn as_slice(&self) -> &[i32] {
        &self.uv
    }
    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [i32] {
        &mut self.uv
    }
}

/// What [`ModulateFacet`] keeps per triangle: the texture coordinates' set-up and the
/// triangle's intensity.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FacetTriangle {
    /// The texture binding's per-triangle data.
    pub tex: TexTriangle,
    /// Intensity, Q8 `0..=256` (256 = 1.0).
    pub intensity: u16,
}

/// The intensity of a triangle: the mean of its vertices' Q8.16 intensities (`i64`, so no
/// sum overflows), shifted to Q8 (rounded down, as the per-pixel `q8` does) and clamped to
/// `0..=256`.
#[inline]
pub fn facet_intensity(v: [i32; 3]) -> u16 {
    let mean = (i64::from(v[0]) + i64::from(v[1]) + i64::from(v[2])).div_euclid(3);
    (mean >> 16).clamp(0, 256) as u16
}

/// Texel times one intensity per triangle (lit textures on faceted meshes). Varyings:
/// [`FacetVaryings`] (`u, v` interpolated, the intensity read per triangle).
#[derive(Clone, Copy, Debug)]
pub struct ModulateFacet<'a, F, WU, WV> {
    /// The texture.
    pub tex: TexBinding<'a, F, WU, WV>,
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> Shader for ModulateFacet<'_, F, WU, WV> {
    type Varyings = FacetVaryings;
    type Triangle = FacetTriangle;
    const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));
    const LOD: bool = F::LOD;
    const SMALL: bool = WU::DYNAMIC || WV::DYNAMIC;
    #[inline(always)]
    fn lod_granularity(&self) -> crate::texture::LodGranularity {
        self.tex.lod().granularity
    }
    #[inline(always)]
    fn can_draw(&self) -> bool {
        self.tex.can_draw()
    }
    #[inline(always)]
    fn coord_shift(t: &FacetTriangle) -> u32 {
        u32::from(t.tex.shift)
    }
    #[inline]
    fn triangle(&self, v: &mut [FacetVaryings; 3]) -> FacetTriangle {
        let intensity = facet_intensity([v[0].intensity, v[1].intensity, v[2].intensity]);
        let tex = self.tex.triangle(v, (0, 1));
        FacetTriangle { tex, intensity }
    }
    #[inline(always)]
    fn shade(&self, f: &Fragment<FacetVaryings, FacetTriangle>) -> Option<u16> {
        let [u, v] = f.varyings.uv;
        let t = f.triangle;
        Some(self.tex.sample_scaled(t.tex, u, v, f.lambda, t.intensity))
    }
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> Classic for ModulateFacet<'_, F, WU, WV> {
    #[inline(always)]
    fn from_classic(v: &[i32; CLASSIC_VARYINGS]) -> FacetVaryings {
        FacetVaryings {
            uv: [v[0], v[1]],
            intensity: v[2],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn intensity_is_the_clamped_mean() {
        let one = 256 << 16;
        assert_eq!(facet_intensity([one; 3]), 256);
        assert_eq!(facet_intensity([77 << 16; 3]), 77);
        assert_eq!(facet_intensity([(77 << 16) + 0xFFFF; 3]), 77);
        assert_eq!(facet_intensity([0, 0, 3 << 16]), 1);
        assert_eq!(facet_intensity([-5, 0, 0]), 0);
        assert_eq!(facet_intensity([i32::MAX; 3]), 256);
        assert_eq!(facet_intensity([i32::MIN; 3]), 0);
        assert_eq!(facet_intensity([i32::MAX, i32::MAX, i32::MIN]), 256);
    }

    #[test]
    fn varyings_show_uv_alone() {
        let mut v = FacetVaryings {
            uv: [1, 2],
            intensity: 3,
        };
        assert_eq!(<FacetVaryings as Varyings>::N, 2);
        assert_eq!(v.as_slice(), &[1, 2]);
        v.as_mut_slice()[1] = 5;
        assert_eq!((v.uv, v.intensity), ([1, 5], 3));
        assert_eq!(FacetVaryings::zero(), FacetVaryings::default());
    }
}
