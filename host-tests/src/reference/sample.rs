//! Texture sampling of the reference renderer, straight from the OpenGL ES 3.0
//! rules (coordinate wrapping, filters), in f64. Texel-space coordinates are
//! `u = s * width`, `v = t * height`. NEAREST takes `wrap(floor(u))`; LINEAR
//! takes `i0 = floor(u - 0.5)`, `alpha = frac(u - 0.5)` and blends the four
//! wrapped texels `(i0|i0+1, j0|j0+1)`. Texels are RGB565 expanded to
//! `r5/31, g6/63, b5/31` before blending. Wrap acts on integer indices.

use super::types::{rgb565_to_f64, RefFilter, RefTexture, RefWrap};

/// Maps an integer texel index into `0..size`, or `None` for the border
/// (only `ClampToBorder` returns `None`, for indices outside `0..size`).
///
/// - Repeat: `i mod size`.
/// - MirroredRepeat: `(size - 1) - mirror((i mod 2 size) - size)` with
///   `mirror(a) = a if a >= 0 else -(1 + a)`.
/// - ClampToEdge: `clamp(i, 0, size - 1)`.
pub fn wrap_index(i: i64, size: u32, wrap: RefWrap) -> Option<u32> {
    let n = i64::from(size);
    let r = match wrap {
        RefWrap::Repeat => i.rem_euclid(n),
        RefWrap::MirroredRepeat => {
            let a = i.rem_euclid(2 * n) - n;
            let m = if a >= 0 { a } else { -(1 + a) };
            (n - 1) - m
        }
        RefWrap::ClampToEdge => i.clamp(0, n - 1),
        RefWrap::ClampToBorder => {
            if (0..n).contains(&i) {
                i
            } else {
                return None;
            }
        }
    };
    Some(r as u32)
}

/// The normalised colour of texel `(i, j)` after wrapping (border if outside).
pub fn fetch(tex: &RefTexture, i: i64, j: i64, wrap_u: RefWrap, wrap_v: RefWrap) -> [f64; 3] {
    match (
        wrap_index(i, tex.width, wrap_u),
        wrap_index(j, tex.height, wrap_v),
    ) {
        (Some(i), Some(j)) => rgb565_to_f64(tex.texel(i, j)),
        _ => rgb565_to_f64(tex.border),
    }
}

/// Samples `tex` at normalised coordinates `uv = [s, t]`.
pub fn sample(
    tex: &RefTexture,
    uv: [f64; 2],
    filter: RefFilter,
    wrap_u: RefWrap,
    wrap_v: RefWrap,
) -> [f64; 3] {
    let u = uv[0] * f64::from(tex.width);
    let v = uv[1] * f64::from(tex.height);
    match filter {
        RefFilter::Nearest => fetch(tex, u.floor() as i64, v.floor() as i64, wrap_u, wrap_v),
        RefFilter::Bilinear => {
            let (fu, fv) = ((u - 0.5).floor(), (v - 0.5).floor());
            let (a, b) = (u - 0.5 - fu, v - 0.5 - fv);
            let (i0, j0) = (fu as i64, fv as i64);
            let t00 = fetch(tex, i0, j0, wrap_u, wrap_v);
            let t10 = fetch(tex, i0 + 1, j0, wrap_u, wrap_v);
            let t01 = fetch(tex, i0, j0 + 1, wrap_u, wrap_v);
            let t11 = fetch(tex, i0 + 1, j0 + 1, wrap_u, wrap_v);
            core::array::from_fn(|c| {
                (1.0 - a) * (1.0 - b) * t00[c]
                    + a * (1.0 - b) * t10[c]
                    + (1.0 - a) * b * t01[c]
                    + a * b * t11[c]
            })
        }
    }
}
