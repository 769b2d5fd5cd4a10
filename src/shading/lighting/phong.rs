//! Per-pixel lighting ("Phong shading"): the normal and the light vector are interpolated
//! as varyings and renormalised at every pixel ([`unit_q14`]: a table, no square root or
//! divide), then lit with a [`Material`]. The viewer is at infinity along view-space `+z`
//! (GL's default, `GL_LIGHT_MODEL_LOCAL_VIEWER` false), so `v = (0, 0, 1)`.
//!
//! Varyings ([`PhongVaryings`], written by
//! [`LitMesh::phong_triangles`](crate::scene::LitMesh::phong_triangles)):
//!
//! | index | what | format |
//! |---|---|---|
//! | 0, 1 | texture coordinates | normalized I16F16 (texel units after the hook) |
//! | 2..5 | view-space normal | any length below `2^30` (the mesh writes Q24 units) |
//! | 5..8 | view-space vector towards the light | any length below `2^30` (Q24 unit for a directional light, Q20 view units for a point light) |
//!
//! Untextured surfaces bind a 1 x 1 texture of their colour.

use super::material::{lit_texel, Material};
use crate::math::{unit_q14, UNIT_Q14};
use crate::shading::{Fragment, Shader, TexBinding, TexTriangle};
use crate::texture::{TexSampler, WrapMode};

/// Varyings of [`Phong`]: `u, v, n (3), l (3)`.
pub type PhongVaryings = [i32; 8];

/// The view vector of an infinite viewer, Q14.
pub(crate) const VIEW_Z: [i32; 3] = [0, 0, UNIT_Q14];

/// Per-pixel lit texture: `texel × (ka + kd n·l) + ks highlight`.
#[derive(Clone, Copy, Debug)]
pub struct Phong<'a, F, WU, WV> {
    /// The surface colour.
    pub tex: TexBinding<'a, F, WU, WV>,
    /// How it responds to light.
    pub material: Material<'a>,
}

impl<F: TexSampler, WU: WrapMode, WV: WrapMode> Shader for Phong<'_, F, WU, WV> {
    type Varyings = PhongVaryings;
    crate::shading::builtin::textured_common!();

    #[inline(always)]
    fn shade(&self, f: &Fragment<PhongVaryings, TexTriangle>) -> Option<u16> {
        let v = f.varyings;
        let n = unit_q14([v[2], v[3], v[4]]);
        let l = unit_q14([v[5], v[6], v[7]]);
        let (i, s) = self.material.light(n, l, VIEW_Z);
        let texel = self.tex.sample(f.triangle, v[0], v[1], f.lambda);
        Some(lit_texel(texel, i, s))
    }
}
