//! Back-face culling in model space, before a triangle's vertices are transformed.
//!
//! A closed mesh turns about half of its triangles away from the camera. The screen-space
//! test ([`keeps_xy`](crate::geometry::clip::keeps_xy)) can only reject them once their
//! three vertices are transformed, outcoded and projected, and a vertex whose triangles all
//! face away is then prepared for nothing: on the benchmark sphere that is about 780 of the
//! 1,223 vertices it prepared per frame. This test rejects such triangles from their model-space
//! positions alone, so their vertices are never touched.
//!
//! # The test
//!
//! The clip-space `x`, `y` and `w` of a model-space point `p` are `A (p, 1)`, with `A` the
//! three rows `x`, `y`, `w` of the model-view-projection matrix. A triangle is front-facing
//! (counter-clockwise in normalized device coordinates) exactly when
//! `det[A P0, A P1, A P2] > 0` for its three vertices in front of the camera (and every
//! visible piece of a clipped triangle has the same orientation). By the Cauchy-Binet
//! formula that determinant is
//!
//! `s = n . (g + W p0)`, `n = (p1 - p0) x (p2 - p0)`,
//!
//! where `W` and `g` are 3x3 minors of `A` (`(g, W)` is the camera's centre in homogeneous
//! model coordinates): computed exactly once per frame by
//! [`MeshTransform::new`](super::MeshTransform::new) and kept to 62 bits ([`Eye`]).
//!
//! Per triangle the walker evaluates `s` in 32- and 64-bit integers from positions cut to
//! 14 signed bits by a per-mesh shift ([`coord_shift`], found by [`Mesh::new`]), and culls only
//! when `s` is below minus a bound on that rounding's error: a culled triangle is
//! back-facing in exact arithmetic. Near edge-on triangles are left to the screen-space test.
//! Every mesh path applies the same test (the walker, [`draw_mesh`](super::draw_mesh)), so
//! they draw the same pixels.
//!
//! Cost on Cortex-M4F: about 100 instructions per triangle tested, against about 430 per
//! vertex prepared. The walker tests a triangle with a corner not prepared yet first, and
//! one whose corners are all prepared only once the cheaper screen-space test kept it
//! (the two can disagree on a sliver whose projection rounds to the other orientation, and
//! this test must decide on every path, whatever the walker's cache holds).

use crate::geometry::Cull;
use crate::math::wide::{mul_wide, mul_wide_signed};
use crate::math::{Mat4, Vec3};

use super::face_planes::FacePlane;
use super::Mesh;
use crate::geometry::mesh_checks::COORD_BITS;

/// The camera's centre in homogeneous model coordinates, `(g, W)` (see the module docs),
/// as `mant * 2^exp`: the exact 3x3 minors of the rows `x`, `y`, `w` of an MVP matrix
/// (I16F16 bits; below 2^96), kept to 62 bits (exact when they fit).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Eye {
    mant: [i64; 4],
    exp: u32,
}

/// The camera's centre of `mvp` ([`Eye`]). Once per frame, and compact (loops, one
/// out-of-line copy): 128-bit arithmetic unrolled cost every mesh firmware kilobytes of
/// flash.
#[inline(never)]
pub(super) fn camera_centre(mvp: &Mat4) -> Eye {
    let rows = [0, 1, 3].map(|r| mvp.m[r].map(|c| c.to_bits()));
    // Column `skip` left out: g = (D123, -D023, D013) (skip 0, 1, 2) and W (skip 3).
    let exact = [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]]
        .map(|cols: [usize; 3]| det3(&rows.map(|r| cols.map(|c| r[c & 3]))))
        .iter()
        .enumerate()
        .fold([0i128; 4], |mut out, (skip, &det)| {
            out[skip & 3] = if skip == 1 { -det } else { det };
            out
        });
    let or = exact.iter().fold(0u128, |a, v| a | v.unsigned_abs());
    let exp = (u128::BITS - or.leading_zeros()).saturating_sub(62);
    Eye {
        mant: exact.map(|v| (v >> exp) as i64),
        exp,
    }
}

/// The determinant of a 3x3 integer matrix, exactly (below 2^96).
#[inline(never)]
fn det3(m: &[[i32; 3]; 3]) -> i128 {
    let mut det = 0i128;
    for j in 0..3 {
        let (a, b) = ((j + 1) % 3, (j + 2) % 3);
        // Each product below 2^62; their difference exact in i128.
        let p = |x: i32, y: i32| i128::from(i64::from(x) * i64::from(y));
        let minor = p(m[1][a], m[2][b]) - p(m[1][b], m[2][a]);
        det += i128::from(m[0][j]) * minor;
    }
    det
}

