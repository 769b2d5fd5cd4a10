//! Displacement mapping (Cook, "Shade Trees", SIGGRAPH 1984): the geometry itself moves,
//! each vertex along its normal by a height map, and the normals are recomputed from the
//! moved surface. Unlike bump mapping, which only tilts normals per pixel, the silhouette
//! becomes bumpy.
//!
//! # The formula
//! For a vertex at `p` with unit normal `n` and texture coordinates `uv`,
//!
//! ```text
//! p' = p + n · scale · (h(uv + offset) − bias)
//! ```
//!
//! where `h` is the bilinear height of a [`HeightMap`] ([`HeightMap::bilinear`], repeating)
//! as a fraction of 256 steps (`0..=255/256`), `scale` is model units per 256 steps and
//! `bias` the height that stays in place (`0.5` for mid-grey). The new normal of a vertex is
//! the normalised sum of the (area-weighted) cross products `(p1 − p0) × (p2 − p0)` of its
//! triangles; a vertex whose sum is zero (a flat fold, zero-area triangles only) keeps its
//! undisplaced normal. A fold (a scale large enough to turn triangles over) is no error: its
//! normals point where the folded triangles face, unit and finite.
//!
//! Fine meshes come from [`subdivide`](fn@super::subdivide) (the midpoints carry interpolated
//! normals and coordinates). Vertices copied along a texture seam or at a pole would move
//! apart wherever the height map differs across the seam: [`weld`](super::weld) finds
//! them once, and with its `twins` every copy takes the first copy's position and normal.
//!
//! # Animation
//! [`displace`] reads the undisplaced mesh and writes only positions and normals, so an
//! animated surface (a water grid whose `offset` moves every frame) subdivides once and
//! displaces the same base mesh each frame into the same two buffers, 24 bytes per vertex.
//!
//! # Cost
//! Per vertex, per frame, exact instruction counts:
//!
//! | where | mesh | [`displace_positions`] | [`recompute_normals`] | [`displace`] |
//! |---|---|---:|---:|---:|
//! | x86-64 (callgrind) | rocky sphere, 4655 vertices, 8832 triangles | 166 | 891 | 1057 |
//! | Cortex-M4F (QEMU) | water grid, 169 vertices, 288 triangles | | | 1191 |
//! | Cortex-M0+ (QEMU) | water grid | | | 2857 |
//!
//! (x86: `host-tests/examples/displace_cost.rs` under callgrind, release; Cortex-M: the
//! `water_displace` firmware, `examples/firmware`.) The positions cost a 16-bit bilinear
//! height and three products; the normals two exact cross products per triangle (about two
//! triangles per vertex; a first pass over the edges finds the mesh's scale) and one
//! 32-bit square root and table reciprocal per vertex. No step needs a 64-bit product but
//! the cross products and the moves along the normal. The `water` scene, displaced and drawn
//! every frame, costs about 250 instructions per pixel on the M4F and 550 on the M0+
//! (39,610 pixels), the displacement about 2% of it (0.2 M and 0.5 M instructions).
//!
//! # Fixed point and error
//! The height is bilinear with a 16-bit texel fraction, rounded to Q8 steps between the two
//! weightings and then to a Q16 fraction (not the 8-bit fraction of
//! [`HeightMap::bilinear`], which would put up to `2 Δh / 65536` of the range on every
//! vertex, `Δh` the largest step between neighbouring texels);
//! `scale · (h − bias)` is rounded once to I16F16, and so is its product with the normal.
//! Against the f64 reference (host-tests, `displacement.rs`) the positions are within
//! `1 + |scale| + levels / 2` LSB of I16F16, plus, once subdivided,
//! `|scale| Δh (w + h) / 256` LSB because the midpoints' texture coordinates are rounded to
//! I16F16 (on the rocky demo sphere: 1.1, 9.2 and 15.8 LSB at 0, 1 and 2 levels); normals
//! within 2^-7 per component (measured 3.4e-4, 9.0e-4, 3.1e-3; unit length within 2^-15).
//! Face normals are computed exactly in Q32 and scaled by one power of two per mesh before
//! they are summed in I16F16 (edges are clamped to ±16384 units, the one limit).
//!
//! ```
//! use fixel::math::{fx, Fx, Vec3};
//! use fixel::scene::{displace, Displacement, Mesh};
//! use fixel::texture::HeightMap;
//!
//! // A flat quad facing +z over a 2 x 2 height map: the corners at the white texel rise.
//! let p = [Vec3::from_num(0, 0, 0), Vec3::from_num(1, 0, 0), Vec3::from_num(1, 1, 0), Vec3::from_num(0, 1, 0)];
//! let n = [Vec3::from_num(0, 0, 1); 4];
//! let uv = [[fx(0.25), fx(0.25)], [fx(0.75), fx(0.25)], [fx(0.75), fx(0.75)], [fx(0.25), fx(0.75)]];
//! let ix = [[0u16, 1, 2], [0, 2, 3]];
//! let base = Mesh::new(&p, Some(&n), &uv, &ix)?;
//! let heights = [0u8, 0, 0, 255];
//! let d = Displacement { map: HeightMap::new(&heights, 2, 2, 1)?, scale: fx(1), bias: Fx::ZERO, offset: [Fx::ZERO; 2] };
//! let (mut dp, mut dn) = ([Vec3::ZERO; 4], [Vec3::ZERO; 4]);
//! let moved = displace(&d, &base, None, &mut dp, &mut dn)?;
//! let (p, n) = (moved.positions(), moved.normals().unwrap_or(&[]));
//! assert_eq!(p[2].z, fx(255.0 / 256.0)); // texel (1, 1) is 255 of 256 steps high
//! assert_eq!(p[0].z, Fx::ZERO);
//! assert!(n[0].z < fx(1) && n[0].z > fx(0.5)); // tilted away from the raised corner
//! # Ok::<(), fixel::Error>(())
//! ```

