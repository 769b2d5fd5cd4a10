//! Environment mapping in f64, written from the formulas (Blinn & Newell; OpenGL ES
//! 3.2's cube map texture selection), sharing only data with fixel (texels, vertex bits).
//!
//! * [`reflect`]: `r = 2 (n·v) n − (n·n) v`, the mirror image of `v` about `n` (any
//!   lengths; the direction of the unit formula `2 (n̂·v̂) n̂ − v̂`).
//! * [`cube_face_st`]: GL's face table with an exact division by the major axis. Ties
//!   (equal magnitudes) pick x before y before z, fixel's documented choice; the zero
//!   direction gives the centre of face 0.
//! * [`cube_sample`]: the face sampled with the reference's GL nearest or bilinear filter,
//!   `CLAMP_TO_EDGE` on both axes.
//! * [`cube_sample_seamless`]: GL's seamless bilinear filter across face edges.
//! * [`render_varyings`]: a depth-tested, back-face-culled rasterization of clip-space
//!   triangles with `N` varyings interpolated perspective-correctly, each pixel's colour
//!   computed by a closure of the pixel and the interpolated varyings (as f64 of their bits).

use fixel::geometry::Vertex;

use super::raster::{rasterize, signed_area2, to_window};
use super::sample::sample;
use super::{rgb565_from_f64, RefFilter, RefTexture, RefVertex, RefWrap};

/// `2 (n·v) n − (n·n) v`.
pub fn reflect(n: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    let nv = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    let nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    [0, 1, 2].map(|i| 2.0 * nv * n[i] - nn * v[i])
}

/// Face (GL order `+X, -X, +Y, -Y, +Z, -Z`) and `(s, t)` in `[0, 1]` of direction `d`.
pub fn cube_face_st(d: [f64; 3]) -> (usize, f64, f64) {
    let [x, y, z] = d;
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    // (face, sc, tc, ma) from Table 3.21.
    let (face, sc, tc, ma) = if ax >= ay && ax >= az {
        if x >= 0.0 {
            (0, -z, -y, ax)
        } else {
            (1, z, -y, ax)
        }
    } else if ay >= az {
        if y >= 0.0 {
            (2, x, z, ay)
        } else {
            (3, x, -z, ay)
        }
    } else if z >= 0.0 {
        (4, x, -y, az)
    } else {
        (5, -x, -y, az)
    };
    if ma == 0.0 {
        return (0, 0.5, 0.5);
    }
    (face, 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0))
}

/// The cube map's colour (RGB in `0..=1`) in direction `d`.
pub fn cube_sample(faces: &[RefTexture; 6], d: [f64; 3], filter: RefFilter) -> [f64; 3] {
    let (f, s, t) = cube_face_st(d);
    sample(
        &faces[f],
        [s, t],
        filter,
        RefWrap::ClampToEdge,
        RefWrap::ClampToEdge,
    )
}

