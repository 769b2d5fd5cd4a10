//! Texture coordinates generated from model-space positions: planar, cylindrical and
//! spherical projections (Bier & Sloan, "Two-Part Texture Mappings", IEEE CG&A 1986), per
//! vertex, at bake time, at run time or per pixel.
//!
//! For a position `p`, with `d = p − center` split along the mapping's axis into `up`
//! (along the axis), `right` and `front` (a right-handed frame: for [`Axis::Y`] they are
//! `+x`, `+y` and `+z`):
//!
//! ```text
//! planar       u = (p − origin)·s                 v = (p − origin)·t
//! cylindrical  u = 1/2 + atan2(right, front) / 2π  v = (top − up) / (top − bottom)
//! spherical    u = 1/2 + atan2(right, front) / 2π  v = 1/2 − atan2(up, |(right, front)|) / π
//! ```
//!
//! So the front of the object (`+z` for [`Axis::Y`]) shows the middle column of the texture,
//! the seam is at the back, `u` grows to the right seen from the front (no mirroring), and
//! `v = 0` (the first row of the image, GL's `t = 0`) is at the top.
//!
//! # Fixed point and error
//!
//! Positions are I16F16 ([`Vec3`]); `u, v` are I16F16 in texture units (1.0 = one texture).
//! The angles come from the table `atan2` of
//! [`env::angles`](super::env::angles) (no square root, no division): `u` and the
//! spherical `v` are within 2 units of 2^-16 of the exact values (tested against the f64
//! reference in `host-tests`); the planar and cylindrical products are exact then rounded
//! once.
//!
//! [`map_mesh`](crate::scene::map_mesh) applies a mapping to a mesh, seams and poles included.

use crate::math::{Fx, Vec3};
use crate::shading::env::angles::atan2_hypot;
use crate::Error;

/// An axis of model space (the "up" of a cylindrical or spherical mapping).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Axis {
    /// `+x` up; right `+z`, front `+y`.
    X,
    /// `+y` up (the default); right `+x`, front `+z`.
    #[default]
    Y,
    /// `+z` up; right `+x`, front `−y`.
    Z,
}

impl Axis {
    /// `(right, up, front)` components of `d`, I16F16 bits.
    fn frame(self, d: Vec3) -> (i32, i32, i32) {
        let (x, y, z) = (d.x.to_bits(), d.y.to_bits(), d.z.to_bits());
        match self {
            Axis::X => (z, x, y),
            Axis::Y => (x, y, z),
            Axis::Z => (x, z, y.saturating_neg()),
        }
    }
}

/// How texture coordinates come from a model-space position (see the module docs for the
/// formulas).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UvMapping {
    /// A projection onto a plane: `u = (p − origin)·s`, `v = (p − origin)·t` (the lengths
    /// of `s` and `t` are textures per model unit).
    Planar {
        /// Where `u = v = 0`.
        origin: Vec3,
        /// The `u` direction, scaled.
        s: Vec3,
        /// The `v` direction, scaled.
        t: Vec3,
    },
    /// A cylinder around `axis` through `center`: `u` by angle, `v` from `top` (0) to
    /// `bottom` (1) along the axis (model units from `center`).
    Cylindrical {
        /// A point on the axis.
        center: Vec3,
        /// The axis direction.
        axis: Axis,
        /// Height of `v = 0`.
        top: Fx,
        /// Height of `v = 1` (must differ from `top`).
        bottom: Fx,
    },
    /// A sphere around `center`: `u` by longitude, `v` by latitude (0 at the top pole).
    Spherical {
        /// The sphere's centre.
        center: Vec3,
        /// The polar axis.
        axis: Axis,
    },
}

/// `1/2 + atan2(right, front) / 2π` in Q16 (`0..65536`): the middle column faces front.
fn longitude(right: i32, front: i32) -> i32 {
    let (turns, _) = atan2_hypot(
        right.unsigned_abs(),
        right < 0,
        front.unsigned_abs(),
        front < 0,
    );
    ((turns + 32768) & 0xFFFF) as i32
}

/// A source of texture coordinates per vertex, for [`map_mesh_with`](crate::scene::map_mesh_with): a [`UvMapping`], a
/// [`TwoStage`](crate::scene::TwoStage) mapping, or your own.
pub trait UvGenerator {
    /// The checked generator with its per-call constants.
    type Ready: UvAt;
    /// Checks the generator (a degenerate one is an error) and prepares it.
    fn ready(&self) -> Result<Self::Ready, Error>;
}

