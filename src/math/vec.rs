//! 3- and 4-component vectors of [`Fx`] (I16F16: ±32768, resolution 2^-16).
//!
//! Nothing here panics. Component-wise `add`, `sub`, `neg` and `scale` saturate at the
//! `Fx` range (as do the `+`, `-` and unary `-` operators, unlike `fixed`'s own operators,
//! which panic on overflow in debug builds). Products are exact Q32 `i64` values summed
//! without overflow (see the `acc` module) and rounded once to Q16 (half up), so
//! [`Vec3::dot`] and [`Vec3::cross`] are correctly rounded before they saturate.
//!
//! [`Vec3::length_squared_bits`] is returned as raw Q32 bits in a `u64` (up to 3·2^62), so
//! it never overflows. [`Vec3::normalize`] scales that to a full 64-bit mantissa before the
//! integer square root and uses the division-free reciprocal, so unit vectors are accurate
//! to about half an ulp (2^-17) per component for any non-zero input, relative to the
//! exact direction of the (already quantised) input.

use super::acc::{dot3_q16_shared, fit, prod, saturate, sum_q32};
use super::recip::{isqrt_u64, reciprocal_u32};
use super::Fx;
use core::ops::{Add, Neg, Sub};
use fixed::traits::ToFixed;

/// A 3-vector of [`Fx`]: a point or direction in model, world or view space.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Vec3 {
    /// X component.
    pub x: Fx,
    /// Y component.
    pub y: Fx,
    /// Z component.
    pub z: Fx,
}

/// A 4-vector of [`Fx`]: a homogeneous point, e.g. in clip space.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Vec4 {
    /// X component.
    pub x: Fx,
    /// Y component.
    pub y: Fx,
    /// Z component.
    pub z: Fx,
    /// W component.
    pub w: Fx,
}

// The inherent `add`/`sub`/`neg` are `const` (usable in constant tables); the operator
// traits below call them.
#[allow(clippy::should_implement_trait)]
impl Vec3 {
    /// The zero vector.
    pub const ZERO: Vec3 = Vec3::new(Fx::ZERO, Fx::ZERO, Fx::ZERO);

    /// A vector from its components.
    pub const fn new(x: Fx, y: Fx, z: Fx) -> Vec3 {
        Vec3 { x, y, z }
    }

    /// A vector from raw I16F16 bits (value = bits / 65536).
    pub const fn from_bits(x: i32, y: i32, z: i32) -> Vec3 {
        Vec3::new(Fx::from_bits(x), Fx::from_bits(y), Fx::from_bits(z))
    }

    /// A vector from any numbers `fixed` can convert (integers, fixed-point, and floats in
    /// host code; the three may be of different types), saturating each component to the
    /// `Fx` range as [`fx`](super::fx) does; NaN becomes zero, so this never panics. Not
    /// `const` (trait-generic): use [`Vec3::from_bits`] in `const` contexts.
    ///
    /// ```
    /// use fixel::math::{Fx, Vec3};
    /// assert_eq!(Vec3::from_num(1, 0.5f32, -2i64), Vec3::from_bits(65536, 32768, -131072));
    /// assert_eq!(Vec3::from_num(40000, f32::NAN, 0).x, Fx::MAX); // saturates, NaN is 0
    /// ```
    pub fn from_num<X, Y, Z>(x: X, y: Y, z: Z) -> Vec3
    where
        X: ToFixed + Copy + PartialOrd,
        Y: ToFixed + Copy + PartialOrd,
        Z: ToFixed + Copy + PartialOrd,
    {
        Vec3::new(super::fx(x), super::fx(y), super::fx(z))
    }

    /// Component-wise sum, saturating.
    pub const fn add(self, o: Vec3) -> Vec3 {
        Vec3::new(
            self.x.saturating_add(o.x),
            self.y.saturating_add(o.y),
            self.z.saturating_add(o.z),
        )
    }

    /// Component-wise difference, saturating.
    pub const fn sub(self, o: Vec3) -> Vec3 {
        Vec3::new(
            self.x.saturating_sub(o.x),
            self.y.saturating_sub(o.y),
            self.z.saturating_sub(o.z),
        )
    }

    /// Negation, saturating (`-Fx::MIN` becomes `Fx::MAX`).
    pub const fn neg(self) -> Vec3 {
        Vec3::new(
            self.x.saturating_neg(),
            self.y.saturating_neg(),
            self.z.saturating_neg(),
        )
    }

