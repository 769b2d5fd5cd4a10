//! Texture coordinates and sizes: huge and negative uv in every wrap and filter, extreme
//! minification, uv exactly on texel boundaries, tiny and big textures.

use crate::common::*;
use crate::helpers::*;
use host_tests::reference::{
    RefCull, RefFilter, RefMode, RefProjection, RefShading, RefTexture, RefTriangle, RefWrap,
};

/// The whole viewport as two triangles, with `uv` at the corners (top-left, top-right,
/// bottom-right, bottom-left) and clip `w` per corner (1 everywhere: affine geometry).
fn quad(uv: [[f64; 2]; 4], w: [f64; 4]) -> Vec<RefTriangle> {
    let p = [
        (0.0, 0.0),
        (W as f64, 0.0),
        (W as f64, H as f64),
        (0.0, H as f64),
    ];
    let v: Vec<_> = (0..4)
        .map(|k| {
            let mut v = at_px(p[k].0, p[k].1, 0.0, w[k], W, H);
            v.uv = uv[k].map(q16);
            v
        })
        .collect();
    vec![tri(v[0], v[3], v[2]), tri(v[0], v[2], v[1])]
}

fn uv_rect(u0: f64, v0: f64, u1: f64, v1: f64) -> [[f64; 2]; 4] {
    [[u0, v0], [u1, v0], [u1, v1], [u0, v1]]
}

const WRAPS: [RefWrap; 4] = [
    RefWrap::Repeat,
    RefWrap::MirroredRepeat,
    RefWrap::ClampToEdge,
    RefWrap::ClampToBorder,
];

fn tex_mode(p: RefProjection, f: RefFilter, wrap: RefWrap) -> RefMode {
    RefMode {
        projection: p,
        filter: f,
        wrap_u: wrap,
        wrap_v: wrap,
        depth_test: false,
        shading: RefShading::Replace,
        cull: RefCull::None,
        ..RefMode::default()
    }
}

/// The worst measured report over every wrap mode, for one filter and projection.
fn worst_over_wraps(
    name: &str,
    tris: &[RefTriangle],
    tex: &RefTexture,
    p: RefProjection,
    f: RefFilter,
) -> (u32, f64) {
    let (mut max, mut share) = (0, 0.0f64);
    for wrap in WRAPS {
        let c = check_ref(
            &format!("{name} {p:?} {f:?} {wrap:?}"),
            tris,
            Some(tex),
            &tex_mode(p, f, wrap),
            W,
            H,
        );
        assert!(c.diff.is_empty(), "{name}: coverage differs");
        max = max.max(c.rep.max);
        share = share.max(c.rep.share_over_2);
    }
    (max, share)
}

#[test]
fn huge_and_negative_uv_every_wrap_and_filter() {
    let tex = noise_texture(16, 16, 7);
    // w per corner for the perspective variant: a plane receding 4:1.
    let persp = [1.0, 1.0, 4.0, 4.0];
    for (name, uv) in [
        // Magnified (1/8 texel per pixel) thousands of periods away from 0.
        ("huge offset", uv_rect(1000.1, -2000.3, 1000.6, -1999.8)),
        ("negative", uv_rect(-2.5, -1.75, -1.5, -0.6)),
        ("straddling 0", uv_rect(-0.3, 0.4, 0.35, -0.2)),
    ] {
        for (p, w) in [
            (RefProjection::Affine, [1.0; 4]),
            (RefProjection::Perspective, persp),
        ] {
            let tris = quad(uv, w);
            let (bmax, _) = worst_over_wraps(name, &tris, &tex, p, RefFilter::Bilinear);
            // Bilinear is continuous: uv error ~2^-12 texel and Q8 weights keep it within
            // 1 LSB of the exact value (sampler's own bound); measured 1.
            assert!(bmax <= 2, "{name} {p:?} bilinear max {bmax}");
            let (_, nshare) = worst_over_wraps(name, &tris, &tex, p, RefFilter::Nearest);
            // Nearest flips texel only where the exact uv is within the interpolation error
            // of a texel boundary: measured 0 pixels over 2 LSB.
            assert!(
                nshare <= 0.002,
                "{name} {p:?} nearest share over 2 LSB {nshare}"
            );
        }
    }
}