/// One mesh draw's model-space cull test (see the module docs).
#[derive(Clone, Copy, Debug)]
pub(super) struct FaceCull {
    /// Right shift of the mesh's coordinates (I16F16 bits).
    shift: u32,
    /// `g` scaled (`|g'| <= 2^29`), negated when front faces are culled (so the test is
    /// always `s < -margin`).
    g: [i32; 3],
    /// `W` scaled and signed alike (`|W'| <= 2^16`).
    w: i32,
    /// Bound on `|g' + W' p|` (`<= 2^30`) plus the bound on its error (`err6 / 6`; below 2^31).
    d_err: u32,
    /// Six times the bound on the error of `g' + W' p` against the exact value, in its
    /// units (below 2^20).
    err6: u32,
}

/// The error margin of a triangle whose edge components are below `e` (`<= 2^14`), from
/// the test's bounds `d_err` and `err6` (see [`FaceCull::culls`]); below 2^51.
#[inline(always)]
fn margin(e: u32, d_err: u32, err6: u32) -> u64 {
    3 * mul_wide(4 * e + 2, d_err) + mul_wide(e * e, err6)
}

impl FaceCull {
    /// The test for `mesh` under the camera centre `eye` ([`camera_centre`]), or `None`
    /// when `cull` culls nothing.
    #[inline(never)]
    pub fn new(eye: &Eye, mesh: &Mesh<'_>, cull: Cull) -> Option<FaceCull> {
        let negate = match cull {
            Cull::None => return None,
            Cull::Back => false,
            Cull::Front => true,
        };
        let shift = u32::from(mesh.coord_shift);
        // d(p) = 2^16 g + W p for I16F16 bits p (the homogeneous 1.0 is 2^16); in units of
        // 2^shift with p = 2^shift q: 2^(16 - shift) g + W q. Scaled by 2^-k so that
        // |g'| <= 2^29 and |W'| <= 2^16: g' = g 2^(exp + 16 - shift - k), W' = W 2^(exp - k)
        // from the mantissas.
        let bits = |v: i64| u64::BITS - v.unsigned_abs().leading_zeros();
        let g_bits = eye.mant[..3].iter().map(|&v| bits(v)).max().unwrap_or(0);
        let (tg, tw) = (eye.exp as i32 + 16 - shift as i32, eye.exp as i32);
        let k = (g_bits as i32 + tg - 29)
            .max(bits(eye.mant[3]) as i32 + tw - 16)
            .max(0);
        // A left shift only where the result fits (then it is exact); right shifts floor.
        let scale = |m: i64, t: i32| {
            let t = t - k;
            if t >= 0 {
                m << t.min(63)
            } else {
                m >> (-t).min(63)
            }
        };
        let g = [0, 1, 2].map(|i| scale(eye.mant[i], tg) as i32);
        let w = scale(eye.mant[3], tw) as i32;
        // Culling front faces is culling back faces of the negated test.
        let (g, w) = if negate { (g.map(|v| -v), -w) } else { (g, w) };
        // Each scaled value is below its exact one by less than 2 (the floor of its mantissa,
        // then of the scaling), so |error| < 2 (g) + 2 |q| (W, times q) + |W'| + 2 (W times
        // the coordinate's cut-off fraction, below 1).
        let err = (2 << COORD_BITS) + w.unsigned_abs() + 4;
        let g_max = g.iter().map(|v| v.unsigned_abs()).max().unwrap_or(0);
        let d_max = g_max + (w.unsigned_abs() << COORD_BITS);
        let (d_err, err6) = (d_max + err, 6 * err);
        Some(FaceCull {
            shift,
            g,
            w,
            d_err,
            err6,
        })
    }

