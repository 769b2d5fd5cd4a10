//! Tangent frames for bump and normal mapping, at run time for generated meshes (baked
//! meshes get theirs from `cargo xtask bake-obj --tangents`).
//!
//! For a triangle with edges `e1 = p1 − p0`, `e2 = p2 − p0` and uv differences
//! `(du1, dv1)`, `(du2, dv2)`, the surface derivatives are (Blinn's `Pu`, `Pv`):
//!
//! ```text
//! det = du1 dv2 − du2 dv1
//! Pu  = (e1 dv2 − e2 dv1) / det      (direction of increasing u)
//! Pv  = (e2 du1 − e1 du2) / det      (direction of increasing v)
//! ```
//!
//! Each vertex sums the unit `Pu` of its triangles (equal weights), is made orthogonal to
//! its normal (Gram-Schmidt) and normalised; its handedness is `+1` when `n × Pu` points
//! along `Pv` and `−1` when the uvs are mirrored, by majority of its triangles. The
//! bitangent the shaders use is `handedness · (n × t)`.
//!
//! Degenerate input never fails: a triangle whose uvs are collinear (`det = 0`) or whose
//! `Pu` is zero says nothing and is skipped; a vertex left with no tangent (or one parallel
//! to its normal) gets an arbitrary unit vector orthogonal to the normal, handedness `+1`.

use crate::math::{Fx, Vec3};
use crate::Error;

/// A unit tangent (direction of increasing `u`) and the sign of the bitangent.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tangent {
    /// Unit model-space tangent, orthogonal to the vertex normal.
    pub direction: Vec3,
    /// `+1`, or `−1` where the uvs are mirrored (the bitangent is `handedness · n × t`).
    pub handedness: i8,
}

/// The largest of `|v|`'s components as an `i64` vector shifted to fit `2^24`, as a `Vec3`
/// of raw bits (direction kept), or `None` for zero.
fn shrink(v: [i64; 3]) -> Option<Vec3> {
    let m = v.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
    if m == 0 {
        return None;
    }
    let sh = (64 - m.leading_zeros()).saturating_sub(24);
    let c = v.map(|x| (x >> sh) as i32);
    Some(Vec3::from_bits(c[0], c[1], c[2]))
}

/// A unit vector orthogonal to unit `n`.
pub(crate) fn any_orthogonal(n: Vec3) -> Vec3 {
    let axis = if n.x.abs() < Fx::from_bits(58982) {
        Vec3::from_num(1, 0, 0)
    } else {
        Vec3::from_num(0, 1, 0)
    };
    orthogonalize(axis, n).unwrap_or(Vec3::from_num(0, 0, 1))
}

/// `normalize(t − (t·n) n)`, or `None` when `t` is parallel to `n` (or zero).
pub(crate) fn orthogonalize(t: Vec3, n: Vec3) -> Option<Vec3> {
    let d = t.dot(n);
    let o = Vec3::new(
        t.x.saturating_sub(d.saturating_mul(n.x)),
        t.y.saturating_sub(d.saturating_mul(n.y)),
        t.z.saturating_sub(d.saturating_mul(n.z)),
    );
    // Below ~1e-3 of a unit the direction is noise.
    if o.length_squared_bits() < 1 << 22 {
        return None;
    }
    o.normalize()
}

