//! Fixed-point math: the geometry scalar [`Fx`], angles and trigonometry, division-free
//! reciprocals and square roots, 3- and 4-vectors and 4×4 matrices.
//!
//! Units and formats: every geometric quantity (model, view and clip coordinates, matrix
//! entries, vector components) is an [`Fx`] = I16F16: range ±32768 with a resolution of
//! 2^-16 ≈ 1.5e-5. That is enough headroom for scenes a few hundred units across seen
//! through a projection matrix, and enough resolution for unit vectors and rotation
//! entries (accurate to about 2^-16). Angles are binary ([`Angle`], 65536 per turn) so that
//! wrap-around is free. Nothing here uses floats, `unsafe` or the heap; only [`div`] uses
//! (32-bit) divide instructions, and nothing panics: every operation that can overflow either saturates or
//! returns `None`/`Err`, as documented on it.

mod acc;
pub mod div;
pub mod mat;
pub mod recip;
pub mod trig;
pub mod vec;

/// The geometry scalar: I16F16 fixed point (±32768, resolution 2^-16).
pub type Fx = fixed::types::I16F16;

pub use div::{div_floor_i64, div_round_i64, div_u64, SmallDivisor, HW_DIVIDE};
pub use mat::Mat4;
pub use recip::{div_fx, isqrt_u32, isqrt_u64, recip_fx, reciprocal_u32};
pub use trig::{sin_cos, Angle};
pub use vec::{Vec3, Vec4};
