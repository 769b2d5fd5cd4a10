//! The reflection vector `r = 2 (n·v) n − v`, per pixel or per vertex, and the two
//! environment-mapping shaders built on it.
//!
//! `n` is the surface normal and `v` the vector from the surface point towards the eye, both
//! in the space the environment map is in (world space; with an identity view matrix, view
//! space). For vectors of any length the shaders compute
//!
//! ```text
//! r = 2 (n·v) n − (n·n) v
//! ```
//!
//! which is the mirror image of `v` about `n` scaled by `|n|²`: the same direction as the
//! unit formula, so neither `n` nor `v` has to be normalised per pixel (no square root), and
//! interpolated normals, shorter than 1 inside a curved triangle, need no renormalising.
//! `v = eye − p` interpolated (not normalised per vertex) is exact at every pixel, since
//! `p` is linear across the triangle. A zero `n` (or `v`) gives `r = 0`, which every
//! [`EnvLookup`] maps to a documented colour.
//!
//! * [`ReflectPerPixel`]: varyings `nx, ny, nz, vx, vy, vz` (any common scale per vector,
//!   for example I16F16 bits as [`EnvVertices::per_pixel`] gives them); reflects per pixel.
//! * [`ReflectPerVertex`]: varyings `rx, ry, rz` (the unit `r` in Q14, from
//!   [`reflect_unit`] at each vertex, [`EnvVertices::per_vertex`]); interpolates `r`. Cheaper
//!   (3 varyings, no products per pixel) but wrong inside large triangles: the
//!   interpolated `r` is not the reflection of the interpolated `n` and `v`, and the error
//!   grows with the angle `r` turns across a triangle.
//!
//! # Fixed point of the per-pixel reflection
//!
//! The shaders' [`Shader::triangle`] hook shifts the three vertices' normals (and,
//! separately, their eye vectors, or the per-vertex `r`) by a common power of two so that
//! the largest component magnitude is in `[2^23, 2^24)`: the direction is kept, tiny and
//! huge inputs alike are interpolated with 24 significant bits (the span interpolators'
//! error is a roughly constant number of units, so small varyings would lose precision).
//! Per pixel each component is shifted right by 11 (below 2^13), then (all `i32`, no
//! overflow since `|n|, |v| < 2^13 √3`): `k = (2 n·v) >> 13`, `m = (n·n) >> 13`,
//! `r = k n − m v` (components below 2^30).

use super::cube::EnvLookup;
use crate::geometry::Vertex;
use crate::math::{div_round_i64, isqrt_u64, Mat4, Vec3};
use crate::shading::{Fragment, Shader};

/// Bits of the components the per-pixel products use (`< 2^13`).
pub(crate) const FIT_BITS: u32 = 13;

/// Bits of the largest varying magnitude after the per-triangle rescale (`< 2^24`): the
/// span interpolators' error is a roughly constant number of units (about 2^7 on the
/// benchmark cube), so varyings are interpolated large and shifted down per pixel.
pub(crate) const VARYING_BITS: u32 = 24;

/// Shifts components `g..g + 3` of the three vertices by one power of two so that their
/// largest magnitude is in `[2^(BITS-1), 2^BITS)` (all zero stays zero).
#[inline]
pub(crate) fn fit_group<const N: usize, const BITS: u32>(v: &mut [[i32; N]; 3], g: usize) {
    let mut max = 0u32;
    for vert in v.iter() {
        for c in vert.iter().skip(g).take(3) {
            max = max.max(c.unsigned_abs());
        }
    }
    if max == 0 {
        return;
    }
    let bits = 32 - max.leading_zeros();
    for vert in v.iter_mut() {
        for c in vert.iter_mut().skip(g).take(3) {
            *c = if bits > BITS {
                *c >> (bits - BITS)
            } else {
                // |c| < 2^bits, so the shift keeps it below 2^BITS.
                *c << (BITS - bits)
            };
        }
    }
}