/// Fills `out` (one per position) with the tangent frames of the module docs.
///
/// ```
/// use fixel::math::{Fx, Vec3};
/// use fixel::scene::{tangents, Tangent};
/// // A quad in the xy plane, u along +x and v along -y (rows down, as images).
/// let p = [Vec3::from_num(0, 0, 0), Vec3::from_num(1, 0, 0), Vec3::from_num(1, -1, 0), Vec3::from_num(0, -1, 0)];
/// let n = [Vec3::from_num(0, 0, 1); 4];
/// let uv = [[Fx::ZERO, Fx::ZERO], [Fx::ONE, Fx::ZERO], [Fx::ONE, Fx::ONE], [Fx::ZERO, Fx::ONE]];
/// let mut out = [Tangent::default(); 4];
/// tangents(&p, &n, &uv, &[[0, 3, 2], [0, 2, 1]], &mut out)?;
/// assert_eq!(out[0], Tangent { direction: Vec3::from_num(1, 0, 0), handedness: -1 });
/// # Ok::<(), fixel::Error>(())
/// ```
///
/// (`n × t = +y` points against `Pv = −y` here: handedness `−1`.)
///
/// # Errors
/// [`Error::WrongLength`] when `normals`, `uvs` or `out` is not as long as `positions`,
/// [`Error::IndexOutOfRange`] for an index past the vertices.
pub fn tangents(
    positions: &[Vec3],
    normals: &[Vec3],
    uvs: &[[Fx; 2]],
    indices: &[[u16; 3]],
    out: &mut [Tangent],
) -> Result<(), Error> {
    let n = positions.len();
    for len in [normals.len(), uvs.len(), out.len()] {
        if len != n {
            return Err(Error::WrongLength {
                expected: n,
                actual: len,
            });
        }
    }
    crate::geometry::mesh_checks::check_indices(indices, n)?;
    // Accumulate unit Pu in `direction` (saturating: a vertex has a handful of triangles)
    // and the handedness votes in `handedness`.
    for t in out.iter_mut() {
        *t = Tangent {
            direction: Vec3::ZERO,
            handedness: 0,
        };
    }
    let bits = |v: Vec3| [v.x, v.y, v.z].map(|c| i64::from(c.to_bits()));
    for tri in indices {
        let i = tri.map(usize::from);
        let (Some(p0), Some(p1), Some(p2)) = (
            positions.get(i[0]),
            positions.get(i[1]),
            positions.get(i[2]),
        ) else {
            continue;
        };
        let (a, b, c) = (bits(*p0), bits(*p1), bits(*p2));
        let e1: [i64; 3] = core::array::from_fn(|k| b[k] - a[k]);
        let e2: [i64; 3] = core::array::from_fn(|k| c[k] - a[k]);
        let uv = |k: usize| {
            uvs.get(k)
                .map_or([0, 0], |t| t.map(|x| i64::from(x.to_bits())))
        };
        let (t0, t1, t2) = (uv(i[0]), uv(i[1]), uv(i[2]));
        let (du1, dv1) = (t1[0] - t0[0], t1[1] - t0[1]);
        let (du2, dv2) = (t2[0] - t0[0], t2[1] - t0[1]);
        let det = du1 * dv2 - du2 * dv1;
        if det == 0 {
            continue;
        }
        let s = det.signum();
        // Pu and Pv times |det| (positions and uvs are at most 2^31 in bits: products
        // below 2^63).
        let pu: [i64; 3] =
            core::array::from_fn(|k| s * (e1[k].saturating_mul(dv2) - e2[k].saturating_mul(dv1)));
        let pv: [i64; 3] =
            core::array::from_fn(|k| s * (e2[k].saturating_mul(du1) - e1[k].saturating_mul(du2)));
        let (Some(pu), Some(pv)) = (shrink(pu), shrink(pv)) else {
            continue;
        };
        let (Some(u), Some(v)) = (pu.normalize(), pv.normalize()) else {
            continue;
        };
        for &k in &i {
            let (Some(t), Some(nk)) = (out.get_mut(k), normals.get(k)) else {
                continue;
            };
            t.direction = Vec3::new(
                t.direction.x.saturating_add(u.x),
                t.direction.y.saturating_add(u.y),
                t.direction.z.saturating_add(u.z),
            );
            let vote = if nk.cross(u).dot(v) >= Fx::ZERO {
                1
            } else {
                -1
            };
            t.handedness = t.handedness.saturating_add(vote);
        }
    }
    for (t, nk) in out.iter_mut().zip(normals) {
        let nu = nk.normalize().unwrap_or(Vec3::from_num(0, 0, 1));
        let dir = orthogonalize(t.direction, nu).unwrap_or_else(|| any_orthogonal(nu));
        *t = Tangent {
            direction: dir,
            handedness: if t.handedness < 0 { -1 } else { 1 },
        };
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn collapsed_uvs_fall_back_to_an_orthogonal_frame() {
        let p = [
            Vec3::from_num(0, 0, 0),
            Vec3::from_num(1, 0, 0),
            Vec3::from_num(0, 1, 0),
        ];
        let n = [Vec3::from_num(0, 0, 1); 3];
        // v collapsed: every vertex has v = 0.
        let uv = [
            [Fx::ZERO; 2],
            [Fx::ONE, Fx::ZERO],
            [Fx::from_num(0.5), Fx::ZERO],
        ];
        let mut out = [Tangent::default(); 3];
        tangents(&p, &n, &uv, &[[0, 1, 2]], &mut out).unwrap();
        for t in out {
            assert_eq!(t.handedness, 1);
            assert!(t.direction.dot(n[0]).abs() < Fx::from_bits(64));
            let len = t.direction.length_squared_bits() as f64 / 2f64.powi(32);
            assert!((len - 1.0).abs() < 1e-3, "{t:?}");
        }
        let mut short = [Tangent::default(); 2];
        assert!(tangents(&p, &n, &uv, &[[0, 1, 2]], &mut short).is_err());
        assert!(tangents(&p, &n, &uv, &[[0, 1, 3]], &mut out).is_err());
    }

    #[test]
    fn mirrored_uvs_flip_the_handedness() {
        let p = [
            Vec3::from_num(0, 0, 0),
            Vec3::from_num(1, 0, 0),
            Vec3::from_num(0, 1, 0),
        ];
        let n = [Vec3::from_num(0, 0, 1); 3];
        let uv = [[Fx::ZERO; 2], [Fx::ONE, Fx::ZERO], [Fx::ZERO, Fx::ONE]];
        let mut out = [Tangent::default(); 3];
        tangents(&p, &n, &uv, &[[0, 1, 2]], &mut out).unwrap();
        assert_eq!(out[0].handedness, 1);
        let mirrored = uv.map(|[u, v]| [-u, v]);
        tangents(&p, &n, &mirrored, &[[0, 1, 2]], &mut out).unwrap();
        assert_eq!(out[0].handedness, -1);
        assert_eq!(out[0].direction, Vec3::from_num(-1, 0, 0));
    }
}
