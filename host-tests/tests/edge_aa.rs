//! Silhouette anti-aliasing from depth (`fixel::surface::EdgeAa`) against its definition in
//! f64: two 4-neighbours are across an edge when their depths differ by more than the
//! threshold, and a pixel with neighbours `E` across edges becomes
//! `p + Σ_{q ∈ E} (q − p) / 4` per channel, from the unsmoothed frame (neighbours outside
//! the frame are the pixel itself).
//!
//! Budgets: every channel within 0.5 LSB of that value (fixel rounds it once, half up), and
//! pixels with no neighbour across an edge exactly as drawn. Bands of any height give the
//! whole frame's pixels bit for bit (the held row carries across each seam). Checked on the
//! `aa_edge` firmware's frame (the cube), over random frames (proptest), and on hard cases:
//! edges along the frame's border and along a band seam, bands of one row. The quality
//! against a 16 x 16 supersampled reference is in `docs/report/aa.md`.

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Viewport};
use fixel::pipeline::{DepthLess, Draw, ModulateFacet, Pipeline, QuadraticBy};
use fixel::scene::{draw_mesh, DirectionalLight};
use fixel::surface::{EdgeAa, Frame};
use fixel::texture::{Bilinear, Repeat, Texture};
use fixel_scenes as demo;
use host_tests::golden::assert_golden;
use proptest::prelude::*;

mod common;

/// The `aa_edge` firmware's threshold (`examples/firmware/src/edge_scene.rs`).
const THRESHOLD: u16 = 2047;

fn channels(c: Rgb565) -> [f64; 3] {
    let v = RawU16::from(c).into_inner();
    [
        f64::from(v >> 11),
        f64::from((v >> 5) & 63),
        f64::from(v & 31),
    ]
}

/// The rule in f64 over a whole `w x h` frame.
fn reference(c: &[Rgb565], d: &[u16], w: usize, h: usize, t: u16) -> Vec<[f64; 3]> {
    let mut out = Vec::with_capacity(c.len());
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            let p = channels(c[i]);
            let mut v = p;
            let around = [
                (x > 0).then(|| i - 1),
                (x + 1 < w).then(|| i + 1),
                (y > 0).then(|| i - w),
                (y + 1 < h).then(|| i + w),
            ];
            for j in around.into_iter().flatten() {
                if (f64::from(d[i]) - f64::from(d[j])).abs() > f64::from(t) {
                    let q = channels(c[j]);
                    for k in 0..3 {
                        v[k] += (q[k] - p[k]) / 4.0;
                    }
                }
            }
            out.push(v);
        }
    }
    out
}

/// The frame through [`EdgeAa`] in bands of `rows` rows (the last band may be shorter).
fn banded(c: &[Rgb565], d: &[u16], w: usize, rows: usize, t: u16) -> Vec<Rgb565> {
    let h = c.len() / w;
    let (mut hc, mut hd) = (vec![Rgb565::new(0, 0, 0); 2 * w], vec![0u16; 2 * w]);
    let mut aa = EdgeAa::new(w as u32, t, &mut hc, &mut hd).unwrap();
    let mut all = Vec::with_capacity(c.len());
    let mut out = vec![Rgb565::new(0, 0, 0); (rows + 1) * w];
    let mut y = 0;
    while y < h {
        let r = rows.min(h - y);
        let last = y + r == h;
        let band = y * w..(y + r) * w;
        let expected = aa.out_len(r, last);
        let n = aa
            .band_into(&c[band.clone()], &d[band], last, &mut out)
            .unwrap();
        assert_eq!(n, expected);
        all.extend_from_slice(&out[..n]);
        y += r;
    }
    all
}

/// Largest channel difference from the reference, and whether every pixel with no edge is
/// exactly as drawn.
fn check(c: &[Rgb565], d: &[u16], w: usize, t: u16, got: &[Rgb565]) -> (f64, usize) {
    let h = c.len() / w;
    let r = reference(c, d, w, h, t);
    let mut worst = 0.0f64;
    let mut touched = 0;
    for i in 0..c.len() {
        let g = channels(got[i]);
        for k in 0..3 {
            worst = worst.max((g[k] - r[i][k]).abs());
        }
        if r[i] != channels(c[i]) {
            touched += 1;
        } else {
            assert_eq!(got[i], c[i], "pixel {i}: no edge, yet changed");
        }
    }
    (worst, touched)
}

