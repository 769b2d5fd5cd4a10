//! Meshes to [`SolidShader`](super::SolidShader) vertices: the clip-space position, the
//! object-space point in lattice units (varyings 0..3) and a Gouraud intensity (varying 3).

use crate::geometry::{Vertex, COLOR_ONE};
use crate::math::{Fx, Mat4, Vec3};
use crate::scene::{Camera, DirectionalLight};

/// The object-space point `p · scale` as I16F16 lattice-unit bits (saturating).
#[inline]
pub fn lattice_point(p: Vec3, scale: Fx) -> [i32; 3] {
    let s = i64::from(scale.to_bits());
    [p.x, p.y, p.z].map(|c| {
        let v = (i64::from(c.to_bits()) * s) >> 16;
        v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
    })
}

/// An indexed mesh seen as a solid-texture block: positions, unit normals (or none),
/// counter-clockwise `indices`, and the scale from model units to lattice cells.
#[derive(Clone, Copy, Debug)]
pub struct SolidMesh<'a> {
    /// Model-space positions (I16F16).
    pub positions: &'a [Vec3],
    /// Unit model-space normals, one per position, or none (unlit).
    pub normals: Option<&'a [Vec3]>,
    /// Triangles, counter-clockwise from the front.
    pub indices: &'a [[u16; 3]],
    /// Lattice cells per model unit.
    pub scale: Fx,
}

impl SolidMesh<'_> {
    /// Calls `emit` with each triangle as solid-texture vertices: clip position under
    /// `camera · model`, the model-space point times [`SolidMesh::scale`] as varyings 0..3,
    /// and the intensity of `light` (Q8.16; 1.0 without a light or normals) as varying 3.
    /// Triangles with an index out of range or a vertex that overflows the fixed-point
    /// range are skipped.
    pub fn triangles(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: Option<&DirectionalLight>,
        mut emit: impl FnMut(&[Vertex<4>; 3]),
    ) {
        let (model_view, mvp) = Self::matrices(model, camera);
        let vertex = |i: u16| self.vertex(usize::from(i), &model_view, &mvp, light);
        for tri in self.indices {
            if let (Some(a), Some(b), Some(c)) = (vertex(tri[0]), vertex(tri[1]), vertex(tri[2])) {
                emit(&[a, b, c]);
            }
        }
    }

    /// Each vertex once, as [`SolidMesh::triangles`] makes them, into `out` (one entry per
    /// position; `None` for a vertex that overflows; extra entries, or positions past the
    /// end of `out`, are left alone): for firmware that keeps a vertex cache.
    pub fn vertices(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: Option<&DirectionalLight>,
        out: &mut [Option<Vertex<4>>],
    ) {
        let (model_view, mvp) = Self::matrices(model, camera);
        for (i, slot) in out.iter_mut().enumerate().take(self.positions.len()) {
            *slot = self.vertex(i, &model_view, &mvp, light);
        }
    }

    fn matrices(model: &Mat4, camera: &Camera) -> (Mat4, Mat4) {
        let model_view = camera.view.mul(model);
        let mvp = camera.projection.mul(&model_view);
        (model_view, mvp)
    }

    fn vertex(
        &self,
        i: usize,
        model_view: &Mat4,
        mvp: &Mat4,
        light: Option<&DirectionalLight>,
    ) -> Option<Vertex<4>> {
        let p = *self.positions.get(i)?;
        let c = mvp.transform_point(p)?;
        let intensity = match (light, self.normals) {
            (Some(l), Some(ns)) => {
                let n = model_view.transform_vector(*ns.get(i)?)?;
                l.intensity(n.normalize().unwrap_or(Vec3::ZERO))
            }
            _ => COLOR_ONE,
        };
        let [x, y, z] = lattice_point(p, self.scale);
        Some(Vertex::new(
            [c.x, c.y, c.z, c.w],
            [x, y, z, i32::from(intensity) << 16],
        ))
    }
}
