//! Band frames made of draws of different shader types (the classic `Draw` and open
//! `ShadedDraw`s with 0 to 8 varyings, each with its own projection and depth stage):
//!
//! * equal to the whole frame bit for bit, through `BandRenderer::render` (bins big enough
//!   or too small) and `BandRenderer::render_spans` (bins, band ranges, short ranges, with
//!   and without kept set-ups), over random scenes;
//! * bad input refused before any band is flushed: a draw index past the list, a triangle
//!   whose varying count is not its draw's, a depth-testing draw without a depth band.

mod common;

use common::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{ClipVertex, Cull, ScreenTriangle, Vertex, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{
    Adaptive, Affine, DepthLess, Draw, DrawMode, Exact, KeptSetup, NoDepth, Projection,
    QuadraticBy, ShadedDraw, Shading, SubdividedBy,
};
use fixel::shading::{Flat, Fragment, Gouraud, Shader};
use fixel::surface::{BandDraw, BandError, BandRange, BandRenderer, Binned, Frame, RenderTarget};
use fixel::Error;
use proptest::prelude::*;

/// A test shader of `N` varyings: a hash of the interpolated varyings.
#[derive(Clone, Copy, Debug)]
struct Mix<const N: usize>;

impl<const N: usize> Shader for Mix<N> {
    type Varyings = [i32; N];
    type Triangle = ();
    fn triangle(&self, _: &mut [[i32; N]; 3]) {}
    fn shade(&self, f: &Fragment<[i32; N], ()>) -> Option<u16> {
        let mut h = 0x9E37u32;
        for (k, v) in f.varyings.iter().enumerate() {
            h = h
                .wrapping_mul(31)
                .wrapping_add((*v >> 12) as u32 ^ k as u32);
        }
        Some(h as u16 | 0x0821)
    }
}

/// The open vertex of `N` varyings made from a classic one: its five varyings, repeated
/// with offsets.
fn open<const N: usize>(v: &ClipVertex) -> Vertex<N> {
    let c = v.to_vertex();
    let mut a = [0; N];
    for (k, x) in a.iter_mut().enumerate() {
        *x = c.varyings[k % 5].wrapping_add(k as i32 * 70_000);
    }
    Vertex::new(c.position, a)
}

/// One clip-space triangle as open vertices of `N` varyings.
fn o<const N: usize>(t: &[ClipVertex; 3]) -> [[Vertex<N>; 3]; 1] {
    [t.each_ref().map(open)]
}

/// The draws of a scene: one of each kind.
struct Draws<'a> {
    classic: Draw<'a, Rgb565>,
    gouraud: ShadedDraw<Gouraud, Exact, DepthLess>,
    flat: ShadedDraw<Flat, Affine, NoDepth>,
    mix8: ShadedDraw<Mix<8>, QuadraticBy<2>, DepthLess>,
    mix1: ShadedDraw<Mix<1>, SubdividedBy<2>, NoDepth>,
    mix4: ShadedDraw<Mix<4>, Adaptive, DepthLess>,
}

const KINDS: u8 = 6;

impl<'a> Draws<'a> {
    fn new(mode: DrawMode, tex: fixel::texture::Texture<'a>, vp: Viewport) -> Self {
        Draws {
            classic: Draw::dynamic(mode, Some(tex), vp).unwrap(),
            gouraud: ShadedDraw::new(Gouraud, vp, Cull::Back).unwrap(),
            flat: ShadedDraw::new(Flat(0xF81F), vp, Cull::None).unwrap(),
            mix8: ShadedDraw::new(Mix, vp, Cull::None).unwrap(),
            mix1: ShadedDraw::new(Mix, vp, Cull::Front).unwrap(),
            mix4: ShadedDraw::new(Mix, vp, Cull::None).unwrap(),
        }
    }

    fn list(&self) -> [&dyn BandDraw<Rgb565>; KINDS as usize] {
        [
            &self.classic,
            &self.gouraud,
            &self.flat,
            &self.mix8,
            &self.mix1,
            &self.mix4,
        ]
    }

