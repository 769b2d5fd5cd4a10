//! Meshes to clip space and onto a target: one vertex transformed (and lit), the triangles of
//! a mesh with the facing test before lighting, and the one-call draws.

use crate::color::TargetColor;
use crate::geometry::{ClipVertex, Cull, COLOR_ONE};
use crate::math::{Mat4, Vec3};
use crate::pipeline::Draw;
use crate::surface::RenderTarget;
use crate::Error;

use super::face_cull::{camera_centre, FaceCull};
use super::{Camera, DirectionalLight, Mesh};

/// One vertex to clip space, lit if there is a light and a normal. `None` on overflow.
///
/// Inlined so that a caller whose light is a constant `None` links no lighting (no normal
/// transform, no `normalize`): the two cases are separate functions.
#[inline(always)]
pub(super) fn vertex(
    mesh: &Mesh<'_>,
    i: u16,
    model_view: &Mat4,
    mvp: &Mat4,
    light: Option<&DirectionalLight>,
) -> Option<ClipVertex> {
    match light {
        None => vertex_unlit(mesh, usize::from(i), mvp),
        Some(l) => vertex_lit(mesh, usize::from(i), model_view, mvp, l),
    }
}

/// [`vertex`] without a light: white.
fn vertex_unlit(mesh: &Mesh<'_>, i: usize, mvp: &Mat4) -> Option<ClipVertex> {
    let p = mvp.transform_point(*mesh.positions.get(i)?)?;
    let uv = *mesh.uvs.get(i)?;
    Some(ClipVertex {
        position: [p.x, p.y, p.z, p.w],
        uv,
        color: [COLOR_ONE; 3],
    })
}

/// [`vertex`] lit by `light`.
#[inline(never)]
fn vertex_lit(
    mesh: &Mesh<'_>,
    i: usize,
    model_view: &Mat4,
    mvp: &Mat4,
    light: &DirectionalLight,
) -> Option<ClipVertex> {
    let mut v = vertex_unlit(mesh, i, mvp)?;
    v.color = [vertex_intensity(mesh, i, model_view, light)?; 3];
    Some(v)
}

/// Per-vertex Gouraud intensity of vertex `i` (Q8, `0..=256`) under `light`, its normal
/// taken to view space by `model_view`; [`COLOR_ONE`] when the mesh has no normals. `None`
/// when the normal overflows the fixed-point range (its triangles are skipped).
pub fn vertex_intensity(
    mesh: &Mesh<'_>,
    i: usize,
    model_view: &Mat4,
    light: &DirectionalLight,
) -> Option<u16> {
    let Some(nm) = mesh.normals else {
        return Some(COLOR_ONE);
    };
    let n = model_view.transform_vector(*nm.get(i)?)?;
    // A rotation keeps unit normals unit: renormalise (a square root and a
    // reciprocal) only when the length is off by more than 2^-12, which changes
    // the intensity by less than its Q8 step.
    // In u64: a long normal's squared length (up to 3 * 2^62) does not fit an i64.
    let off = n.length_squared_bits().abs_diff(1 << 32);
    let n = if off < 1 << 20 {
        n
    } else {
        n.normalize().unwrap_or(Vec3::ZERO)
    };
    Some(light.intensity(n))
}

/// Like [`mesh_triangles`], but transforms and lights each vertex once into `cache`
/// (caller-provided scratch, at least one entry per vertex) instead of once per triangle
/// corner: about 5x fewer transforms on a closed mesh such as the benchmark sphere
/// (1225 vertices, 6624 corners). Falls back to [`mesh_triangles`] when `cache` is too
/// short. Vertices that overflow the fixed-point range skip their triangles, as there.
pub fn mesh_triangles_cached(
    mesh: &Mesh<'_>,
    model: &Mat4,
    camera: &Camera,
    light: Option<&DirectionalLight>,
    cache: &mut [Option<ClipVertex>],
    emit: impl FnMut(&[ClipVertex; 3]),
) {
    facing_triangles::<false>(mesh, model, camera, light, Cull::None, cache, emit);
}

/// Calls `emit` with each triangle of `mesh` in clip space (model, then camera), lit per
/// vertex by `light` when given and the mesh has normals. Triangles with a vertex that
/// overflows the fixed-point range are skipped.
pub fn mesh_triangles(
    mesh: &Mesh<'_>,
    model: &Mat4,
    camera: &Camera,
    light: Option<&DirectionalLight>,
    emit: impl FnMut(&[ClipVertex; 3]),
) {
    facing_triangles::<false>(mesh, model, camera, light, Cull::None, &mut [], emit);
}