/// The `aa_edge` firmware's frame before the pass: the cube, frame 0, drawn whole.
fn cube_frame() -> (Vec<Rgb565>, Vec<u16>) {
    let (w, h) = (320u32, 240u32);
    let mut t = vec![Rgb565::new(0, 0, 0); 128 * 128];
    demo::checker_texture(128, 128, &mut t).unwrap();
    let tex = Texture::new(&t, 128, 128).unwrap();
    // The `cube` scene's draw (`scenes::Lit`: its footprint twin gives the same pixels).
    type Lit = Pipeline<QuadraticBy<4>, Bilinear, Repeat, Repeat, ModulateFacet, DepthLess>;
    let draw = Draw::new::<Lit>(Some(tex), Viewport::new(0, 0, w, h).unwrap(), Cull::Back).unwrap();
    let (mut c, mut d) = (
        vec![Rgb565::new(0, 0, 0); (w * h) as usize],
        vec![0u16; (w * h) as usize],
    );
    let mut frame = Frame::new(&mut c, w, h)
        .unwrap()
        .with_depth(&mut d)
        .unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    let cube = demo::cube();
    draw_mesh(
        &draw,
        &cube.mesh().unwrap(),
        &demo::cube_model(0),
        &demo::camera(20),
        Some(&DirectionalLight::default()),
        &mut frame,
    )
    .unwrap();
    (c, d)
}

#[test]
fn the_cube_matches_the_f64_rule_and_its_golden() {
    let (c, d) = cube_frame();
    let whole = banded(&c, &d, 320, 240, THRESHOLD);
    let (worst, touched) = check(&c, &d, 320, THRESHOLD, &whole);
    println!("cube: {touched} pixels smoothed, worst channel {worst:.3} LSB from the f64 rule");
    assert!(worst <= 0.5, "{worst}");
    // The silhouette only: a few pixels per column and row it crosses, never the faces.
    assert!((400..4000).contains(&touched), "{touched}");
    for rows in [1, 3, 8, 17] {
        assert!(
            banded(&c, &d, 320, rows, THRESHOLD) == whole,
            "bands of {rows}"
        );
    }
    let raw: Vec<u16> = whole
        .iter()
        .map(|&p| RawU16::from(p).into_inner())
        .collect();
    assert_golden("aa-edge-cube-0", 320, 240, &raw);
}

/// A random frame of a few depth-sorted rectangles over a far background.
#[derive(Debug, Clone)]
struct Case {
    w: usize,
    h: usize,
    rects: Vec<(usize, usize, usize, usize, u16, u16, u16)>,
    rows: usize,
    t: u16,
}

fn case() -> impl Strategy<Value = Case> {
    (1usize..24, 1usize..24, 1usize..10, 0u16..2000).prop_flat_map(|(w, h, rows, t)| {
        prop::collection::vec(
            (
                0..w,
                0..h,
                1..=w,
                1..=h,
                any::<u16>(),
                any::<u16>(),
                0u16..64,
            ),
            0..5,
        )
        .prop_map(move |rects| Case {
            w,
            h,
            rects,
            rows,
            t,
        })
    })
}

fn paint(k: &Case) -> (Vec<Rgb565>, Vec<u16>) {
    let mut c = vec![Rgb565::new(3, 7, 9); k.w * k.h];
    let mut d = vec![u16::MAX; k.w * k.h];
    for &(x0, y0, rw, rh, colour, depth, slope) in &k.rects {
        for y in y0..(y0 + rh).min(k.h) {
            for x in x0..(x0 + rw).min(k.w) {
                let z = depth.saturating_add(slope * (x - x0) as u16);
                let i = y * k.w + x;
                if z < d[i] {
                    d[i] = z;
                    c[i] = Rgb565::from(RawU16::new(colour ^ (x as u16 * 2113)));
                }
            }
        }
    }
    (c, d)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(common::cases(512)))]

    #[test]
    fn bands_give_the_whole_frame_within_half_an_lsb_of_the_rule(k in case()) {
        let (c, d) = paint(&k);
        let whole = banded(&c, &d, k.w, k.h, k.t);
        let (worst, _) = check(&c, &d, k.w, k.t, &whole);
        prop_assert!(worst <= 0.5, "{}", worst);
        prop_assert_eq!(banded(&c, &d, k.w, k.rows, k.t), whole);
    }
}