    /// Component-wise difference, or `None` if any component overflows.
    pub fn checked_sub(self, o: Vec3) -> Option<Vec3> {
        Some(Vec3::new(
            self.x.checked_sub(o.x)?,
            self.y.checked_sub(o.y)?,
            self.z.checked_sub(o.z)?,
        ))
    }

    /// Multiplies every component by `s`, rounded to nearest and saturating.
    pub fn scale(self, s: Fx) -> Vec3 {
        let m = |c: Fx| saturate(sum_q32([prod(c, s)]));
        Vec3::new(m(self.x), m(self.y), m(self.z))
    }

    /// Dot product, exact then rounded once, saturating.
    pub fn dot(self, o: Vec3) -> Fx {
        saturate(self.dot_bits(o))
    }

    /// Dot product, exact then rounded once; `None` if it does not fit in `Fx`.
    pub fn checked_dot(self, o: Vec3) -> Option<Fx> {
        fit(self.dot_bits(o))
    }

    fn dot_bits(self, o: Vec3) -> i64 {
        dot3_q16_shared(
            [self.x.to_bits(), self.y.to_bits(), self.z.to_bits()],
            [o.x.to_bits(), o.y.to_bits(), o.z.to_bits()],
        )
    }

    /// Cross product (right-handed: `x × y = z`), each component exact then rounded once,
    /// saturating.
    pub fn cross(self, o: Vec3) -> Vec3 {
        let (a, b) = (self, o);
        Vec3::new(
            saturate(sum_q32([prod(a.y, b.z), -prod(a.z, b.y)])),
            saturate(sum_q32([prod(a.z, b.x), -prod(a.x, b.z)])),
            saturate(sum_q32([prod(a.x, b.y), -prod(a.y, b.x)])),
        )
    }

    /// `x² + y² + z²` as exact Q32 bits (value = bits / 2^32); at most 3·2^62, no overflow.
    pub fn length_squared_bits(self) -> u64 {
        let sq = |c: Fx| {
            let a = c.to_bits().unsigned_abs();
            super::wide::mul_wide(a, a)
        };
        sq(self.x) + sq(self.y) + sq(self.z)
    }

    /// Euclidean length, rounded down to `Fx`, saturating at `Fx::MAX` (only possible for
    /// lengths of 32768 or more).
    pub fn length(self) -> Fx {
        let l = isqrt_u64(self.length_squared_bits());
        Fx::from_bits(i32::try_from(l).unwrap_or(i32::MAX))
    }

    /// The unit vector in the direction of `self`, or `None` for the zero vector.
    ///
    /// Each component is within about 2^-17 (half an ulp) of the exact direction of the
    /// input, for any non-zero input (lengths from 2^-16 to 2^15·√3).
    pub fn normalize(self) -> Option<Vec3> {
        let l2 = self.length_squared_bits();
        if l2 == 0 {
            return None;
        }
        // Scale by an even power of two so the root has a full 32-bit mantissa:
        // s = floor(|v| · 2^16 · 2^half) in [2^31, 2^32).
        let shift = l2.leading_zeros() & !1;
        let half = shift / 2;
        let s = isqrt_u64(l2 << shift);
        let (m, e) = reciprocal_u32(s);
        // c / |v| in Q16 = c_bits · 2^(16 + half) / s ≈ c_bits · m / 2^(e - 16 - half).
        // e >= 62 and half <= 31, so the shift is at least 15.
        let sh = e - 16 - half;
        let unit = |c: Fx| {
            let mag = u64::from(c.to_bits().unsigned_abs()) * u64::from(m);
            let mag = ((mag + (1 << (sh - 1))) >> sh).min(1 << 16) as i32;
            Fx::from_bits(if c < Fx::ZERO { -mag } else { mag })
        };
        Some(Vec3::new(unit(self.x), unit(self.y), unit(self.z)))
    }

    /// The homogeneous 4-vector `(x, y, z, w)`.
    pub const fn extend(self, w: Fx) -> Vec4 {
        Vec4::new(self.x, self.y, self.z, w)
    }
}

#[allow(clippy::should_implement_trait)]
impl Vec4 {
    /// The zero vector.
    pub const ZERO: Vec4 = Vec4::new(Fx::ZERO, Fx::ZERO, Fx::ZERO, Fx::ZERO);