/// [`mesh_triangles`] (with `cache` long enough, [`mesh_triangles_cached`]: each vertex
/// transformed once into it) without the triangles that surely face the way `cull` drops
/// (tested in model space before their vertices are transformed, as the mesh walker does:
/// see `face_cull`), so every mesh path draws the same triangles.
fn facing_triangles<const CULLS: bool>(
    mesh: &Mesh<'_>,
    model: &Mat4,
    camera: &Camera,
    light: Option<&DirectionalLight>,
    cull: Cull,
    cache: &mut [Option<ClipVertex>],
    mut emit: impl FnMut(&[ClipVertex; 3]),
) {
    let model_view = camera.view.mul(model);
    let mvp = camera.projection.mul(&model_view);
    // `CULLS` false (the public functions, which never cull): no camera centre, no test.
    let faces = if CULLS {
        FaceCull::new(&camera_centre(&mvp), mesh, cull)
    } else {
        None
    };
    // Indices are u16: at most 65536 vertices can be referenced.
    let mut cache = cache.get_mut(..mesh.positions.len().min(1 << 16));
    if let Some(cache) = cache.as_deref_mut() {
        for (i, slot) in cache.iter_mut().enumerate() {
            *slot = vertex(mesh, i as u16, &model_view, &mvp, light);
        }
    }
    let cache = cache.as_deref();
    for (t, tri) in mesh.indices.iter().enumerate() {
        if faces.is_some_and(|f| f.culls_in(mesh, t, tri)) {
            continue;
        }
        let v = |k: usize| match cache {
            Some(c) => c.get(usize::from(tri[k])).copied().flatten(),
            None => vertex(mesh, tri[k], &model_view, &mvp, light),
        };
        if let (Some(a), Some(b), Some(c)) = (v(0), v(1), v(2)) {
            emit(&[a, b, c]);
        }
    }
}

/// Draws `mesh` with `draw` into `target`; returns the pixels written (with a depth test:
/// that passed it), or [`Error::NoDepthBuffer`] before drawing anything when the draw tests
/// depth and `target` has no depth buffer.
pub fn draw_mesh<C: TargetColor, T: RenderTarget<Color = C>>(
    draw: &Draw<'_, C>,
    mesh: &Mesh<'_>,
    model: &Mat4,
    camera: &Camera,
    light: Option<&DirectionalLight>,
    target: &mut T,
) -> Result<u32, Error> {
    draw.check_target(target)?;
    let mut pixels = 0u32;
    facing_triangles::<true>(mesh, model, camera, light, draw.mode().cull, &mut [], |t| {
        draw.project(t, &mut |s| {
            pixels = pixels.wrapping_add(draw.screen_triangle_checked(s, target));
        });
    });
    Ok(pixels)
}

/// Like [`draw_mesh`] with a vertex cache (see [`mesh_triangles_cached`]).
pub fn draw_mesh_cached<C: TargetColor, T: RenderTarget<Color = C>>(
    draw: &Draw<'_, C>,
    mesh: &Mesh<'_>,
    model: &Mat4,
    camera: &Camera,
    light: Option<&DirectionalLight>,
    cache: &mut [Option<ClipVertex>],
    target: &mut T,
) -> Result<u32, Error> {
    draw.check_target(target)?;
    let mut pixels = 0u32;
    facing_triangles::<true>(mesh, model, camera, light, draw.mode().cull, cache, |t| {
        draw.project(t, &mut |s| {
            pixels = pixels.wrapping_add(draw.screen_triangle_checked(s, target));
        });
    });
    Ok(pixels)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Fx;

    /// A model-view matrix that scales by -32768 takes the normal (1, 1, 0) to
    /// (-32768, -32768, 0), whose squared length (2^63 in Q32) does not fit an `i64`: the
    /// normal is renormalised and lit, not overflowed.
    #[test]
    fn huge_scale_normal_is_renormalised() {
        let positions = [Vec3::ZERO; 3];
        let normals = [Vec3::from_num(1, 1, 0); 3];
        let uvs = [[Fx::ZERO; 2]; 3];
        let mesh = Mesh::new(&positions, Some(&normals), &uvs, &[[0, 1, 2]]).unwrap();
        let s = Fx::from_num(-32768);
        let model_view = Mat4::scaling(Vec3::new(s, s, s));
        let light = DirectionalLight::new(Vec3::from_num(-1, -1, 0), Fx::ZERO, Fx::ONE).unwrap();
        // The unit normal (-1, -1, 0) / sqrt 2 faces the light: full intensity.
        assert_eq!(vertex_intensity(&mesh, 0, &model_view, &light), Some(256));
    }
}
