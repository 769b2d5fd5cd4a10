//! Light space: the light's world-to-clip matrix ([`LightSpace`]) for a directional
//! (orthographic) or spot (perspective) light, the light-space varyings each vertex
//! carries, and a pixel's map position and depth from them ([`LightKind`]).

use super::{DEPTH_STEP, ST_ONE};
use crate::math::recip_q30::{mul_q16, recip_q30};
use crate::math::{Angle, Fx, Mat4, Vec3};
use crate::Error;

/// Values of light-space varyings saturate here (their differences must fit `i32`).
const LIMIT: i64 = 1 << 30;

/// The light's kind: how vertices carry light-space coordinates and how a pixel gets its
/// map position from them.
pub trait LightKind: Copy + core::fmt::Debug + 'static {
    /// Varyings per vertex (3 or 4).
    const VARYINGS: usize;
    /// Name for reports.
    const NAME: &'static str;
    /// True when [`LightKind::project`] inside the frustum returns the first three varyings
    /// as they are (no divide): a triangle whose three vertices lie inside the frustum then
    /// has every pixel inside it (the varyings of its pixels lie between its vertices'), and
    /// the lookup skips the per-pixel frustum test. Default false.
    const AFFINE: bool = false;
    /// The light-space varyings of model-space point `p` under `m` (light clip from model);
    /// unused trailing entries are 0.
    fn vertex(m: &Mat4, p: Vec3) -> [i32; 4];
    /// Map position `(s, t)` (Q12.20) and depth `d` (Q16.4) from interpolated varyings, or
    /// `None` outside the light's frustum.
    fn project(v: [i32; 4]) -> Option<(i32, i32, i32)>;
    /// Whether a triangle whose vertices have the light varyings `v` faces the light (its
    /// front, counter-clockwise in the light's clip space as in GL, is turned towards the
    /// light). A triangle that does not, edge-on included, is in its own shade. The default
    /// says every triangle faces the light.
    fn faces_light(v: &[[i32; 4]; 3]) -> bool {
        let _ = v;
        true
    }
}

/// Whether the triangle of homogeneous light-space points `p` (`(a, b, w)`, `a` growing to
/// the right and `b` downwards, as the map's `s` and `t`) faces the light: the determinant
/// of the three points, which has the sign of the triangle's area seen from the light for
/// any `w` (the volume of the tetrahedron the light's eye makes with it), is negative (`b`
/// points down: a front face's counter-clockwise turn is clockwise here).
///
/// Exact in `i64` up to the rounding of one step: the edges `p1 - p0` and `p2 - p0` halved
/// (each below 2^30), their cross product (below 2^61) shifted to below 2^31, then its dot
/// product with `p0` (each term below 2^61). Only a triangle within that rounding of edge-on
/// can be called either way.
#[inline]
pub(crate) fn turned_towards(p: [[i32; 3]; 3]) -> bool {
    let e = |k: usize| -> [i64; 3] {
        core::array::from_fn(|j| (i64::from(p[k][j]) - i64::from(p[0][j])) >> 1)
    };
    let (e1, e2) = (e(1), e(2));
    let mut c = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    let m = c.iter().fold(0u64, |m, v| m | v.unsigned_abs());
    let k = (64 - m.leading_zeros()).saturating_sub(31);
    for v in c.iter_mut() {
        *v >>= k;
    }
    let det: i64 = (0..3).map(|j| i64::from(p[0][j]) * c[j]).sum();
    det < 0
}

/// A directional light: an orthographic light space (parallel rays).
#[derive(Clone, Copy, Debug, Default)]
pub struct Directional;

/// A spot light: a perspective light space from a point.
#[derive(Clone, Copy, Debug, Default)]
pub struct Spot;

/// Row `r` of `m` applied to `(p, 1)`, with 32 fraction bits (saturating: each product is
/// below 2^62, their sum may not be).
#[inline]
fn row(m: &Mat4, r: usize, p: Vec3) -> i64 {
    let e = m.m[r];
    let t = |a: Fx, b: Fx| i64::from(a.to_bits()) * i64::from(b.to_bits());
    t(e[0], p.x)
        .saturating_add(t(e[1], p.y))
        .saturating_add(t(e[2], p.z))
        .saturating_add(i64::from(e[3].to_bits()) << 16)
}

#[inline]
fn sat(v: i64) -> i32 {
    v.clamp(-LIMIT, LIMIT) as i32
}