    /// Clips and projects `tri` with draw `d`, handing each screen triangle to `emit`.
    fn project(&self, d: u8, tri: &[ClipVertex; 3], emit: &mut dyn FnMut(Screen)) {
        match d {
            0 => self.classic.project(tri, &mut |s| emit(Screen::V5(*s))),
            1 => self
                .gouraud
                .project(&tri.each_ref().map(open), &mut |s| emit(Screen::V3(*s))),
            2 => self
                .flat
                .project(&tri.each_ref().map(open), &mut |s| emit(Screen::V0(*s))),
            3 => self
                .mix8
                .project(&tri.each_ref().map(open), &mut |s| emit(Screen::V8(*s))),
            4 => self
                .mix1
                .project(&tri.each_ref().map(open), &mut |s| emit(Screen::V1(*s))),
            _ => self
                .mix4
                .project(&tri.each_ref().map(open), &mut |s| emit(Screen::V4(*s))),
        }
    }

    /// Draws `tris` into one whole frame, as each draw's own `clip_triangles` does.
    fn whole(&self, tris: &[(u8, [ClipVertex; 3])], w: usize, h: usize) -> Vec<u16> {
        let mut color = vec![Rgb565::default(); w * h];
        let mut depth = vec![0u16; w * h];
        let mut f = Frame::new(&mut color, w as u32, h as u32)
            .unwrap()
            .with_depth(&mut depth)
            .unwrap();
        f.clear(raw(0x1234));
        for (d, t) in tris {
            let one = std::slice::from_ref(t);
            match d {
                0 => self.classic.clip_triangles(one, &mut f),
                1 => self.gouraud.clip_triangles(&o(t), &mut f),
                2 => self.flat.clip_triangles(&o(t), &mut f),
                3 => self.mix8.clip_triangles(&o(t), &mut f),
                4 => self.mix1.clip_triangles(&o(t), &mut f),
                _ => self.mix4.clip_triangles(&o(t), &mut f),
            }
            .unwrap();
        }
        color.iter().map(|&c| bits(c)).collect()
    }
}

/// A screen triangle of one of the draws.
enum Screen {
    V0(ScreenTriangle<0>),
    V1(ScreenTriangle<1>),
    V3(ScreenTriangle<3>),
    V4(ScreenTriangle<4>),
    V5(ScreenTriangle<5>),
    V8(ScreenTriangle<8>),
}

/// Pushes `s` with `$push(tri)` whatever its varying count.
macro_rules! push_screen {
    ($s:expr, |$t:ident| $push:expr) => {
        match $s {
            Screen::V0($t) => $push,
            Screen::V1($t) => $push,
            Screen::V3($t) => $push,
            Screen::V4($t) => $push,
            Screen::V5($t) => $push,
            Screen::V8($t) => $push,
        }
    };
}

fn scene_vertex() -> impl Strategy<Value = ClipVertex> {
    (
        (-1.6f64..1.6, -1.6f64..1.6, -1.3f64..1.1),
        prop_oneof![4 => 0.3f64..3.0, 1 => -0.5f64..0.3],
        (-3.0f64..3.0, -3.0f64..3.0),
        [0u16..=256, 0u16..=256, 0u16..=256],
    )
        .prop_map(|((x, y, z), w, (u, v), color)| ClipVertex {
            position: [x * w, y * w, z * w.abs(), w].map(Fx::from_num),
            uv: [Fx::from_num(u), Fx::from_num(v)],
            color,
        })
}

fn any_mode() -> impl Strategy<Value = DrawMode> {
    (
        prop::sample::select(vec![
            Projection::Affine,
            Projection::Exact,
            Projection::Subdivided { log2_n: 3 },
            Projection::Quadratic { log2_n: 4 },
        ]),
        prop::sample::select(vec![
            Shading::Replace,
            Shading::ModulateIntensity,
            Shading::Gouraud,
        ]),
        any::<bool>(),
    )
        .prop_map(|(projection, shading, depth)| DrawMode {
            projection,
            shading,
            depth: if depth {
                fixel::pipeline::DepthTest::Less
            } else {
                fixel::pipeline::DepthTest::Off
            },
            cull: Cull::None,
            ..DrawMode::default()
        })
}