/// GL's seamless cube-map bilinear filter (`TEXTURE_CUBE_MAP_SEAMLESS`, OpenGL 4.6)
/// in direction `d`: the four taps around `(s n − 1/2, t n − 1/2)`; a tap outside
/// the face is the texel, on whichever face it lands, that contains the tap's centre on
/// the face's extended plane (found by GL's face selection of that point); a tap outside in
/// both `i` and `j` is the average of the other three, as the specification recommends.
pub fn cube_sample_seamless(faces: &[RefTexture; 6], d: [f64; 3]) -> [f64; 3] {
    let (f, s, t) = cube_face_st(d);
    let n = faces[0].width;
    let nf = f64::from(n);
    let (u, v) = (s * nf - 0.5, t * nf - 0.5);
    let (i0, j0) = (u.floor() as i64, v.floor() as i64);
    let (a, b) = (u - u.floor(), v - v.floor());
    let inside = |k: i64| (0..i64::from(n)).contains(&k);
    let tap = |i: i64, j: i64| -> Option<[f64; 3]> {
        if inside(i) && inside(j) {
            return Some(super::types::rgb565_to_f64(
                faces[f].texel(i as u32, j as u32),
            ));
        }
        if !inside(i) && !inside(j) {
            return None;
        }
        // The tap's centre on the extended plane of face f, as a direction.
        let sc = 2.0 * (i as f64 + 0.5) / nf - 1.0;
        let tc = 2.0 * (j as f64 + 0.5) / nf - 1.0;
        let (g, s2, t2) = cube_face_st(face_point(f, sc, tc));
        let idx = |c: f64| ((c * nf).floor() as i64).clamp(0, i64::from(n) - 1) as u32;
        Some(super::types::rgb565_to_f64(
            faces[g].texel(idx(s2), idx(t2)),
        ))
    };
    let taps = [
        tap(i0, j0),
        tap(i0 + 1, j0),
        tap(i0, j0 + 1),
        tap(i0 + 1, j0 + 1),
    ];
    let got: Vec<[f64; 3]> = taps.iter().flatten().copied().collect();
    let corner = if got.len() == 3 {
        [0, 1, 2].map(|c| (got[0][c] + got[1][c] + got[2][c]) / 3.0)
    } else {
        [0.0; 3]
    };
    let c = taps.map(|t| t.unwrap_or(corner));
    let w = [(1.0 - a) * (1.0 - b), a * (1.0 - b), (1.0 - a) * b, a * b];
    [0, 1, 2].map(|ch| (0..4).map(|k| w[k] * c[k][ch]).sum())
}

/// [`cube_sample_trilinear`] with GL's seamless rule on every level: the same face, LOD and
/// level selection, each level sampled with [`cube_sample_seamless`]. `levels[k]` holds the
/// six faces of level `k`.
pub fn cube_sample_trilinear_seamless(
    levels: &[[RefTexture; 6]],
    d: [f64; 3],
    around: [[f64; 3]; 4],
) -> [f64; 3] {
    let (f, _, _) = cube_face_st(d);
    let size = f64::from(levels[0][0].width);
    let st = around.map(|a| face_plane_st(f, a));
    let deriv = [
        [(st[1].0 - st[0].0) * size, (st[1].1 - st[0].1) * size],
        [(st[3].0 - st[2].0) * size, (st[3].1 - st[2].1) * size],
    ];
    let lambda = super::mip::lambda(deriv, &super::RefLod::default());
    let sel = super::mip::select(lambda, super::RefMip::Linear, levels.len() as u32);
    let at = |k: u32| cube_sample_seamless(&levels[(k as usize).min(levels.len() - 1)], d);
    if sel.magnify {
        return at(0);
    }
    let a = at(sel.a);
    if sel.b == sel.a || sel.frac == 0.0 {
        return a;
    }
    let b = at(sel.b);
    core::array::from_fn(|c| (1.0 - sel.frac) * a[c] + sel.frac * b[c])
}

/// Rasterizes `tris` into a `width x height` frame (depth test less, back faces culled;
/// every vertex must have `w > 0`: no clipping), calling `shade` with the perspective-
/// correct interpolation of the varyings (f64 of their raw bits). Returns RGB565 per pixel
/// and coverage.
pub fn render_varyings<const N: usize>(
    tris: &[[Vertex<N>; 3]],
    width: u32,
    height: u32,
    mut shade: impl FnMut(u32, u32, [f64; N]) -> [f64; 3],
) -> (Vec<u16>, Vec<bool>) {
    render_varyings_with_derivatives(tris, width, height, |x, y, a, _| shade(x, y, a))
}

/// [`render_varyings`], and `shade` also gets the varyings half a pixel left and right and
/// half a pixel up and down of the pixel centre (`[x − ½, x + ½, y − ½, y + ½]`), each
/// interpolated perspective-correctly on the same triangle's planes (extrapolated past its
/// edges), for central differences.
pub fn render_varyings_with_derivatives<const N: usize>(
    tris: &[[Vertex<N>; 3]],
    width: u32,
    height: u32,
    shade: impl FnMut(u32, u32, [f64; N], [[f64; N]; 4]) -> [f64; 3],
) -> (Vec<u16>, Vec<bool>) {
    render_varyings_around(tris, width, height, 1.0, shade)
}