/// Inside `[0, 1)` (Q12.20).
#[inline(always)]
fn in_map(s: i32) -> bool {
    (s as u32) < ST_ONE as u32
}

/// Q12.20 depth `r` (1.0 = far plane) to Q16.4 window depth: `r * 65535 / 65536`.
#[inline(always)]
fn depth_q4(r: i32) -> i32 {
    r - (r >> 16)
}

impl LightKind for Directional {
    const VARYINGS: usize = 3;
    const NAME: &'static str = "directional";
    const AFFINE: bool = true;
    fn vertex(m: &Mat4, p: Vec3) -> [i32; 4] {
        let one = 1i64 << 32;
        let (x, y, z) = (row(m, 0, p), row(m, 1, p), row(m, 2, p));
        // (x + 1) / 2 with 32 fraction bits -> 20; depth 65535 * 16 * (z + 1) / 2.
        let d = ((z.saturating_add(one) >> 12).saturating_mul(65535)) >> 17;
        [
            sat(x.saturating_add(one) >> 13),
            sat(one.saturating_sub(y) >> 13),
            sat(d),
            0,
        ]
    }
    fn faces_light(v: &[[i32; 4]; 3]) -> bool {
        // Parallel rays: `w = 1` (any positive constant).
        turned_towards(v.map(|[s, t, _, _]| [s, t, 1]))
    }
    #[inline(always)]
    fn project(v: [i32; 4]) -> Option<(i32, i32, i32)> {
        let [s, t, d, _] = v;
        (in_map(s) && in_map(t) && (0..=65535 * DEPTH_STEP).contains(&d)).then_some((s, t, d))
    }
}

impl LightKind for Spot {
    const VARYINGS: usize = 4;
    const NAME: &'static str = "spot";
    fn vertex(m: &Mat4, p: Vec3) -> [i32; 4] {
        let (x, y, z, w) = (row(m, 0, p), row(m, 1, p), row(m, 2, p), row(m, 3, p));
        [
            sat(x.saturating_add(w) >> 17),
            sat(w.saturating_sub(y) >> 17),
            sat(z.saturating_add(w) >> 17),
            sat(w >> 16),
        ]
    }
    fn faces_light(v: &[[i32; 4]; 3]) -> bool {
        turned_towards(v.map(|[a, b, _, w]| [a, b, w]))
    }
    #[inline(always)]
    fn project(v: [i32; 4]) -> Option<(i32, i32, i32)> {
        let [a, b, c, w] = v;
        // Inside the frustum without dividing: 0 <= a < w, 0 <= b < w, 0 <= c <= w.
        if w <= 0 || !(0..w).contains(&a) || !(0..w).contains(&b) || !(0..=w).contains(&c) {
            return None;
        }
        // Normalise w to [2^29, 2^30] (a Q30 value the span loop's table reciprocal takes):
        // a, b, c shifted alike stay below 2^30, and n / w in Q30 is n r >> 16, one 32x32
        // product (split on ARMv6-M), then Q20. Relative error below 2^-16: under 1/256
        // texel on a 256 map, under one depth step.
        let k = w.leading_zeros().saturating_sub(2);
        let r = recip_q30(w << k);
        let q = |n: i32| mul_q16(n << k, r) >> 10;
        Some((
            q(a).min(ST_ONE - 1),
            q(b).min(ST_ONE - 1),
            depth_q4(q(c).min(ST_ONE)),
        ))
    }
}

/// The light's world-to-clip matrix, for a light kind `K`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LightSpace<K> {
    matrix: Mat4,
    _kind: core::marker::PhantomData<K>,
}

impl<K: LightKind> LightSpace<K> {
    /// The world-to-light-clip matrix (view, then projection).
    pub fn matrix(&self) -> &Mat4 {
        &self.matrix
    }

    /// Light clip from model space: `matrix * model` (per mesh).
    pub fn with_model(&self, model: &Mat4) -> Mat4 {
        self.matrix.mul(model)
    }

    /// The light-space varyings of model-space point `p` under `with_model(model)`.
    #[inline]
    pub fn varyings(m: &Mat4, p: Vec3) -> [i32; 4] {
        K::vertex(m, p)
    }
}

