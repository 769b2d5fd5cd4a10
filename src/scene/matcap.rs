//! Sphere-map (matcap) texture coordinates per vertex: the real-time form of an
//! environment map. At each vertex the walker reflects the eye vector about the normal,
//! both in view space, and turns the reflection into the coordinates of a sphere map
//! ([`SphereMap::coords`]: GL's `GL_SPHERE_MAP`); the draw is then a plain textured draw of
//! the sphere-map image (any filter and projection mode of [`Draw`](crate::pipeline::Draw),
//! clamp-to-edge wrapping), interpolating `s, t` across each triangle.
//!
//! ```text
//! r = 2 (n·v) n − (n·n) v      n = model_view · normal,  v = −(model_view · p)
//! m = 2 sqrt(rx² + ry² + (rz + 1)²),   s = rx / m + 1/2,   t = ry / m + 1/2
//! ```
//!
//! The sphere map is indexed in view space, so it is the environment as seen from the
//! camera (for a camera looking down `−z`, [`sky_spheremap`](crate::shading::env::sky)
//! bakes the sky that way; a matcap image painted as a lit ball works the same way).
//!
//! # Cost and error
//!
//! Per vertex: a normal transform, the reflection (exact in `i64` from 15-bit vectors) and
//! two table `atan2` and two table sines (no square root, no division). Per pixel: nothing beyond the textured draw. The error is that of
//! interpolating `s, t` rather than reflecting per pixel: small inside a finely tessellated
//! mesh and largest where the reflection turns fast across a triangle (near the silhouette,
//! where the whole rim of the map is squeezed into a few pixels). `host-tests` measures it
//! against the f64 per-pixel reflection.

use super::vertex_uv::VertexUv;
use super::Mesh;
use crate::math::{Fx, Mat4, Vec3};
use crate::shading::env::SphereMap;
use crate::texture::Nearest;

/// Texture coordinates from the view-space reflection at each vertex (see the module
/// docs); give it to [`MeshTransform::with_uvs`](super::MeshTransform::with_uvs). The
/// mesh needs normals (without them, or on overflow, a vertex's triangles are skipped).
/// Coordinates are I16F16 in `[0, 1]`: draw with clamp-to-edge wrapping.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SphereMapUvs;

/// The components of `c` shifted (by one shift for all three) so the largest magnitude is
/// below 2^`BITS`.
#[inline(always)]
fn fit<const BITS: u32>(c: [i32; 3]) -> [i32; 3] {
    let max = c[0].unsigned_abs() | c[1].unsigned_abs() | c[2].unsigned_abs();
    let bits = 32 - max.leading_zeros();
    if bits > BITS {
        c.map(|x| x >> (bits - BITS))
    } else {
        c.map(|x| x << (BITS - bits))
    }
}

impl SphereMapUvs {
    /// The sphere-map coordinates (I16F16 in `[0, 1]`) of a view-space normal `n` (any
    /// length) at the view-space point `p` (eye at the origin). The zero normal, or `p` at
    /// the eye, gives the map's centre.
    ///
    /// Both vectors are shifted to 15 bits, the dot products are exact (`i32` products
    /// summed in `i64`), and `r = 2 (n·v) n − (n·n) v` is exact in `i64` (below 2^49), then
    /// shifted to 30 bits for the table `atan2`: the direction keeps about 15 bits at any
    /// angle, grazing ones included (where `n·v` is small).
    pub fn at(n: Vec3, p: Vec3) -> [Fx; 2] {
        let n = fit::<15>([n.x.to_bits(), n.y.to_bits(), n.z.to_bits()]);
        let v = fit::<15>([p.x.to_bits(), p.y.to_bits(), p.z.to_bits()].map(i32::wrapping_neg));
        // Each product below 2^30 in magnitude: exact in i32, summed in i64.
        let dot = |a: [i32; 3], b: [i32; 3]| {
            i64::from(a[0] * b[0]) + i64::from(a[1] * b[1]) + i64::from(a[2] * b[2])
        };
        let (nv, nn) = (2 * dot(n, v), dot(n, n));
        // |2 n·v|, n·n < 2^32 and components below 2^15: each term below 2^47.
        let r = [0, 1, 2].map(|i| nv * i64::from(n[i]) - nn * i64::from(v[i]));
        let max = r.iter().fold(0u64, |m, c| m | c.unsigned_abs());
        let shift = (64 - max.leading_zeros()).saturating_sub(30);
        let (s, t) = SphereMap::<Nearest>::coords(r.map(|c| (c >> shift) as i32));
        [Fx::from_bits(s as i32), Fx::from_bits(t as i32)]
    }
}

impl VertexUv for SphereMapUvs {
    #[inline]
    fn uv(&self, mesh: &Mesh<'_>, i: usize, model_view: &Mat4, _: [Fx; 2]) -> Option<[Fx; 2]> {
        let n = model_view.transform_vector(*mesh.normals()?.get(i)?)?;
        let p = model_view.transform_point(*mesh.positions().get(i)?)?;
        Some(Self::at(n, Vec3::new(p.x, p.y, p.z)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn facing_the_eye_is_the_centre_and_edge_on_is_the_rim() {
        // A point straight ahead, normal towards the eye: r = +z, the centre.
        let c = SphereMapUvs::at(Vec3::from_num(0, 0, 1), Vec3::from_num(0, 0, -5));
        assert_eq!(c, [Fx::from_num(0.5), Fx::from_num(0.5)]);
        // Normal +x at a point ahead: r = -v mirrored... r points along -z: the rim.
        let [s, t] = SphereMapUvs::at(Vec3::from_num(1, 0, 0), Vec3::from_num(0, 0, -5));
        let rho = (s.to_num::<f64>() - 0.5).hypot(t.to_num::<f64>() - 0.5);
        assert!((rho - 0.5).abs() < 1e-3, "{s} {t}");
        // The zero normal: the centre.
        let z = SphereMapUvs::at(Vec3::ZERO, Vec3::from_num(1, 2, -5));
        assert_eq!(z, [Fx::from_num(0.5), Fx::from_num(0.5)]);
    }

    #[test]
    fn normal_tilted_up_reads_above_the_centre() {
        // Normal tilted to +y at 45 degrees: r turns 90 degrees to +y: t = 1/2 + sin(45)/2.
        let [s, t] = SphereMapUvs::at(Vec3::from_num(0, 1, 1), Vec3::from_num(0, 0, -5));
        assert!((s.to_num::<f64>() - 0.5).abs() < 1e-3);
        let want = 0.5 + (core::f64::consts::FRAC_PI_4).sin() / 2.0;
        assert!((t.to_num::<f64>() - want).abs() < 2e-3, "{t}");
    }
}