/// [`render_varyings_with_derivatives`] with the four neighbours `step / 2` pixels from the
/// centre instead of half a pixel: a small `step` (say 1/256) makes their differences
/// divided by `step` the analytic screen derivatives, to within `step^2`.
pub fn render_varyings_around<const N: usize>(
    tris: &[[Vertex<N>; 3]],
    width: u32,
    height: u32,
    step: f64,
    mut shade: impl FnMut(u32, u32, [f64; N], [[f64; N]; 4]) -> [f64; 3],
) -> (Vec<u16>, Vec<bool>) {
    let h = step / 2.0;
    let n = (width * height) as usize;
    let (mut rgb, mut cov, mut depth) = (vec![0u16; n], vec![false; n], vec![f64::MAX; n]);
    for tri in tris {
        let win = tri.map(|v| {
            to_window(
                &RefVertex {
                    clip: v.position.map(|c| c.to_num::<f64>()),
                    uv: [0.0; 2],
                    color: [0.0; 3],
                },
                width,
                height,
            )
        });
        let [Some(a), Some(b), Some(c)] = win else {
            continue;
        };
        let win = [a, b, c];
        // Negative area: counter-clockwise in NDC, a front face.
        if signed_area2(&win) >= 0.0 {
            continue;
        }
        let vary = tri.map(|v| v.varyings.map(f64::from));
        // Screen barycentrics at any point, from the exact window positions.
        let area = (win[1].ex - win[0].ex) * (win[2].ey - win[0].ey)
            - (win[2].ex - win[0].ex) * (win[1].ey - win[0].ey);
        let bary = |px: f64, py: f64| -> [f64; 3] {
            let e = |a: usize, b: usize| {
                (win[b].ex - win[a].ex) * (py - win[a].ey)
                    - (px - win[a].ex) * (win[b].ey - win[a].ey)
            };
            [e(1, 2) / area, e(2, 0) / area, e(0, 1) / area]
        };
        let interp = |l: [f64; 3]| -> [f64; N] {
            let q = [0, 1, 2].map(|k| l[k] * win[k].inv_w);
            let qs = q[0] + q[1] + q[2];
            core::array::from_fn(|j| (0..3).map(|k| q[k] * vary[k][j]).sum::<f64>() / qs)
        };
        rasterize(&win, width, height, |x, y, l| {
            let i = (y * width + x) as usize;
            let z = l[0] * win[0].z + l[1] * win[1].z + l[2] * win[2].z;
            if z >= depth[i] {
                return;
            }
            depth[i] = z;
            let (cx, cy) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            let around = [
                interp(bary(cx - h, cy)),
                interp(bary(cx + h, cy)),
                interp(bary(cx, cy - h)),
                interp(bary(cx, cy + h)),
            ];
            rgb[i] = rgb565_from_f64(shade(x, y, interp(l), around));
            cov[i] = true;
        });
    }
    (rgb, cov)
}

/// `(s, t)` of direction `d` on face `face`'s plane (GL's table, `(sc / ma + 1) / 2`),
/// extended beyond the face's edges.
pub fn face_plane_st(face: usize, d: [f64; 3]) -> (f64, f64) {
    let [x, y, z] = d;
    let (sc, tc, ma) = match face {
        0 => (-z, -y, x),
        1 => (z, -y, -x),
        2 => (x, z, y),
        3 => (x, -z, -y),
        4 => (x, -y, z),
        _ => (-x, -y, -z),
    };
    (0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0))
}

