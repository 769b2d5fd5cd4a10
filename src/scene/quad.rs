//! Textured quadrilaterals on screen with exact projective mapping and no 3D set-up
//! (Heckbert, "Fundamentals of Texture Mapping and Image Warping", 1989): a photo, a dial or
//! a sprite on any convex four-corner shape, for user interfaces.
//!
//! [`draw_quad`] finds the homography of the unit square onto the corners
//! ([`Homography`]), clips the quad to the viewport (plus a quarter pixel) in screen space,
//! snaps it to the raster's 1/16 pixel, and draws the clipped convex polygon (up to eight
//! corners) as a fan of screen triangles whose `w` are proportional to the homography's
//! denominator at each corner, so the span loop's perspective-correct interpolation of `(u, v)` is the
//! projective map itself: exact at every pixel with
//! [`Projection::Exact`](crate::pipeline::Projection::Exact), within the subdivision's error
//! with `Subdivided`, and a plain affine map per triangle with `Affine` (the classic
//! two-triangle seam). The draw's texture, filter, wrap, shading and depth test apply as
//! to any triangle; the quad lies at depth 1/2 and its colour is white.
//!
//! The corners never pass through clip space, whose `w` range would drop corners with a
//! tiny weight: the outline is the quad's, to the raster's 1/16 pixel, whatever the
//! weights. The weights keep 22 bits of range (the largest is `2^30` in I16F16, the
//! smallest the clipper's minimum `w`); a smaller one (a corner within about a millionth
//! of the quad's size of the line through its neighbours) is raised to it, which bends the
//! texture map near that corner but never the outline.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::scene::draw_quad;
//!
//! let texels = [Rgb565::new(31, 0, 0), Rgb565::new(0, 63, 0), Rgb565::new(0, 0, 31), Rgb565::WHITE];
//! let tex = Texture::new(&texels, 2, 2)?;
//! let mode = DrawMode { projection: Projection::Exact, cull: Cull::None, ..DrawMode::default() };
//! let draw = Draw::dynamic(mode, Some(tex), Viewport::new(0, 0, 64, 48)?)?;
//! let mut pixels = [Rgb565::BLACK; 64 * 48];
//! let mut frame = Frame::new(&mut pixels, 64, 48)?;
//! // A card seen in perspective: the far edge shorter than the near one.
//! let corners = [[fx(20), fx(8)], [fx(44), fx(8)], [fx(60), fx(40)], [fx(4), fx(40)]];
//! assert!(draw_quad(&draw, corners, &mut frame)? > 800);
//! # Ok::<(), fixel::Error>(())
//! ```

use crate::color::TargetColor;
use crate::geometry::{keeps, Homography, ScreenTriangle, ScreenVertex, COLOR_ONE};
use crate::math::Fx;
use crate::pipeline::Draw;
use crate::raster::{ATTR_SUBPIXEL_BITS, SUBPIXEL_BITS};
use crate::surface::RenderTarget;
use crate::Error;

/// The most triangles [`quad_triangles`] makes: a convex quad clipped to a rectangle has at
/// most eight corners.
pub const QUAD_TRIANGLES_MAX: usize = 6;

/// Margin of the screen-space clip around the viewport, I16F16 pixels (1/4): pixel centres
/// on the viewport's edge stay strictly inside the clipped polygon.
const MARGIN: i64 = 1 << 14;
/// The largest corner weight, I16F16 `w` bits (1/4 in value).
const W_TOP: i128 = 1 << 30;
/// The smallest corner weight: the clipper's minimum `w`, which the span set-up's
/// reciprocals are built for.
const W_FLOOR: i128 = crate::geometry::W_MIN_BITS as i128;
/// Window depth of the quad: 1/2 (`0..=65535 << 14`), where clip `z = 0` lands.
const QUAD_DEPTH: i32 = 65535 << 13;
/// Colour 1.0 in a screen vertex's Q8.16 colour varyings: the quad is white.
const WHITE_Q16: i32 = (COLOR_ONE as i32) << 16;

/// The screen triangles of a quad ([`quad_triangles`]): up to [`QUAD_TRIANGLES_MAX`].
#[derive(Clone, Copy, Debug)]
pub struct QuadTriangles {
    tris: [ScreenTriangle; QUAD_TRIANGLES_MAX],
    len: u8,
}

impl QuadTriangles {
    /// The triangles (none when the quad misses the viewport or is culled).
    pub fn as_slice(&self) -> &[ScreenTriangle] {
        &self.tris[..usize::from(self.len)]
    }
}