    /// Whether the triangle `idx` of `positions` surely faces the culled way (then no
    /// screen-space test could keep it, up to the rounding of the projection). `false`
    /// when unsure, or for an index out of range.
    #[inline(always)]
    pub fn culls(&self, positions: &[Vec3], idx: &[u16; 3]) -> bool {
        let q = |k: usize| {
            positions
                .get(usize::from(idx[k]))
                .map(|p| [p.x, p.y, p.z].map(|c| c.to_bits() >> self.shift))
        };
        let (Some(p0), Some(p1), Some(p2)) = (q(0), q(1), q(2)) else {
            return false;
        };
        // |p| <= 2^13: the edges and the cross product fit i32.
        let (edges, n) = super::face_planes::edges_and_normal([p0, p1, p2]);
        // |g'| <= 2^29, |W' p| <= 2^29.
        let d = [0, 1, 2].map(|i| self.g[i] + self.w * p0[i]);
        // 32 x 32 -> 64-bit products (no library call on Cortex-M0+).
        let s = (0..3).fold(0i64, |acc, i| acc + mul_wide_signed(n[i], d[i]));
        // An upper bound on every |edge component| (below 2^14).
        let e = super::face_planes::edge_bound(edges);
        // n's error per component is below 2 (|e1| + |e2|) + 2 <= 4 e + 2, |n| <= 2 e^2:
        // |s - exact| <= 3 (4 e + 2) (|d| + err) + 3 (2 e^2) err (below 2^51).
        s < -(margin(e, self.d_err, self.err6) as i64)
    }

    /// [`culls`](Self::culls) from the triangle's baked plane ([`FacePlane`]): the same
    /// `s`, since `n . g + W (n . p0)` is `n . (g + W p0)` exactly (every product and sum
    /// below 2^61 in `i64`), and the same margin, so the same decision. Five 32 x 32 -> 64-bit
    /// products and no position, index or cross product. `margin_max` is
    /// [`margin_max`](Self::margin_max) of the mesh `f` belongs to.
    #[inline(always)]
    pub fn culls_plane(&self, f: &FacePlane, margin_max: u64) -> bool {
        let s = mul_wide_signed(f.n[0], self.g[0])
            + mul_wide_signed(f.n[1], self.g[1])
            + mul_wide_signed(f.n[2], self.g[2]);
        // W (n . p0) with n . p0 split at bit 16: |hi| < 2^30, 0 <= lo < 2^16.
        let (hi, lo) = ((f.np0 >> 16) as i32, (f.np0 & 0xFFFF) as i32);
        let wp = (mul_wide_signed(self.w, hi) << 16) + mul_wide_signed(self.w, lo);
        let s = s + wp;
        // The margin grows with `e`: below minus the mesh's largest, or not negative, the
        // triangle's own margin cannot change the answer (most of a sphere's back faces are
        // far below).
        if s < -(margin_max as i64) {
            return true;
        }
        s < 0 && s < -(margin(f.e, self.d_err, self.err6) as i64)
    }

    /// The largest margin of `mesh`'s baked face planes (from their largest edge bound,
    /// `Mesh::face_e_max`): no triangle's margin is larger. Kept apart from the test, so
    /// that meshes without planes carry none of it.
    #[inline(always)]
    pub fn margin_max(&self, mesh: &Mesh<'_>) -> u64 {
        margin(mesh.face_e_max, self.d_err, self.err6)
    }

    /// The test of triangle `t` (corners `idx`) of `mesh`: from its baked plane when the
    /// mesh has them ([`Mesh::with_face_planes`]), else from its positions.
    #[inline(always)]
    pub fn culls_in(&self, mesh: &Mesh<'_>, t: usize, idx: &[u16; 3]) -> bool {
        match mesh.face_planes.get(t) {
            Some(f) => self.culls_plane(f, self.margin_max(mesh)),
            None => self.culls(mesh.positions, idx),
        }
    }

    /// [`culls`](Self::culls) out of line, for the walker's second call site (a triangle
    /// whose corners were all prepared already, once the screen-space test kept it: about
    /// 300 of the benchmark sphere's 2,208 triangles), where a call costs less than the
    /// kilobyte of flash of another inlined copy.
    #[inline(never)]
    pub fn culls_out_of_line(&self, positions: &[Vec3], idx: &[u16; 3]) -> bool {
        self.culls(positions, idx)
    }
}

