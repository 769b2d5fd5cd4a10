//! Binary angles and table-based sine/cosine/tangent.
//!
//! An [`Angle`] is a `u16` fraction of a turn (65536 = 360° = 2π rad), so addition and
//! negation wrap for free and every `u16` is a valid angle; resolution is 2π/65536 ≈
//! 9.6e-5 rad ≈ 0.0055°.
//!
//! Sine and cosine come from a quarter-wave table of `sin(i·π/512)`, `i = 0..=256`, in
//! Q2.30 (`u32`, 1028 bytes of flash). Between entries, instead of linear interpolation
//! (whose error, ~h²/8 ≈ 2^-17.7, would eat the whole I16F16 error budget), the angle
//! addition formulas are used with the offset `d < π/512`: `sin d ≈ d - d³/6` and
//! `cos d ≈ 1 - d²/2` (both better than 2^-33). The table gives both `sin(a)` and
//! `cos(a) = sin(π/2 - a)`, so one evaluation costs two table reads and a handful of
//! `u64` multiplies. Internally results are Q2.30 (error a few 2^-30), which [`Mat4`]
//! uses for `cot` in the projection; the public [`sin_cos`] rounds them to `Fx`
//! (I16F16), max abs error ≈ 2^-17 (half an ulp, measured over all 65536 angles).
//!
//! [`Mat4`]: super::Mat4

use super::recip::{div_round, signed_fx};
use super::Fx;
use core::ops::{Add, Neg, Sub};

/// `round(sin(i·π/512)·2^30)` for `i = 0..=256` (a quarter wave, Q2.30).
const SIN_Q30: [u32; 257] = [
    0, 6588356, 13176464, 19764076, 26350943, 32936819, 39521455, 46104602, 52686014, 59265442,
    65842639, 72417357, 78989349, 85558366, 92124163, 98686491, 105245103, 111799753, 118350194,
    124896179, 131437462, 137973796, 144504935, 151030634, 157550647, 164064728, 170572633,
    177074115, 183568930, 190056834, 196537583, 203010932, 209476638, 215934457, 222384147,
    228825464, 235258165, 241682010, 248096755, 254502159, 260897982, 267283981, 273659918,
    280025552, 286380643, 292724951, 299058239, 305380268, 311690799, 317989595, 324276419,
    330551034, 336813204, 343062693, 349299266, 355522689, 361732726, 367929144, 374111709,
    380280190, 386434353, 392573967, 398698801, 404808624, 410903207, 416982319, 423045732,
    429093217, 435124548, 441139496, 447137835, 453119340, 459083786, 465030947, 470960600,
    476872522, 482766489, 488642281, 494499676, 500338453, 506158392, 511959275, 517740883,
    523502998, 529245404, 534967884, 540670223, 546352205, 552013618, 557654248, 563273883,
    568872310, 574449320, 580004702, 585538248, 591049748, 596538995, 602005783, 607449906,
    612871159, 618269338, 623644239, 628995660, 634323400, 639627258, 644907034, 650162530,
    655393548, 660599890, 665781362, 670937767, 676068911, 681174602, 686254647, 691308855,
    696337036, 701339000, 706314559, 711263525, 716185713, 721080937, 725949013, 730789757,
    735602987, 740388522, 745146182, 749875788, 754577161, 759250125, 763894504, 768510122,
    773096806, 777654384, 782182683, 786681534, 791150767, 795590213, 799999706, 804379079,
    808728167, 813046808, 817334838, 821592095, 825818421, 830013654, 834177638, 838310216,
    842411232, 846480531, 850517961, 854523370, 858496606, 862437520, 866345964, 870221790,
    874064853, 877875009, 881652112, 885396022, 889106597, 892783698, 896427186, 900036924,
    903612776, 907154608, 910662286, 914135678, 917574653, 920979082, 924348837, 927683790,
    930983817, 934248793, 937478595, 940673101, 943832191, 946955747, 950043650, 953095785,
    956112036, 959092290, 962036435, 964944360, 967815955, 970651112, 973449725, 976211688,
    978936898, 981625251, 984276646, 986890984, 989468165, 992008094, 994510675, 996975812,
    999403415, 1001793390, 1004145648, 1006460100, 1008736660, 1010975242, 1013175761, 1015338134,
    1017462281, 1019548121, 1021595575, 1023604567, 1025575020, 1027506862, 1029400018, 1031254418,
    1033069992, 1034846671, 1036584389, 1038283080, 1039942680, 1041563127, 1043144360, 1044686319,
    1046188946, 1047652185, 1049075980, 1050460278, 1051805027, 1053110176, 1054375676, 1055601479,
    1056787540, 1057933813, 1059040255, 1060106826, 1061133483, 1062120190, 1063066909, 1063973603,
    1064840240, 1065666786, 1066453210, 1067199483, 1067905576, 1068571464, 1069197120, 1069782521,
    1070327646, 1070832474, 1071296985, 1071721163, 1072104991, 1072448455, 1072751542, 1073014240,
    1073236540, 1073418433, 1073559913, 1073660973, 1073721611, 1073741824,
];