/// A convex polygon in I16F16 screen pixels, each corner tagged with the quad corner it is
/// (`0..4`) or `4` for a corner made by the clip.
#[derive(Clone, Copy)]
struct Polygon {
    p: [[i64; 2]; 8],
    tag: [u8; 8],
    len: usize,
}

/// `a + (b - a) t` with `t = num / den` (`den != 0`), rounded to nearest.
fn lerp(a: i64, b: i64, num: i64, den: i64) -> i64 {
    let (n, d) = (i128::from(b - a) * i128::from(num), i128::from(den));
    let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
    a + (2 * n + d).div_euclid(2 * d) as i64
}

/// Sutherland–Hodgman against one line `p[axis] = bound`, keeping `p[axis] >= bound`
/// (`keep_above`) or `<=` it. Exact on the line's axis; the other coordinate of a new
/// corner is rounded to the nearest I16F16 bit.
fn clip(poly: &Polygon, axis: usize, bound: i64, keep_above: bool) -> Polygon {
    let inside = |p: &[i64; 2]| {
        if keep_above {
            p[axis] >= bound
        } else {
            p[axis] <= bound
        }
    };
    let mut out = Polygon {
        p: [[0; 2]; 8],
        tag: [4; 8],
        len: 0,
    };
    let mut push = |p: [i64; 2], tag: u8| {
        if out.len < out.p.len() {
            out.p[out.len] = p;
            out.tag[out.len] = tag;
            out.len += 1;
        }
    };
    for k in 0..poly.len {
        let (a, b) = (poly.p[k], poly.p[(k + 1) % poly.len]);
        let (ia, ib) = (inside(&a), inside(&b));
        if ia {
            push(a, poly.tag[k]);
        }
        if ia != ib {
            let o = 1 - axis;
            let mut p = [0; 2];
            p[axis] = bound;
            p[o] = lerp(a[o], b[o], bound - a[axis], b[axis] - a[axis]);
            push(p, 4);
        }
    }
    out
}

/// Rounds `v` (I16F16 bits) to the nearest multiple of `2^shift` bits, ties up, in
/// multiples of it.
fn round_shift(v: i64, shift: u32) -> i64 {
    (v + (1 << (shift - 1))) >> shift
}

/// Removes corners of `p` (1/16-pixel positions) that do not turn the polygon's way (the
/// sign of twice its area `orient`): after snapping, nearly collinear corners can dent the
/// clipped polygon, and a fan over a dent would draw a pixel twice.
fn make_convex(poly: &mut Polygon, sub: &mut [[i64; 2]; 8], orient: i64) {
    let mut k = 0;
    while poly.len >= 3 && k < poly.len {
        let n = poly.len;
        let (a, b, c) = (sub[(k + n - 1) % n], sub[k], sub[(k + 1) % n]);
        let turn = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
        if turn.signum() == orient.signum() {
            k += 1;
            continue;
        }
        for j in k..n - 1 {
            sub[j] = sub[j + 1];
            poly.p[j] = poly.p[j + 1];
            poly.tag[j] = poly.tag[j + 1];
        }
        poly.len -= 1;
        k = 0;
    }
}