/// The model-space back-face test of one mesh under one [`MeshTransform`], as the mesh
/// walker runs it before it transforms a triangle's vertices: for a firmware that walks a
/// mesh itself, or to measure the test on its own. Built by [`MeshTransform::facing_test`].
///
/// A triangle it culls faces the culled way in exact arithmetic, and every mesh path drops
/// it, even where the rounded projection of a sliver would turn it the other way and the
/// screen-space test alone would keep it; triangles it is unsure of (nearly edge-on, or
/// tiny against the mesh's extent) are left to the screen-space test.
///
/// ```
/// use fixel_scenes as demo;
/// use fixel::geometry::Cull;
/// use fixel::scene::MeshTransform;
///
/// let data = demo::sphere();
/// let mesh = data.mesh().unwrap();
/// let camera = demo::camera(0);
/// let test = MeshTransform::new(&demo::sphere_model(0), &camera)
///     .facing_test(&mesh, Cull::Back)
///     .unwrap();
/// let culled = (0..mesh.triangles()).filter(|&t| test.culls(t)).count();
/// // A camera sees less than half of a sphere: most triangles face away, and the test
/// // drops most of those (1,447 of the 2,208 here; 656 are drawn).
/// assert_eq!(culled, 1447);
/// // Out of range: never culled.
/// assert!(!test.culls(mesh.triangles()));
/// ```
///
/// [`MeshTransform`]: super::MeshTransform
/// [`MeshTransform::facing_test`]: super::MeshTransform::facing_test
#[derive(Clone, Copy, Debug)]
pub struct FacingTest<'m> {
    test: FaceCull,
    mesh: &'m Mesh<'m>,
}

impl<'m> FacingTest<'m> {
    /// The test of `mesh` under the camera centre `eye`, or `None` for [`Cull::None`].
    pub(super) fn new(eye: &Eye, mesh: &'m Mesh<'m>, cull: Cull) -> Option<Self> {
        FaceCull::new(eye, mesh, cull).map(|test| FacingTest { test, mesh })
    }

    /// Whether triangle `t` of the mesh surely faces the culled way. `false` when unsure, or
    /// for `t` out of range.
    #[inline]
    pub fn culls(&self, t: usize) -> bool {
        self.mesh
            .indices()
            .get(t)
            .is_some_and(|idx| self.test.culls_in(self.mesh, t, idx))
    }
}