/// `round(2π·2^29)`: radians per 2^-32 turn, in Q32 after a right shift by 29.
const TWO_PI_Q29: u64 = 3_373_259_426;
/// `round(2^48 / 2π)`: `Fx` radian bits to angle units, times 2^32.
const TURNS_PER_RADIAN_Q48: i64 = 44_798_133_900_177;
/// `round(2^48 / 360)`: `Fx` degree bits to angle units, times 2^32.
const TURNS_PER_DEGREE_Q48: i64 = 781_874_935_307;

/// A binary angle: `Angle(n)` is `n / 65536` of a full turn (`n · 2π / 65536` rad).
///
/// Arithmetic (`+`, `-`, unary `-`) wraps around the circle, which is exact.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Angle(pub u16);

impl Angle {
    /// Zero.
    pub const ZERO: Angle = Angle(0);
    /// 90° (π/2).
    pub const QUARTER_TURN: Angle = Angle(1 << 14);
    /// 180° (π).
    pub const HALF_TURN: Angle = Angle(1 << 15);

    /// An angle of `t / 65536` turns (the same as `Angle(t)`).
    pub const fn from_turns(t: u16) -> Angle {
        Angle(t)
    }

    /// An angle from radians, rounded to the nearest 1/65536 turn. Any value is accepted
    /// and wraps around the circle; never panics.
    pub const fn from_radians(r: Fx) -> Angle {
        Angle(scale_to_turns(r, TURNS_PER_RADIAN_Q48))
    }

    /// An angle from degrees, rounded to the nearest 1/65536 turn. Any value is accepted
    /// and wraps around the circle; never panics.
    pub const fn from_degrees(d: Fx) -> Angle {
        Angle(scale_to_turns(d, TURNS_PER_DEGREE_Q48))
    }

    /// Sine, max abs error ≈ 2^-17 (see [`sin_cos`]).
    pub fn sin(self) -> Fx {
        sin_cos(self).0
    }

    /// Cosine, max abs error ≈ 2^-17 (see [`sin_cos`]).
    pub fn cos(self) -> Fx {
        sin_cos(self).1
    }

    /// Tangent, or `None` where it does not fit in `Fx` (within about 0.0017° of ±90°).
    ///
    /// Computed as a correctly rounded quotient of the internal Q2.30 sine and cosine, so
    /// the error is about half an ulp plus `(1 + tan²)·2^-29`.
    pub fn tan(self) -> Option<Fx> {
        let (s, c) = sin_cos_q30(u32::from(self.0) << 16);
        let q = div_round(u64::from(s.unsigned_abs()) << 16, c.unsigned_abs());
        signed_fx(q, (s < 0) != (c < 0))
    }
}

impl Add for Angle {
    type Output = Angle;
    /// Wrapping (exact on the circle).
    fn add(self, rhs: Angle) -> Angle {
        Angle(self.0.wrapping_add(rhs.0))
    }
}

impl Sub for Angle {
    type Output = Angle;
    /// Wrapping (exact on the circle).
    fn sub(self, rhs: Angle) -> Angle {
        Angle(self.0.wrapping_sub(rhs.0))
    }
}