/// Screen triangles of the quad `corners` (I16F16 pixels, the images of texture
/// coordinates `(0,0), (1,0), (1,1), (0,1)`) in `draw`'s viewport: the quad clipped to the
/// viewport as a fan (see the module docs), culled as `draw` culls. Refused as
/// [`Homography::square_to_quad`] refuses, except that only the inverse map must hold the
/// corners (the outline is the corners themselves).
pub fn quad_triangles<C: TargetColor>(
    draw: &Draw<'_, C>,
    corners: [[Fx; 2]; 4],
) -> Result<QuadTriangles, Error> {
    // Drawn through the inverse alone: only its corners need to hold.
    let (h, _) = Homography::square_to_quad_unchecked(corners)?;
    h.check_corners(corners, false)?;
    let inverse = h.inverse();
    let r = draw.viewport().rect();
    let mut poly = Polygon {
        p: [[0; 2]; 8],
        tag: [4; 8],
        len: 4,
    };
    for (k, c) in corners.iter().enumerate() {
        poly.p[k] = c.map(|v| i64::from(v.to_bits()));
        poly.tag[k] = k as u8;
    }
    let lo = [i64::from(r.x0), i64::from(r.y0)].map(|v| (v << 16) - MARGIN);
    let hi = [i64::from(r.x1), i64::from(r.y1)].map(|v| (v << 16) + MARGIN);
    for axis in 0..2 {
        poly = clip(&poly, axis, lo[axis], true);
        poly = clip(&poly, axis, hi[axis], false);
    }
    let mut out = QuadTriangles {
        tris: [[ScreenVertex::default(); 3]; QUAD_TRIANGLES_MAX],
        len: 0,
    };
    // Snapped to the raster's 1/16 pixel (every corner is now within the viewport plus the
    // margin, well inside i32), then made strictly convex.
    let shift = 16 - SUBPIXEL_BITS;
    let mut sub = poly.p.map(|c| c.map(|v| round_shift(v, shift)));
    let area2 = |sub: &[[i64; 2]; 8], n: usize| -> i64 {
        (0..n)
            .map(|k| {
                let (a, b) = (sub[k], sub[(k + 1) % n]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum()
    };
    let orient = area2(&sub, poly.len);
    if poly.len < 3 || orient == 0 {
        return Ok(out);
    }
    make_convex(&mut poly, &mut sub, orient);
    if poly.len < 3 {
        return Ok(out);
    }
    let at = |k: usize| poly.p[k].map(|v| Fx::from_bits(v as i32));
    // The inverse's denominator is proportional to 1 / w; its sign is the determinant's.
    let mut den = [0i128; 8];
    for (k, d) in den.iter_mut().enumerate().take(poly.len) {
        let [x, y] = at(k);
        *d = inverse.denominator(x, y);
    }
    let negative = den[..poly.len].iter().sum::<i128>() < 0;
    let den = den.map(|d| (if negative { -d } else { d }).max(1));
    let dmin = den[..poly.len].iter().copied().min().unwrap_or(1);
    let square = [[0, 0], [1, 0], [1, 1], [0, 1]].map(|c: [i32; 2]| c.map(Fx::from_num));
    let attr_shift = 16 - ATTR_SUBPIXEL_BITS;
    let vertex = |k: usize| {
        let w = (W_TOP * dmin / den[k]).max(W_FLOOR);
        let uv = match square.get(usize::from(poly.tag[k])) {
            Some(&uv) => uv,
            None => {
                let [x, y] = at(k);
                inverse
                    .map(x, y)
                    .unwrap_or([Fx::ZERO; 2])
                    .map(|t| t.clamp(Fx::ZERO, Fx::ONE))
            }
        };
        // The position to 1/4096 pixel, as an offset from the 1/16-pixel corner.
        let fine = poly.p[k].map(|v| round_shift(v, attr_shift));
        let offset =
            |i: usize| (fine[i] - (sub[k][i] << (ATTR_SUBPIXEL_BITS - SUBPIXEL_BITS))) as i16;
        ScreenVertex {
            x: sub[k][0] as i32,
            y: sub[k][1] as i32,
            sub: [offset(0), offset(1)],
            z: QUAD_DEPTH,
            w: w as i32,
            varyings: [
                uv[0].to_bits(),
                uv[1].to_bits(),
                WHITE_Q16,
                WHITE_Q16,
                WHITE_Q16,
            ],
        }
    };
    let cull = draw.mode().cull;
    for k in 1..poly.len - 1 {
        let tri = [vertex(0), vertex(k), vertex(k + 1)];
        if keeps(&tri, cull) {
            out.tris[usize::from(out.len)] = tri;
            out.len += 1;
        }
    }
    Ok(out)
}

/// Draws the draw's texture onto the convex quad `corners` (I16F16 screen pixels, the
/// images of texture coordinates `(0,0), (1,0), (1,1), (0,1)`, either winding; see the
/// module docs), returning the pixels written: every pixel whose centre the quad covers
/// within the viewport. Corners may lie off screen (anywhere in I16F16); refused with
/// [`Error::BadQuad`] when three are collinear, they cross, the quad is concave, or the
/// corners are too extreme for the fixed-point map (see [`Homography::square_to_quad`]).
pub fn draw_quad<C: TargetColor, T: RenderTarget<Color = C>>(
    draw: &Draw<'_, C>,
    corners: [[Fx; 2]; 4],
    target: &mut T,
) -> Result<u32, Error> {
    draw.check_target(target)?;
    let tris = quad_triangles(draw, corners)?;
    let mut pixels = 0u32;
    for tri in tris.as_slice() {
        pixels = pixels.saturating_add(draw.screen_triangle(tri, target)?);
    }
    Ok(pixels)
}
