//! Meshes through shadow mapping's two passes: the light pass (positions only, into a
//! [`DepthMap`]) and the lit pass's vertices (the classic vertex plus light-space
//! varyings).
//!
//! Both passes transform the same model-space positions by one matrix each (`light * model`
//! and the camera's), so the depth a pixel compares is the depth the light pass stored for
//! the same surface, up to the map's sampling.

use crate::geometry::{ClipVertex, Vertex};
use crate::math::Mat4;
use crate::pipeline::DepthOnlyDraw;
use crate::shading::shadow::{LightKind, LightSpace};
use crate::surface::DepthMap;

use super::mesh_draw::vertex;
use super::{Camera, DirectionalLight, Mesh};

/// Draws `mesh` (placed by `model`) into the shadow map `map` as seen by `light`; returns
/// the texels written. Triangles with a vertex outside the fixed-point range are skipped.
///
/// # Errors
/// [`Error::ShadowMapSizeMismatch`](crate::Error::ShadowMapSizeMismatch) when `map` is not
/// the size `draw` was built for (nothing is drawn).
pub fn light_pass_mesh<K: LightKind>(
    draw: &DepthOnlyDraw,
    mesh: &Mesh<'_>,
    model: &Mat4,
    light: &LightSpace<K>,
    map: &mut DepthMap<'_>,
) -> Result<u32, crate::Error> {
    draw.check_map(map)?;
    let m = light.with_model(model);
    let mut n = 0u32;
    for tri in mesh.indices {
        let v = |k: usize| {
            let p = m.transform_point(*mesh.positions.get(usize::from(tri[k]))?)?;
            Some(Vertex::new([p.x, p.y, p.z, p.w], []))
        };
        if let (Some(a), Some(b), Some(c)) = (v(0), v(1), v(2)) {
            n = n.wrapping_add(draw.clip_checked::<0>(&[[a, b, c]], map));
        }
    }
    Ok(n)
}

/// Calls `emit` with each triangle of `mesh` for the lit pass: its classic clip-space
/// vertices (camera, per-vertex `light` as in [`mesh_triangles`](super::mesh_triangles))
/// and their light-space varyings under `space` ([`LightKind::vertex`]).
pub fn shadowed_mesh_triangles<K: LightKind>(
    mesh: &Mesh<'_>,
    model: &Mat4,
    camera: &Camera,
    light: Option<&DirectionalLight>,
    space: &LightSpace<K>,
    mut emit: impl FnMut(&[ClipVertex; 3], &[[i32; 4]; 3]),
) {
    let model_view = camera.view.mul(model);
    let mvp = camera.projection.mul(&model_view);
    let lm = space.with_model(model);
    for tri in mesh.indices {
        let v = |k: usize| vertex(mesh, tri[k], &model_view, &mvp, light);
        let l = |k: usize| {
            mesh.positions
                .get(usize::from(tri[k]))
                .map(|&p| K::vertex(&lm, p))
                .unwrap_or_default()
        };
        if let (Some(a), Some(b), Some(c)) = (v(0), v(1), v(2)) {
            emit(&[a, b, c], &[l(0), l(1), l(2)]);
        }
    }
}