impl Neg for Angle {
    type Output = Angle;
    /// Wrapping (exact on the circle).
    fn neg(self) -> Angle {
        Angle(self.0.wrapping_neg())
    }
}

/// `round(x · k / 2^48) mod 2^16`. Only bits 47..63 of the product matter, and those are
/// exact in wrapping 64-bit arithmetic, so the product may wrap freely.
const fn scale_to_turns(x: Fx, k: i64) -> u16 {
    let p = (x.to_bits() as i64).wrapping_mul(k).wrapping_add(1 << 47);
    (p >> 48) as u16
}

/// Sine and cosine of `a`, rounded to `Fx` (I16F16).
///
/// Table lookup plus a short angle-addition correction (see the module docs); max abs
/// error ≈ 2^-17 over all 65536 angles. Exact at multiples of 90°, and
/// `sin² + cos²` is 1 within a couple of ulps.
pub fn sin_cos(a: Angle) -> (Fx, Fx) {
    let t = u32::from(a.0) << 16;
    let (s, c) = quarter_q30(t & ((1 << 30) - 1));
    // Round the (non-negative) magnitudes to Q16 before applying signs, so that the
    // result is exactly odd/even-symmetric.
    let r = |v: u32| Fx::from_bits(((v + (1 << 13)) >> 14) as i32);
    apply_quadrant(t >> 30, r(s), r(c))
}

/// Sine and cosine in Q2.30 (value = bits / 2^30) of an angle in 2^-32 turns.
/// Abs error a few 2^-30.
pub fn sin_cos_q30(t: u32) -> (i32, i32) {
    let (s, c) = quarter_q30(t & ((1 << 30) - 1));
    apply_quadrant(t >> 30, s as i32, c as i32)
}

