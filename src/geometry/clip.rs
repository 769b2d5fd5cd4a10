//! Homogeneous clipping in clip space, then projection to the screen.
//!
//! A triangle is clipped (Sutherland–Hodgman) against up to seven planes: `w >= W_MIN`,
//! near `z >= -w`, far `z <= w`, and the four guard-band planes `|x| <= gx w`,
//! `|y| <= gy w` (see [`Viewport`]). Only planes that some vertex violates are visited; a
//! triangle entirely outside one plane is dropped; the common all-inside case does no clipping
//! work at all. The surviving convex polygon (at most 10 vertices) is projected and
//! fan-triangulated; back- or front-facing and zero-area triangles are skipped.
//!
//! Watertightness: an edge is always cut from its inside vertex towards its outside vertex,
//! so two triangles sharing an edge compute bit-identical intersection points.
//!
//! Arithmetic: plane distances and interpolation in `i64`; the parameter `t` is Q30.
//! Attributes (position and any number of varyings) are interpolated linearly in clip space, which is
//! correct for perspective (GL does the same).

use super::vertex::{ClipVertex, ScreenTriangle, ScreenVertex, Vertex, CLASSIC_VARYINGS};
use super::viewport::{Cull, Viewport};
use crate::math::div_u64;

/// Smallest clip-space `w` that reaches the rasterizer: 2^-8 (I16F16 bits 256). Keeps
/// `1/w` bounded for any input, including a low-level caller's w-near-zero vertices.
pub const W_MIN_BITS: i32 = 256;

const MAX_POLY: usize = 10;
const PLANES: usize = 7;

/// A clip vertex as plain integers: position `x, y, z, w` (I16F16 bits) and the varyings.
#[derive(Clone, Copy)]
struct Attr<const N: usize> {
    p: [i32; 4],
    v: [i32; N],
}

#[inline]
fn attr<const N: usize>(v: &Vertex<N>) -> Attr<N> {
    Attr {
        p: v.position.map(|c| c.to_bits()),
        v: v.varyings,
    }
}

/// `g w` exactly, for a guard-band factor `0 < g < 2^15` ([`Viewport`] keeps it below
/// 2 x 4096). On ARMv6-M, where an `i64` product is an `__aeabi_lmul` call, two 32-bit
/// products of `g` and the halves of `w` (each below 2^30 in magnitude).
#[inline(always)]
fn guard_times(g: i32, w: i32) -> i64 {
    if cfg!(all(target_arch = "arm", not(target_has_atomic = "32"))) {
        guard_times_split(g, w)
    } else {
        i64::from(g) * i64::from(w)
    }
}

/// The ARMv6-M form of [`guard_times`] (compiled everywhere, so the host tests it).
#[inline(always)]
fn guard_times_split(g: i32, w: i32) -> i64 {
    (i64::from(g.wrapping_mul(w >> 16)) << 16) + i64::from(g.wrapping_mul(w & 0xFFFF))
}

#[inline]
fn dist(plane: usize, p: &[i32; 4], guard: (i32, i32)) -> i64 {
    let [x, y, z, w] = p.map(i64::from);
    match plane {
        0 => w - i64::from(W_MIN_BITS),
        1 => z + w,
        2 => w - z,
        3 => guard_times(guard.0, p[3]) - x,
        4 => guard_times(guard.0, p[3]) + x,
        5 => guard_times(guard.1, p[3]) - y,
        _ => guard_times(guard.1, p[3]) + y,
    }
}

/// [`dist`] for a plane known only at run time (the clipping loop), from tables rather than
/// a seven-way match: the same integers in fewer bytes, on the rare path.
#[inline(never)]
fn dist_any(plane: usize, p: &[i32; 4], guard: (i32, i32)) -> i64 {
    let w = i64::from(p[3]);
    let Some(k) = plane.checked_sub(1).filter(|&k| k < 6) else {
        return w - i64::from(W_MIN_BITS);
    };
    // Planes 1..=6: w + z, w - z, gx w - x, gx w + x, gy w - y, gy w + y.
    let c = i64::from(p[[2, 2, 0, 0, 1, 1][k]]);
    let gw = guard_times([1, 1, guard.0, guard.0, guard.1, guard.1][k], p[3]);
    if (0b10_1001 >> k) & 1 == 1 {
        gw + c
    } else {
        gw - c
    }
}

