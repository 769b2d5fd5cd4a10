//! Texture coordinates generated per pixel: the cylindrical or spherical (or any)
//! [`UvMapping`] evaluated at each pixel's interpolated
//! model-space point instead of at the vertices.
//!
//! Per vertex, `u = atan2(...)` is interpolated linearly across each triangle, which is
//! wrong wherever the angle turns fast within a triangle: large triangles near the axis,
//! the poles, and the seam (which [`map_mesh`](crate::scene::map_mesh) fixes per triangle
//! with vertex copies). Per pixel there is nothing to fix: every pixel gets the exact
//! mapping of its own point, the seam falls between two pixels and the wrap is the
//! texture's repeat. The price is two table `atan2` per pixel (spherical; one for the
//! cylinder) and three interpolated varyings.
//!
//! Varyings (see [`PerPixelMesh`]): `0..3` the model-space point (I16F16 model units), `3`
//! the Gouraud intensity (Q8.16). `u` repeats, `v` clamps to the edge.

use super::uv_mapping::{ReadyMapping, UvAt, UvGenerator, UvMapping};
use crate::color::modulate_scalar;
use crate::geometry::Camera;
use crate::geometry::{Vertex, COLOR_ONE};
use crate::math::{Fx, Mat4, Vec3};
use crate::shading::DirectionalLight;
use crate::shading::{Fragment, Shader};
use crate::texture::{ClampToEdge, Repeat, Sampler, Texture};
use crate::Error;

/// The per-pixel mapping shader over `tex`, filtered with `F`.
#[derive(Clone, Copy, Debug)]
pub struct PerPixelUv<'a, F> {
    tex: Texture<'a>,
    mapping: ReadyMapping,
    filter: core::marker::PhantomData<F>,
}

impl<'a, F: Sampler> PerPixelUv<'a, F> {
    /// `tex` mapped by `mapping` at every pixel. Errors if the mapping is degenerate.
    pub fn new(tex: Texture<'a>, mapping: &UvMapping, _filter: F) -> Result<Self, Error> {
        Ok(PerPixelUv {
            tex,
            mapping: mapping.ready()?,
            filter: core::marker::PhantomData,
        })
    }
}

impl<F: Sampler> Shader for PerPixelUv<'_, F> {
    type Varyings = [i32; 4];
    type Triangle = ();

    fn triangle(&self, _: &mut [[i32; 4]; 3]) {}

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 4], ()>) -> Option<u16> {
        let v = f.varyings;
        let p = Vec3::from_bits(v[0], v[1], v[2]);
        let (uv, _) = UvAt::at(&self.mapping, p, Vec3::ZERO);
        // Normalized I16F16 to I16F16 texels.
        let (lw, lh) = (self.tex.log2_width(), self.tex.log2_height());
        let u = uv[0].to_bits().wrapping_shl(lw);
        let t = uv[1].to_bits().wrapping_shl(lh);
        let c = F::sample(&self.tex, Repeat, ClampToEdge, u, t);
        let k = (v[3].saturating_add(1 << 15) >> 16).clamp(0, i32::from(COLOR_ONE)) as u16;
        Some(modulate_scalar(c, k))
    }
}

/// A mesh seen by [`PerPixelUv`]: positions, unit normals (for the light, or none) and
/// counter-clockwise indices.
#[derive(Clone, Copy, Debug)]
pub struct PerPixelMesh<'a> {
    /// Model-space positions (I16F16).
    pub positions: &'a [Vec3],
    /// Unit model-space normals, one per position, or none (unlit).
    pub normals: Option<&'a [Vec3]>,
    /// Triangles, counter-clockwise from the front.
    pub indices: &'a [[u16; 3]],
}

impl PerPixelMesh<'_> {
    /// Calls `emit` with each triangle as [`PerPixelUv`] vertices: clip position under
    /// `camera · model`, the model-space point, and the Gouraud intensity of `light` (Q8.16;
    /// 1.0 without one or without normals). Triangles with an index out of range or a vertex
    /// that overflows are skipped.
    pub fn triangles(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: Option<&DirectionalLight>,
        mut emit: impl FnMut(&[Vertex<4>; 3]),
    ) {
        let model_view = camera.view.mul(model);
        let mvp = camera.projection.mul(&model_view);
        let vertex = |i: u16| -> Option<Vertex<4>> {
            let i = usize::from(i);
            let p = *self.positions.get(i)?;
            let c = mvp.transform_point(p)?;
            let intensity = match (light, self.normals) {
                (Some(l), Some(ns)) => {
                    let n = model_view.transform_vector(*ns.get(i)?)?;
                    l.intensity(n.normalize().unwrap_or(Vec3::ZERO))
                }
                _ => COLOR_ONE,
            };
            let b = |x: Fx| x.to_bits();
            Some(Vertex::new(
                [c.x, c.y, c.z, c.w],
                [b(p.x), b(p.y), b(p.z), i32::from(intensity) << 16],
            ))
        };
        for tri in self.indices {
            if let (Some(a), Some(b), Some(c)) = (vertex(tri[0]), vertex(tri[1]), vertex(tri[2])) {
                emit(&[a, b, c]);
            }
        }
    }
}
