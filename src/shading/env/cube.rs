//! Cube maps: six square power-of-two RGB565 faces, indexed by a direction that need not
//! be a unit vector.
//!
//! # Face selection and face coordinates (OpenGL ES 3.2, cube map texture selection)
//!
//! The face is the one of the direction's major axis (the component of largest magnitude)
//! and its sign; `sc`, `tc` and `ma` come from the table, and
//! `s = (sc / |ma| + 1) / 2`, `t = (tc / |ma| + 1) / 2`:
//!
//! | major | face | `sc` | `tc` | `ma` |
//! |---|---|---|---|---|
//! | `+rx` | 0 (`POSITIVE_X`) | `-rz` | `-ry` | `rx` |
//! | `-rx` | 1 (`NEGATIVE_X`) | `+rz` | `-ry` | `rx` |
//! | `+ry` | 2 (`POSITIVE_Y`) | `+rx` | `+rz` | `ry` |
//! | `-ry` | 3 (`NEGATIVE_Y`) | `+rx` | `-rz` | `ry` |
//! | `+rz` | 4 (`POSITIVE_Z`) | `+rx` | `-ry` | `rz` |
//! | `-rz` | 5 (`NEGATIVE_Z`) | `-rx` | `-ry` | `rz` |
//!
//! `t = 0` is the first row of a face, as for every fixel texture.
//!
//! **Ties** (GL leaves them to the implementation): when two or three magnitudes are equal
//! the major axis is x before y before z (`|x| >= |y| && |x| >= |z|` picks x, else
//! `|y| >= |z|` picks y). On a tie both faces meet at that edge with the same `s` or `t`
//! (`±1` there), so the choice only decides which face's edge texels are read.
//! **The zero direction** (for example a zero normal) reads the centre of face 0 (`+X`).
//!
//! # Division by the major axis without a divide
//!
//! Directions are three `i32` of any common scale (only the direction matters). The major
//! magnitude `|ma|` (as `u32`, so `i32::MIN` is fine) is normalised by its leading zeros to a
//! 16-bit mantissa `d` in `[2^15, 2^16)`; the minor magnitudes get the same shift (they are
//! not larger, so they fit). `2^31 / d` comes from fixel's 256-entry Q1.15 reciprocal seed
//! (shared with [`reciprocal_u32`](crate::math::reciprocal_u32)) and one Newton–Raphson step
//! in `u32` (error 2^-18 from the step, 2^-15 from the Q1.15 result); then
//! `|sc| / |ma|` in Q16 is one `u32` multiply and a rounding shift. Cost: 4 multiplies, one
//! table load, no division, no square root. Face coordinates are accurate to about
//! `2^-15 * size` texels (1/256 texel for 128-texel faces), see the tests.
//!
//! # Filtering
//!
//! Within a face, with any [`Sampler`] (`Nearest` or `Bilinear`) and `CLAMP_TO_EDGE`: what
//! GL does for cube maps without `TEXTURE_CUBE_MAP_SEAMLESS`; [`CubeMap::seamless`] gives
//! the seamless filter ([`SeamlessCubeMap`](super::SeamlessCubeMap)).

use crate::texture::{ClampToEdge, Sampler, Texture};
use crate::Error;

/// The direction lookup shared by every environment map: the colour (raw RGB565) seen in
/// direction `dir` (three `i32` components of any common scale; only the direction
/// matters, so no unit vector and no square root is needed).
pub trait EnvLookup: Copy + core::fmt::Debug {
    /// The colour in direction `dir`. Never panics, for any input (the zero direction
    /// included: each map documents what it returns for it).
    fn lookup(&self, dir: [i32; 3]) -> u16;
}

/// Face indices in GL order: `+X, -X, +Y, -Y, +Z, -Z`.
pub const FACE_NAMES: [&str; 6] = ["+X", "-X", "+Y", "-Y", "+Z", "-Z"];