/// Copies a flushed band into the frame `got` (`w` wide).
fn keep(got: &mut [u16], w: usize, b: &Frame<'_, Rgb565>) {
    let start = b.first_row() as usize * w;
    for (o, &c) in got[start..start + b.pixels().len()]
        .iter_mut()
        .zip(b.pixels())
    {
        *o = bits(c);
    }
}

/// 256 cases, or `PROPTEST_CASES` when set (for long local runs).
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(256)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    /// Bands of any height, through `render` with bins big enough or too small and through
    /// `render_spans` with any bins, ranges and kept set-ups, give the whole frame bit for
    /// bit, whatever the mix of shader types.
    #[test]
    fn bands_of_mixed_shaders_equal_whole_frame(
        tris in prop::collection::vec((0u8..KINDS, [scene_vertex(), scene_vertex(), scene_vertex()]), 1..14),
        mode in any_mode(),
        (w, h) in (1usize..48, 1usize..40),
        rows in 1u32..40,
        (nbins, nranges, nsetups) in (0usize..24, 0usize..16, 0usize..6),
    ) {
        let tex = noise_texture(8, 16, 21);
        let texels = host_tests::adapter::texels(&tex);
        let t = texture(&tex, &texels);
        let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
        let draws = Draws::new(mode, t, vp);
        let list = draws.list();
        let expected = draws.whole(&tris, w, h);
        let mut screen = 0usize;
        for (d, tri) in &tris {
            draws.project(*d, tri, &mut |_| screen += 1);
        }

        let rows = rows.min(h as u32);
        let mut cbuf = vec![Rgb565::default(); w * rows as usize];
        let mut dbuf = vec![0u16; w * rows as usize];
        let mut setups = vec![KeptSetup::EMPTY; nsetups];
        let mut band = BandRenderer::new(&mut cbuf, w as u32, rows, h as u32)
            .unwrap()
            .with_depth(&mut dbuf)
            .unwrap()
            .with_setup_cache(&mut setups);

        // Binned once (or re-walked when the bins are too small).
        let mut bins = vec![Binned::default(); nbins];
        let mut got = vec![0u16; w * h];
        let stats = band
            .render(
                &list,
                &mut bins,
                raw(0x1234),
                |sink| {
                    for (d, tri) in &tris {
                        draws.project(*d, tri, &mut |s| push_screen!(s, |t| sink.push(*d, &t)));
                    }
                },
                |b| {
                    keep(&mut got, w, b);
                    Ok::<(), ()>(())
                },
            )
            .unwrap();
        prop_assert_eq!(stats.rewalked, screen > nbins);
        prop_assert_eq!(stats.bands as usize, h.div_ceil(rows as usize));
        prop_assert!(got == expected, "render: band frame differs from whole frame ({:?})", stats);

        // Band ranges per triangle id, re-projected in the bands each meets.
        let mut ranges = vec![BandRange::EMPTY; nranges];
        let mut got = vec![0u16; w * h];
        let stats = band
            .render_spans(
                &list,
                &mut bins,
                &mut ranges,
                raw(0x1234),
                |sink| {
                    for (id, (d, tri)) in tris.iter().enumerate() {
                        if sink.wants(id) {
                            draws.project(*d, tri, &mut |s| push_screen!(s, |t| sink.push(id, *d, &t)));
                        }
                    }
                },
                |b| {
                    keep(&mut got, w, b);
                    Ok::<(), ()>(())
                },
            )
            .unwrap();
        prop_assert!(got == expected, "render_spans: band frame differs from whole frame ({:?})", stats);
    }
}

/// A tiny scene: one triangle covering the 16 x 16 frame's middle, as the open vertices
/// of `N` varyings.
fn middle<const N: usize>() -> [Vertex<N>; 3] {
    let p = |x: f32, y: f32| [Fx::from_num(x), Fx::from_num(y), Fx::ZERO, Fx::ONE];
    [
        Vertex::new(p(-0.8, -0.8), [1 << 16; N]),
        Vertex::new(p(0.8, -0.8), [1 << 16; N]),
        Vertex::new(p(0.0, 0.8), [1 << 16; N]),
    ]
}

