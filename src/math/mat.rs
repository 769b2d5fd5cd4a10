//! 4×4 matrices of [`Fx`] (I16F16) for model, view and projection transforms.
//!
//! Conventions (the OpenGL ones): storage is row-major, `m[row][col]`; vectors are
//! columns, `p' = M · p`, so `A * B` applies `B` first; right-handed; the camera looks down
//! -z; clip space is OpenGL's (after the divide by w, NDC z is in [-1, 1]).
//!
//! Every entry and every product is I16F16 (±32768, 2^-16). Products of rows and columns
//! are exact `i64` sums rounded once to Q16 (see the `acc` module): [`Mat4::mul`]
//! saturates, while [`Mat4::transform_point`] and [`Mat4::transform_vector`] return `None`
//! when a component overflows, so that the caller can skip that vertex instead of drawing
//! garbage. Rotation entries are sines and cosines accurate to ~2^-17; the projection's
//! `cot(fovy/2)` and quotients are computed from Q2.30 sines and correctly rounded
//! division-free quotients, so every entry is within about one ulp of the exact value.

use super::acc::{dot3_plus_fit, prod, saturate, sum_q32};
use super::recip::{div_round, signed_fx};
use super::trig::{sin_cos, sin_cos_q30};
use super::{Angle, Fx, Vec3, Vec4};
use crate::Error;
use core::ops::Mul;

/// A 4×4 matrix, row-major (`m[row][col]`), acting on column vectors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mat4 {
    /// The entries, `m[row][col]`.
    pub m: [[Fx; 4]; 4],
}

const O: Fx = Fx::ZERO;
const I: Fx = Fx::ONE;

/// Smallest accepted `|forward × up|²` in `look_at`, as Q32 bits: sin(angle) >= 2^-8.
const MIN_SIN2_BITS: u64 = 1 << 16;

impl Default for Mat4 {
    /// The identity.
    fn default() -> Mat4 {
        Mat4::IDENTITY
    }
}

impl Mat4 {
    /// The identity matrix.
    pub const IDENTITY: Mat4 = Mat4 {
        m: [[I, O, O, O], [O, I, O, O], [O, O, I, O], [O, O, O, I]],
    };

    /// A matrix from its rows.
    pub const fn from_rows(m: [[Fx; 4]; 4]) -> Mat4 {
        Mat4 { m }
    }

    /// Translation by `t`.
    pub const fn translation(t: Vec3) -> Mat4 {
        Mat4 {
            m: [[I, O, O, t.x], [O, I, O, t.y], [O, O, I, t.z], [O, O, O, I]],
        }
    }

    /// Scaling by `s` along the axes.
    pub const fn scaling(s: Vec3) -> Mat4 {
        Mat4 {
            m: [[s.x, O, O, O], [O, s.y, O, O], [O, O, s.z, O], [O, O, O, I]],
        }
    }

    /// Right-handed rotation by `a` about the x axis (y towards z).
    pub fn rotation_x(a: Angle) -> Mat4 {
        let (s, c) = sin_cos(a);
        let n = s.saturating_neg();
        Mat4 {
            m: [[I, O, O, O], [O, c, n, O], [O, s, c, O], [O, O, O, I]],
        }
    }

    /// Right-handed rotation by `a` about the y axis (z towards x).
    pub fn rotation_y(a: Angle) -> Mat4 {
        let (s, c) = sin_cos(a);
        let n = s.saturating_neg();
        Mat4 {
            m: [[c, O, s, O], [O, I, O, O], [n, O, c, O], [O, O, O, I]],
        }
    }

    /// Right-handed rotation by `a` about the z axis (x towards y).
    pub fn rotation_z(a: Angle) -> Mat4 {
        let (s, c) = sin_cos(a);
        let n = s.saturating_neg();
        Mat4 {
            m: [[c, n, O, O], [s, c, O, O], [O, O, I, O], [O, O, O, I]],
        }
    }

