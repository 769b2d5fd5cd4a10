//! Fixed-point math: the geometry scalar [`Fx`], angles and trigonometry, division-free
//! reciprocals and square roots, 3- and 4-vectors and 4×4 matrices.
//!
//! Units and formats: every geometric quantity (model, view and clip coordinates, matrix
//! entries, vector components) is an [`Fx`] = I16F16: range ±32768 with a resolution of
//! 2^-16 ≈ 1.5e-5. That is enough headroom for scenes a few hundred units across seen
//! through a projection matrix, and enough resolution for unit vectors and rotation
//! entries (accurate to about 2^-16). Angles are binary ([`Angle`], 65536 per turn) so that
//! wrap-around is free. Nothing here uses floats, `unsafe` or the heap; only [`div_u64`] and its kin use
//! (32-bit) divide instructions, and nothing panics: every operation that can overflow either saturates or
//! returns `None`/`Err`, as documented on it.
//!
//! ## Numbers into fixed point
//!
//! Every constructor takes [`Fx`] (or raw bits). Make them with:
//!
//! | conversion | out of range (beyond ±32768) | NaN | where |
//! |---|---|---|---|
//! | [`fx`]`(v)` | saturates to `Fx::MIN`/`Fx::MAX` | zero | anywhere; the one to use |
//! | [`try_fx`]`(v)` | `Err(Error::OutOfRange)` | `Err(Error::OutOfRange)` | input you want to refuse |
//! | [`Vec3::from_num`]`(x, y, z)` | saturates, as `fx` | zero | vectors, mixed types |
//! | `Fx::from_bits(b)` | (bits: always exact) | — | `const` contexts |
//! | `Fx::from_num(v)` (the `fixed` crate's) | **panics in debug, wraps in release** (`40000` becomes `-25536`) | **panics** | only for constants known to fit |
//!
//! ```
//! use fixel::math::{fx, try_fx, Fx};
//! assert_eq!(fx(1.5f32), Fx::from_bits(3 << 15));
//! assert_eq!(fx(40000), Fx::MAX);         // saturates, never wraps
//! assert_eq!(fx(f32::NAN), Fx::ZERO);     // never panics
//! assert!(try_fx(40000.0f64).is_err());   // or refuse it
//! assert_eq!(try_fx(-2)?, Fx::from_bits(-2 << 16));
//! # Ok::<(), fixel::Error>(())
//! ```

/// True on ARMv6-M (Cortex-M0/M0+): no divide instruction, no 32 x 32 -> 64-bit multiply,
/// eight low registers. The measured per-core choices of the pipeline test it.
pub(crate) const ARMV6M: bool = cfg!(all(target_arch = "arm", not(target_has_atomic = "32")));

pub(crate) mod acc;
pub(crate) mod div;
pub(crate) mod mat;
pub(crate) mod recip;
pub(crate) mod recip32;
pub mod recip_q30;
pub(crate) mod trig;
pub(crate) mod unit;
pub(crate) mod vec;
pub(crate) mod wide;

/// The geometry scalar: I16F16 fixed point (±32768, resolution 2^-16).
///
/// Convert numbers into it with [`fx`] (saturating) or [`try_fx`] (checked), not with the
/// `fixed` crate's `Fx::from_num`, which panics on NaN and wraps on overflow in release
/// builds (see the [module docs](self)).
pub type Fx = fixed::types::I16F16;

/// `v` (an integer, a float or a fixed-point number) as an [`Fx`], saturated to
/// `Fx::MIN..=Fx::MAX`; NaN becomes zero. Never panics, never wraps.
pub fn fx<T: fixed::traits::ToFixed + Copy + PartialOrd>(v: T) -> Fx {
    if v.partial_cmp(&v).is_none() {
        Fx::ZERO
    } else {
        Fx::saturating_from_num(v)
    }
}

/// `v` as an [`Fx`], or [`Error::OutOfRange`](crate::Error::OutOfRange) when it is NaN or
/// outside `Fx::MIN..=Fx::MAX`. Values inside the range round to the nearest step of 2^-16
/// (towards negative infinity for floats' excess bits, as the `fixed` crate does).
pub fn try_fx<T: fixed::traits::ToFixed + Copy>(v: T) -> Result<Fx, crate::Error> {
    v.checked_to_fixed()
        .ok_or(crate::Error::OutOfRange { what: "number" })
}

pub use div::{div_floor_i64, div_round_i64, div_u64, Divisor32, HW_DIVIDE};
pub use mat::Mat4;
pub use recip::{div_fx, isqrt_u32, isqrt_u64, recip_fx, reciprocal_u32};
pub use trig::{sin_cos, sin_cos_q30, Angle};
pub use unit::{dot_q14, unit_q14, UNIT_Q14};
pub use vec::{Vec3, Vec4};