#[test]
fn extreme_minification_thousands_of_repeats() {
    // 6000 repeats across 64 pixels (about 1500 texels per pixel) without mipmaps: every
    // pixel samples an essentially arbitrary texel, and a uv error of 2^-16 texel per pixel
    // of distance is enough to pick a different one. Colour is therefore not comparable;
    // this checks stability (no panic, no out-of-bounds write, coverage exact) and that the
    // clamp modes, which sample the edge or border everywhere outside [0, 1], still agree.
    let tex = noise_texture(16, 16, 9);
    for (p, w) in [
        (RefProjection::Affine, [1.0; 4]),
        (RefProjection::Perspective, [1.0, 2.0, 8.0, 3.0]),
    ] {
        let tris = quad(uv_rect(-3000.0, 2999.5, 3000.0, -3000.25), w);
        for f in [RefFilter::Nearest, RefFilter::Bilinear] {
            for wrap in WRAPS {
                let c = check_ref(
                    &format!("minified {p:?} {f:?} {wrap:?}"),
                    &tris,
                    Some(&tex),
                    &tex_mode(p, f, wrap),
                    W,
                    H,
                );
                assert!(c.diff.is_empty());
                if matches!(wrap, RefWrap::ClampToBorder) {
                    // Border everywhere except the few pixels whose uv is inside the texture.
                    assert!(c.rep.share_over_2 <= 0.01, "{}", c.rep);
                }
            }
        }
    }
}

#[test]
fn uv_exactly_on_texel_boundaries() {
    let tex = noise_texture(16, 16, 3);
    // Affine, w = 1: 2 texels per pixel, so every pixel centre lies exactly on a texel
    // boundary (u = 2x + 1): the nearest filter's floor() tie. The plane is exact here
    // (integer texel steps), so fixel must agree with the reference bit for bit.
    let tris = quad(uv_rect(0.0, 0.0, 8.0, 8.0), [1.0; 4]);
    for wrap in WRAPS {
        let c = check_ref(
            &format!("boundary ties {wrap:?}"),
            &tris,
            Some(&tex),
            &tex_mode(RefProjection::Affine, RefFilter::Nearest, wrap),
            W,
            H,
        );
        assert_eq!(c.rep.max, 0, "{wrap:?}");
    }
    // One texel per pixel: bilinear at exact texel centres (alpha = beta = 0) and
    // perspective mode with equal w (q = 1 exactly): the texels themselves.
    let tris = quad(uv_rect(-1.0, 3.0, 3.0, 7.0), [2.0; 4]);
    for wrap in WRAPS {
        for f in [RefFilter::Nearest, RefFilter::Bilinear] {
            for p in [RefProjection::Affine, RefProjection::Perspective] {
                let c = check_ref(
                    &format!("texel centres {wrap:?} {f:?} {p:?}"),
                    &tris,
                    Some(&tex),
                    &tex_mode(p, f, wrap),
                    W,
                    H,
                );
                assert_eq!(c.rep.max, 0, "{wrap:?} {f:?} {p:?}");
            }
        }
    }
}

#[test]
fn tiny_and_big_textures() {
    let persp = [1.0, 1.5, 5.0, 2.0];
    for (tw, th) in [(1, 1), (1, 64), (64, 1), (1024, 1024)] {
        let tex = noise_texture(tw, th, tw ^ (th << 8));
        for (p, w) in [
            (RefProjection::Affine, [1.0; 4]),
            (RefProjection::Perspective, persp),
        ] {
            // Slightly more than the texture, off the texel grid, so edges and borders are
            // sampled; for 1024 x 1024 that is 16:1 minification.
            let tris = quad(uv_rect(-0.1373, 1.0917, 1.0741, -0.0629), w);
            let name = format!("{tw}x{th}");
            let (bmax, _) = worst_over_wraps(&name, &tris, &tex, p, RefFilter::Bilinear);
            let (_, nshare) = worst_over_wraps(&name, &tris, &tex, p, RefFilter::Nearest);
            // Bilinear: measured 1 LSB (2 for 1024^2 perspective). Nearest: only boundary
            // flips, measured <= 0.122 % (64x1 perspective, 5 pixels) except 1024^2
            // perspective: the per-pixel reciprocal
            // has a relative error of 2^-16, so u = s / q is off by up to |u| 2^-16 texel,
            // and the periodic modes rebase u into [0, period) (here [884, 2124] texels for
            // Repeat and [1908, 3148] for MirroredRepeat): up to 0.05 texel, so a few % of
            // centres within that of a texel boundary flip (measured 0.95 % and 1.83 %).
            let nbound = if tw >= 1024 && p == RefProjection::Perspective {
                0.02
            } else {
                0.0015
            };
            assert!(bmax <= 2, "{name} {p:?} bilinear max {bmax}");
            assert!(nshare <= nbound, "{name} {p:?} nearest share {nshare}");
        }
    }
}