use super::Mesh;
use crate::geometry::mesh_checks::check_indices;
use crate::math::{isqrt_u32, reciprocal_u32, Fx, Vec3};
use crate::texture::HeightMap;
use crate::Error;

/// A height map and how it moves vertices (see the module docs for the formula).
#[derive(Clone, Copy, Debug)]
pub struct Displacement<'a> {
    /// The heights (level 0 is used).
    pub map: HeightMap<'a>,
    /// Model units per 256 height steps (negative pushes inwards).
    pub scale: Fx,
    /// The height fraction (`0..1`) that stays in place.
    pub bias: Fx,
    /// Added to every vertex's texture coordinates (1.0 = one map): a moving offset
    /// animates the surface.
    pub offset: [Fx; 2],
}

impl Displacement<'_> {
    /// How far a vertex at `uv` moves along its normal: `scale · (h(uv + offset) − bias)`,
    /// I16F16, rounded once and saturated.
    pub fn distance(&self, uv: [Fx; 2]) -> Fx {
        let s = uv[0].to_bits().wrapping_add(self.offset[0].to_bits());
        let t = uv[1].to_bits().wrapping_add(self.offset[1].to_bits());
        let h = height_q16(&self.map, s, t) - i64::from(self.bias.to_bits());
        let d = (h * i64::from(self.scale.to_bits()) + (1 << 15)) >> 16;
        Fx::from_bits(d.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32)
    }
}

/// The bilinear height of level 0 at `(s, t)` (I16F16 bits, repeating; texel centres at
/// `(i + 0.5) / size`) as a Q16 fraction of 256 steps (`0..=65280`), with a 16-bit texel
/// fraction: [`HeightMap::bilinear`] keeps 8 bits (enough per pixel), which would put up to
/// `2 Δh / 65536` of the map's range on every displaced vertex.
fn height_q16(map: &HeightMap<'_>, s: i32, t: i32) -> i64 {
    let (lw, lh) = map.log2_size();
    // Texel coordinates in Q16 minus the half-texel offset of the centres, wrapping at
    // 65536 texels (a multiple of the map's side, so the repeat is unchanged).
    let tu = (s as u32).wrapping_shl(lw).wrapping_sub(1 << 15);
    let tv = (t as u32).wrapping_shl(lh).wrapping_sub(1 << 15);
    let (i, j) = ((tu >> 16) as i32, (tv >> 16) as i32);
    let (fu, fv) = (tu & 0xFFFF, tv & 0xFFFF);
    let h = |di: i32, dj: i32| u32::from(map.height(0, i.wrapping_add(di), j.wrapping_add(dj)));
    // Q16 steps (at most 255 · 2^16), rounded to Q8 so the second weighting stays in u32
    // (at most 65280 · 2^16 < 2^32): no 64-bit product, which a Cortex-M0+ lacks.
    let top = (h(0, 0) * (65536 - fu) + h(1, 0) * fu + 128) >> 8;
    let bottom = (h(0, 1) * (65536 - fu) + h(1, 1) * fu + 128) >> 8;
    // Q24 steps; a Q16 fraction of 256 steps is Q8 steps.
    i64::from((top * (65536 - fv) + bottom * fv + (1 << 15)) >> 16)
}