/// Maps first-quadrant `(sin θ, cos θ)` to `(sin, cos)` of `θ + quadrant·π/2`.
fn apply_quadrant<T: Neg<Output = T>>(quadrant: u32, s: T, c: T) -> (T, T) {
    match quadrant & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// `(sin, cos)` in Q2.30 of `p` 2^-32-turn units, `p < 2^30` (first quadrant).
/// Both results are in [0, 2^30].
fn quarter_q30(p: u32) -> (u32, u32) {
    let i = (p >> 22) as usize; // table cell, 0..=255
    let s = u64::from(SIN_Q30[i]);
    let c = u64::from(SIN_Q30[256 - i]);
    // Offset within the cell in radians, Q32: d < π/512 · 2^32 < 2^24.7.
    let d = (u64::from(p & ((1 << 22) - 1)) * TWO_PI_Q29) >> 29;
    let d2 = (d * d) >> 32; // d², Q32, < 2^17.4
    let d3 = (d2 * d) >> 32; // d³, Q32, < 2^10.1
    let sin_d = d - ((d3 * 0x2AAA_AAAB) >> 32); // d - d³/6
    let cos_d = (1u64 << 32) - (d2 >> 1); // 1 - d²/2
                                          // Q30 · Q32 = Q62; every product < 2^62.
    let sin = (s * cos_d + c * sin_d + (1 << 31)) >> 32;
    let cos = (c * cos_d + (1 << 31)).saturating_sub(s * sin_d) >> 32;
    (sin.min(1 << 30) as u32, cos.min(1 << 30) as u32)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use core::f64::consts::PI;

    fn f(x: Fx) -> f64 {
        x.to_num::<f64>()
    }

    #[test]
    fn sin_cos_all_angles() {
        let mut worst = 0.0f64;
        let mut worst_pyth = 0.0f64;
        for n in 0..=u16::MAX {
            let a = Angle(n);
            let (s, c) = sin_cos(a);
            let x = f64::from(n) * 2.0 * PI / 65536.0;
            worst = worst
                .max((f(s) - x.sin()).abs())
                .max((f(c) - x.cos()).abs());
            worst_pyth = worst_pyth.max((f(s) * f(s) + f(c) * f(c) - 1.0).abs());
            assert_eq!(a.sin(), s);
            assert_eq!(a.cos(), c);
            // Exact symmetry.
            assert_eq!(sin_cos(-a), (-s, c));
        }
        std::println!(
            "sin_cos max abs err = {worst:e} = 2^{:.2}; |s²+c²-1| <= {worst_pyth:e}",
            worst.log2()
        );
        assert!(worst <= 2f64.powi(-14));
        assert!(worst <= 2f64.powi(-16));
        assert_eq!(sin_cos(Angle(0)), (Fx::ZERO, Fx::ONE));
        assert_eq!(sin_cos(Angle::QUARTER_TURN), (Fx::ONE, Fx::ZERO));
        assert_eq!(sin_cos(Angle::HALF_TURN), (Fx::ZERO, -Fx::ONE));
        assert_eq!(sin_cos(Angle(3 << 14)), (-Fx::ONE, Fx::ZERO));
    }

    #[test]
    fn sin_cos_q30_random() {
        let mut worst = 0.0f64;
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        for k in 0..400_000u32 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let t = if k < 1000 { k << 22 } else { (x >> 32) as u32 };
            let (s, c) = sin_cos_q30(t);
            let r = f64::from(t) * 2.0 * PI / 4_294_967_296.0;
            let e = 2f64.powi(30);
            worst = worst
                .max((f64::from(s) - r.sin() * e).abs())
                .max((f64::from(c) - r.cos() * e).abs());
        }
        std::println!("sin_cos_q30 max abs err = {worst:.2} * 2^-30");
        assert!(worst <= 4.0);
    }

    #[test]
    fn conversions() {
        let rad = |x: f64| Angle::from_radians(Fx::from_num(x));
        let deg = |x: f64| Angle::from_degrees(Fx::from_num(x));
        assert_eq!(deg(45.0), Angle(8192));
        assert_eq!(deg(90.0), Angle::QUARTER_TURN);
        assert_eq!(deg(-90.0), Angle(49152));
        assert_eq!(deg(360.0), Angle(0));
        assert_eq!(deg(720.5), deg(0.5));
        assert_eq!(rad(PI), Angle::HALF_TURN);
        assert_eq!(rad(-PI / 2.0), Angle(49152));
        assert_eq!(Angle::from_turns(123), Angle(123));
        // Against f64 over the whole Fx range, including the extremes.
        let mut bits = 0x1234_5678u32;
        for k in 0..200_000 {
            bits ^= bits << 13;
            bits ^= bits >> 17;
            bits ^= bits << 5;
            let b = match k {
                0 => i32::MIN,
                1 => i32::MAX,
                _ => (bits as i32) >> (k % 31),
            };
            let v = f64::from(b) / 65536.0;
            for (got, per_unit) in [
                (Angle::from_radians(Fx::from_bits(b)), 2.0 * PI / 65536.0),
                (Angle::from_degrees(Fx::from_bits(b)), 360.0 / 65536.0),
            ] {
                let want = (v / per_unit).rem_euclid(65536.0);
                let diff = (f64::from(got.0) - want).abs();
                let diff = diff.min(65536.0 - diff);
                assert!(diff <= 0.5 + 1e-3, "b={b} got={} want={want}", got.0);
            }
        }
        assert_eq!(Angle(65535) + Angle(2), Angle(1));
        assert_eq!(Angle(1) - Angle(2), Angle(65535));
    }

    #[test]
    fn tangent() {
        let mut worst = 0.0f64;
        for n in 0..=u16::MAX {
            let x = f64::from(n) * 2.0 * PI / 65536.0;
            let want = x.tan();
            match Angle(n).tan() {
                Some(t) => {
                    let err = (f(t) - want).abs();
                    let allowed = 2f64.powi(-16) + (1.0 + want * want) * 2f64.powi(-28);
                    assert!(err <= allowed, "n={n} got={t} want={want}");
                    if want.abs() < 100.0 {
                        worst = worst.max(err);
                    }
                }
                None => assert!(want.abs() > 32767.0, "n={n} want={want}"),
            }
        }
        std::println!("tan max abs err (|tan| < 100) = {worst:e}");
        assert_eq!(Angle::QUARTER_TURN.tan(), None);
        assert_eq!(Angle(8192).tan(), Some(Fx::ONE));
    }
}