/// The planes `pos` violates (bit `p` for plane `p`). Out of line for the clipper and the
/// unclipped projection, which test three corners (one copy instead of three: 0.2 to 0.4 KB
/// of flash); [`outcode_inline`] for the mesh walker's one vertex at a time.
#[inline(never)]
fn outcode(pos: &[i32; 4], guard: (i32, i32)) -> u8 {
    outcode_inline(pos, guard)
}

/// [`outcode`] inlined: the mesh walker prepares each vertex once per band it touches, and
/// the call costs Cortex-M0+ about 1 % of the banded sphere.
#[inline(always)]
fn outcode_inline(pos: &[i32; 4], guard: (i32, i32)) -> u8 {
    let mut c = 0;
    for p in 0..PLANES {
        if dist(p, pos, guard) < 0 {
            c |= 1 << p;
        }
    }
    c
}

/// A triangle's vertices as integers, and the planes each violates, for
/// [`project_unclipped_varyings`]. The clipper writes the corners straight into its polygon
/// buffer instead; both classify a corner through the one [`outcode`], so alike.
#[inline(always)]
fn attrs_and_codes<const N: usize>(
    tri: &[Vertex<N>; 3],
    guard: (i32, i32),
) -> ([Attr<N>; 3], [u8; 3]) {
    let a = [attr(&tri[0]), attr(&tri[1]), attr(&tri[2])];
    let codes = [
        outcode(&a[0].p, guard),
        outcode(&a[1].p, guard),
        outcode(&a[2].p, guard),
    ];
    (a, codes)
}

/// `a + (b - a) t` for Q30 `t` in `[0, 1]`, rounded; exact in `i64` for any `i32` ends.
/// Out of line: LLVM unrolls the loop of [`lerp_all`] into copies of its 64-bit product.
#[inline(never)]
fn lerp_q30(a: i32, b: i32, t: i64) -> i32 {
    let a = i64::from(a);
    let d = i64::from(b) - a;
    (a + ((d * t + (1 << 29)) >> 30)) as i32
}

/// `a[k] = lerp_q30(a[k], b[k], t)` for every `k`: one copy for the position and the
/// varyings (the clipper is the rare path, written for flash).
#[inline(never)]
fn lerp_all(a: &mut [i32], b: &[i32], t: i64) {
    for (a, &b) in a.iter_mut().zip(b) {
        *a = lerp_q30(*a, b, t);
    }
}

/// Point on the edge from `inside` (distance `di >= 0`) to `outside` (`do_ < 0`).
///
/// The position is interpolated in clip space at the parameter `t` where the edge meets the
/// plane. The varyings too (`noperspective == false`: perspective-correct), or, for affine
/// draws, at the parameter `t' = t w_out / w(t)` of the new vertex's *screen* position
/// along the edge, so that they stay linear in screen space over the whole original
/// triangle as GL's `noperspective` is: affine output then does not depend on where the
/// guard band cuts. (Where an end has `w <= 0` it has no screen position, and `t` is kept.)
#[inline(never)]
fn intersect<const N: usize>(
    inside: &Attr<N>,
    outside: &Attr<N>,
    di: i64,
    do_: i64,
    noperspective: bool,
) -> Attr<N> {
    let mut num = di;
    let mut den = di - do_;
    while den >= 1 << 32 {
        num >>= 1;
        den >>= 1;
    }
    // Q30 in [0, 1]: 0 <= num <= den < 2^32 (the inside end's distance over the edge's),
    // so the unsigned 32-bit paths of `div_u64` give the same quotient as `i64` `/` without
    // linking the 64-bit library division.
    let t = div_u64((num.max(0) << 30) as u64, den.max(1) as u64) as i64;
    let mut out = *inside;
    lerp_all(&mut out.p, &outside.p, t);
    let (w_in, w_out, w_t) = (inside.p[3], outside.p[3], out.p[3]);
    let t = if noperspective && w_in > 0 && w_out > 0 && w_t > 0 {
        // t w_out < 2^61; the quotient is in [0, 2^30] up to rounding.
        (div_u64((t * i64::from(w_out)) as u64, w_t as u64).min(1 << 30)) as i64
    } else {
        t
    };
    lerp_all(&mut out.v, &outside.v, t);
    out
}

