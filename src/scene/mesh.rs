//! Indexed triangle meshes and their transformation to clip space.

use crate::math::{Fx, Vec3};
use crate::Error;

use super::face_planes::{check_face_planes, FacePlane};
use crate::geometry::mesh_checks::{check_indices, check_vertices};

/// An indexed triangle mesh borrowed from slices (flash or RAM).
///
/// Positions and normals are I16F16 model-space vectors; `uvs` are normalized texture
/// coordinates (1.0 = one texture); each index triple is one triangle, counter-clockwise
/// seen from its front.
#[derive(Clone, Copy, Debug)]
pub struct Mesh<'a> {
    pub(super) positions: &'a [Vec3],
    pub(super) normals: Option<&'a [Vec3]>,
    pub(super) uvs: &'a [[Fx; 2]],
    pub(super) indices: &'a [[u16; 3]],
    /// Right shift that brings every coordinate into `-2^13..2^13` (the model-space cull
    /// test's precision, see `face_cull`).
    pub(super) coord_shift: u8,
    /// Baked face planes, one per triangle, or empty ([`Mesh::with_face_planes`]).
    pub(super) face_planes: &'a [FacePlane],
    /// The largest edge bound `e` of the face planes (0 without them): the scale of the
    /// back-face test's largest error margin over the mesh.
    pub(super) face_e_max: u32,
}

impl<'a> Mesh<'a> {
    /// Validates and wraps the slices: `normals` (if any) and `uvs` must have one entry per
    /// position, every index must be in range, and there must be at most 65536 positions
    /// (what a `u16` index can reach: [`Error::MeshTooLarge`] otherwise). Also finds the
    /// coordinates' magnitude (one pass over the positions), which sets the precision of
    /// the model-space back-face test of the mesh draws.
    pub fn new(
        positions: &'a [Vec3],
        normals: Option<&'a [Vec3]>,
        uvs: &'a [[Fx; 2]],
        indices: &'a [[u16; 3]],
    ) -> Result<Self, Error> {
        let n = positions.len();
        check_vertices(n, normals)?;
        if uvs.len() != n {
            return Err(Error::WrongLength {
                expected: n,
                actual: uvs.len(),
            });
        }
        check_indices(indices, n)?;
        Ok(Mesh {
            positions,
            normals,
            uvs,
            indices,
            coord_shift: crate::geometry::mesh_checks::coord_shift(positions),
            face_planes: &[],
            face_e_max: 0,
        })
    }

    /// The mesh with its baked face planes ([`face_planes`](super::face_planes) at compile
    /// time, [`write_face_planes`](super::write_face_planes) at run time): the model-space
    /// back-face test of every mesh draw then reads one plane per triangle instead of its
    /// three corners' positions, and culls exactly the same triangles. Checks every plane
    /// against the positions once (about as much work as one frame's tests):
    /// [`Error::FacePlaneMismatch`] names the first triangle whose plane is not its own.
    pub fn with_face_planes(self, planes: &'a [FacePlane]) -> Result<Self, Error> {
        let e_max = check_face_planes(self.positions, self.indices, self.coord_shift, planes)?;
        Ok(Mesh {
            face_planes: planes,
            face_e_max: e_max,
            ..self
        })
    }

    /// The baked face planes ([`Mesh::with_face_planes`]); empty when there are none.
    pub fn face_planes(&self) -> &'a [FacePlane] {
        self.face_planes
    }

    /// Number of triangles.
    pub fn triangles(&self) -> usize {
        self.indices.len()
    }

    /// Number of vertices.
    pub fn vertices(&self) -> usize {
        self.positions.len()
    }

    /// The positions (I16F16 model space).
    pub fn positions(&self) -> &'a [Vec3] {
        self.positions
    }

    /// The normals, if the mesh has them.
    pub fn normals(&self) -> Option<&'a [Vec3]> {
        self.normals
    }

    /// The texture coordinates.
    pub fn uvs(&self) -> &'a [[Fx; 2]] {
        self.uvs
    }

    /// The triangles.
    pub fn indices(&self) -> &'a [[u16; 3]] {
        self.indices
    }
}
