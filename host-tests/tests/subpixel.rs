//! Sub-pixel precision against GL's rules, with a reference that does not share fixel's
//! assumptions:
//!
//! * attributes come from the unsnapped vertex positions (the reference interpolates from the
//!   exact projections; coverage alone uses the 1/16-pixel grid);
//! * on the nearest perspective floor, fixel picks the exact f64 texel on every pixel more
//!   than 1/64 texel from a texel edge;
//! * affine interpolation is linear in screen space over the whole original triangle (GL's
//!   `noperspective`), so it does not depend on the guard band: the same triangle at two
//!   viewport sizes gives the same texels where the two overlap.

use host_tests::reference::{clip, raster};
use host_tests::reference::{RefProjection, RefTexture};
use host_tests::{adapter, scenes};

/// A 64 x 64 texture whose every texel has its own colour: `r` = x mod 32, `g` = y,
/// `b` = x / 32.
fn unique_texture() -> RefTexture {
    let texels = (0..64u16)
        .flat_map(|y| (0..64u16).map(move |x| ((x & 31) << 11) | (y << 5) | (x >> 5)))
        .collect();
    RefTexture {
        width: 64,
        height: 64,
        texels,
        border: 0,
    }
}

/// The texel `(x, y)` a pixel of [`unique_texture`] shows.
fn texel_of(c: u16) -> (u32, u32) {
    let (r, g, b) = (
        u32::from(c >> 11),
        u32::from((c >> 5) & 63),
        u32::from(c & 31),
    );
    (r + 32 * b, g)
}

/// Per covered pixel: the exact texture coordinates (in texels) of the f64 reference.
fn exact_texels(scene: &scenes::SceneDesc, proj: RefProjection) -> Vec<Option<(f64, f64)>> {
    let (w, h) = (scene.width, scene.height);
    let mut out = vec![None; (w * h) as usize];
    for tri in scenes::to_ref_triangles(scene) {
        for sub in clip::fan(&clip::clip_triangle(&tri)) {
            let [Some(a), Some(b), Some(c)] = sub.0.map(|v| raster::to_window(&v, w, h)) else {
                continue;
            };
            let v = [a, b, c];
            raster::rasterize(&v, w, h, |x, y, l| {
                let uv = match proj {
                    RefProjection::Affine => {
                        [0, 1].map(|k| (0..3).map(|i| l[i] * v[i].uv[k]).sum::<f64>())
                    }
                    RefProjection::Perspective => {
                        let q: f64 = (0..3).map(|i| l[i] * v[i].inv_w).sum();
                        [0, 1].map(|k| {
                            (0..3).map(|i| l[i] * v[i].inv_w * v[i].uv[k]).sum::<f64>() / q
                        })
                    }
                };
                out[(y * w + x) as usize] = Some((uv[0] * 64.0, uv[1] * 64.0));
            });
        }
    }
    out
}

#[test]
fn nearest_floor_picks_the_exact_texel_away_from_texel_edges() {
    let mut scene = scenes::floor();
    scene.texture = unique_texture();
    let tris = adapter::clip_triangles(&scenes::to_ref_triangles(&scene));
    let mode = adapter::draw_mode(&scene.mode, None, true);
    let f = adapter::render(&tris, Some(&scene.texture), mode, scene.width, scene.height);
    let exact = exact_texels(&scene, RefProjection::Perspective);
    let (mut checked, mut exceptions, mut near_edge) = (0, 0, 0);
    let mut worst: Option<(f64, u32, u32)> = None;
    for (i, e) in exact.iter().enumerate() {
        let Some((u, v)) = *e else { continue };
        if !f.covered[i] {
            continue;
        }
        let edge = |t: f64| {
            let fr = t - t.floor();
            fr.min(1.0 - fr)
        };
        let d = edge(u).min(edge(v));
        let want = (
            u.floor().rem_euclid(64.0) as u32,
            v.floor().rem_euclid(64.0) as u32,
        );
        let got = texel_of(f.pixels[i]);
        if d > 1.0 / 64.0 {
            checked += 1;
            if got != want {
                exceptions += 1;
                if worst.is_none_or(|w| d > w.0) {
                    worst = Some((d, i as u32 % scene.width, i as u32 / scene.width));
                }
            }
        } else {
            near_edge += 1;
        }
    }
    println!(
        "nearest floor: {checked} pixels more than 1/64 texel from a texel edge, \
         {exceptions} on another texel (worst {worst:?}); {near_edge} pixels within 1/64"
    );
    assert!(checked > 30_000);
    assert_eq!(exceptions, 0, "worst (distance, x, y): {worst:?}");
}

/// A triangle given in pixels (x right, y down) and clip `w`, as clip-space vertices for a
/// `vw x vh` viewport at the origin: the same pixel positions whatever the viewport size.
fn in_viewport(
    px: [(f64, f64, f64, [f64; 2]); 3],
    vw: f64,
    vh: f64,
) -> [fixel::geometry::ClipVertex; 3] {
    use fixel::math::{fx, Fx};
    px.map(|(x, y, w, uv)| {
        let (nx, ny) = (2.0 * x / vw - 1.0, 1.0 - 2.0 * y / vh);
        fixel::geometry::ClipVertex::new([fx(nx * w), fx(ny * w), Fx::ZERO, fx(w)], uv.map(fx))
    })
}