/// A prepared [`UvGenerator`].
pub trait UvAt {
    /// `(uv, on the axis)` of a vertex at model-space position `p` with unit normal `n`
    /// (zero when the mesh has none): "on the axis" marks a pole (every `u` is the same
    /// point), which takes its triangle's mean `u`.
    fn at(&self, p: Vec3, n: Vec3) -> ([Fx; 2], bool);
    /// Whether `u` wraps around (so seams and poles are fixed per triangle).
    fn wraps(&self) -> bool;
}

impl UvGenerator for UvMapping {
    type Ready = ReadyMapping;
    fn ready(&self) -> Result<ReadyMapping, Error> {
        ReadyMapping::new(self)
    }
}

impl UvAt for ReadyMapping {
    fn at(&self, p: Vec3, _: Vec3) -> ([Fx; 2], bool) {
        ReadyMapping::at(self, p)
    }
    fn wraps(&self) -> bool {
        ReadyMapping::wraps(self)
    }
}

/// A mapping checked once, with its per-call constants.
#[derive(Clone, Copy, Debug)]
pub struct ReadyMapping {
    mapping: UvMapping,
    /// Cylindrical: `1 / (top − bottom)` in Q32 (signed), as `i64`.
    inv_height: i64,
}

impl ReadyMapping {
    fn new(mapping: &UvMapping) -> Result<Self, Error> {
        let inv_height = match *mapping {
            UvMapping::Cylindrical { top, bottom, .. } => {
                let h = i64::from(top.to_bits()) - i64::from(bottom.to_bits());
                if h == 0 {
                    return Err(Error::OutOfRange {
                        what: "cylinder height (top equals bottom)",
                    });
                }
                // 2^48 / h in Q32 per I16F16 unit: (top − up) * inv >> 32 is v in Q16.
                (1i64 << 48) / h
            }
            _ => 0,
        };
        Ok(ReadyMapping {
            mapping: *mapping,
            inv_height,
        })
    }

    /// `(u, v, on the axis)` of `p`, I16F16.
    fn at(&self, p: Vec3) -> ([Fx; 2], bool) {
        match self.mapping {
            UvMapping::Planar { origin, s, t } => {
                let d = p.sub(origin);
                ([d.dot(s), d.dot(t)], false)
            }
            UvMapping::Cylindrical {
                center, axis, top, ..
            } => {
                let (right, up, front) = axis.frame(p.sub(center));
                let u = longitude(right, front);
                let dh = i64::from(top.to_bits()) - i64::from(up);
                let v = (dh.saturating_mul(self.inv_height) + (1 << 31)) >> 32;
                let v = v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32;
                (
                    [Fx::from_bits(u), Fx::from_bits(v)],
                    right == 0 && front == 0,
                )
            }
            UvMapping::Spherical { center, axis } => {
                let (right, up, front) = axis.frame(p.sub(center));
                let u = longitude(right, front);
                let (_, radial) = atan2_hypot(
                    right.unsigned_abs(),
                    right < 0,
                    front.unsigned_abs(),
                    front < 0,
                );
                let (beta, _) = atan2_hypot(up.unsigned_abs(), up < 0, radial, false);
                // Signed quarter turns: north in 0..=16384, south in 49152..65536.
                let beta = if beta >= 32768 {
                    beta as i32 - 65536
                } else {
                    beta as i32
                };
                let v = (32768 - 2 * beta).clamp(0, 65536);
                (
                    [Fx::from_bits(u), Fx::from_bits(v)],
                    right == 0 && front == 0,
                )
            }
        }
    }

    /// Whether `u` wraps around (so seams and poles need fixing).
    fn wraps(&self) -> bool {
        !matches!(self.mapping, UvMapping::Planar { .. })
    }
}

impl UvMapping {
    /// The texture coordinates of one model-space position (no seam or pole handling: see
    /// [`map_mesh`](crate::scene::map_mesh)). Errors if the mapping is degenerate (a cylinder with `top == bottom`).
    pub fn uv(&self, p: Vec3) -> Result<[Fx; 2], Error> {
        Ok(ReadyMapping::new(self)?.at(p).0)
    }

    /// Writes the texture coordinates of `positions` into `uvs` (same length), per vertex
    /// with no seam or pole handling: right for planar mappings and for meshes that stay
    /// clear of the seam; [`map_mesh`](crate::scene::map_mesh) otherwise.
    pub fn generate(&self, positions: &[Vec3], uvs: &mut [[Fx; 2]]) -> Result<(), Error> {
        if uvs.len() != positions.len() {
            return Err(Error::WrongLength {
                expected: positions.len(),
                actual: uvs.len(),
            });
        }
        let m = ReadyMapping::new(self)?;
        for (uv, &p) in uvs.iter_mut().zip(positions) {
            *uv = m.at(p).0;
        }
        Ok(())
    }
}