    /// gluPerspective: with `f = cot(fovy / 2)`,
    ///
    /// ```text
    /// [ f/aspect  0   0                        0                       ]
    /// [ 0         f   0                        0                       ]
    /// [ 0         0   (far+near)/(near-far)    2·far·near/(near-far)   ]
    /// [ 0         0  -1                        0                       ]
    /// ```
    ///
    /// `fovy` is the full vertical field of view, `aspect` is width / height. Every entry
    /// is within about one ulp (2^-16) of the exact value for the given inputs when
    /// `fovy >= 1°` (`fovy/2` is taken exactly, at 2^-17-turn resolution); below that the
    /// Q2.30 sine limits `f` to a relative error of about `2^-30 / sin(fovy/2)`.
    ///
    /// # Errors
    ///
    /// [`Error::BadProjection`] if `near <= 0`, `far <= near`, `fovy` is not strictly
    /// between 0 and a half turn, `aspect <= 0`, or an entry does not fit in `Fx`.
    pub fn perspective(fovy: Angle, aspect: Fx, near: Fx, far: Fx) -> Result<Mat4, Error> {
        if near <= Fx::ZERO {
            return Err(Error::BadProjection("near must be > 0"));
        }
        if far <= near {
            return Err(Error::BadProjection("far must be > near"));
        }
        if fovy.0 == 0 || fovy.0 >= Angle::HALF_TURN.0 {
            return Err(Error::BadProjection("fovy must be in (0, half turn)"));
        }
        if aspect <= Fx::ZERO {
            return Err(Error::BadProjection("aspect must be > 0"));
        }
        const OVERFLOW: Error = Error::BadProjection("projection entry overflows Fx");
        // Half angle in 2^-32 turns is in (0, quarter turn): sine and cosine are > 0.
        let (s, c) = sin_cos_q30(u32::from(fovy.0) << 15);
        let f = div_round(u64::from(c.unsigned_abs()) << 16, s.unsigned_abs());
        let f = signed_fx(f, false).ok_or(OVERFLOW)?;
        let fa = div_round(
            u64::from(f.to_bits().unsigned_abs()) << 16,
            aspect.to_bits().unsigned_abs(),
        );
        let fa = signed_fx(fa, false).ok_or(OVERFLOW)?;
        // 0 < near < far <= 2^31 - 1 (as bits), so these all fit comfortably in u64.
        let (n, fr) = (
            u64::from(near.to_bits().unsigned_abs()),
            u64::from(far.to_bits().unsigned_abs()),
        );
        let span = far.to_bits().unsigned_abs() - near.to_bits().unsigned_abs();
        let a22 = signed_fx(div_round((fr + n) << 16, span), true).ok_or(OVERFLOW)?;
        let a23 = signed_fx(div_round(2 * fr * n, span), true).ok_or(OVERFLOW)?;
        let m1 = -Fx::ONE;
        Ok(Mat4 {
            m: [[fa, O, O, O], [O, f, O, O], [O, O, a22, a23], [O, O, m1, O]],
        })
    }

    /// gluLookAt: the view matrix of a camera at `eye` looking at `target`, with `up`
    /// pointing roughly up on screen. With `f = normalize(target - eye)`,
    /// `s = normalize(f × normalize(up))` and `u = s × f`:
    ///
    /// ```text
    /// [  s.x   s.y   s.z  -s·eye ]
    /// [  u.x   u.y   u.z  -u·eye ]
    /// [ -f.x  -f.y  -f.z   f·eye ]
    /// [  0     0     0     1     ]
    /// ```
    ///
    /// # Errors
    ///
    /// [`Error::BadProjection`] if `eye == target`, `up` is zero or within about 0.22°
    /// (sin < 2^-8) of the viewing direction, or `target - eye` or a translation entry
    /// does not fit in `Fx`.
    pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Result<Mat4, Error> {
        let fwd = target
            .checked_sub(eye)
            .ok_or(Error::BadProjection("look_at: target - eye overflows"))?;
        let f = fwd
            .normalize()
            .ok_or(Error::BadProjection("look_at: eye == target"))?;
        let up = up
            .normalize()
            .ok_or(Error::BadProjection("look_at: up is zero"))?;
        const PARALLEL: Error = Error::BadProjection("look_at: up is parallel to the view");
        let side = f.cross(up);
        if side.length_squared_bits() < MIN_SIN2_BITS {
            return Err(PARALLEL);
        }
        let s = side.normalize().ok_or(PARALLEL)?;
        let u = s.cross(f);
        const FAR: Error = Error::BadProjection("look_at: eye too far from the origin");
        let ts = (-s).checked_dot(eye).ok_or(FAR)?;
        let tu = (-u).checked_dot(eye).ok_or(FAR)?;
        let tf = f.checked_dot(eye).ok_or(FAR)?;
        Ok(Mat4 {
            m: [
                [s.x, s.y, s.z, ts],
                [u.x, u.y, u.z, tu],
                [-f.x, -f.y, -f.z, tf],
                [O, O, O, I],
            ],
        })
    }