/// Renders a 16 x 16 frame in 4-row bands (with a depth band when `depth`) of `draws`,
/// through `render` and `render_spans`, with `geometry` pushing through both sinks;
/// returns both results and how many bands were flushed.
fn try_bands(
    draws: &[&dyn BandDraw<Rgb565>],
    depth: bool,
    push: &Geometry<'_>,
) -> [(Result<(), BandError<()>>, u32); 2] {
    let mut cbuf = [Rgb565::default(); 16 * 4];
    let mut dbuf = [0u16; 16 * 4];
    let mut r = BandRenderer::new(&mut cbuf, 16, 4, 16).unwrap();
    if depth {
        r = r.with_depth(&mut dbuf).unwrap();
    }
    let mut bins = [Binned::default(); 4];
    let mut flushed = 0;
    let a = r
        .render(
            draws,
            &mut bins,
            Rgb565::default(),
            |sink| {
                push(&mut |d, p| match p {
                    Pushed::Three(t) => sink.push(d, t),
                    Pushed::None(t) => sink.push(d, t),
                })
            },
            |_| {
                flushed += 1;
                Ok(())
            },
        )
        .map(|_| ());
    let first = (a, flushed);
    let mut flushed = 0;
    let mut ranges = [BandRange::EMPTY; 4];
    let b = r
        .render_spans(
            draws,
            &mut bins,
            &mut ranges,
            Rgb565::default(),
            |sink| {
                push(&mut |d, p| match p {
                    Pushed::Three(t) => sink.push(0, d, t),
                    Pushed::None(t) => sink.push(0, d, t),
                })
            },
            |_| {
                flushed += 1;
                Ok(())
            },
        )
        .map(|_| ());
    [first, (b, flushed)]
}

/// The bad-input tests' geometry: pushes triangles through the sink it is given.
type Geometry<'a> = dyn Fn(&mut dyn FnMut(u8, &Pushed)) + 'a;

/// What the bad-input tests push.
enum Pushed {
    Three(ScreenTriangle<3>),
    None(ScreenTriangle<0>),
}

fn screen<const N: usize>(
    draw: &ShadedDraw<impl Shader<Varyings = [i32; N]>, Exact, impl fixel::pipeline::DepthStage>,
) -> ScreenTriangle<N> {
    let mut out = None;
    draw.project(&middle::<N>(), &mut |s| out = Some(*s));
    out.unwrap()
}

#[test]
fn a_triangle_with_another_varying_count_than_its_draw_is_refused_before_drawing() {
    let vp = Viewport::new(0, 0, 16, 16).unwrap();
    let gouraud = ShadedDraw::<_, Exact, NoDepth>::new(Gouraud, vp, Cull::None).unwrap();
    let flat = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0xFFFF), vp, Cull::None).unwrap();
    let (g, f) = (screen(&gouraud), screen(&flat));
    let draws: [&dyn BandDraw<Rgb565>; 2] = [&gouraud, &flat];
    // Right: each triangle to its draw.
    for (r, flushed) in try_bands(&draws, false, &|push| {
        push(0, &Pushed::Three(g));
        push(1, &Pushed::None(f));
    }) {
        assert_eq!((r, flushed), (Ok(()), 4));
    }
    // The Gouraud triangle (3 varyings) sent to the flat draw (none).
    for (r, flushed) in try_bands(&draws, false, &|push| {
        push(0, &Pushed::Three(g));
        push(1, &Pushed::Three(g));
    }) {
        let want = Error::WrongVaryings {
            draw: 1,
            expected: 0,
            actual: 3,
        };
        assert_eq!((r, flushed), (Err(BandError::Input(want)), 0));
        assert!(want.to_string().contains("carries 3 varyings"));
    }
}