    /// A vector from its components.
    pub const fn new(x: Fx, y: Fx, z: Fx, w: Fx) -> Vec4 {
        Vec4 { x, y, z, w }
    }

    /// A vector from raw I16F16 bits (value = bits / 65536).
    pub const fn from_bits(x: i32, y: i32, z: i32, w: i32) -> Vec4 {
        Vec4::new(
            Fx::from_bits(x),
            Fx::from_bits(y),
            Fx::from_bits(z),
            Fx::from_bits(w),
        )
    }

    /// The first three components (no division by `w`).
    pub const fn xyz(self) -> Vec3 {
        Vec3::new(self.x, self.y, self.z)
    }

    /// Component-wise sum, saturating.
    pub const fn add(self, o: Vec4) -> Vec4 {
        Vec4::new(
            self.x.saturating_add(o.x),
            self.y.saturating_add(o.y),
            self.z.saturating_add(o.z),
            self.w.saturating_add(o.w),
        )
    }

    /// Component-wise difference, saturating.
    pub const fn sub(self, o: Vec4) -> Vec4 {
        Vec4::new(
            self.x.saturating_sub(o.x),
            self.y.saturating_sub(o.y),
            self.z.saturating_sub(o.z),
            self.w.saturating_sub(o.w),
        )
    }

    /// Negation, saturating.
    pub const fn neg(self) -> Vec4 {
        Vec4::new(
            self.x.saturating_neg(),
            self.y.saturating_neg(),
            self.z.saturating_neg(),
            self.w.saturating_neg(),
        )
    }

    /// 4-component dot product, exact then rounded once, saturating.
    pub fn dot(self, o: Vec4) -> Fx {
        saturate(sum_q32([
            prod(self.x, o.x),
            prod(self.y, o.y),
            prod(self.z, o.z),
            prod(self.w, o.w),
        ]))
    }
}

/// Saturating conversion; NaN (the only value not equal to itself) becomes zero, because
/// `fixed`'s saturating conversion panics on NaN.
impl Add for Vec3 {
    type Output = Vec3;
    /// Saturating (see [`Vec3::add`]).
    fn add(self, o: Vec3) -> Vec3 {
        Vec3::add(self, o)
    }
}

impl Sub for Vec3 {
    type Output = Vec3;
    /// Saturating (see [`Vec3::sub`]).
    fn sub(self, o: Vec3) -> Vec3 {
        Vec3::sub(self, o)
    }
}

impl Neg for Vec3 {
    type Output = Vec3;
    /// Saturating (see [`Vec3::neg`]).
    fn neg(self) -> Vec3 {
        Vec3::neg(self)
    }
}

impl Add for Vec4 {
    type Output = Vec4;
    /// Saturating (see [`Vec4::add`]).
    fn add(self, o: Vec4) -> Vec4 {
        Vec4::add(self, o)
    }
}

impl Sub for Vec4 {
    type Output = Vec4;
    /// Saturating (see [`Vec4::sub`]).
    fn sub(self, o: Vec4) -> Vec4 {
        Vec4::sub(self, o)
    }
}