/// A frame of one depth with a few single pixels moved nearer or farther (by a little or a
/// lot, across a multiple of the quick test's step or not), any colours: lone edges at every
/// position of rows long enough for the four-pixel skip, in the row, above and below.
#[derive(Debug, Clone)]
struct Speckle {
    w: usize,
    h: usize,
    base: u16,
    moved: Vec<(usize, usize, i32)>,
    colours: Vec<u16>,
    rows: usize,
    t: u16,
}

fn speckle() -> impl Strategy<Value = Speckle> {
    (1usize..70, 1usize..12, 1usize..10, 0u16..4096, any::<u16>()).prop_flat_map(
        |(w, h, rows, t, base)| {
            let step = prop_oneof![-40i32..40, -5000i32..5000, any::<u16>().prop_map(i32::from)];
            (
                prop::collection::vec((0..w, 0..h, step), 0..8),
                prop::collection::vec(any::<u16>(), w * h),
            )
                .prop_map(move |(moved, colours)| Speckle {
                    w,
                    h,
                    base,
                    moved,
                    colours,
                    rows,
                    t,
                })
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(common::cases(512)))]

    #[test]
    fn lone_edges_anywhere_are_found(k in speckle()) {
        let mut d = vec![k.base; k.w * k.h];
        for &(x, y, step) in &k.moved {
            d[y * k.w + x] = (i32::from(k.base) + step).clamp(0, 65535) as u16;
        }
        let c: Vec<Rgb565> = k.colours.iter().map(|&v| Rgb565::from(RawU16::new(v))).collect();
        let whole = banded(&c, &d, k.w, k.h, k.t);
        let (worst, _) = check(&c, &d, k.w, k.t, &whole);
        prop_assert!(worst <= 0.5, "{}", worst);
        prop_assert_eq!(banded(&c, &d, k.w, k.rows, k.t), whole);
    }
}

#[test]
fn edges_on_the_frame_border_and_on_a_band_seam() {
    // A near square touching the left, top and right borders, its lower edge between rows
    // 7 and 8: the seam of 8-row bands.
    let (w, h) = (12usize, 16usize);
    let mut c = vec![Rgb565::new(0, 0, 0); w * h];
    let mut d = vec![u16::MAX; w * h];
    for y in 0..8 {
        for x in 0..w {
            c[y * w + x] = Rgb565::new(31, 63, 31);
            d[y * w + x] = 100;
        }
    }
    let whole = banded(&c, &d, w, h, 1000);
    // Rows 7 and 8 become the ramp 3/4, 1/4; the rest is as drawn (no edge at the border).
    assert_eq!(whole[7 * w], Rgb565::new(23, 47, 23));
    assert_eq!(whole[8 * w + w - 1], Rgb565::new(8, 16, 8));
    assert_eq!(whole[0], c[0]);
    assert_eq!(whole[6 * w + w - 1], c[6 * w + w - 1]);
    assert_eq!(whole[9 * w], c[9 * w]);
    for rows in [1, 2, 7, 8, 9, 16] {
        assert!(banded(&c, &d, w, rows, 1000) == whole, "bands of {rows}");
    }
    assert!(check(&c, &d, w, 1000, &whole).0 <= 0.5);
}

#[test]
fn a_one_pixel_frame_and_short_buffers() {
    let c = [Rgb565::new(1, 2, 3)];
    assert_eq!(banded(&c, &[7], 1, 1, 0), c);
    let (mut hc, mut hd) = (vec![Rgb565::new(0, 0, 0); 8], vec![0u16; 8]);
    let mut aa = EdgeAa::new(4, 0, &mut hc, &mut hd).unwrap();
    let c = [Rgb565::new(0, 0, 0); 8];
    // Not whole rows, depth of another length, output short: refused, nothing written
    // or handed on.
    let mut out = [Rgb565::new(1, 1, 1); 8];
    assert!(aa.band_into(&c[..6], &[0; 6], true, &mut out).is_err());
    assert!(aa.band_into(&c, &[0; 4], true, &mut out).is_err());
    assert!(aa.band_into(&c, &[0; 8], true, &mut out[..7]).is_err());
    assert_eq!(out, [Rgb565::new(1, 1, 1); 8]);
    let r = aa.band(&c, &[0; 7], true, |_| -> Result<(), fixel::Error> {
        panic!("a run handed on")
    });
    assert!(r.is_err());
    assert_eq!(aa.band_into(&c, &[0; 8], true, &mut out).unwrap(), 8);
}
