//! Meshes to [`SolidShader`](super::SolidShader) vertices: the clip-space position, the
//! object-space point in lattice units (varyings 0..3) and a Gouraud intensity (varying 3).

use crate::geometry::mesh_checks::{check_indices, check_vertices};
use crate::geometry::Camera;
use crate::geometry::{Vertex, COLOR_ONE};
use crate::math::{Fx, Mat4, Vec3};
use crate::shading::DirectionalLight;
use crate::Error;

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
/// counter-clockwise `indices`, and the scale from model units to lattice cells. Built by
/// [`SolidMesh::new`], which validates the slices as [`Mesh::new`](crate::scene::Mesh::new)
/// does.
#[derive(Clone, Copy, Debug)]
pub struct SolidMesh<'a> {
    positions: &'a [Vec3],
    normals: Option<&'a [Vec3]>,
    indices: &'a [[u16; 3]],
    scale: Fx,
}

impl<'a> SolidMesh<'a> {
    /// Wraps model-space `positions` (I16F16), unit model-space `normals` (one per
    /// position, or none: unlit), triangles `indices` (counter-clockwise from the front) and
    /// `scale` (lattice cells per model unit).
    ///
    /// # Errors
    /// [`Error::MeshTooLarge`] past 65536 positions, [`Error::WrongLength`] when `normals`
    /// is not one per position, [`Error::IndexOutOfRange`] at the first index past the
    /// positions.
    pub fn new(
        positions: &'a [Vec3],
        normals: Option<&'a [Vec3]>,
        indices: &'a [[u16; 3]],
        scale: Fx,
    ) -> Result<Self, Error> {
        let n = positions.len();
        check_vertices(n, normals)?;
        check_indices(indices, n)?;
        Ok(SolidMesh {
            positions,
            normals,
            indices,
            scale,
        })
    }

    /// Model-space positions (I16F16).
    pub fn positions(&self) -> &'a [Vec3] {
        self.positions
    }

    /// Unit model-space normals, one per position, or none (unlit).
    pub fn normals(&self) -> Option<&'a [Vec3]> {
        self.normals
    }

    /// Triangles, counter-clockwise from the front.
    pub fn indices(&self) -> &'a [[u16; 3]] {
        self.indices
    }

    /// Lattice cells per model unit.
    pub fn scale(&self) -> Fx {
        self.scale
    }
    /// Calls `emit` with each triangle as solid-texture vertices: clip position under
    /// `camera · model`, the model-space point times [`SolidMesh::scale`] as varyings 0..3,
    /// and the intensity of `light` (Q8.16; 1.0 without a light or normals) as varying 3.
    /// Triangles with a vertex that overflows the fixed-point range are skipped.
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Index 99 of 24 vertices is refused where it enters, as `Mesh::new` refuses it,
    /// instead of its triangle being skipped without a word.
    #[test]
    fn out_of_range_index_is_refused() {
        let positions = [Vec3::ZERO; 24];
        let normals = [Vec3::from_num(0, 0, 1); 24];
        let indices = [[0, 1, 2], [3, 99, 4]];
        let e = SolidMesh::new(&positions, Some(&normals), &indices, Fx::ONE).unwrap_err();
        let want = Error::IndexOutOfRange {
            at: 4,
            index: 99,
            vertices: 24,
        };
        assert_eq!(e, want);
        assert_eq!(
            SolidMesh::new(&positions, Some(&normals[..3]), &[], Fx::ONE).unwrap_err(),
            Error::WrongLength {
                expected: 24,
                actual: 3
            }
        );
        assert!(SolidMesh::new(&positions, None, &indices[..1], Fx::ONE).is_ok());
    }
}