    /// The product `self · o` (applies `o` first), each entry an exact sum rounded once,
    /// saturating at the `Fx` range.
    pub fn mul(&self, o: &Mat4) -> Mat4 {
        let mut m = [[O; 4]; 4];
        // One loop over the 16 entries whose count LLVM cannot see: unrolled, the calls
        // cost about 280 bytes on Cortex-M4F (matrices are multiplied once per draw).
        for k in 0..core::hint::black_box(16usize) {
            let (i, j) = (k / 4 % 4, k % 4);
            m[i][j] = product_entry(&self.m[i], &o.m, j);
        }
        Mat4 { m }
    }

    /// `self · (p, 1)`: a point to homogeneous coordinates. Each component is an exact sum
    /// rounded once; `None` if any component does not fit in `Fx` (skip the vertex).
    // One out-of-line copy on ARMv6-M, where the split products are long: inlined into
    // every caller they cost flash for no speed.
    #[cfg_attr(all(target_arch = "arm", not(target_has_atomic = "32")), inline(never))]
    pub fn transform_point(&self, p: Vec3) -> Option<Vec4> {
        let r = |i: usize| {
            let row = &self.m[i];
            dot3_plus_fit(
                [row[0].to_bits(), row[1].to_bits(), row[2].to_bits()],
                [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()],
                row[3].to_bits(),
            )
        };
        Some(Vec4::new(r(0)?, r(1)?, r(2)?, r(3)?))
    }

    /// `self · (v, 0)`, first three components: a direction (e.g. a normal under a
    /// rotation-only model-view; general matrices need the inverse transpose). `None` if a
    /// component does not fit in `Fx`.
    // One out-of-line copy on ARMv6-M, where the split products are long: inlined into
    // every caller they cost flash for no speed.
    #[cfg_attr(all(target_arch = "arm", not(target_has_atomic = "32")), inline(never))]
    pub fn transform_vector(&self, v: Vec3) -> Option<Vec3> {
        // As a row plus a zero translation: the same value where it fits, `None` where it
        // does not, and where 64-bit products are single instructions three
        // multiply-accumulates and one rounding (tested against the exact split sums; about
        // 0.3 % of the lit whole-frame sphere on Cortex-M4F, through its normals).
        let r = |i: usize| {
            let row = &self.m[i];
            dot3_plus_fit(
                [row[0].to_bits(), row[1].to_bits(), row[2].to_bits()],
                [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()],
                0,
            )
        };
        Some(Vec3::new(r(0)?, r(1)?, r(2)?))
    }

    /// The transpose (for a pure rotation, its inverse).
    pub const fn transpose(&self) -> Mat4 {
        let a = &self.m;
        Mat4 {
            m: [
                [a[0][0], a[1][0], a[2][0], a[3][0]],
                [a[0][1], a[1][1], a[2][1], a[3][1]],
                [a[0][2], a[1][2], a[2][2], a[3][2]],
                [a[0][3], a[1][3], a[2][3], a[3][3]],
            ],
        }
    }
}

impl Mul for Mat4 {
    type Output = Mat4;
    /// `self · rhs` (applies `rhs` first), saturating; see [`Mat4::mul`].
    fn mul(self, rhs: Mat4) -> Mat4 {
        Mat4::mul(&self, &rhs)
    }
}

