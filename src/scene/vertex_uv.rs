//! Where the mesh walker takes each vertex's texture coordinates from: the mesh's own
//! (`MeshUvs`, every draw's default) or coordinates computed per vertex as it is prepared
//! (for example the sphere-map coordinates of
//! [`SphereMapUvs`](super::SphereMapUvs)), so a generated mapping is then a
//! plain textured draw.
//!
//! The source is a type parameter of [`MeshTransform`](super::MeshTransform): a walk with
//! the mesh's coordinates compiles to the code it had before, and a generator's code is
//! linked only by the draws that use it.

use super::Mesh;
use crate::math::{Fx, Mat4};

/// Texture coordinates of a mesh vertex as the walker prepares it.
pub trait VertexUv: Copy {
    /// False for the mesh's own coordinates: the walker then runs no code for them.
    const GENERATES: bool = true;
    /// The coordinates (I16F16, texture units) of vertex `i` of `mesh`, given the mesh's
    /// own `uv` for it and the model-view matrix of the draw. `None` (on overflow) skips the
    /// vertex's triangles.
    fn uv(&self, mesh: &Mesh<'_>, i: usize, model_view: &Mat4, uv: [Fx; 2]) -> Option<[Fx; 2]>;
}

/// The mesh's own texture coordinates (the default of every walk).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MeshUvs;

impl VertexUv for MeshUvs {
    const GENERATES: bool = false;
    #[inline(always)]
    fn uv(&self, _: &Mesh<'_>, _: usize, _: &Mat4, uv: [Fx; 2]) -> Option<[Fx; 2]> {
        Some(uv)
    }
}