/// GL's mipmapped cube-map lookup (trilinear: bilinear within a level, linear between
/// levels, clamp-to-edge) of direction `d`, with `around` the directions half a pixel
/// left, right, up and down: the face is `d`'s, the level-0 texel derivatives of `s`, `t`
/// are central differences on that face's plane, `lambda = log2` of the longer (Heckbert).
pub fn cube_sample_trilinear(
    chains: &[super::mip::RefMipChain; 6],
    d: [f64; 3],
    around: [[f64; 3]; 4],
) -> [f64; 3] {
    let (f, s, t) = cube_face_st(d);
    let size = f64::from(chains[f].base().width);
    let st = around.map(|a| face_plane_st(f, a));
    let deriv = [
        [(st[1].0 - st[0].0) * size, (st[1].1 - st[0].1) * size],
        [(st[3].0 - st[2].0) * size, (st[3].1 - st[2].1) * size],
    ];
    super::mip::sample_mip(
        &chains[f],
        [s, t],
        deriv,
        RefFilter::Bilinear,
        RefFilter::Bilinear,
        super::RefMip::Linear,
        &super::RefLod::default(),
        [RefWrap::ClampToEdge, RefWrap::ClampToEdge],
    )
}

/// GL's cube-map level of detail (OpenGL ES 3.2, 8.13 and 8.14) of a direction field, in
/// closed form: `d` the direction at the pixel (any length), `ddx`, `ddy` its derivatives
/// per pixel right and down, `size` the face side in texels. On the face `d` selects, with
/// `ma` the major component and `c` a minor one, `d(c / ma) = (c' ma − c ma') / ma²`, and
/// `s = (sc / ma + 1) / 2` makes a texel derivative `size / 2` times that; `lambda` is
/// `log2` of the longer of the x and y derivative vectors (Heckbert), before any bias.
pub fn cube_lambda(d: [f64; 3], ddx: [f64; 3], ddy: [f64; 3], size: f64) -> f64 {
    let [ax, ay, az] = d.map(f64::abs);
    let (m, i, j) = if ax >= ay && ax >= az {
        (0, 1, 2)
    } else if ay >= az {
        (1, 0, 2)
    } else {
        (2, 0, 1)
    };
    let rho = |g: [f64; 3]| {
        let q = |c: usize| (g[c] * d[m] - d[c] * g[m]) / (d[m] * d[m]);
        0.5 * size * q(i).hypot(q(j))
    };
    rho(ddx).max(rho(ddy)).log2()
}

/// GL's trilinear cube-map lookup (bilinear within a level, linear between levels,
/// `CLAMP_TO_EDGE`) of direction `d` at level of detail `lambda` (bias included): the
/// face of `d`, the magnification filter on level 0 for `lambda <= 0`.
pub fn cube_sample_lod(
    chains: &[super::mip::RefMipChain; 6],
    d: [f64; 3],
    lambda: f64,
) -> [f64; 3] {
    let (f, s, t) = cube_face_st(d);
    let chain = &chains[f];
    let sel = super::mip::select(lambda, super::RefMip::Linear, chain.levels.len() as u32);
    let at = |k: u32| {
        sample(
            &chain.levels[k as usize],
            [s, t],
            RefFilter::Bilinear,
            RefWrap::ClampToEdge,
            RefWrap::ClampToEdge,
        )
    };
    let a = at(sel.a);
    if sel.b == sel.a || sel.frac == 0.0 {
        return a;
    }
    let b = at(sel.b);
    core::array::from_fn(|c| (1.0 - sel.frac) * a[c] + sel.frac * b[c])
}

/// Sphere-map `(s, t)` of direction `d`: `r̂ = d / |d|`,
/// `m = 2 sqrt(r̂x² + r̂y² + (r̂z + 1)²)`, `s = r̂x / m + 1/2`, `t = r̂y / m + 1/2`. At the
/// rim singularity (`m = 0`, `r̂ = (0, 0, -1)`) and for the zero direction: fixel's
/// documented choices, `(1, 1/2)` and `(1/2, 1/2)`.
pub fn sphere_st(d: [f64; 3]) -> (f64, f64) {
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    if len == 0.0 {
        return (0.5, 0.5);
    }
    let r = d.map(|c| c / len);
    let m = 2.0 * (r[0] * r[0] + r[1] * r[1] + (r[2] + 1.0) * (r[2] + 1.0)).sqrt();
    if m == 0.0 {
        return (1.0, 0.5);
    }
    (r[0] / m + 0.5, r[1] / m + 0.5)
}