/// Entry `j` of `row · b` (one row of [`Mat4::mul`]). Out of line: a product runs once
/// per frame or object, and the sixteen unrolled entries cost about 600 bytes of flash.
#[inline(never)]
fn product_entry(row: &[Fx; 4], b: &[[Fx; 4]; 4], j: usize) -> Fx {
    let col = |k: usize| b[k].get(j).copied().unwrap_or(O);
    saturate(sum_q32([
        prod(row[0], col(0)),
        prod(row[1], col(1)),
        prod(row[2], col(2)),
        prod(row[3], col(3)),
    ]))
}

// Without this impl, `a.mul(&b)` on a by-value `a` would resolve to `Mul<Mat4>::mul`
// (trait methods taking `self` are found before the autoref'd inherent `&self` method)
// and fail to type-check.
impl Mul<&Mat4> for Mat4 {
    type Output = Mat4;
    /// `self · rhs` (applies `rhs` first), saturating; see [`Mat4::mul`].
    fn mul(self, rhs: &Mat4) -> Mat4 {
        Mat4::mul(&self, rhs)
    }
}

impl Mul<&Mat4> for &Mat4 {
    type Output = Mat4;
    /// `self · rhs` (applies `rhs` first), saturating; see [`Mat4::mul`].
    fn mul(self, rhs: &Mat4) -> Mat4 {
        Mat4::mul(self, rhs)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use core::f64::consts::PI;

    type M64 = [[f64; 4]; 4];

    fn f(x: Fx) -> f64 {
        x.to_num::<f64>()
    }

    fn fx(x: f64) -> Fx {
        Fx::from_num(x)
    }

    #[allow(clippy::needless_range_loop)]
    fn mul64(a: &M64, b: &M64) -> M64 {
        let mut c = [[0.0; 4]; 4];
        for i in 0..4 {
            for j in 0..4 {
                c[i][j] = (0..4).map(|k| a[i][k] * b[k][j]).sum();
            }
        }
        c
    }

    fn rx64(t: f64) -> M64 {
        let (s, c) = t.sin_cos();
        [
            [1., 0., 0., 0.],
            [0., c, -s, 0.],
            [0., s, c, 0.],
            [0., 0., 0., 1.],
        ]
    }

    fn ry64(t: f64) -> M64 {
        let (s, c) = t.sin_cos();
        [
            [c, 0., s, 0.],
            [0., 1., 0., 0.],
            [-s, 0., c, 0.],
            [0., 0., 0., 1.],
        ]
    }

    fn rz64(t: f64) -> M64 {
        let (s, c) = t.sin_cos();
        [
            [c, -s, 0., 0.],
            [s, c, 0., 0.],
            [0., 0., 1., 0.],
            [0., 0., 0., 1.],
        ]
    }

    /// Max abs difference between a Mat4 and an f64 matrix.
    #[allow(clippy::needless_range_loop)]
    fn max_err(m: &Mat4, r: &M64) -> f64 {
        let mut e = 0.0f64;
        for i in 0..4 {
            for j in 0..4 {
                e = e.max((f(m.m[i][j]) - r[i][j]).abs());
            }
        }
        e
    }

    fn angle_rad(a: Angle) -> f64 {
        f64::from(a.0) * 2.0 * PI / 65536.0
    }

    #[test]
    #[allow(clippy::op_ref)] // exercising the by-reference operator on purpose
    fn basic_transforms() {
        let p = Vec3::from_num(1, 2, 3);
        assert_eq!(Mat4::IDENTITY.transform_point(p), Some(p.extend(Fx::ONE)));
        assert_eq!(Mat4::default(), Mat4::IDENTITY);
        let t = Mat4::translation(Vec3::from_num(10, 20, 30));
        assert_eq!(
            t.transform_point(p).map(Vec4::xyz),
            Some(Vec3::from_num(11, 22, 33))
        );
        assert_eq!(t.transform_vector(p), Some(p));
        let s = Mat4::scaling(Vec3::from_num(2, 3, 4));
        assert_eq!(
            s.transform_point(p).map(Vec4::xyz),
            Some(Vec3::from_num(2, 6, 12))
        );
        // A * B applies B first: scale, then translate.
        assert_eq!(
            (t * s).transform_point(p).map(Vec4::xyz),
            Some(Vec3::from_num(12, 26, 42))
        );
        assert_eq!(&t * &s, t.mul(&s));
        assert_eq!(t.transpose().transpose(), t);
        assert_eq!(t.transpose().m[3][0], Fx::from_num(10));
        // Right-handed quarter turns.
        let q = Angle::QUARTER_TURN;
        let (x, y, z) = (
            Vec3::from_num(1, 0, 0),
            Vec3::from_num(0, 1, 0),
            Vec3::from_num(0, 0, 1),
        );
        assert_eq!(Mat4::rotation_z(q).transform_vector(x), Some(y));
        assert_eq!(Mat4::rotation_x(q).transform_vector(y), Some(z));
        assert_eq!(Mat4::rotation_y(q).transform_vector(z), Some(x));
        // Overflow: None, not garbage.
        let big = Mat4::scaling(Vec3::from_num(30000, 1, 1));
        assert_eq!(big.transform_point(Vec3::from_num(2, 0, 0)), None);
        assert_eq!(big.transform_vector(Vec3::from_num(2, 0, 0)), None);
        assert_eq!((big * big).m[0][0], Fx::MAX);
        let huge = Mat4::from_rows([[Fx::MIN; 4]; 4]);
        assert_eq!((huge * huge).m[2][1], Fx::MAX);
        assert_eq!(
            huge.transform_point(Vec3::ZERO),
            Some(Vec4::new(Fx::MIN, Fx::MIN, Fx::MIN, Fx::MIN))
        );
    }

    #[test]
    fn rotations_against_f64() {
        let mut worst = 0.0f64;
        for n in (0..=u16::MAX).step_by(97) {
            let a = Angle(n);
            let t = angle_rad(a);
            worst = worst
                .max(max_err(&Mat4::rotation_x(a), &rx64(t)))
                .max(max_err(&Mat4::rotation_y(a), &ry64(t)))
                .max(max_err(&Mat4::rotation_z(a), &rz64(t)));
        }
        assert!(worst <= 2f64.powi(-16), "{worst}");
    }

    #[test]
    fn benchmark_model_matrix() {
        // 0.7 rad about y, then 0.3 rad about x: model = Rx * Ry.
        let (ay, ax) = (Angle::from_radians(fx(0.7)), Angle::from_radians(fx(0.3)));
        let model = Mat4::rotation_x(ax) * Mat4::rotation_y(ay);
        let exact = mul64(&rx64(0.3), &ry64(0.7));
        let quantised = mul64(&rx64(angle_rad(ax)), &ry64(angle_rad(ay)));
        let (e1, e2) = (max_err(&model, &exact), max_err(&model, &quantised));
        std::println!("Rx(0.3)*Ry(0.7): err vs exact angles {e1:e}, vs quantised angles {e2:e}");
        assert!(e1 <= 2f64.powi(-14));
        assert!(e2 <= 2f64.powi(-15));
        // Transforming a point agrees with f64 too.
        let p = Vec3::from_num(1.5, -2.25, 0.75);
        let q = model.transform_point(p).unwrap();
        let pf = [1.5, -2.25, 0.75, 1.0];
        for (i, got) in [q.x, q.y, q.z, q.w].into_iter().enumerate() {
            let want: f64 = (0..4).map(|k| exact[i][k] * pf[k]).sum();
            assert!((f(got) - want).abs() <= 2f64.powi(-13));
        }
    }

    fn persp64(fovy: f64, aspect: f64, near: f64, far: f64) -> M64 {
        let f = 1.0 / (fovy / 2.0).tan();
        [
            [f / aspect, 0., 0., 0.],
            [0., f, 0., 0.],
            [
                0.,
                0.,
                (far + near) / (near - far),
                2. * far * near / (near - far),
            ],
            [0., 0., -1., 0.],
        ]
    }

    #[test]
    fn perspective_against_f64() {
        let fovy = Angle::from_degrees(fx(45.0));
        assert_eq!(fovy, Angle(8192));
        for (near, far) in [(0.5, 20.0), (0.5, 200.0), (0.01, 30000.0), (1.0, 1.5)] {
            let m = Mat4::perspective(fovy, fx(4.0 / 3.0), fx(near), fx(far)).unwrap();
            let e1 = max_err(&m, &persp64(PI / 4.0, 4.0 / 3.0, near, far));
            let e2 = max_err(
                &m,
                &persp64(PI / 4.0, f(fx(4.0 / 3.0)), f(fx(near)), f(fx(far))),
            );
            std::println!("perspective(45°, 4/3, {near}, {far}): err {e1:e} (exact inputs), {e2:e} (quantised inputs)");
            if near >= 0.5 {
                assert!(e1 <= 2f64.powi(-14));
            }
            assert!(e2 <= 2f64.powi(-16));
        }
        // Odd fovy and extremes. The Q2.30 sine limits the relative accuracy of
        // cot(fovy/2) to about 2^-30 / sin(fovy/2): one ulp down to fovy ≈ 1°, and still
        // about 3e-6 relative at the narrowest fovy (one unit, f ≈ 20861).
        for n in [1u16, 3, 100, 182, 1000, 8191, 20000, 32767] {
            let a = Angle(n);
            let h = angle_rad(a) / 2.0;
            let m = Mat4::perspective(a, fx(1.0), fx(1.0), fx(2.0)).unwrap();
            let e = max_err(&m, &persp64(angle_rad(a), 1.0, 1.0, 2.0));
            let tol = 2f64.powi(-16) + 2f64.powi(-29) / h.sin() / h.tan();
            assert!(e <= tol, "n={n} e={e} tol={tol}");
            if n >= 182 {
                assert!(e <= 2f64.powi(-16), "n={n} e={e}");
            }
        }
    }

    #[test]
    fn perspective_refusals() {
        let p = |fovy: u16, aspect: f64, near: f64, far: f64| {
            Mat4::perspective(Angle(fovy), fx(aspect), fx(near), fx(far))
        };
        let bad = |r: Result<Mat4, Error>| matches!(r, Err(Error::BadProjection(_)));
        assert!(bad(p(8192, 1.0, 0.0, 10.0)));
        assert!(bad(p(8192, 1.0, -1.0, 10.0)));
        assert!(bad(p(8192, 1.0, 2.0, 2.0)));
        assert!(bad(p(8192, 1.0, 2.0, 1.0)));
        assert!(bad(p(0, 1.0, 1.0, 10.0)));
        assert!(bad(p(32768, 1.0, 1.0, 10.0)));
        assert!(bad(p(40000, 1.0, 1.0, 10.0)));
        assert!(bad(p(8192, 0.0, 1.0, 10.0)));
        assert!(bad(p(8192, -1.0, 1.0, 10.0)));
        // Entries overflowing: tiny aspect, near ~ far at large distance.
        assert!(bad(p(8192, 1.0 / 65536.0, 1.0, 10.0)));
        assert!(bad(Mat4::perspective(
            Angle(8192),
            Fx::ONE,
            Fx::from_num(30000),
            Fx::from_num(30000) + Fx::from_bits(1)
        )));
        assert!(p(1, 1.0, 1.0, 10.0).is_ok());
        assert!(p(32767, 1.0, 1.0, 10.0).is_ok());
    }

    fn look_at64(eye: [f64; 3], target: [f64; 3], up: [f64; 3]) -> M64 {
        let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        let norm = |a: [f64; 3]| {
            let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
            [a[0] / l, a[1] / l, a[2] / l]
        };
        let cross = |a: [f64; 3], b: [f64; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let fw = norm(sub(target, eye));
        let s = norm(cross(fw, up));
        let u = cross(s, fw);
        [
            [s[0], s[1], s[2], -dot(s, eye)],
            [u[0], u[1], u[2], -dot(u, eye)],
            [-fw[0], -fw[1], -fw[2], dot(fw, eye)],
            [0., 0., 0., 1.],
        ]
    }

    #[test]
    fn look_at_against_f64() {
        let v = |a: [f64; 3]| Vec3::from_num(a[0], a[1], a[2]);
        let m = Mat4::look_at(v([0., 0., 5.]), Vec3::ZERO, v([0., 1., 0.])).unwrap();
        assert_eq!(m, Mat4::translation(v([0., 0., -5.])));
        let cases = [
            ([3., 2., 5.], [0., 0., 0.], [0., 1., 0.]),
            ([-1., 4., 0.5], [2., -1., 3.], [0.2, 1., -0.1]),
            ([100., 50., -20.], [0., 0., 0.], [0., 0., 1.]),
        ];
        for (eye, target, up) in cases {
            let m = Mat4::look_at(v(eye), v(target), v(up)).unwrap();
            let r = look_at64(eye, target, up);
            let scale = 1.0 + eye.iter().map(|c: &f64| c.abs()).sum::<f64>();
            let e = max_err(&m, &r);
            assert!(e <= scale * 2f64.powi(-14), "{eye:?}: {e}");
            // The eye maps to the origin and the target onto -z.
            let o = m.transform_point(v(eye)).unwrap();
            assert!(f(o.x).abs() + f(o.y).abs() + f(o.z).abs() <= scale * 2f64.powi(-13));
            let t = m.transform_point(v(target)).unwrap();
            assert!(f(t.z) < 0.0 && f(t.x).abs() < 1e-3 && f(t.y).abs() < 1e-3);
        }
        let bad = |r: Result<Mat4, Error>| matches!(r, Err(Error::BadProjection(_)));
        let e = v([1., 2., 3.]);
        assert!(bad(Mat4::look_at(e, e, v([0., 1., 0.]))));
        assert!(bad(Mat4::look_at(e, Vec3::ZERO, Vec3::ZERO)));
        assert!(bad(Mat4::look_at(e, Vec3::ZERO, v([2., 4., 6.]))));
        assert!(bad(Mat4::look_at(e, Vec3::ZERO, v([-1., -2., -3.]))));
        let far = Vec3::new(Fx::MAX, Fx::ZERO, Fx::ZERO);
        assert!(bad(Mat4::look_at(far, -far, v([0., 1., 0.]))));
    }

    /// `transform_vector` gives the exactly rounded row sums (`sum_q32` of the exact
    /// products) where they fit `Fx` and `None` where they do not, on random, extreme and
    /// overflowing operands.
    #[test]
    fn transform_vector_is_the_exact_row_sum() {
        let mut rng = crate::test_rng::Rng(0x7e57_0001);
        // Every other case in normal ranges (below 8 in magnitude), the rest anywhere.
        let pick = |r: u64, small: bool| -> i32 {
            if small {
                return ((r >> 8) as i32) >> (12 + r % 8);
            }
            match r % 5 {
                0 => i32::MIN,
                1 => i32::MAX,
                2 => (r >> 8) as i32 >> (r % 31),
                3 => ((r >> 8) as i32 % (1 << 17)) - (1 << 16),
                _ => (r >> 16) as i32,
            }
        };
        let mut fits = [0u32; 2];
        for n in 0..50_000 {
            let small = n % 2 == 0;
            let mut m = Mat4::IDENTITY;
            for row in m.m.iter_mut() {
                for e in row.iter_mut() {
                    *e = Fx::from_bits(pick(rng.next(), small));
                }
            }
            let v = Vec3::new(
                Fx::from_bits(pick(rng.next(), small)),
                Fx::from_bits(pick(rng.next(), small)),
                Fx::from_bits(pick(rng.next(), small)),
            );
            let exact = |i: usize| {
                let p = |k: usize, x: Fx| prod(m.m[i][k], x);
                let bits = sum_q32([p(0, v.x), p(1, v.y), p(2, v.z)]);
                i32::try_from(bits).ok().map(Fx::from_bits)
            };
            let want = (|| Some(Vec3::new(exact(0)?, exact(1)?, exact(2)?)))();
            assert_eq!(m.transform_vector(v), want);
            fits[usize::from(want.is_some())] += 1;
        }
        assert!(fits[0] > 1000 && fits[1] > 1000, "{fits:?}");
    }
}