/// Clips a classic [`ClipVertex`] triangle (see [`clip_and_project_varyings`]); its
/// screen triangles carry the varyings of [`ClipVertex::to_vertex`]. `noperspective`: the
/// varyings of new vertices are those of GL's `noperspective` (for affine draws).
pub fn clip_and_project(
    tri: &[ClipVertex; 3],
    vp: &Viewport,
    cull: Cull,
    noperspective: bool,
    emit: &mut impl FnMut(&ScreenTriangle<CLASSIC_VARYINGS>),
) {
    clip_and_project_varyings(
        &[tri[0].to_vertex(), tri[1].to_vertex(), tri[2].to_vertex()],
        vp,
        cull,
        noperspective,
        emit,
    );
}

/// Clips `tri` to the view volume and guard band, projects it with `vp`, culls per `cull`,
/// and calls `emit` with each resulting screen triangle (0 to 8 of them).
///
/// Varyings at the new vertices: with `noperspective == false`, interpolated linearly in
/// clip space, which is perspective-correct; with `true` (affine draws), linearly in screen
/// space along the cut edge, as GL's `noperspective` (see `intersect`).
pub fn clip_and_project_varyings<const N: usize>(
    tri: &[Vertex<N>; 3],
    vp: &Viewport,
    cull: Cull,
    noperspective: bool,
    emit: &mut impl FnMut(&ScreenTriangle<N>),
) {
    let guard = vp.guard;
    let empty = Attr {
        p: [0; 4],
        v: [0; N],
    };
    // The corners straight into the polygon buffer (as `attrs_and_codes`, without an
    // array of them to copy in: that copy links `memcpy` while `outcode` is out of line).
    let mut poly = [empty; MAX_POLY];
    for (d, v) in poly.iter_mut().zip(tri) {
        *d = attr(v);
    }
    let codes = [
        outcode(&poly[0].p, guard),
        outcode(&poly[1].p, guard),
        outcode(&poly[2].p, guard),
    ];
    if codes[0] & codes[1] & codes[2] != 0 {
        return; // wholly outside one plane
    }
    let mut n = 3;
    let any = codes[0] | codes[1] | codes[2];
    // Clipping alternates between two polygon buffers by swapping references (copying the
    // clipped polygon back each plane linked a variable-length `memcpy`, ~900 bytes).
    let mut spare;
    let fin: &[Attr<N>] = if any != 0 {
        spare = [empty; MAX_POLY];
        let (mut src, mut dst) = (&mut poly, &mut spare);
        // Only the planes some vertex is outside of, one at a time: a loop whose trip count
        // LLVM cannot know is not unrolled into a copy of the polygon loop per plane.
        let mut planes = any;
        while planes != 0 {
            let plane = planes.trailing_zeros() as usize;
            planes &= planes - 1;
            let mut m = 0;
            for i in 0..n {
                let (cur, nxt) = (&src[i], &src[(i + 1) % n]);
                let (dc, dn) = (
                    dist_any(plane, &cur.p, guard),
                    dist_any(plane, &nxt.p, guard),
                );
                if dc >= 0 && m < MAX_POLY {
                    dst[m] = *cur;
                    m += 1;
                }
                if (dc >= 0) != (dn >= 0) && m < MAX_POLY {
                    dst[m] = if dc >= 0 {
                        intersect(cur, nxt, dc, dn, noperspective)
                    } else {
                        intersect(nxt, cur, dn, dc, noperspective)
                    };
                    m += 1;
                }
            }
            n = m;
            if n < 3 {
                return;
            }
            core::mem::swap(&mut src, &mut dst);
        }
        &src[..n]
    } else {
        &poly[..n]
    };
    // A fan from the first vertex, each vertex projected once into a sliding triangle (no
    // array of projected vertices to fill and copy triangles out of).
    let mut t = [ScreenVertex::<N>::default(); 3];
    for (k, a) in fin.iter().enumerate() {
        // Through a local copy: `fin` points into either polygon buffer, and a copy straight
        // from it makes LLVM link `memmove` (1.6 KB) for wide vertices.
        let a = *a;
        t[1] = t[2];
        t[2] = project_attr(&a, vp);
        if k == 0 {
            t[0] = t[2];
        } else if k >= 2 && keeps(&t, cull) {
            emit(&t);
        }
    }
}

