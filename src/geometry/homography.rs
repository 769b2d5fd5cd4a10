//! The projective map of a quadrilateral (Heckbert, "Fundamentals of Texture Mapping and
//! Image Warping", 1989): the 3x3 homography that takes the unit square of texture
//! coordinates onto four screen corners, its inverse, and the per-corner weights that let
//! the ordinary perspective-correct span loop draw it exactly.
//!
//! For corners `p0..p3` (the images of `(0,0), (1,0), (1,1), (0,1)`), Heckbert's
//! construction gives
//!
//! ```text
//! (x, y) = ((a u + b v + c) / (g u + h v + 1), (d u + e v + f) / (g u + h v + 1))
//! Σx = x0 − x1 + x2 − x3,  Σy = y0 − y1 + y2 − y3
//! D  = (x1 − x2)(y3 − y2) − (x3 − x2)(y1 − y2)
//! g  = (Σx (y3 − y2) − Σy (x3 − x2)) / D,   h = ((x1 − x2) Σy − (y1 − y2) Σx) / D
//! a = x1 − x0 + g x1,  b = x3 − x0 + h x3,  c = x0    (and d, e, f with y)
//! ```
//!
//! The denominator `w = g u + h v + 1` at the corners is `1, 1 + g, 1 + g + h, 1 + h`: drawn
//! as two triangles whose clip-space `w` are these values (times any common factor), the
//! perspective-correct interpolation of `(u, v)` *is* the projective map, at every pixel.
//!
//! # Fixed point
//!
//! Corners are I16F16 screen pixels. Everything up to the corner weights is exact integer
//! arithmetic (`i128` intermediates, once per quad); the matrix is then scaled so its largest
//! entry has 30 bits (relative rounding below 2^-29) for [`Homography::map`] and the
//! adjugate [`Homography::inverse`].
//!
//! # Refused quads
//!
//! A projective map takes a square to a convex quad, so [`Homography::square_to_quad`]
//! refuses ([`Error::BadQuad`]) corners with three on a line (the map would be singular),
//! corners that cross (a bow-tie) and concave quads: in each case the weights change sign,
//! i.e. the map passes through infinity inside the square. It also refuses corners whose
//! map, once rounded to 62-bit entries, no longer takes the square's corners to them (and
//! back) within [`CORNER_TOLERANCE`]: corners near the I16F16 limits that are nearly
//! collinear.

use crate::math::Fx;
use crate::Error;

/// How far a corner may map from where it was given (pixels) and back from where it
/// belongs (texture units) for [`Homography::square_to_quad`] to accept the quad: 2^-10.
/// Quads from ordinary screen corners map their corners back within a bit or two of
/// I16F16; only corners near the fixed-point limits and nearly collinear come close.
pub const CORNER_TOLERANCE: Fx = Fx::from_bits(1 << 6);

/// The unit square's corners `(0,0), (1,0), (1,1), (0,1)` (I16F16).
const SQUARE: [[Fx; 2]; 4] = [
    [Fx::ZERO, Fx::ZERO],
    [Fx::ONE, Fx::ZERO],
    [Fx::ONE, Fx::ONE],
    [Fx::ZERO, Fx::ONE],
];

/// A 3x3 projective map (row-major, column vectors: `(X, Y, W) = M (u, v, 1)` and the image
/// is `(X / W, Y / W)`), in I16F16 bits on both sides: entries scaled by a common power of
/// two so the largest has 62 bits (the ratios, which are all that matter, keep at least 30
/// bits for any corners in I16F16).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Homography {
    m: [[i64; 3]; 3],
}

/// Scales `m` by a power of two so the largest magnitude has `bits` bits (rounding).
fn normalize(m: [[i128; 3]; 3], bits: u32) -> [[i64; 3]; 3] {
    let big = m
        .iter()
        .flatten()
        .map(|x| x.unsigned_abs())
        .max()
        .unwrap_or(0);
    let len = 128 - big.leading_zeros();
    let shift = len.saturating_sub(bits);
    m.map(|r| {
        r.map(|x| {
            if shift == 0 {
                x as i64
            } else {
                ((x + (1i128 << (shift - 1))) >> shift) as i64
            }
        })
    })
}

/// Signs of the turn at each corner of `p` (I16F16 bits): `> 0` counter-clockwise on a
/// y-down screen seen as maths axes, `< 0` the other way, `0` collinear.
fn turns(p: &[[i64; 2]; 4]) -> [i128; 4] {
    core::array::from_fn(|k| {
        let (a, b, c) = (p[(k + 3) % 4], p[k], p[(k + 1) % 4]);
        let (e1, e2) = ([b[0] - a[0], b[1] - a[1]], [c[0] - b[0], c[1] - b[1]]);
        i128::from(e1[0]) * i128::from(e2[1]) - i128::from(e1[1]) * i128::from(e2[0])
    })
}