#[test]
fn a_draw_index_past_the_list_is_refused_before_drawing() {
    let vp = Viewport::new(0, 0, 16, 16).unwrap();
    let gouraud = ShadedDraw::<_, Exact, NoDepth>::new(Gouraud, vp, Cull::None).unwrap();
    let g = screen(&gouraud);
    for (r, flushed) in try_bands(&[&gouraud], false, &|push| {
        push(0, &Pushed::Three(g));
        push(3, &Pushed::Three(g));
    }) {
        let want = Error::BadDrawIndex { index: 3, draws: 1 };
        assert_eq!((r, flushed), (Err(BandError::Input(want)), 0));
    }
}

#[test]
fn an_open_draw_testing_depth_needs_a_depth_band() {
    let vp = Viewport::new(0, 0, 16, 16).unwrap();
    let flat = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0xFFFF), vp, Cull::None).unwrap();
    let deep = ShadedDraw::<_, Exact, DepthLess>::new(Gouraud, vp, Cull::None).unwrap();
    let g = screen(&deep);
    let draws: [&dyn BandDraw<Rgb565>; 2] = [&flat, &deep];
    assert!(draws[1].tests_depth() && !draws[0].tests_depth());
    let push = |push: &mut dyn FnMut(u8, &Pushed)| push(1, &Pushed::Three(g));
    for (r, flushed) in try_bands(&draws, false, &push) {
        assert_eq!(
            (r, flushed),
            (Err(BandError::Input(Error::NoDepthBuffer)), 0)
        );
    }
    for (r, flushed) in try_bands(&draws, true, &push) {
        assert_eq!((r, flushed), (Ok(()), 4));
    }
}

#[test]
fn more_draws_than_a_triangle_can_name_are_refused() {
    let vp = Viewport::new(0, 0, 16, 16).unwrap();
    let flat = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0xFFFF), vp, Cull::None).unwrap();
    let draws: Vec<&dyn BandDraw<Rgb565>> = vec![&flat; 257];
    for (r, flushed) in try_bands(&draws, false, &|_| {}) {
        assert_eq!(
            (r, flushed),
            (
                Err(BandError::Input(Error::CapacityExceeded { capacity: 256 })),
                0
            )
        );
    }
    for (r, flushed) in try_bands(&draws[..256], false, &|_| {}) {
        assert_eq!((r, flushed), (Ok(()), 4));
    }
}

/// Every draw of the list draws a piece only when it carries its varying count (the
/// renderer checks while binning; a piece handed over directly is skipped, not misread).
#[test]
fn a_draw_skips_a_piece_of_another_varying_count() {
    let vp = Viewport::new(0, 0, 16, 16).unwrap();
    let gouraud = ShadedDraw::<_, Exact, NoDepth>::new(Gouraud, vp, Cull::None).unwrap();
    let flat = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0xFFFF), vp, Cull::None).unwrap();
    let (g, f) = (screen(&gouraud), screen(&flat));
    let mut color = [Rgb565::default(); 16 * 16];
    let mut frame = Frame::new(&mut color, 16, 16).unwrap();
    use fixel::surface::Binnable;
    let d: &dyn BandDraw<Rgb565> = &gouraud;
    assert_eq!(d.draw_piece(f.as_any(), &mut frame, None), 0);
    assert!(d.draw_piece(g.as_any(), &mut frame, None) > 50);
    assert!(frame.has_depth() || !d.tests_depth());
}

