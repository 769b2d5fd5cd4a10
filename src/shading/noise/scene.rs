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
        let model_view = camera.view.mul(model);
        let mvp = camera.projection.mul(&model_view);
        let vertex = |i: u16| -> Option<Vertex<4>> {
            let p = *self.positions.get(usize::from(i))?;
            let c = mvp.transform_point(p)?;
            let intensity = match (light, self.normals) {
                (Some(l), Some(ns)) => {
                    let n = model_view.transform_vector(*ns.get(usize::from(i))?)?;
                    l.intensity(n.normalize().unwrap_or(Vec3::ZERO))
                }
                _ => COLOR_ONE,
            };
            let [x, y, z] = lattice_point(p, self.scale);
            Some(Vertex::new(
                [c.x, c.y, c.z, c.w],
                [x, y, z, i32::from(intensity) << 16],
            ))
        };
        for tri in self.indices {
            if let (Some(a), Some(b), Some(c)) = (vertex(tri[0]), vertex(tri[1]), vertex(tri[2])) {
                emit(&[a, b, c]);
            }
        }
    }
}
