//! The bump shader: a colour texture lit per pixel by a [`Material`] with the normal from a
//! [`TangentNormals`] source, in each vertex's tangent frame.
//!
//! Varyings ([`BumpVaryings`], written by
//! [`LitMesh::bump_triangles`](crate::scene::LitMesh::bump_triangles)):
//!
//! | index | what | format |
//! |---|---|---|
//! | 0, 1 | texture coordinates | normalized I16F16 (texel units after the hook) |
//! | 2..5 | the light vector in the tangent frame `(l·t, l·b, l·n)` | any length below `2^30` |
//! | 5..8 | the view vector in the tangent frame | any length below `2^30` |
//!
//! Per pixel: three renormalisations (normal, light, view; a fourth for Blinn's half vector),
//! the material and one colour sample. With a flat normal `(0, 0, 1)` this is per-pixel
//! Phong lighting in tangent space.

use super::normals::TangentNormals;
use crate::math::unit_q14;
use crate::shading::lighting::{lit_texel, Material};
use crate::shading::{Fragment, Shader, TexBinding, TexTriangle};
use crate::texture::{TexSampler, WrapMode};
use crate::Error;

/// Varyings of [`Bumped`]: `u, v, l_t (3), v_t (3)`.
pub type BumpVaryings = [i32; 8];

/// A bump-, derivative- or normal-mapped lit texture.
#[derive(Clone, Copy, Debug)]
pub struct Bumped<'a, N, F, WU, WV> {
    tex: TexBinding<'a, F, WU, WV>,
    normals: N,
    material: Material<'a>,
}

impl<'a, N: TangentNormals, F: TexSampler, WU: WrapMode, WV: WrapMode> Bumped<'a, N, F, WU, WV> {
    /// The colour `tex`, lit by `material` with normals from `normals`, whose map has
    /// `normals_size` texels (the sources' `size()`).
    ///
    /// # Errors
    /// [`Error::BadMode`] when the normal source's map is not the colour texture's size
    /// (they share the interpolated texel coordinates).
    pub fn new(
        tex: TexBinding<'a, F, WU, WV>,
        normals: N,
        normals_size: (u32, u32),
        material: Material<'a>,
    ) -> Result<Self, Error> {
        if normals_size != (tex.base().width(), tex.base().height()) {
            return Err(Error::BadMode(
                "the height, derivative or normal map must be the colour texture's size",
            ));
        }
        Ok(Bumped {
            tex,
            normals,
            material,
        })
    }
}

impl<N: TangentNormals, F: TexSampler, WU: WrapMode, WV: WrapMode> Shader
    for Bumped<'_, N, F, WU, WV>
{
    type Varyings = BumpVaryings;
    crate::shading::builtin::textured_common!(F::LOD || N::LOD);

    #[inline(always)]
    fn shade(&self, f: &Fragment<BumpVaryings, TexTriangle>) -> Option<u16> {
        let v = f.varyings;
        let n = unit_q14(self.normals.normal(f.triangle, v[0], v[1], f.lambda));
        let l = unit_q14([v[2], v[3], v[4]]);
        let e = unit_q14([v[5], v[6], v[7]]);
        let (i, s) = self.material.light(n, l, e);
        let texel = self.tex.sample(f.triangle, v[0], v[1], f.lambda);
        Some(lit_texel(texel, i, s))
    }
}