/// Projects and culls a classic [`ClipVertex`] triangle that needs no clipping, as
/// [`clip_and_project`] would (the same screen triangle, bit for bit), without linking the
/// clipper. Returns `false`, emitting nothing, when the triangle crosses a plane of the view
/// volume or guard band (it would have to be clipped); a triangle wholly outside one plane
/// is dropped and counts as handled (`true`).
pub fn project_unclipped(
    tri: &[ClipVertex; 3],
    vp: &Viewport,
    cull: Cull,
    emit: &mut impl FnMut(&ScreenTriangle<CLASSIC_VARYINGS>),
) -> bool {
    let tri = [tri[0].to_vertex(), tri[1].to_vertex(), tri[2].to_vertex()];
    project_unclipped_varyings(&tri, vp, cull, emit)
}

/// [`project_unclipped`] for a triangle of any varyings: as [`clip_and_project_varyings`]
/// would project and cull it (the same screen triangle, bit for bit; `noperspective` only
/// matters for clipped vertices), without linking the clipper. `false`, emitting nothing,
/// when the triangle would have to be clipped; `true` when it was handled (drawn, culled, or
/// wholly outside one plane).
pub fn project_unclipped_varyings<const N: usize>(
    tri: &[Vertex<N>; 3],
    vp: &Viewport,
    cull: Cull,
    emit: &mut impl FnMut(&ScreenTriangle<N>),
) -> bool {
    let (a, codes) = attrs_and_codes(tri, vp.guard);
    if codes[0] & codes[1] & codes[2] != 0 {
        return true; // wholly outside one plane: nothing to draw
    }
    if codes[0] | codes[1] | codes[2] != 0 {
        return false; // it would be clipped
    }
    let t = a.each_ref().map(|a| project_attr(a, vp));
    if keeps(&t, cull) {
        emit(&t);
    }
    true
}

/// Perspective divide and viewport mapping of one clip-space vertex (`w` raised to
/// [`W_MIN_BITS`]).
fn project_attr<const N: usize>(a: &Attr<N>, vp: &Viewport) -> ScreenVertex<N> {
    let w = a.p[3].max(W_MIN_BITS);
    let (x, y, sub, z) = vp.project(a.p[0], a.p[1], a.p[2], w);
    ScreenVertex {
        x,
        y,
        sub,
        z,
        w,
        varyings: a.v,
    }
}

/// Whether a projected triangle survives culling: non-zero area and, per `cull`, the
/// wanted winding (sub-pixel coordinates; the `i64` area is exact for any coordinates that
/// differ by less than 2^31, far beyond the guard band).
pub fn keeps<const N: usize>(t: &ScreenTriangle<N>, cull: Cull) -> bool {
    keeps_xy([(t[0].x, t[0].y), (t[1].x, t[1].y), (t[2].x, t[2].y)], cull)
}