/// `r = 2 (n·v) n − (n·n) v` with the per-pixel scaling of the module docs: `n`, `v`
/// components below 2^13 in magnitude (larger ones wrap, never panic).
#[inline(always)]
pub fn reflect_fit(n: [i32; 3], v: [i32; 3]) -> [i32; 3] {
    let dot = |a: [i32; 3], b: [i32; 3]| {
        a[0].wrapping_mul(b[0])
            .wrapping_add(a[1].wrapping_mul(b[1]))
            .wrapping_add(a[2].wrapping_mul(b[2]))
    };
    let k = dot(n, v) >> (FIT_BITS - 1);
    let m = dot(n, n) >> FIT_BITS;
    [0, 1, 2].map(|i| k.wrapping_mul(n[i]).wrapping_sub(m.wrapping_mul(v[i])))
}

/// Environment mapping with the reflection computed per pixel from interpolated `n` and
/// `v`. Varyings: `nx, ny, nz, vx, vy, vz`, each vector at any scale (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct ReflectPerPixel<M>(pub M);

impl<M: EnvLookup> Shader for ReflectPerPixel<M> {
    type Varyings = [i32; 6];
    type Triangle = ();

    #[inline]
    fn triangle(&self, v: &mut [[i32; 6]; 3]) {
        fit_group::<6, VARYING_BITS>(v, 0);
        fit_group::<6, VARYING_BITS>(v, 3);
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 6], ()>) -> Option<u16> {
        const S: u32 = VARYING_BITS - FIT_BITS;
        let [nx, ny, nz, vx, vy, vz] = f.varyings.map(|c| c >> S);
        Some(self.0.lookup(reflect_fit([nx, ny, nz], [vx, vy, vz])))
    }
}

/// Environment mapping with `r` computed per vertex and interpolated. Varyings:
/// `rx, ry, rz` (any common scale; [`reflect_unit`] gives Q14 unit vectors).
#[derive(Clone, Copy, Debug)]
pub struct ReflectPerVertex<M>(pub M);

impl<M: EnvLookup> Shader for ReflectPerVertex<M> {
    type Varyings = [i32; 3];
    type Triangle = ();

    #[inline]
    fn triangle(&self, v: &mut [[i32; 3]; 3]) {
        fit_group::<3, VARYING_BITS>(v, 0);
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 3], ()>) -> Option<u16> {
        Some(self.0.lookup(f.varyings))
    }
}

/// Shifts an `i64` triple so its largest magnitude is in `[2^(bits-1), 2^bits)`.
fn fit_i64(a: [i64; 3], bits: u32) -> [i64; 3] {
    let max = a.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
    if max == 0 {
        return a;
    }
    let have = 64 - max.leading_zeros();
    if have > bits {
        a.map(|c| c >> (have - bits))
    } else {
        a.map(|c| c << (bits - have))
    }
}

