//! Small synthetic scenes for error budgets and goldens, built in f64 like
//! [`crate::scenes`]: a textured quad seen in perspective (uv beyond
//! `[0, 1]`, for the wrap modes), a quad with coloured vertices (Modulate)
//! and an untextured triangle with coloured vertices spanning a wide depth
//! range (Gouraud). Everything is 160 x 120 (small goldens, fast tests).

use crate::reference::{RefTexture, RefTriangle, RefVertex};
use crate::scenes::math::{self, Mat4};
use crate::scenes::procedural_texture;

/// Width of the synthetic scenes.
pub const WIDTH: u32 = 160;
/// Height of the synthetic scenes.
pub const HEIGHT: u32 = 120;

/// Border colour of [`quad_texture`] (a dull magenta, so ClampToBorder shows).
pub const BORDER: u16 = (20 << 11) | (8 << 5) | 20;

fn mvp(model: &Mat4) -> Mat4 {
    let p = math::perspective(50.0, f64::from(WIDTH) / f64::from(HEIGHT), 0.5, 20.0);
    math::mul(&p, model)
}

/// The quads' texture: `T(32, 32)` (2 x 2 checker blocks) with a visible
/// border colour.
pub fn quad_texture() -> RefTexture {
    RefTexture {
        border: BORDER,
        ..procedural_texture(32, 32)
    }
}

/// A 2 x 2 quad at z = -2.6 tilted back by 1 radian about x (its top
/// recedes, w ranges over about 1.9..3.4), with uv running over
/// `[uv0, uv1]` and the given corner colours (bottom-left, bottom-right,
/// top-right, top-left). Two counter-clockwise triangles.
pub fn quad(uv0: [f64; 2], uv1: [f64; 2], colors: [[f64; 3]; 4]) -> Vec<RefTriangle> {
    let m = mvp(&math::mul(
        &math::translation([0.0, -0.1, -2.6]),
        &math::rotation_x(-1.0),
    ));
    let corners = [
        ([-1.0, -1.0], [uv0[0], uv0[1]]),
        ([1.0, -1.0], [uv1[0], uv0[1]]),
        ([1.0, 1.0], [uv1[0], uv1[1]]),
        ([-1.0, 1.0], [uv0[0], uv1[1]]),
    ];
    let v = |k: usize| {
        let ([x, y], uv) = corners[k];
        RefVertex {
            clip: math::transform(&m, [x, y, 0.0, 1.0]),
            uv,
            color: colors[k],
        }
    };
    vec![
        RefTriangle([v(0), v(1), v(2)]),
        RefTriangle([v(0), v(2), v(3)]),
    ]
}

/// The wrap-mode quad: uv over `[-1.25, 2.25]` in both directions, white.
pub fn wrap_quad() -> Vec<RefTriangle> {
    quad([-1.25, -1.25], [2.25, 2.25], [[1.0; 3]; 4])
}

/// The Modulate quad: uv over `[0, 2]`, corners red, green, blue, yellow-ish.
pub fn colored_quad() -> Vec<RefTriangle> {
    quad(
        [0.0, 0.0],
        [2.0, 2.0],
        [
            [1.0, 0.2, 0.2],
            [0.2, 1.0, 0.2],
            [0.2, 0.2, 1.0],
            [0.9, 0.9, 0.3],
        ],
    )
}

/// An untextured triangle with red, green and blue vertices at depths 2, 6
/// and 3.5 (so perspective-correct and affine colours differ visibly).
pub fn gouraud_triangle() -> Vec<RefTriangle> {
    let m = mvp(&math::IDENTITY);
    let v = |p: [f64; 3], color: [f64; 3]| RefVertex {
        clip: math::transform(&m, [p[0], p[1], p[2], 1.0]),
        uv: [0.0, 0.0],
        color,
    };
    vec![RefTriangle([
        v([-1.0, -0.8, -2.0], [1.0, 0.0, 0.0]),
        v([3.5, -2.0, -6.0], [0.0, 1.0, 0.0]),
        v([-0.3, 1.5, -3.5], [0.0, 0.0, 1.0]),
    ])]
}