/// Where a direction lands on a cube map: the face (0..=5, GL order) and the face
/// coordinates `s`, `t` in Q16 (`0..=65536` is `0.0..=1.0`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FaceCoords {
    /// Face index, `0..=5`: `+X, -X, +Y, -Y, +Z, -Z`.
    pub face: u8,
    /// `s` in Q16, `0..=65536`.
    pub s: u32,
    /// `t` in Q16, `0..=65536`.
    pub t: u32,
}

/// `2^31 / d` for `d` in `[2^15, 2^16)`, as Q1.15 (`(2^15, 2^16]`), within one unit: the
/// shared seed table and one Newton–Raphson step `y + y (1 - d y)`, all in 32 bits.
#[inline(always)]
pub(crate) fn recip16(d: u32) -> u32 {
    let y0 = u32::from(crate::math::recip::SEED[((d >> 7) & 0xFF) as usize]);
    // d y0 is (d / 2^16)(y0 / 2^15) in Q1.31, within 2^-9 of 2^31.
    let p = d.wrapping_mul(y0);
    // 1 - d y in Q1.31: |delta| < 2^22 (seed error 2^-9), so delta >> 8 < 2^14 and
    // y0 (delta >> 8) < 2^30.
    let delta = ((1u32 << 31).wrapping_sub(p) as i32) >> 8;
    // y0 delta in Q1.15 * Q1.23 = Q2.38: back to Q1.15, rounded.
    let corr = ((y0 as i32).wrapping_mul(delta) + (1 << 22)) >> 23;
    y0.wrapping_add(corr as u32)
}

/// Face and face coordinates of direction `dir` (GL's table, ties x before y before z; the
/// zero direction gives the centre of face 0). `s` and `t` in Q16, `0..=65536`.
#[inline(always)]
pub fn face_coords(dir: [i32; 3]) -> FaceCoords {
    let [x, y, z] = dir;
    let (ax, ay, az) = (x.unsigned_abs(), y.unsigned_abs(), z.unsigned_abs());
    // (face, |ma|, |sc|, sc negative, |tc|, tc negative)
    let (face, ma, sm, sn, tm, tn) = if ax >= ay && ax >= az {
        if x >= 0 {
            (0, ax, az, z > 0, ay, y > 0)
        } else {
            (1, ax, az, z < 0, ay, y > 0)
        }
    } else if ay >= az {
        if y >= 0 {
            (2, ay, ax, x < 0, az, z < 0)
        } else {
            (3, ay, ax, x < 0, az, z > 0)
        }
    } else if z >= 0 {
        (4, az, ax, x < 0, ay, y > 0)
    } else {
        (5, az, ax, x > 0, ay, y > 0)
    };
    if ma == 0 {
        return FaceCoords {
            face: 0,
            s: 1 << 15,
            t: 1 << 15,
        };
    }
    let n = ma.leading_zeros();
    let d = (ma << n) >> 16; // [2^15, 2^16)
    let r = recip16(d); // 2^31 / d, Q1.15
                        // |sc| / |ma| in Q16: (m / d) * 2^16 = m * (2^31 / d) / 2^15. m <= d, and m * r stays
                        // within 2^31 (1 + 2^-14) < 2^32.
    let q = |m: u32| ((((m << n) >> 16) * r + (1 << 14)) >> 15).min(1 << 16);
    let (qs, qt) = (q(sm), q(tm));
    // s = (1 ± q) / 2 in Q16.
    let half = |q: u32, neg: bool| {
        if neg {
            (65536 - q) >> 1
        } else {
            (65536 + q) >> 1
        }
    };
    FaceCoords {
        face,
        s: half(qs, sn),
        t: half(qt, tn),
    }
}

/// Six square faces of one power-of-two size, in GL order `+X, -X, +Y, -Y, +Z, -Z`.
///
/// Copying it copies six references.
#[derive(Clone, Copy, Debug)]
pub struct CubeMap<'a, F> {
    faces: [Texture<'a>; 6],
    log2_size: u8,
    filter: core::marker::PhantomData<F>,
}