/// The tests' camera: 50 degrees, 4:3, depth 0.5 to 200.
#[cfg(test)]
pub(super) fn test_camera() -> super::Camera {
    use crate::math::{Angle, Fx};
    super::Camera::perspective(
        Angle::from_degrees(Fx::from_num(50)),
        Fx::from_num(4) / 3,
        Fx::from_num(0.5),
        Fx::from_num(200),
    )
    .unwrap_or_else(|e| panic!("the test camera: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::mesh_checks::coord_shift;
    use crate::math::{Angle, Fx};
    use crate::test_rng::Rng;

    /// `det[A P0, A P1, A P2]` exactly, `A` the rows x, y, w of `mvp`, `P = (p, 1)`.
    fn exact(mvp: &Mat4, p: [Vec3; 3]) -> i128 {
        let clip = |v: Vec3| {
            [0usize, 1, 3].map(|r| {
                let row = mvp.m[r];
                i128::from(row[0].to_bits()) * i128::from(v.x.to_bits())
                    + i128::from(row[1].to_bits()) * i128::from(v.y.to_bits())
                    + i128::from(row[2].to_bits()) * i128::from(v.z.to_bits())
                    + (i128::from(row[3].to_bits()) << 16)
            })
        };
        // Scaled down so the 3x3 determinant fits i128 (clip values below 2^41 here; the
        // cut moves it by far less than any culled triangle's margin).
        let [a, b, c] = p.map(|v| clip(v).map(|x| x >> 4));
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0])
    }

    fn fx_of(rng: &mut Rng, range: f32) -> Fx {
        let u = (rng.next() >> 40) as f32 / (1u64 << 24) as f32;
        Fx::from_num((u * 2.0 - 1.0) * range)
    }

    #[test]
    fn the_minors_are_the_determinant() {
        let mut rng = Rng(0xface_c011);
        for _ in 0..2000 {
            let mut mvp = Mat4::IDENTITY;
            for r in [0, 1, 3] {
                for c in 0..4 {
                    mvp.m[r][c] = fx_of(&mut rng, 4.0);
                }
            }
            let p: [Vec3; 3] = core::array::from_fn(|_| {
                Vec3::new(
                    fx_of(&mut rng, 3.0),
                    fx_of(&mut rng, 3.0),
                    fx_of(&mut rng, 3.0),
                )
            });
            let eye = camera_centre(&mvp);
            let [gx, gy, gz, w] = eye.mant.map(|m| i128::from(m) << eye.exp);
            let b = |v: Vec3| [v.x, v.y, v.z].map(|c| i128::from(c.to_bits()));
            let (p0, p1, p2) = (b(p[0]), b(p[1]), b(p[2]));
            let e1 = [0, 1, 2].map(|i| p1[i] - p0[i]);
            let e2 = [0, 1, 2].map(|i| p2[i] - p0[i]);
            let n = [
                e1[1] * e2[2] - e1[2] * e2[1],
                e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0],
            ];
            let g = [gx, gy, gz];
            // n . (2^16 g + W p0), in pieces that fit i128 (n < 2^66, the rest < 2^98):
            // compared by sign only, against the direct determinant.
            let d = [0, 1, 2].map(|i| ((g[i] << 16) + w * p0[i]) >> 40);
            let s: i128 = (0..3).map(|i| (n[i] >> 8) * d[i]).sum();
            let direct = exact(&mvp, p);
            if s.unsigned_abs() > 1 << 40 && direct.unsigned_abs() > 1 << 40 {
                assert_eq!(s.signum(), direct.signum());
            }
        }
    }

    /// Whatever the matrix, mesh scale and triangle, a culled triangle has the culled
    /// orientation exactly; and most clearly back-facing triangles of a sphere-like mesh are
    /// culled.
    #[test]
    fn a_culled_triangle_faces_away_exactly() {
        let mut rng = Rng(0xbacf_ace5);
        let (mut culled, mut culled_big, mut back) = (0, 0, 0);
        for i in 0..20_000u32 {
            let scale = [0.01f32, 0.5, 2.0, 9.0, 40.0][i as usize % 5];
            let turn = Angle((rng.next() >> 48) as u16);
            let camera = test_camera();
            let s = Fx::from_num(1.0 / scale.max(1.0));
            let model = Mat4::translation(Vec3::new(
                fx_of(&mut rng, 1.0),
                fx_of(&mut rng, 1.0),
                Fx::from_num(-6) - fx_of(&mut rng, 1.0).abs(),
            ))
            .mul(&Mat4::rotation_y(turn))
            .mul(&Mat4::rotation_x(Angle(turn.0.wrapping_mul(3))))
            .mul(&Mat4::scaling(Vec3::new(s, s, s)));
            let mvp = camera.projection.mul(&camera.view.mul(&model));
            let centre = Vec3::new(
                fx_of(&mut rng, scale),
                fx_of(&mut rng, scale),
                fx_of(&mut rng, scale),
            );
            let size = scale * [0.001f32, 0.05, 0.3][i as usize % 3];
            let p: [Vec3; 3] = core::array::from_fn(|_| {
                centre
                    + Vec3::new(
                        fx_of(&mut rng, size),
                        fx_of(&mut rng, size),
                        fx_of(&mut rng, size),
                    )
            });
            // A far corner so the shift is the scale's.
            let positions = [
                p[0],
                p[1],
                p[2],
                Vec3::new(Fx::from_num(scale), Fx::ZERO, Fx::ZERO),
            ];
            let uvs = [[Fx::ZERO; 2]; 4];
            let indices = [[0u16, 1, 2]];
            let mesh = Mesh::new(&positions, None, &uvs, &indices).unwrap();
            let eye = camera_centre(&mvp);
            let direct = exact(&mvp, p);
            for (cull, sign) in [(Cull::Back, 1i128), (Cull::Front, -1)] {
                let fc = FaceCull::new(&eye, &mesh, cull).unwrap();
                if fc.culls(&positions, &indices[0]) {
                    culled += 1;
                    assert!(sign * direct < 0, "culled but faces the kept way: {p:?}");
                }
                // Triangles of a twentieth of the mesh or more (not the thousandth-size ones,
                // whose cut positions say too little), facing away.
                if i % 3 != 0 && sign * direct < 0 {
                    back += 1;
                    if fc.culls(&positions, &indices[0]) {
                        culled_big += 1;
                    }
                }
            }
            assert!(FaceCull::new(&eye, &mesh, Cull::None).is_none());
        }
        assert!(culled > 0);
        assert!(
            culled_big * 10 > back * 8,
            "culled {culled_big} of {back} facing away"
        );
    }

    #[test]
    fn the_shift_bounds_every_coordinate() {
        let big = Fx::from_bits(i32::MIN);
        for (c, want) in [
            (Fx::ZERO, 0u8),
            (Fx::from_bits(8191), 0),
            (Fx::from_bits(-8192), 0),
            (Fx::from_bits(8192), 1),
            (Fx::ONE, 4),
            (big, 18),
            (Fx::from_bits(i32::MAX), 18),
        ] {
            let s = coord_shift(&[Vec3::new(c, Fx::ZERO, Fx::ZERO)]);
            assert_eq!(s, want, "{c:?}");
            let q = c.to_bits() >> s;
            assert!((-(1 << 13)..1 << 13).contains(&q));
        }
    }
}