impl LightSpace<Directional> {
    /// A directional light looking from `eye` towards `target` (`up` roughly up in the
    /// map), whose map covers a square of half-side `half` around the axis and depths
    /// `near..far` along it (an orthographic box, world units).
    ///
    /// # Errors
    /// [`Error::BadProjection`] if `half <= 0`, `far <= near`, `(far + near) / (far - near)`
    /// is 32768 or more in magnitude (a thin range far from the light), or `look_at`
    /// refuses the axis.
    pub fn directional(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        half: Fx,
        near: Fx,
        far: Fx,
    ) -> Result<Self, Error> {
        if half <= Fx::ZERO {
            return Err(Error::BadProjection(
                "directional light: half-side must be > 0",
            ));
        }
        if far <= near {
            return Err(Error::BadProjection(
                "directional light: far must be > near",
            ));
        }
        let (o, i) = (Fx::ZERO, Fx::ONE);
        // The depth row maps near..far to -1..1: -2 / (far - near) and
        // -(far + near) / (far - near). The sum and difference of two I16F16 values need 17
        // integer bits: computed in i64 (truncated toward zero, as `Fx` division), and
        // refused when a quotient does not fit I16F16.
        let (n, f) = (i64::from(near.to_bits()), i64::from(far.to_bits()));
        let quotient = |num: i64| i32::try_from((num << 16) / (f - n)).ok().map(Fx::from_bits);
        let k = quotient(2 << 16).ok_or(Error::BadProjection(
            "directional light: depth range too small",
        ))?;
        let inv = i.checked_div(half).ok_or(Error::BadProjection(
            "directional light: half-side too small",
        ))?;
        let c = quotient(f + n).ok_or(Error::BadProjection(
            "directional light: (far + near) / (far - near) must fit I16F16",
        ))?;
        let ortho = Mat4::from_rows([[inv, o, o, o], [o, inv, o, o], [o, o, -k, -c], [o, o, o, i]]);
        Self::from_matrix(ortho.mul(&Mat4::look_at(eye, target, up)?))
    }

    /// A directional light from any affine world-to-clip matrix.
    ///
    /// # Errors
    /// [`Error::BadProjection`] unless the last row is `(0, 0, 0, 1)`.
    pub fn from_matrix(matrix: Mat4) -> Result<Self, Error> {
        if matrix.m[3] != [Fx::ZERO, Fx::ZERO, Fx::ZERO, Fx::ONE] {
            return Err(Error::BadProjection(
                "directional light: the matrix must be affine (last row 0, 0, 0, 1)",
            ));
        }
        Ok(LightSpace {
            matrix,
            _kind: core::marker::PhantomData,
        })
    }
}

impl LightSpace<Spot> {
    /// A spot light at `eye` looking at `target`, cone of full angle `fov` (a square map),
    /// depths `near..far`.
    ///
    /// # Errors
    /// As [`Mat4::perspective`] and [`Mat4::look_at`].
    pub fn spot(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        fov: Angle,
        near: Fx,
        far: Fx,
    ) -> Result<Self, Error> {
        let proj = Mat4::perspective(fov, Fx::ONE, near, far)?;
        Ok(LightSpace {
            matrix: proj.mul(&Mat4::look_at(eye, target, up)?),
            _kind: core::marker::PhantomData,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::turned_towards;
    use crate::test_rng::Rng;

    /// The sign of the integer determinant is the exact one wherever the exact value is not
    /// within its rounding of zero, for points anywhere in the varyings' range.
    #[test]
    fn facing_is_the_sign_of_the_exact_determinant() {
        let mut rng = Rng(0x5AD0_F1CE);
        let mut checked = 0;
        for round in 0..200_000 {
            let spread = 1i64 << (10 + round % 21);
            let coord = |rng: &mut Rng| {
                let v = (rng.next() >> 33) as i64 % (2 * spread + 1) - spread;
                v.clamp(-(1 << 30), 1 << 30) as i32
            };
            let p: [[i32; 3]; 3] =
                core::array::from_fn(|_| [coord(&mut rng), coord(&mut rng), coord(&mut rng)]);
            let q = p.map(|r| r.map(i128::from));
            let det = q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1])
                - q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0])
                + q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
            // The rounding: the halved edges (one unit each) and the cross product's shift
            // (below 2^-31 of it), times |p0|: far below this margin.
            let scale = q
                .iter()
                .flatten()
                .map(|v| v.unsigned_abs())
                .max()
                .unwrap_or(0);
            if det.unsigned_abs() <= scale * scale * 8 {
                continue;
            }
            checked += 1;
            assert_eq!(turned_towards(p), det < 0, "{p:?}: {det}");
        }
        assert!(checked > 150_000, "{checked}");
    }
}