/// Accumulation through bands gives the same frame and the same pixel count (per sample,
/// over the frame) whatever the band height, open draws included.
#[test]
fn accumulated_frames_do_not_depend_on_the_band_height() {
    use fixel::scene::SamplePattern;
    let vp = Viewport::new(0, 0, 16, 16).unwrap();
    let gouraud = ShadedDraw::<_, Exact, DepthLess>::new(Gouraud, vp, Cull::None).unwrap();
    let mix = ShadedDraw::<_, Exact, NoDepth>::new(Mix::<2>, vp, Cull::None).unwrap();
    let draws: [&dyn BandDraw<Rgb565>; 2] = [&gouraud, &mix];
    let mut offsets = [[Fx::ZERO; 2]; 4];
    SamplePattern::RotatedGrid4.offsets(&mut offsets).unwrap();
    let small = {
        let p = |x: f32, y: f32| [Fx::from_num(x), Fx::from_num(y), Fx::ZERO, Fx::ONE];
        [
            Vertex::new(p(-0.3, 0.1), [1 << 20, 5 << 20]),
            Vertex::new(p(0.9, 0.3), [3 << 20, 0]),
            Vertex::new(p(0.2, 0.95), [0, 7 << 20]),
        ]
    };
    let run = |rows: u32| {
        let n = 16 * rows as usize;
        let (mut c, mut d) = (vec![Rgb565::default(); n], vec![0u16; n]);
        let mut sums = vec![[0u16; 3]; n];
        let mut bins = [Binned::default(); 4];
        let mut r = BandRenderer::new(&mut c, 16, rows, 16)
            .unwrap()
            .with_depth(&mut d)
            .unwrap();
        let mut got = vec![0u16; 16 * 16];
        let stats = r
            .render_accumulated(
                &draws,
                &mut bins,
                Rgb565::default(),
                &offsets,
                &mut sums,
                |sink| {
                    gouraud.project(&middle::<3>(), &mut |s| sink.push(0, s));
                    mix.project(&small, &mut |s| sink.push(1, s));
                },
                |b| {
                    keep(&mut got, 16, b);
                    Ok::<(), ()>(())
                },
            )
            .unwrap();
        (got, stats.pixels)
    };
    let whole = run(16);
    assert!(whole.1 > 50);
    for rows in [1, 3, 4, 7, 8] {
        assert_eq!(run(rows), whole, "{rows}-row bands");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    /// An open mesh through `scene::triangles_to_sink` (bins full or not, band ranges
    /// short or not: the binning pass projects positions alone once the bins are full)
    /// gives the whole frame bit for bit.
    #[test]
    fn triangles_to_sink_equals_whole_frame(
        tris in prop::collection::vec([scene_vertex(), scene_vertex(), scene_vertex()], 1..14),
        (w, h) in (1usize..48, 1usize..40),
        rows in 1u32..40,
        (nbins, nranges) in (0usize..12, 0usize..16),
    ) {
        let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
        let draw = ShadedDraw::<_, QuadraticBy<2>, DepthLess>::new(Mix::<8>, vp, Cull::Back).unwrap();
        let open: Vec<[Vertex<8>; 3]> = tris.iter().map(|t| t.each_ref().map(open)).collect();
        let mut color = vec![Rgb565::default(); w * h];
        let mut depth = vec![0u16; w * h];
        let mut f = Frame::new(&mut color, w as u32, h as u32).unwrap().with_depth(&mut depth).unwrap();
        f.clear(raw(0x1234));
        let px = draw.clip_triangles(&open, &mut f).unwrap();
        let expected: Vec<u16> = color.iter().map(|&c| bits(c)).collect();

        let rows = rows.min(h as u32);
        let mut cbuf = vec![Rgb565::default(); w * rows as usize];
        let mut dbuf = vec![0u16; w * rows as usize];
        let mut band = BandRenderer::new(&mut cbuf, w as u32, rows, h as u32)
            .unwrap()
            .with_depth(&mut dbuf)
            .unwrap();
        let mut bins = vec![Binned::default(); nbins];
        let mut ranges = vec![BandRange::EMPTY; nranges];
        let mut got = vec![0u16; w * h];
        let stats = band
            .render_spans(
                &[&draw],
                &mut bins,
                &mut ranges,
                raw(0x1234),
                |sink| {
                    fixel::scene::triangles_to_sink(&draw, 0, open.len(), 0, |k, _| open.get(k).copied(), sink);
                },
                |b| {
                    keep(&mut got, w, b);
                    Ok::<(), ()>(())
                },
            )
            .unwrap();
        prop_assert_eq!(stats.pixels, px);
        prop_assert!(got == expected, "triangles_to_sink: band frame differs ({:?})", stats);
    }
}
