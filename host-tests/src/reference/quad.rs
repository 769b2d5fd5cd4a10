//! The f64 reference for projective quads: Heckbert's square-to-quad
//! homography from the formulas, its inverse by the adjugate, and the two clip-space
//! triangles (corner `w` = the homography's denominator) through which the reference
//! rasterizer's hyperbolic interpolation reproduces the map.

use super::types::{RefTriangle, RefVertex};

/// Row-major 3x3, column vectors: `(x w, y w, w) = H (u, v, 1)`.
pub type Mat3 = [[f64; 3]; 3];

/// The homography of the unit square onto `p` (images of `(0,0), (1,0), (1,1), (0,1)`),
/// or `None` when the denominator vanishes (three corners collinear).
pub fn square_to_quad(p: [[f64; 2]; 4]) -> Option<Mat3> {
    let sx = p[0][0] - p[1][0] + p[2][0] - p[3][0];
    let sy = p[0][1] - p[1][1] + p[2][1] - p[3][1];
    let (dx1, dx2) = (p[1][0] - p[2][0], p[3][0] - p[2][0]);
    let (dy1, dy2) = (p[1][1] - p[2][1], p[3][1] - p[2][1]);
    let den = dx1 * dy2 - dx2 * dy1;
    if den == 0.0 {
        return None;
    }
    let g = (sx * dy2 - sy * dx2) / den;
    let h = (dx1 * sy - dy1 * sx) / den;
    Some([
        [
            p[1][0] - p[0][0] + g * p[1][0],
            p[3][0] - p[0][0] + h * p[3][0],
            p[0][0],
        ],
        [
            p[1][1] - p[0][1] + g * p[1][1],
            p[3][1] - p[0][1] + h * p[3][1],
            p[0][1],
        ],
        [g, h, 1.0],
    ])
}

/// `H (u, v, 1)` divided through.
pub fn map(h: &Mat3, u: f64, v: f64) -> [f64; 2] {
    let r = |k: usize| h[k][0] * u + h[k][1] * v + h[k][2];
    let w = r(2);
    [r(0) / w, r(1) / w]
}

/// The inverse (adjugate over determinant).
pub fn inverse(m: &Mat3) -> Mat3 {
    let c =
        |r0: usize, c0: usize, r1: usize, c1: usize| m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
    let adj = [
        [c(1, 1, 2, 2), -c(0, 1, 2, 2), c(0, 1, 1, 2)],
        [-c(1, 0, 2, 2), c(0, 0, 2, 2), -c(0, 0, 1, 2)],
        [c(1, 0, 2, 1), -c(0, 0, 2, 1), c(0, 0, 1, 1)],
    ];
    let det = m[0][0] * adj[0][0] + m[0][1] * adj[1][0] + m[0][2] * adj[2][0];
    adj.map(|r| r.map(|x| x / det))
}

/// The quad's two triangles in clip space for a `width x height` viewport at the origin:
/// NDC of each corner times its denominator `w = g u + h v + 1`, depth 0, white, uv at the
/// square's corners. `None` for a singular map.
pub fn triangles(p: [[f64; 2]; 4], width: f64, height: f64) -> Option<[RefTriangle; 2]> {
    let h = square_to_quad(p)?;
    let uv = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let v = |k: usize| {
        let w = h[2][0] * uv[k][0] + h[2][1] * uv[k][1] + 1.0;
        let nx = 2.0 * p[k][0] / width - 1.0;
        let ny = 1.0 - 2.0 * p[k][1] / height;
        RefVertex {
            clip: [nx * w, ny * w, 0.0, w],
            uv: uv[k],
            color: [1.0; 3],
        }
    };
    Some([
        RefTriangle([v(0), v(1), v(2)]),
        RefTriangle([v(0), v(2), v(3)]),
    ])
}