/// [`keeps`] from the three vertices' sub-pixel positions alone (a walker can cull before
/// it builds the screen vertices).
#[inline]
pub fn keeps_xy(t: [(i32, i32); 3], cull: Cull) -> bool {
    // Wrapping only where coordinates differ by 2^31 or more (never a panic).
    let d = |a: i32, b: i32| i64::from(a) - i64::from(b);
    let area2 = crate::math::wide::det2(
        d(t[1].0, t[0].0),
        d(t[2].0, t[0].0),
        d(t[1].1, t[0].1),
        d(t[2].1, t[0].1),
    );
    // y points down on screen, so counter-clockwise in NDC (front) has negative area.
    let front = area2 < 0;
    area2 != 0
        && match cull {
            Cull::None => true,
            Cull::Back => front,
            Cull::Front => !front,
        }
}

/// One vertex prepared for [`clip_and_project`]'s unclipped case: its outcode (the planes
/// it violates, 0 when inside the view volume and guard band) and its projection. When the
/// three vertices of a triangle have outcode 0, `clip_and_project` emits exactly
/// `[a.screen, b.screen, c.screen]` if [`keeps`] holds, so a caller that caches prepared
/// vertices gets the same screen triangles without projecting a shared vertex again.
pub fn prepare(v: &ClipVertex, vp: &Viewport) -> (u8, ScreenVertex) {
    let a = attr(&v.to_vertex());
    (outcode_inline(&a.p, vp.guard), project_attr(&a, vp))
}

/// [`prepare`] without the depth division: the screen vertex's `z` holds the *clip-space*
/// `z` (I16F16 bits) until [`complete_depth`] replaces it. For passes that need only rows
/// and winding (band binning).
pub fn prepare_without_depth(v: &ClipVertex, vp: &Viewport) -> (u8, ScreenVertex) {
    let a = attr(&v.to_vertex());
    let w = a.p[3].max(W_MIN_BITS);
    let (x, y, sub) = vp.project_xy(a.p[0], a.p[1], w);
    let s = ScreenVertex {
        x,
        y,
        sub,
        z: a.p[2],
        w,
        varyings: a.v,
    };
    (outcode_inline(&a.p, vp.guard), s)
}