/// Latitude-longitude `(s, t)` of direction `d`: `s = atan2(x, −z) / 2π + 1/2` in `[0, 1)`,
/// `t = 1/2 − asin(y / |d|) / π`. The zero direction gives `(1/2, 1/2)`.
pub fn latlong_st(d: [f64; 3]) -> (f64, f64) {
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    if len == 0.0 {
        return (0.5, 0.5);
    }
    let s = (d[0].atan2(-d[2]) / core::f64::consts::TAU + 0.5).rem_euclid(1.0);
    let t = 0.5 - (d[1] / len).asin() / core::f64::consts::PI;
    (s, t)
}

/// The sphere map's colour in direction `d` (clamp-to-edge).
pub fn sphere_sample(tex: &RefTexture, d: [f64; 3], filter: RefFilter) -> [f64; 3] {
    let (s, t) = sphere_st(d);
    sample(
        tex,
        [s, t],
        filter,
        RefWrap::ClampToEdge,
        RefWrap::ClampToEdge,
    )
}

/// The latitude-longitude map's colour in direction `d` (repeat along `s`, clamp along `t`).
pub fn latlong_sample(tex: &RefTexture, d: [f64; 3], filter: RefFilter) -> [f64; 3] {
    let (s, t) = latlong_st(d);
    sample(tex, [s, t], filter, RefWrap::Repeat, RefWrap::ClampToEdge)
}

/// The point `(sc, tc)` (each in `[-1, 1]` on the face, beyond it outside) of face `face`'s
/// plane at distance 1 from the centre: GL's face table inverted.
pub fn face_point(face: usize, sc: f64, tc: f64) -> [f64; 3] {
    match face {
        0 => [1.0, -tc, -sc],
        1 => [-1.0, -tc, sc],
        2 => [sc, 1.0, tc],
        3 => [sc, -1.0, -tc],
        4 => [sc, -tc, 1.0],
        _ => [-sc, -tc, -1.0],
    }
}

/// The unit direction through the centre of texel `(i, j)` of face `face` (GL order) of a
/// cube map of side `size` (the inverse of GL's face table).
pub fn texel_dir(face: usize, i: u32, j: u32, size: u32) -> [f64; 3] {
    let sc = 2.0 * (f64::from(i) + 0.5) / f64::from(size) - 1.0;
    let tc = 2.0 * (f64::from(j) + 0.5) / f64::from(size) - 1.0;
    let d = face_point(face, sc, tc);
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    d.map(|c| c / l)
}

/// Diffuse and glossy environment maps by brute force, in f64: the environment `faces`
/// (RGB565, GL order)
/// convolved with the cosine lobe (`exponent = None`: `(1/π) ∫ L max(0, n·ω) dω`) or the
/// Phong lobe (`((e + 1)/2π) ∫ L max(0, r·ω)^e dω`) in unit direction `n`, each source texel
/// weighted by its solid angle `(2/S)² / (1 + sc² + tc²)^(3/2)`.
pub fn convolve(faces: &[RefTexture; 6], n: [f64; 3], exponent: Option<u32>) -> [f64; 3] {
    let size = faces[0].width;
    let mut acc = [0.0; 3];
    for (f, tex) in faces.iter().enumerate() {
        for j in 0..size {
            for i in 0..size {
                let sc = 2.0 * (f64::from(i) + 0.5) / f64::from(size) - 1.0;
                let tc = 2.0 * (f64::from(j) + 0.5) / f64::from(size) - 1.0;
                let dw = 4.0 / f64::from(size * size) / (1.0 + sc * sc + tc * tc).powf(1.5);
                let w = texel_dir(f, i, j, size);
                let c = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
                if c <= 0.0 {
                    continue;
                }
                let k = match exponent {
                    None => c / core::f64::consts::PI,
                    Some(e) => c.powi(e as i32) * f64::from(e + 1) / core::f64::consts::TAU,
                };
                let l = super::types::rgb565_to_f64(tex.texel(i, j));
                for ch in 0..3 {
                    acc[ch] += l[ch] * k * dw;
                }
            }
        }
    }
    acc
}
