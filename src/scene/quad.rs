//! Textured quadrilaterals on screen with exact projective mapping and no 3D set-up (seed
//! 000 §2.1): a photo, a dial or a sprite on any convex four-corner shape, for user
//! interfaces.
//!
//! [`draw_quad`] finds the homography of the unit square onto the corners
//! ([`Homography`]), and draws the quad as two triangles whose clip-space `w` are the
//! homography's denominators at the corners, so the span loop's perspective-correct
//! interpolation of `(u, v)` is the projective map itself: exact at every pixel with
//! [`Projection::Exact`](crate::pipeline::Projection::Exact), within the subdivision's error
//! with `Subdivided`, and a plain affine map per triangle with `Affine` (the classic
//! two-triangle seam). The draw's texture, filter, wrap, shading and depth test apply as
//! to any triangle; the quad lies at depth 1/2 and its colour is white.
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
use crate::geometry::{ClipVertex, Homography};
use crate::math::Fx;
use crate::pipeline::Draw;
use crate::surface::RenderTarget;
use crate::Error;

/// Clip-space corners of the quad `corners` (I16F16 pixels, the images of texture
/// coordinates `(0,0), (1,0), (1,1), (0,1)`) in `draw`'s viewport, and its two triangles.
pub fn quad_triangles<C: TargetColor>(
    draw: &Draw<'_, C>,
    corners: [[Fx; 2]; 4],
) -> Result<[[ClipVertex; 3]; 2], Error> {
    let (_, weights) = Homography::square_to_quad(corners)?;
    let r = draw.viewport().rect();
    let (w, h) = (i128::from(r.x1 - r.x0), i128::from(r.y1 - r.y0));
    // NDC in Q16: x = 2 (px − x0) / width − 1, y = 1 − 2 (py − y0) / height (y up).
    let ndc = corners.map(|c| {
        let (x, y) = (i128::from(c[0].to_bits()), i128::from(c[1].to_bits()));
        [
            (2 * (x - (i128::from(r.x0) << 16))) / w - (1 << 16),
            (1 << 16) - (2 * (y - (i128::from(r.y0) << 16))) / h,
        ]
    });
    // Clip coordinates in Q46 (NDC Q16 times weight Q30), then one shift so the largest
    // fits I16F16 below 2^14 (room for the clipper's sums).
    let clip: [[i128; 3]; 4] = core::array::from_fn(|k| {
        let wk = i128::from(weights[k]);
        [ndc[k][0] * wk, ndc[k][1] * wk, wk << 16]
    });
    let big = clip
        .iter()
        .flatten()
        .map(|v| v.unsigned_abs())
        .max()
        .unwrap_or(1);
    let shift = (128 - big.leading_zeros()).saturating_sub(30);
    let fx = |v: i128| Fx::from_bits((v >> shift) as i32);
    let uv = [(0, 0), (1, 0), (1, 1), (0, 1)].map(|(u, v)| [Fx::from_num(u), Fx::from_num(v)]);
    let vert = |k: usize| {
        ClipVertex::new(
            [fx(clip[k][0]), fx(clip[k][1]), Fx::ZERO, fx(clip[k][2])],
            uv[k],
        )
    };
    Ok([[vert(0), vert(1), vert(2)], [vert(0), vert(2), vert(3)]])
}

/// Draws the draw's texture onto the convex quad `corners` (I16F16 screen pixels, the
/// images of texture coordinates `(0,0), (1,0), (1,1), (0,1)`, either winding; see the
/// module docs), returning the pixels written. Corners may lie off screen (within I16F16);
/// refused with [`Error::BadQuad`] when three are collinear, they cross or the quad is
/// concave.
pub fn draw_quad<C: TargetColor, T: RenderTarget<Color = C>>(
    draw: &Draw<'_, C>,
    corners: [[Fx; 2]; 4],
    target: &mut T,
) -> Result<u32, Error> {
    let tris = quad_triangles(draw, corners)?;
    draw.clip_triangles(&tris, target)
}