impl Neg for Vec4 {
    type Output = Vec4;
    /// Saturating (see [`Vec4::neg`]).
    fn neg(self) -> Vec4 {
        Vec4::neg(self)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    fn f(x: Fx) -> f64 {
        x.to_num::<f64>()
    }

    use crate::test_rng::Rng;

    /// Uniform in [-1, 1).
    fn unit(rng: &mut Rng) -> f64 {
        2.0 * rng.unit01() - 1.0
    }

    #[test]
    fn saturating_ops() {
        let big = Vec3::new(Fx::MAX, Fx::MIN, Fx::ONE);
        assert_eq!(big + big, Vec3::new(Fx::MAX, Fx::MIN, Fx::from_num(2)));
        assert_eq!(-big, Vec3::new(-Fx::MAX, Fx::MAX, -Fx::ONE));
        assert_eq!(big - (-big), Vec3::new(Fx::MAX, Fx::MIN, Fx::from_num(2)));
        assert_eq!(big.scale(Fx::from_num(2)).x, Fx::MAX);
        assert_eq!(big.dot(big), Fx::MAX);
        assert_eq!(big.checked_dot(big), None);
        assert_eq!(big.length(), Fx::MAX);
        assert_eq!(big.checked_sub(-big), None);
        let v = Vec3::from_num(1, 2, 3);
        assert_eq!(v.scale(Fx::from_num(0.5)), Vec3::from_num(0.5, 1.0, 1.5));
        assert_eq!(v.dot(v), Fx::from_num(14));
        assert_eq!(v.length_squared_bits(), 14 << 32);
        assert_eq!(Vec3::from_bits(1 << 16, 0, 0), Vec3::from_num(1, 0, 0));
        assert_eq!(
            Vec3::from_num(1e9, -1e9, f64::NAN),
            Vec3::new(Fx::MAX, Fx::MIN, Fx::ZERO)
        );
        let w = v.extend(Fx::ONE);
        assert_eq!(w.xyz(), v);
        assert_eq!(w + w, Vec4::from_num_test(2, 4, 6, 2));
        assert_eq!(-w - w, Vec4::from_num_test(-2, -4, -6, -2));
        assert_eq!(w.dot(w), Fx::from_num(15));
    }

    impl Vec4 {
        fn from_num_test(x: i32, y: i32, z: i32, w: i32) -> Vec4 {
            Vec4::from_bits(x << 16, y << 16, z << 16, w << 16)
        }
    }

    #[test]
    fn cross_and_dot_against_f64() {
        let x = Vec3::from_num(1, 0, 0);
        let y = Vec3::from_num(0, 1, 0);
        assert_eq!(x.cross(y), Vec3::from_num(0, 0, 1));
        assert_eq!(y.cross(x), Vec3::from_num(0, 0, -1));
        let mut rng = Rng(0x5eed);
        for _ in 0..50_000 {
            let s = 2f64.powi((rng.next() % 14) as i32);
            let a = Vec3::from_num(unit(&mut rng) * s, unit(&mut rng) * s, unit(&mut rng) * s);
            let b = Vec3::from_num(unit(&mut rng) * s, unit(&mut rng) * s, unit(&mut rng) * s);
            let (ax, ay, az, bx, by, bz) = (f(a.x), f(a.y), f(a.z), f(b.x), f(b.y), f(b.z));
            let c = a.cross(b);
            let ulp = 2f64.powi(-16);
            let ok = |got: Fx, want: f64| {
                let want = want.clamp(f(Fx::MIN), f(Fx::MAX));
                (f(got) - want).abs() <= ulp / 2.0 + 1e-12
            };
            assert!(ok(c.x, ay * bz - az * by));
            assert!(ok(c.y, az * bx - ax * bz));
            assert!(ok(c.z, ax * by - ay * bx));
            assert!(ok(a.dot(b), ax * bx + ay * by + az * bz));
        }
    }

    #[test]
    fn normalize_accuracy() {
        assert_eq!(Vec3::ZERO.normalize(), None);
        assert_eq!(
            Vec3::from_num(0, -5, 0).normalize(),
            Some(Vec3::from_num(0, -1, 0))
        );
        assert_eq!(
            Vec3::new(Fx::MIN, Fx::ZERO, Fx::ZERO).normalize(),
            Some(Vec3::from_num(-1, 0, 0))
        );
        assert!(Vec3::new(Fx::MIN, Fx::MIN, Fx::MIN).normalize().is_some());
        assert!(Vec3::from_bits(1, 0, 0).normalize() == Some(Vec3::from_num(1, 0, 0)));
        let mut rng = Rng(0xabcdef);
        let mut worst = 0.0f64;
        for k in 0..200_000 {
            // Lengths from 2^-8 to 2^14 (as asked), plus a few extremes.
            let e = match k % 100 {
                0 => -16,
                1 => 15,
                _ => (k % 23) - 8,
            };
            let l = 2f64.powi(e);
            let v = Vec3::from_num(unit(&mut rng) * l, unit(&mut rng) * l, unit(&mut rng) * l);
            let (x, y, z) = (f(v.x), f(v.y), f(v.z));
            let len = (x * x + y * y + z * z).sqrt();
            match v.normalize() {
                None => assert_eq!(len, 0.0),
                Some(n) => {
                    for (got, c) in [(n.x, x), (n.y, y), (n.z, z)] {
                        worst = worst.max((f(got) - c / len).abs());
                    }
                }
            }
        }
        std::println!(
            "normalize max abs err per component = {worst:e} = 2^{:.2}",
            worst.log2()
        );
        assert!(worst <= 2f64.powi(-16));
    }
}