/// The unit reflection vector `2 (n·v) n − v` of unit `n`, `v` for any `n`, `v` (I16F16, any
/// length: both are rescaled, not normalised, first), in Q14 (`|r| = 16384` within one
/// unit per component). `[0, 0, 0]` when `n` or `v` is zero. One square root and three
/// divisions: meant for vertices.
pub fn reflect_unit(n: Vec3, v: Vec3) -> [i32; 3] {
    let bits = |a: Vec3| [a.x, a.y, a.z].map(|c| i64::from(c.to_bits()));
    let (n, v) = (fit_i64(bits(n), 15), fit_i64(bits(v), 15));
    let dot = |a: [i64; 3], b: [i64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let (nv, nn) = (dot(n, v), dot(n, n));
    if nn == 0 || dot(v, v) == 0 {
        return [0; 3];
    }
    // |n|, |v| < 2^15 √3: every term below 2^48.
    let r = fit_i64([0, 1, 2].map(|i| 2 * nv * n[i] - nn * v[i]), 30);
    let len2 = r.iter().map(|&c| (c * c) as u64).sum::<u64>();
    let len = i64::from(isqrt_u64(len2));
    if len == 0 {
        return [0; 3];
    }
    r.map(|c| div_round_i64(c << 14, len) as i32)
}

/// Turns mesh vertices (model space) into the varyings of the two reflection shaders.
///
/// `model` takes model space to world space (rotation and translation: normals are
/// transformed by it as directions), `view_proj` world space to clip space, and `eye` is
/// the camera position in world space. The cube map is indexed in world space.
#[derive(Clone, Copy, Debug)]
pub struct EnvVertices {
    /// Model to world.
    pub model: Mat4,
    /// Model to clip (`view_proj · model`).
    pub mvp: Mat4,
    /// The eye in world space.
    pub eye: Vec3,
}

impl EnvVertices {
    /// Set-up from `model`, `view_proj` and the eye position (world space).
    pub fn new(model: &Mat4, view_proj: &Mat4, eye: Vec3) -> Self {
        EnvVertices {
            model: *model,
            mvp: view_proj.mul(model),
            eye,
        }
    }

    /// Clip position, world normal and world eye vector of a vertex; `None` on overflow.
    fn parts(&self, p: Vec3, n: Vec3) -> Option<([crate::math::Fx; 4], Vec3, Vec3)> {
        let c = self.mvp.transform_point(p)?;
        let w = self.model.transform_point(p)?;
        let nw = self.model.transform_vector(n)?;
        let to_eye = Vec3::new(
            self.eye.x.checked_sub(w.x)?,
            self.eye.y.checked_sub(w.y)?,
            self.eye.z.checked_sub(w.z)?,
        );
        Some(([c.x, c.y, c.z, c.w], nw, to_eye))
    }

    /// A vertex for [`ReflectPerPixel`]: varyings `n` then `eye − p`, I16F16 bits, world
    /// space. `None` when a component overflows (skip the triangle).
    pub fn per_pixel(&self, p: Vec3, n: Vec3) -> Option<Vertex<6>> {
        let (c, n, e) = self.parts(p, n)?;
        let b = |a: Vec3| [a.x.to_bits(), a.y.to_bits(), a.z.to_bits()];
        let (n, e) = (b(n), b(e));
        Some(Vertex::new(c, [n[0], n[1], n[2], e[0], e[1], e[2]]))
    }

    /// A vertex for [`ReflectPerVertex`]: varyings the unit `r` in Q14 ([`reflect_unit`]),
    /// world space. `None` when a component overflows.
    pub fn per_vertex(&self, p: Vec3, n: Vec3) -> Option<Vertex<3>> {
        let (c, n, e) = self.parts(p, n)?;
        Some(Vertex::new(c, reflect_unit(n, e)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflect_fit_mirrors_v_about_n() {
        // n = +y, v = (1, 1, 0) -> r = (-1, 1, 0) times |n|^2.
        let r = reflect_fit([0, 4096, 0], [4096, 4096, 0]);
        assert_eq!(r, [-4096 * 2048, 4096 * 2048, 0]);
        assert_eq!(reflect_fit([0; 3], [4096, 1, 2]), [0; 3]);
    }

    #[test]
    fn fit_group_keeps_direction_and_bounds() {
        let mut v = [[3, -1, 0, i32::MAX, i32::MIN, 5]; 3];
        fit_group::<6, FIT_BITS>(&mut v, 0);
        fit_group::<6, FIT_BITS>(&mut v, 3);
        assert_eq!(&v[0][..3], &[3 << 11, -(1 << 11), 0]);
        assert!(v[0][3..].iter().all(|c| c.unsigned_abs() < 1 << 13));
        assert_eq!(v[0][4], -(1 << 12));
    }

    #[test]
    fn reflect_unit_is_unit() {
        let r = reflect_unit(Vec3::from_num(0, 1, 0), Vec3::from_num(3, 3, 0));
        let s = 16384.0 / 2f64.sqrt();
        assert!((f64::from(r[0]) + s).abs() <= 1.0 && (f64::from(r[1]) - s).abs() <= 1.0);
        assert_eq!(reflect_unit(Vec3::ZERO, Vec3::from_num(1, 0, 0)), [0; 3]);
    }
}