impl Homography {
    /// The map from the unit square onto `corners` (I16F16 screen pixels, the images of
    /// `(0,0), (1,0), (1,1), (0,1)`, in either winding), and the four corner weights `w`
    /// (positive, the largest `2^30`): see the module docs.
    ///
    /// Refused ([`Error::BadQuad`]) when three corners are collinear, they cross, the quad
    /// is concave, or the rounded map misses a corner by more than [`CORNER_TOLERANCE`]
    /// (either way: see the module docs).
    pub fn square_to_quad(corners: [[Fx; 2]; 4]) -> Result<(Homography, [i64; 4]), Error> {
        let (h, w) = Self::square_to_quad_unchecked(corners)?;
        h.check_corners(corners, true)?;
        Ok((h, w))
    }

    /// [`square_to_quad`](Self::square_to_quad) with the corner check left to the caller
    /// ([`check_corners`](Self::check_corners)): a quad drawn by its inverse alone only
    /// needs the inverse to hold.
    pub(crate) fn square_to_quad_unchecked(
        corners: [[Fx; 2]; 4],
    ) -> Result<(Homography, [i64; 4]), Error> {
        let p = corners.map(|c| c.map(|v| i64::from(v.to_bits())));
        let t = turns(&p);
        if t.contains(&0) {
            return Err(Error::BadQuad("three corners are collinear"));
        }
        let pos = t.iter().filter(|&&x| x > 0).count();
        if pos == 2 {
            return Err(Error::BadQuad("the corners cross (a bow-tie)"));
        }
        if pos != 0 && pos != 4 {
            return Err(Error::BadQuad("the quad is concave"));
        }
        let q = p.map(|c| c.map(i128::from));
        let (sx, sy) = (
            q[0][0] - q[1][0] + q[2][0] - q[3][0],
            q[0][1] - q[1][1] + q[2][1] - q[3][1],
        );
        let (dx1, dx2) = (q[1][0] - q[2][0], q[3][0] - q[2][0]);
        let (dy1, dy2) = (q[1][1] - q[2][1], q[3][1] - q[2][1]);
        // Corners within ±2^31 (I16F16 bits): every product below fits i128.
        let den = dx1 * dy2 - dx2 * dy1;
        if den == 0 {
            return Err(Error::BadQuad("three corners are collinear"));
        }
        let ng = sx * dy2 - sy * dx2;
        let nh = dx1 * sy - dy1 * sx;
        // Everything times D (so g = ng, h = nh, 1 = D); x in I16F16 bits.
        let m = [
            [
                (q[1][0] - q[0][0]) * den + ng * q[1][0],
                (q[3][0] - q[0][0]) * den + nh * q[3][0],
                q[0][0] * den,
            ],
            [
                (q[1][1] - q[0][1]) * den + ng * q[1][1],
                (q[3][1] - q[0][1]) * den + nh * q[3][1],
                q[0][1] * den,
            ],
            [ng, nh, den],
        ];
        let w = [den, den + ng, den + ng + nh, den + nh];
        if w.iter().any(|&x| x == 0 || (x < 0) != (den < 0)) {
            // A convex quad never gets here; kept so no input divides by zero.
            return Err(Error::BadQuad("the map passes through infinity"));
        }
        let sign = if den < 0 { -1 } else { 1 };
        let wmax = w.iter().map(|x| x.unsigned_abs()).max().unwrap_or(1) as i128;
        let weights = w.map(|x| ((sign * x) << 30).checked_div(wmax).unwrap_or(0) as i64);
        // Normalise with the sign of D folded in, so the bottom row is positive inside.
        let m = m.map(|r| r.map(|x| x * sign));
        let h = Homography {
            m: normalize(m, 62),
        };
        Ok((h, weights.map(|x| x.max(1))))
    }