/// Turns a vertex from [`prepare_without_depth`] into what [`prepare`] gives.
pub fn complete_depth<const N: usize>(s: &mut ScreenVertex<N>, vp: &Viewport) {
    s.z = vp.project_z(s.z, s.w);
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::math::Fx;
    use std::vec::Vec;

    fn v(x: f32, y: f32, z: f32, w: f32) -> ClipVertex {
        ClipVertex::new(
            [
                Fx::from_num(x),
                Fx::from_num(y),
                Fx::from_num(z),
                Fx::from_num(w),
            ],
            [Fx::ZERO; 2],
        )
    }

    fn run(tri: [ClipVertex; 3], cull: Cull) -> Vec<ScreenTriangle> {
        let vp = Viewport::new(0, 0, 320, 240).unwrap();
        let mut out = Vec::new();
        clip_and_project(&tri, &vp, cull, false, &mut |t| out.push(*t));
        out
    }

    #[test]
    fn inside_triangle_passes_unclipped_and_culls_by_winding() {
        let ccw = [
            v(-0.5, -0.5, 0.0, 1.0),
            v(0.5, -0.5, 0.0, 1.0),
            v(0.0, 0.5, 0.0, 1.0),
        ];
        assert_eq!(run(ccw, Cull::Back).len(), 1);
        assert_eq!(run(ccw, Cull::Front).len(), 0);
        let cw = [ccw[0], ccw[2], ccw[1]];
        assert_eq!(run(cw, Cull::Back).len(), 0);
        assert_eq!(run(cw, Cull::None).len(), 1);
    }

    #[test]
    fn behind_camera_is_dropped_and_near_crossing_is_clipped() {
        let behind = [
            v(-1.0, -1.0, -3.0, -2.0),
            v(1.0, -1.0, -3.0, -2.0),
            v(0.0, 1.0, -3.0, -2.0),
        ];
        assert!(run(behind, Cull::None).is_empty());
        let crossing = [
            v(-1.0, -1.0, -2.0, 0.001),
            v(1.0, -1.0, 0.5, 1.0),
            v(0.0, 1.0, 0.5, 1.0),
        ];
        let out = run(crossing, Cull::None);
        assert!(!out.is_empty());
        for t in &out {
            for s in t {
                assert!(s.w >= W_MIN_BITS && s.z >= 0 && s.z <= 65535 << 14);
            }
        }
    }

    /// Without the clipper: the same screen triangles for triangles in view, `false` and
    /// nothing for those that cross a plane, `true` and nothing for those wholly outside.
    #[test]
    fn unclipped_projection_is_the_clippers_for_triangles_in_view() {
        let vp = Viewport::new(0, 0, 320, 240).unwrap();
        let mut rng = crate::test_rng::Rng(0xc11f_0ff5);
        let mut coord = |span: f64| (rng.unit01() * 2.0 - 1.0) * span;
        let (mut inside, mut crossing, mut outside) = (0, 0, 0);
        for i in 0..4000 {
            let span = [0.9, 1.5, 40.0][i % 3];
            let mut c = [[0.0f32; 4]; 3];
            for p in c.iter_mut() {
                let w = 0.3 + coord(1.0).abs() * 4.0;
                *p = [
                    (coord(span) * w) as f32,
                    (coord(span) * w) as f32,
                    (coord(1.2) * w) as f32,
                    if i % 7 == 0 { -w as f32 } else { w as f32 },
                ];
            }
            let tri = c.map(|[x, y, z, w]| v(x, y, z, w));
            for cull in [Cull::None, Cull::Back] {
                let mut clipped = Vec::new();
                clip_and_project(&tri, &vp, cull, false, &mut |t| clipped.push(*t));
                let mut direct = Vec::new();
                let handled = project_unclipped(&tri, &vp, cull, &mut |t| direct.push(*t));
                if handled {
                    assert_eq!(direct, clipped, "{tri:?}");
                    if clipped.is_empty() {
                        outside += 1;
                    } else {
                        inside += 1;
                    }
                } else {
                    assert!(direct.is_empty());
                    crossing += 1;
                }
            }
        }
        assert!(
            inside > 500 && crossing > 500 && outside > 500,
            "{inside} {crossing} {outside}"
        );
    }

    #[test]
    fn split_guard_products_are_exact() {
        let mut rng = crate::test_rng::Rng(0x9E37_79B9_7F4A_7C15);
        for i in 0..100_000 {
            let x = rng.next();
            let w = match i % 5 {
                0 => i32::MIN,
                1 => i32::MAX,
                _ => x as i32,
            };
            let g = 1 + ((x >> 40) as i32 & 0x7FFE);
            assert_eq!(
                guard_times_split(g, w),
                i64::from(g) * i64::from(w),
                "{g} {w}"
            );
        }
    }

    #[test]
    fn table_distances_are_the_match_distances() {
        let mut rng = crate::test_rng::Rng(0x2545_F491_4F6C_DD1D);
        for i in 0..20_000 {
            let x = rng.next();
            let p = [
                x as i32,
                (x >> 16) as i32,
                (x >> 32) as i32,
                (x >> 24) as i32,
            ];
            let p = if i % 4 == 0 { p.map(|c| c >> 12) } else { p };
            let guard = (i32::from((x >> 40) as u16), i32::from((x >> 48) as u16));
            for plane in 0..PLANES {
                assert_eq!(
                    dist_any(plane, &p, guard),
                    dist(plane, &p, guard),
                    "{plane}"
                );
            }
        }
    }

    #[test]
    fn enormous_triangles_stay_inside_the_guard_band() {
        let big = 30000.0;
        let tri = [
            v(-big, -big, 0.0, 1.0),
            v(big, -big, 0.0, 1.0),
            v(0.0, big, 0.0, 0.004),
        ];
        let out = run(tri, Cull::None);
        assert!(!out.is_empty());
        let lim = crate::geometry::GUARD_BAND_PX * 16;
        for t in &out {
            for s in t {
                assert!(s.x.abs() <= lim && s.y.abs() <= lim, "{s:?}");
            }
        }
    }
}