/// `twins` (from [`weld`](super::weld)) has one entry per vertex, each at most its own
/// index.
fn check_twins(twins: Option<&[u16]>, n: usize) -> Result<(), Error> {
    let Some(tw) = twins else {
        return Ok(());
    };
    if tw.len() != n {
        return Err(Error::WrongLength {
            expected: n,
            actual: tw.len(),
        });
    }
    for (i, &t) in tw.iter().enumerate() {
        if usize::from(t) > i {
            return Err(Error::IndexOutOfRange {
                at: i,
                index: t,
                vertices: n,
            });
        }
    }
    Ok(())
}

fn check_len(n: usize, len: usize) -> Result<(), Error> {
    if len == n {
        Ok(())
    } else {
        Err(Error::WrongLength {
            expected: n,
            actual: len,
        })
    }
}

/// Moves every vertex of `base` along its normal by [`Displacement::distance`] into `out`
/// (one entry per vertex); vertex `i` with `twins[i] != i` takes the position of its twin.
///
/// # Errors
/// [`Error::WrongLength`] when `out` or `twins` is not one per vertex, or `base` has no
/// normals (length 0), [`Error::IndexOutOfRange`] for a twin after its vertex.
pub fn displace_positions(
    d: &Displacement<'_>,
    base: &Mesh<'_>,
    twins: Option<&[u16]>,
    out: &mut [Vec3],
) -> Result<(), Error> {
    let n = base.vertices();
    let normals = base.normals.unwrap_or(&[]);
    check_len(n, normals.len())?;
    check_len(n, out.len())?;
    check_twins(twins, n)?;
    for i in 0..n {
        let t = twins.map_or(i, |tw| usize::from(tw[i]));
        if t < i {
            out[i] = out[t];
            continue;
        }
        let dist = i64::from(d.distance(base.uvs[i]).to_bits());
        let along = |p: Fx, c: Fx| {
            let off = (i64::from(c.to_bits()) * dist + (1 << 15)) >> 16;
            Fx::from_bits(
                (i64::from(p.to_bits()) + off).clamp(i64::from(i32::MIN), i64::from(i32::MAX))
                    as i32,
            )
        };
        let (p, nm) = (base.positions[i], normals[i]);
        out[i] = Vec3::new(along(p.x, nm.x), along(p.y, nm.y), along(p.z, nm.z));
    }
    Ok(())
}

/// Edge components are clamped to ±16384 units (2^30 bits) so the Q32 products fit.
const EDGE_LIMIT: i64 = 1 << 30;

/// `(p1 − p0) × (p2 − p0)` exactly, Q32 per component.
#[inline]
fn face_normal(p: [Vec3; 3]) -> [i64; 3] {
    let e = |a: Fx, b: Fx| {
        (i64::from(b.to_bits()) - i64::from(a.to_bits())).clamp(-EDGE_LIMIT, EDGE_LIMIT)
    };
    let (ax, ay, az) = (e(p[0].x, p[1].x), e(p[0].y, p[1].y), e(p[0].z, p[1].z));
    let (bx, by, bz) = (e(p[0].x, p[2].x), e(p[0].y, p[2].y), e(p[0].z, p[2].z));
    [ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx]
}

/// The three corners of `tri` (every index checked by the caller).
#[inline]
fn corners(positions: &[Vec3], tri: &[u16; 3]) -> [Vec3; 3] {
    tri.map(|i| positions.get(usize::from(i)).copied().unwrap_or(Vec3::ZERO))
}