    /// Refuses a map whose 62-bit entries no longer carry the corners: through the inverse
    /// each corner must map to its texture corner within [`CORNER_TOLERANCE`] of the
    /// texture and, when `forward`, each texture corner to its corner within
    /// [`CORNER_TOLERANCE`] pixels. Corners far apart in I16F16 with others nearly collinear
    /// need more than 62 bits for some entries' ratios (the forward map's bottom row first).
    pub(crate) fn check_corners(&self, corners: [[Fx; 2]; 4], forward: bool) -> Result<(), Error> {
        const TOO_EXTREME: Error = Error::BadQuad(
            "the corners are too extreme for a fixed-point map (nearly collinear, far apart)",
        );
        let inverse = self.inverse();
        let near = |a: [Fx; 2], b: [Fx; 2]| {
            a.iter().zip(&b).all(|(x, y)| {
                x.to_bits().abs_diff(y.to_bits()) <= CORNER_TOLERANCE.to_bits() as u32
            })
        };
        for (uv, c) in SQUARE.iter().zip(corners) {
            let back = inverse.map(c[0], c[1]).ok_or(TOO_EXTREME)?;
            let image = if forward {
                self.map(uv[0], uv[1]).ok_or(TOO_EXTREME)?
            } else {
                c
            };
            if !near(image, c) || !near(back, *uv) {
                return Err(TOO_EXTREME);
            }
        }
        Ok(())
    }

    /// The third output of the map at `(u, v)` (I16F16), before the division: positive
    /// where a [`square_to_quad`](Self::square_to_quad) map is finite. On the inverse it is
    /// proportional to `1 / w` at screen point `(u, v)` (the reciprocal of the corner
    /// weights' interpolant), in units that only matter as ratios.
    pub fn denominator(&self, u: Fx, v: Fx) -> i128 {
        let (u, v) = (i128::from(u.to_bits()), i128::from(v.to_bits()));
        let r = self.m[2];
        i128::from(r[0]) * u + i128::from(r[1]) * v + (i128::from(r[2]) << 16)
    }

    /// The image of `(u, v)` (I16F16): screen pixels for a square-to-quad map, texture
    /// coordinates for its [`inverse`](Self::inverse). `None` where the map is at infinity
    /// or the result does not fit I16F16.
    pub fn map(&self, u: Fx, v: Fx) -> Option<[Fx; 2]> {
        let (u, v) = (i128::from(u.to_bits()), i128::from(v.to_bits()));
        // (u, v, 1) in I16F16 bits: the third input is 2^16. Entries below 2^62 and inputs
        // below 2^31: each product below 2^93.
        let row =
            |r: [i64; 3]| i128::from(r[0]) * u + i128::from(r[1]) * v + (i128::from(r[2]) << 16);
        let (x, y, w) = (row(self.m[0]), row(self.m[1]), row(self.m[2]));
        if w == 0 {
            return None;
        }
        let (x, y, w) = if w < 0 { (-x, -y, -w) } else { (x, y, w) };
        // Round to nearest: floor((2 n + w) / 2 w).
        let div = |n: i128| {
            i32::try_from((2 * n + w).div_euclid(2 * w))
                .ok()
                .map(Fx::from_bits)
        };
        Some([div(x)?, div(y)?])
    }

    /// The inverse map (screen I16F16 pixels to texture coordinates): the adjugate, with the
    /// `1` of both sides kept in I16F16 bits.
    pub fn inverse(&self) -> Homography {
        // Entries below 2^62: the 2 x 2 minors below 2^125 fit i128.
        let m = self.m.map(|r| r.map(i128::from));
        let c = |r0: usize, c0: usize, r1: usize, c1: usize| {
            m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]
        };
        let adj = [
            [c(1, 1, 2, 2), -c(0, 1, 2, 2), c(0, 1, 1, 2)],
            [-c(1, 0, 2, 2), c(0, 0, 2, 2), -c(0, 0, 1, 2)],
            [c(1, 0, 2, 1), -c(0, 0, 2, 1), c(0, 0, 1, 1)],
        ];
        // The stored M maps (u, v, 1) to (x W, y W, W), `u` real and `x` in I16F16 bits;
        // `map` feeds (x, y, 2^16) and wants `u` in I16F16 bits, so the inverse is
        // diag(2^16, 2^16, 1) adj(M) diag(1, 1, 2^-16), here times 2^16: entry (i, j)
        // scaled by 2^s with s = 16 ([i < 2] + [j < 2]). One common shift brings the
        // largest scaled entry to 62 bits (no entry is shifted left out of i128).
        let s = |i: usize, j: usize| 16 * (u32::from(i < 2) + u32::from(j < 2));
        let len = |x: i128| 128 - x.unsigned_abs().leading_zeros();
        let top = (0..9)
            .map(|k| len(adj[k / 3][k % 3]) + s(k / 3, k % 3))
            .max()
            .unwrap_or(0);
        let k = top.saturating_sub(62);
        let out: [[i64; 3]; 3] = core::array::from_fn(|i| {
            core::array::from_fn(|j| {
                let (x, e) = (adj[i][j], s(i, j));
                if e >= k {
                    (x << (e - k)) as i64
                } else {
                    let sh = k - e;
                    ((x + (1i128 << (sh - 1))) >> sh) as i64
                }
            })
        });
        Homography { m: out }
    }
}