#[test]
fn affine_does_not_depend_on_where_the_guard_band_cuts() {
    use fixel::pipeline::{DrawMode, Projection, Shading};
    use fixel::texture::Filter;
    // One vertex 6,000 px to the right: a 320 px viewport's guard band cuts it at 4,000 px,
    // a 640 px one's at 3,840 px. Different w per vertex, so clip-space and screen-space
    // interpolation differ along the cut edges.
    let tri = [
        (20.0, 10.0, 1.0, [0.0, 0.0]),
        (6000.0, 120.0, 3.0, [40.0, 2.0]),
        (40.0, 230.0, 1.5, [0.5, 3.0]),
    ];
    let tex = unique_texture();
    let mode = DrawMode {
        projection: Projection::Affine,
        filter: Filter::Nearest,
        shading: Shading::Replace,
        cull: fixel::geometry::Cull::None,
        ..DrawMode::default()
    };
    let draw = |vw: u32, vh: u32| {
        let clip = in_viewport(tri, f64::from(vw), f64::from(vh));
        // Drawn into a 320 x 240 frame: the larger viewport is cropped (documented).
        let f = adapter::render_viewport(&[clip], Some(&tex), mode, (vw, vh), 320, 240);
        f.pixels
            .iter()
            .zip(&f.covered)
            .map(|(p, c)| c.then(|| texel_of(*p)))
            .collect::<Vec<_>>()
    };
    // GL's noperspective texel at each pixel centre: barycentrics of the original triangle
    // (in pixels), exact.
    let p = tri.map(|(x, y, _, _)| (x, y));
    let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
    let exact = |i: usize| {
        let (cx, cy) = ((i % 320) as f64 + 0.5, (i / 320) as f64 + 0.5);
        let e = |a: usize, b: usize| {
            ((p[b].0 - p[a].0) * (cy - p[a].1) - (p[b].1 - p[a].1) * (cx - p[a].0)) / area
        };
        let l = [e(1, 2), e(2, 0), e(0, 1)];
        [0, 1].map(|k| (0..3).map(|j| l[j] * tri[j].3[k]).sum::<f64>() * 64.0)
    };
    let edge = |t: f64| (t - t.floor()).min(t.ceil() - t);
    for (name, px) in [("320 x 240", draw(320, 240)), ("640 x 480", draw(640, 480))] {
        let (mut checked, mut wrong) = (0, 0);
        for (i, got) in px.iter().enumerate() {
            let Some(got) = got else { continue };
            let [u, v] = exact(i);
            if edge(u).min(edge(v)) <= 1.0 / 64.0 {
                continue;
            }
            checked += 1;
            let want = (
                u.floor().rem_euclid(64.0) as u32,
                v.floor().rem_euclid(64.0) as u32,
            );
            wrong += usize::from(*got != want);
        }
        println!("affine, viewport {name}: {wrong} of {checked} pixels off GL's texel");
        assert!(checked > 20_000);
        assert_eq!(wrong, 0, "viewport {name}");
    }
}

/// Coverage of `scene` with window positions snapped to `1/steps` pixel (`None`: exact).
fn coverage(scene: &scenes::SceneDesc, steps: Option<f64>) -> Vec<bool> {
    let (w, h) = (scene.width, scene.height);
    let mut out = vec![false; (w * h) as usize];
    for tri in scenes::to_ref_triangles(scene) {
        for sub in clip::fan(&clip::clip_triangle(&tri)) {
            let [Some(a), Some(b), Some(c)] = sub.0.map(|v| raster::to_window(&v, w, h)) else {
                continue;
            };
            let snap = |mut v: raster::WindowVertex| {
                let s = |e: f64| steps.map_or(e, |k| (e * k + 0.5).floor() / k);
                (v.x, v.y) = (s(v.ex), s(v.ey));
                v
            };
            let v = [snap(a), snap(b), snap(c)];
            // Back faces culled, as the scenes draw them (front faces have negative area).
            if raster::signed_area2(&v) >= 0.0 {
                continue;
            }
            raster::rasterize(&v, w, h, |x, y, _| out[(y * w + x) as usize] = true);
        }
    }
    out
}

/// 4 against 8 sub-pixel bits for coverage: pixels whose coverage differs from exact
/// (unsnapped) edges, and between the two, over the benchmark scenes. Printed for the
/// README; the assertion only keeps the figures honest (8 bits is never worse).
#[test]
fn coverage_with_4_and_8_subpixel_bits() {
    let mut cases = vec![scenes::sphere(0), scenes::floor()];
    cases.extend([0, 33, 66].map(scenes::cube));
    let (mut px, mut d4, mut d8, mut d48) = (0usize, 0usize, 0usize, 0usize);
    for s in &cases {
        let exact = coverage(s, None);
        let c4 = coverage(s, Some(16.0));
        let c8 = coverage(s, Some(256.0));
        let diff = |a: &[bool], b: &[bool]| a.iter().zip(b).filter(|(x, y)| x != y).count();
        let (e4, e8, e48) = (diff(&c4, &exact), diff(&c8, &exact), diff(&c4, &c8));
        let n = exact.iter().filter(|&&c| c).count();
        println!(
            "coverage {}: {n} px; 4 bits {e4} ({:.3} %), 8 bits {e8} ({:.3} %) off exact; 4 vs 8: {e48}",
            s.name,
            100.0 * e4 as f64 / n as f64,
            100.0 * e8 as f64 / n as f64
        );
        (px, d4, d8, d48) = (px + n, d4 + e4, d8 + e8, d48 + e48);
        assert!(e8 <= e4);
    }
    println!(
        "coverage, all: {px} px; off exact: 4 bits {d4} ({:.3} %), 8 bits {d8} ({:.3} %); 4 vs 8: {d48}",
        100.0 * d4 as f64 / px as f64,
        100.0 * d8 as f64 / px as f64
    );
}