impl<'a, F: Sampler> CubeMap<'a, F> {
    /// A cube map from six faces (GL order), sampled with `filter` within a face.
    ///
    /// # Errors
    /// [`Error::BadCubeMap`] naming the first face that is not square or not the size of
    /// face 0.
    pub fn new(faces: [Texture<'a>; 6], _filter: F) -> Result<Self, Error> {
        let size = faces[0].width();
        for (i, f) in faces.iter().enumerate() {
            if f.width() != size || f.height() != size {
                return Err(Error::BadCubeMap {
                    face: i as u8,
                    width: f.width(),
                    height: f.height(),
                });
            }
        }
        Ok(CubeMap {
            faces,
            log2_size: faces[0].log2_width() as u8,
            filter: core::marker::PhantomData,
        })
    }

    /// The faces, GL order.
    pub fn faces(&self) -> &[Texture<'a>; 6] {
        &self.faces
    }

    /// The side of every face in texels.
    pub fn size(&self) -> u32 {
        1 << self.log2_size
    }

    /// The same faces with another filter.
    pub fn with_filter<G: Sampler>(&self, _filter: G) -> CubeMap<'a, G> {
        CubeMap {
            faces: self.faces,
            log2_size: self.log2_size,
            filter: core::marker::PhantomData,
        }
    }

    /// The face and its I16F16 texel coordinates (`s * size`, `t * size`) for `dir`.
    #[inline(always)]
    pub fn texel_coords(&self, dir: [i32; 3]) -> (usize, i32, i32) {
        let c = face_coords(dir);
        // s <= 2^16 and size <= 2^12: s << log2 <= 2^28 fits i32.
        let l = u32::from(self.log2_size);
        (usize::from(c.face), (c.s << l) as i32, (c.t << l) as i32)
    }
}

impl<F: Sampler> EnvLookup for CubeMap<'_, F> {
    #[inline(always)]
    fn lookup(&self, dir: [i32; 3]) -> u16 {
        let (face, u, v) = self.texel_coords(dir);
        // face <= 5 by construction of face_coords.
        let tex = &self.faces[face % 6];
        F::sample(tex, ClampToEdge, ClampToEdge, u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recip16_is_accurate() {
        for d in (1u32 << 15)..(1 << 16) {
            let exact = (1u64 << 31) as f64 / f64::from(d);
            let got = f64::from(recip16(d));
            assert!((got - exact).abs() <= 1.0, "d={d}: {got} vs {exact}");
        }
    }

    #[test]
    fn gl_table_at_face_centres_and_corners() {
        let c = |d| face_coords(d);
        for (i, d) in [
            [1, 0, 0],
            [-1, 0, 0],
            [0, 1, 0],
            [0, -1, 0],
            [0, 0, 1],
            [0, 0, -1],
        ]
        .into_iter()
        .enumerate()
        {
            let f = c(d.map(|v| v * 1000));
            assert_eq!((f.face, f.s, f.t), (i as u8, 32768, 32768), "{d:?}");
        }
        // +X: sc = -z, tc = -y: direction (1, 0.5, 0.5) -> s = 0.25, t = 0.25.
        let f = c([1000, 500, 500]);
        assert_eq!((f.face, f.s, f.t), (0, 16384, 16384));
        // -Z: sc = -x, tc = -y: (0.5, -0.5, -1) -> s = 0.25, t = 0.75.
        let f = c([500, -500, -1000]);
        assert_eq!((f.face, f.s, f.t), (5, 16384, 49152));
        // Corner tie (1, 1, 1): x wins; s = 0 (sc = -z), t = 0 (tc = -y).
        let f = c([7, 7, 7]);
        assert_eq!((f.face, f.s, f.t), (0, 0, 0));
        // Edge tie y/z: y wins. (0, -3, 3): -Y, tc = -z -> t = 0.
        let f = c([0, -3, 3]);
        assert_eq!((f.face, f.s, f.t), (3, 32768, 0));
        // The zero direction: centre of +X.
        let f = c([0, 0, 0]);
        assert_eq!((f.face, f.s, f.t), (0, 32768, 32768));
        // Extremes do not overflow.
        let f = c([i32::MIN, i32::MAX, i32::MIN]);
        assert_eq!(f.face, 1);
        assert!(f.s <= 65536 && f.t <= 65536);
    }
}