/// The area-weighted vertex normals of the mesh `positions` / `indices` into `out`,
/// renormalised; a vertex whose sum is zero (no triangle, or only zero-area ones, or
/// folds that cancel) gets `fallback[i]`. With `twins`, copies of a vertex share the sum
/// of all their triangles. All slices have one entry per vertex.
///
/// # Errors
/// [`Error::WrongLength`] for a slice of another length, [`Error::IndexOutOfRange`] for an
/// index past the vertices or a twin after its vertex.
pub fn recompute_normals(
    positions: &[Vec3],
    indices: &[[u16; 3]],
    fallback: &[Vec3],
    twins: Option<&[u16]>,
    out: &mut [Vec3],
) -> Result<(), Error> {
    let n = positions.len();
    check_len(n, fallback.len())?;
    check_len(n, out.len())?;
    check_twins(twins, n)?;
    check_indices(indices, n)?;
    let twin = |i: usize| twins.map_or(i, |tw| usize::from(tw[i]));
    // One power of two for the whole mesh keeps the largest face's sum (up to 127
    // triangles a vertex) within I16F16 and the small faces' digits.
    // No component of a face's cross product exceeds 2 e², `e` its largest edge component.
    let edge = indices
        .iter()
        .map(|tri| {
            let p = corners(positions, tri);
            let e = |a: Fx, b: Fx| {
                (i64::from(b.to_bits()) - i64::from(a.to_bits()))
                    .clamp(-EDGE_LIMIT, EDGE_LIMIT)
                    .unsigned_abs()
            };
            [
                e(p[0].x, p[1].x),
                e(p[0].y, p[1].y),
                e(p[0].z, p[1].z),
                e(p[0].x, p[2].x),
                e(p[0].y, p[2].y),
                e(p[0].z, p[2].z),
            ]
            .into_iter()
            .max()
            .unwrap_or(0)
        })
        .max()
        .unwrap_or(0);
    let most = 2 * edge * edge;
    let shift = (64 - most.leading_zeros()).saturating_sub(24);
    let down = |c: i64| -> i32 {
        let c = if shift == 0 {
            c
        } else {
            (c + (1 << (shift - 1))) >> shift
        };
        c.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
    };
    out.fill(Vec3::ZERO);
    for tri in indices {
        let f = face_normal(corners(positions, tri)).map(down);
        for &i in tri {
            let slot = &mut out[twin(usize::from(i))];
            let add = |a: Fx, b: i32| Fx::from_bits(a.to_bits().saturating_add(b));
            *slot = Vec3::new(add(slot.x, f[0]), add(slot.y, f[1]), add(slot.z, f[2]));
        }
    }
    for i in 0..n {
        let t = twin(i);
        out[i] = if t < i {
            out[t]
        } else {
            let s = out[i];
            unit_of_sum([s.x.to_bits(), s.y.to_bits(), s.z.to_bits()]).unwrap_or(fallback[i])
        };
    }
    Ok(())
}

/// The unit vector along `v` (any scale), I16F16, or `None` for zero: the components are
/// shifted so that the largest has 15 bits, then divided by the rounded 32-bit square root
/// of their squares through the table reciprocal. Within about 2^-15 per component: less
/// exact than [`Vec3::normalize`] (2^-17) and, on a Cortex-M0+ without 64-bit arithmetic,
/// far cheaper (no 64-bit square root).
fn unit_of_sum(v: [i32; 3]) -> Option<Vec3> {
    let most = v.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
    if most == 0 {
        return None;
    }
    let bits = 32 - most.leading_zeros();
    let c = v.map(|x| {
        if bits > 15 {
            x >> (bits - 15)
        } else {
            x << (15 - bits)
        }
    });
    // Each square is below 2^30 (|c| <= 2^15), three below 2^32.
    let l2 = c.iter().map(|x| x.unsigned_abs().pow(2)).sum::<u32>();
    let l = u32::from(isqrt_u32(l2));
    // Round to nearest: l + 1/2 squared is l^2 + l + 1/4.
    let l = if l2 - l * l > l { l + 1 } else { l };
    let (m, e) = reciprocal_u32(l);
    // c / l in Q16 = |c| m / 2^(e - 16); l >= 2^14, so e - 16 >= 29.
    let sh = e.saturating_sub(16).max(1);
    let unit = |x: i32| {
        let mag = (u64::from(x.unsigned_abs()) * u64::from(m) + (1 << (sh - 1))) >> sh;
        let mag = mag.min(1 << 16) as i32;
        Fx::from_bits(if x < 0 { -mag } else { mag })
    };
    Some(Vec3::new(unit(c[0]), unit(c[1]), unit(c[2])))
}

/// Displaces `base` ([`displace_positions`]) and recomputes its normals
/// ([`recompute_normals`], falling back to `base`'s) into `positions` and `normals` (one
/// entry per vertex each); returns the displaced mesh, which shares `base`'s texture
/// coordinates and triangles. Call it again each frame with a new [`Displacement`] (a
/// moving `offset`) to animate: `base` is never changed.
///
/// # Errors
/// As [`displace_positions`] and [`recompute_normals`].
pub fn displace<'a>(
    d: &Displacement<'_>,
    base: &Mesh<'a>,
    twins: Option<&[u16]>,
    positions: &'a mut [Vec3],
    normals: &'a mut [Vec3],
) -> Result<Mesh<'a>, Error> {
    displace_positions(d, base, twins, positions)?;
    let fallback = base.normals.unwrap_or(&[]);
    recompute_normals(positions, base.indices, fallback, twins, normals)?;
    Mesh::new(positions, Some(normals), base.uvs, base.indices)
}
