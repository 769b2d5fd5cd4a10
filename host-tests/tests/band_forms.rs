//! Every draw of the band path in every form: the spans frame (`render_spans`) and the
//! accumulated frame (`render_accumulated`) drawn
//!
//! * as an `async` frame (`render_spans_async`, `render_accumulated_async`) through one
//!   buffer or a ring, with transfers finished at their first poll or kept pending;
//! * on two to four cores (`SpansFrame` + `render_spans_share_to`, `BinnedFrame` +
//!   `render_accumulated_share_to`), each core its own buffers, vertex cache and set-up
//!   cache, the bands of all the shares put in row order;
//!
//! send the bands of the serial one-buffer frame, bit for bit, over random turns of the
//! cube and the sphere, frame and band sizes, storage (bins, band ranges, set-up caches),
//! rings and core counts. And a spans frame binned for other bands is refused.

mod common;

use std::future::Future;
use std::pin::pin;
use std::task::{Context, Poll, Waker};

use common::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::Viewport;
use fixel::math::Fx;
use fixel::pipeline::{Draw, DrawMode, KeptSetup, Shading};
use fixel::scene::{
    mesh_to_sink, mesh_triangles, CachedVertex, DirectionalLight, MeshTransform, SamplePattern,
};
use fixel::surface::{
    AsyncBandSender, BandDraw, BandError, BandRange, BandRenderer, BandShare, Binned, BinnedFrame,
    Blocking, Frame, MeshSink, SpansFrame, TriangleSink,
};
use fixel::Error;
use fixel_scenes as demo;
use proptest::prelude::*;

/// One band as it reached the display: its first row and pixels.
type Sent = (i32, Vec<u16>);

fn keep(out: &mut Vec<Sent>, b: &Frame<'_, Rgb565>) {
    out.push((b.first_row(), b.pixels().iter().map(|&c| bits(c)).collect()));
}

/// Runs a future to its end with a waker that does nothing (the test senders make progress
/// on each poll).
fn run<F: Future>(f: F) -> F::Output {
    let mut f = pin!(f);
    let mut cx = Context::from_waker(Waker::noop());
    loop {
        if let Poll::Ready(v) = f.as_mut().poll(&mut cx) {
            return v;
        }
    }
}

/// An async sender whose transfers take `polls` polls; it keeps the bands.
struct Slow {
    polls: u32,
    sent: Vec<Sent>,
}

impl AsyncBandSender<Rgb565> for Slow {
    type Error = ();
    async fn send(&mut self, band: &Frame<'_, Rgb565>) -> Result<(), ()> {
        keep(&mut self.sent, band);
        let mut left = self.polls;
        std::future::poll_fn(|_| {
            if left == 0 {
                Poll::Ready(())
            } else {
                left -= 1;
                Poll::Pending
            }
        })
        .await;
        Ok(())
    }
}

/// A renderer's colour storage: one buffer (`ring` 1) or a ring of `ring` buffers.
struct Store {
    one: Vec<Rgb565>,
    ring: Vec<Vec<Rgb565>>,
}

impl Store {
    fn new(n: usize, ring: usize) -> Self {
        Store {
            one: vec![Rgb565::default(); n],
            ring: vec![vec![Rgb565::default(); n]; if ring > 1 { ring } else { 0 }],
        }
    }
}

/// Puts the bands of every share in row order.
fn in_row_order(mut bands: Vec<Sent>) -> Vec<Sent> {
    bands.sort_by_key(|b| b.0);
    bands
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(64), ..ProptestConfig::default() })]

    /// `render_spans_async` and `render_spans_share_to` on every core send the bands of
    /// `render_spans` through one buffer.
    #[test]
    fn spans_async_and_shared_are_the_serial_frame(
        sphere in any::<bool>(),
        turn in 0u32..200,
        (w, h) in (1u32..48, 1u32..72),
        rows in 1u32..12,
        ring in 1usize..4,
        polls in 0u32..3,
        cores in 1u32..5,
        bins_len in prop_oneof![Just(0usize), 1usize..40, Just(2400)],
        ranges_len in prop_oneof![Just(0usize), 0usize..3000, Just(3000)],
        setups_len in prop_oneof![Just(0usize), 1usize..8],
    ) {
        let rows = rows.min(h);
        let vp = Viewport::new(0, 0, w, h).unwrap();
        let tex = noise_texture(16, 8, 4);
        let texels = host_tests::adapter::texels(&tex);
        let draw = Draw::dynamic(DrawMode::default(), Some(texture(&tex, &texels)), vp).unwrap();
        let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
        let (cube, ball) = (demo::cube(), demo::sphere());
        let mesh = if sphere { ball.mesh().unwrap() } else { cube.mesh().unwrap() };
        let model = if sphere { demo::sphere_model(turn) } else { demo::cube_model(turn) };
        let xf = MeshTransform::new(&model, &demo::camera(20));
        let light = DirectionalLight::default();
        let (mesh, xf, light, draw_ref) = (&mesh, &xf, &light, &draw);
        // A geometry with its own vertex cache (one per core).
        let geometry = || {
            let mut cache = vec![CachedVertex::default(); 64];
            move |sink: &mut MeshSink<'_, '_, '_, Rgb565>| {
                mesh_to_sink(draw_ref, 0, mesh, xf, Some(light), &mut cache, 0, sink);
            }
        };
        let clear = raw(0x0821);
        let n = (w * rows) as usize;
        let mut bins = vec![Binned::default(); bins_len];
        let mut ranges = vec![BandRange::EMPTY; ranges_len];
        let mut depth = vec![0u16; n];

        let mut want = Vec::new();
        let mut c = vec![Rgb565::default(); n];
        let mut setups = vec![KeptSetup::EMPTY; setups_len];
        let serial = BandRenderer::new(&mut c, w, rows, h).unwrap()
            .with_depth(&mut depth).unwrap().with_setup_cache(&mut setups)
            .render_spans(&draws, &mut bins, &mut ranges, clear, geometry(), |b| {
                keep(&mut want, b);
                Ok::<(), ()>(())
            })
            .unwrap();

        // Async, through one buffer or a ring.
        let mut store = Store::new(n, ring);
        let mut buffers: Vec<&mut [Rgb565]> = store.ring.iter_mut().map(|b| &mut b[..]).collect();
        let bands = if ring == 1 {
            BandRenderer::new(&mut store.one, w, rows, h).unwrap()
        } else {
            BandRenderer::with_buffers(&mut buffers, w, rows, h).unwrap()
        };
        let mut setups = vec![KeptSetup::EMPTY; setups_len];
        let mut bands = bands.with_depth(&mut depth).unwrap().with_setup_cache(&mut setups);
        let mut sender = Slow { polls, sent: Vec::new() };
        let stats = run(bands.render_spans_async(&draws, &mut bins, &mut ranges, clear, geometry(), &mut sender)).unwrap();
        prop_assert_eq!(stats, serial);
        prop_assert!(sender.sent == want, "render_spans_async sent other bands");

        // Shared between cores: binned once, each core its own buffers and caches.
        // No more cores than bands (more are refused, tested below).
        let cores = cores.min(h.div_ceil(rows));
        let frame = SpansFrame::new(&draws, &mut bins, &mut ranges, rows, h, geometry()).unwrap();
        prop_assert_eq!(frame.triangles(), serial.triangles);
        let (mut got, mut pixels) = (Vec::new(), 0);
        for core in 0..cores {
            let mut store = Store::new(n, ring);
            let mut buffers: Vec<&mut [Rgb565]> = store.ring.iter_mut().map(|b| &mut b[..]).collect();
            let bands = if ring == 1 {
                BandRenderer::new(&mut store.one, w, rows, h).unwrap()
            } else {
                BandRenderer::with_buffers(&mut buffers, w, rows, h).unwrap()
            };
            let mut d = vec![0u16; n];
            let mut setups = vec![KeptSetup::EMPTY; setups_len];
            let mut bands = bands.with_depth(&mut d).unwrap().with_setup_cache(&mut setups);
            let mut mine = Vec::new();
            let share = BandShare::new(core, cores).unwrap();
            let mut send = Blocking(|b: &Frame<'_, Rgb565>| {
                keep(&mut mine, b);
                Ok::<(), ()>(())
            });
            let stats = bands.render_spans_share_to(&frame, clear, share, geometry(), &mut send).unwrap();
            prop_assert_eq!(stats.bands as usize, mine.len());
            prop_assert_eq!((stats.reprojected, stats.rewalked), (serial.reprojected, serial.rewalked));
            for (i, (row, _)) in mine.iter().enumerate() {
                prop_assert_eq!(*row as u32, (core + i as u32 * cores) * rows, "core {} band {}", core, i);
            }
            pixels += stats.pixels;
            got.extend(mine);
        }
        prop_assert_eq!(pixels, serial.pixels);
        prop_assert!(in_row_order(got) == want, "the shares are not the serial frame");
    }

    /// `render_accumulated_async` and `render_accumulated_share_to` on every core send the
    /// averaged bands of `render_accumulated` through one buffer.
    #[test]
    fn accumulation_async_and_shared_is_the_serial_frame(
        sphere in any::<bool>(),
        turn in 0u32..200,
        (w, h) in (1u32..40, 1u32..48),
        rows in 1u32..10,
        ring in 1usize..4,
        polls in 0u32..3,
        cores in 1u32..5,
        pattern in prop_oneof![
            Just(SamplePattern::RotatedGrid4),
            (1u8..4).prop_map(SamplePattern::Grid),
            (any::<u32>()).prop_map(|seed| SamplePattern::Jittered { n: 4, seed }),
        ],
    ) {
        let rows = rows.min(h);
        let vp = Viewport::new(0, 0, w, h).unwrap();
        let tex = noise_texture(16, 8, 4);
        let texels = host_tests::adapter::texels(&tex);
        let draw = Draw::dynamic(DrawMode::default(), Some(texture(&tex, &texels)), vp).unwrap();
        let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
        let (cube, ball) = (demo::cube(), demo::sphere());
        let mesh = if sphere { ball.mesh().unwrap() } else { cube.mesh().unwrap() };
        let model = if sphere { demo::sphere_model(turn) } else { demo::cube_model(turn) };
        let light = DirectionalLight::default();
        let geometry = |sink: &mut TriangleSink<'_, '_, '_, Rgb565>| {
            mesh_triangles(&mesh, &model, &demo::camera(20), Some(&light), |t| {
                draw.project(t, &mut |s| sink.push(0, s))
            })
        };
        let mut offsets = [[Fx::ZERO; 2]; 16];
        let k = pattern.offsets(&mut offsets).unwrap();
        let offsets = &offsets[..k];
        let clear = raw(0x1234);
        let n = (w * rows) as usize;
        let mut bins = vec![Binned::default(); 2400];
        let mut depth = vec![0u16; n];
        let mut sums = vec![[0u16; 3]; n];

        let mut want = Vec::new();
        let mut c = vec![Rgb565::default(); n];
        let serial = BandRenderer::new(&mut c, w, rows, h).unwrap().with_depth(&mut depth).unwrap()
            .render_accumulated(&draws, &mut bins, clear, offsets, &mut sums, geometry, |b| {
                keep(&mut want, b);
                Ok::<(), ()>(())
            })
            .unwrap();

        let mut store = Store::new(n, ring);
        let mut buffers: Vec<&mut [Rgb565]> = store.ring.iter_mut().map(|b| &mut b[..]).collect();
        let bands = if ring == 1 {
            BandRenderer::new(&mut store.one, w, rows, h).unwrap()
        } else {
            BandRenderer::with_buffers(&mut buffers, w, rows, h).unwrap()
        };
        let mut bands = bands.with_depth(&mut depth).unwrap();
        let mut sender = Slow { polls, sent: Vec::new() };
        let stats = run(bands.render_accumulated_async(&draws, &mut bins, clear, offsets, &mut sums, geometry, &mut sender)).unwrap();
        prop_assert_eq!(stats, serial);
        prop_assert!(sender.sent == want, "render_accumulated_async sent other bands");

        // No more cores than bands (more are refused, tested below).
        let cores = cores.min(h.div_ceil(rows));
        let frame = BinnedFrame::new(&draws, &mut bins, geometry).unwrap();
        let (mut got, mut pixels) = (Vec::new(), 0);
        for core in 0..cores {
            let mut store = Store::new(n, ring);
            let mut buffers: Vec<&mut [Rgb565]> = store.ring.iter_mut().map(|b| &mut b[..]).collect();
            let bands = if ring == 1 {
                BandRenderer::new(&mut store.one, w, rows, h).unwrap()
            } else {
                BandRenderer::with_buffers(&mut buffers, w, rows, h).unwrap()
            };
            let (mut d, mut s) = (vec![0u16; n], vec![[0u16; 3]; n]);
            let mut bands = bands.with_depth(&mut d).unwrap();
            let mut mine = Vec::new();
            let share = BandShare::new(core, cores).unwrap();
            let mut send = Blocking(|b: &Frame<'_, Rgb565>| {
                keep(&mut mine, b);
                Ok::<(), ()>(())
            });
            let stats = bands.render_accumulated_share_to(&frame, clear, offsets, &mut s, share, &mut send).unwrap();
            prop_assert_eq!(stats.bands as usize, mine.len());
            pixels += stats.pixels;
            got.extend(mine);
        }
        // Pixels per sample, summed over the shares: each share divides its own sum.
        prop_assert!(pixels.abs_diff(serial.pixels) < cores, "{} vs {}", pixels, serial.pixels);
        prop_assert!(in_row_order(got) == want, "the shares are not the serial frame");
    }
}

/// A spans frame binned for bands of other rows or another height, too few bands for the
/// cores, short sums or no offsets for an accumulated share: refused before any band is
/// drawn, each with a message that names the problem.
#[test]
fn bad_shares_of_the_other_draws_are_refused() {
    let (w, h) = (16u32, 32u32);
    let vp = Viewport::new(0, 0, w, h).unwrap();
    let flat = DrawMode {
        shading: Shading::Flat,
        ..DrawMode::default()
    };
    let draw = Draw::dynamic(flat, None, vp).unwrap();
    let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
    let nothing = |_: &mut MeshSink<'_, '_, '_, Rgb565>| {};
    let mut ranges = [BandRange::EMPTY; 4];
    let frame = SpansFrame::new(&draws, &mut [], &mut ranges, 8, h, nothing).unwrap();
    let mut c = vec![Rgb565::default(); (w * 8) as usize];
    let mut send = Blocking(|_: &Frame<'_, Rgb565>| Ok::<(), ()>(()));
    let two = BandShare::new(1, 2).unwrap();
    for (rows, height) in [(4, h), (8, 24)] {
        let mut c = vec![Rgb565::default(); (w * rows) as usize];
        let e = BandRenderer::new(&mut c, w, rows, height)
            .unwrap()
            .render_spans_share_to(&frame, raw(0), two, nothing, &mut send)
            .unwrap_err();
        assert_eq!(
            e,
            BandError::Input(Error::BadMode(
                "the spans frame was binned for bands of other rows or height"
            ))
        );
    }
    let mut ranges = [BandRange::EMPTY; 4];
    let short = SpansFrame::new(&draws, &mut [], &mut ranges, 8, 8, nothing).unwrap();
    let e = BandRenderer::new(&mut c, w, 8, 8)
        .unwrap()
        .render_spans_share_to(&short, raw(0), two, nothing, &mut send)
        .unwrap_err();
    assert_eq!(
        e,
        BandError::Input(Error::TooFewBands { bands: 1, cores: 2 })
    );

    let mut bins = [Binned::default(); 2];
    let binned = BinnedFrame::new(&draws, &mut bins, |_| {}).unwrap();
    let mut bands = BandRenderer::new(&mut c, w, 8, h).unwrap();
    let offsets = [[Fx::ZERO; 2]];
    let mut sums = vec![[0u16; 3]; (w * 8) as usize];
    let e = bands
        .render_accumulated_share_to(&binned, raw(0), &offsets, &mut sums[..10], two, &mut send)
        .unwrap_err();
    assert_eq!(
        e,
        BandError::Input(Error::WrongLength {
            expected: (w * 8) as usize,
            actual: 10
        })
    );
    let e = bands
        .render_accumulated_share_to(&binned, raw(0), &[], &mut sums, two, &mut send)
        .unwrap_err();
    assert_eq!(e, BandError::Input(Error::BadSize(0)));
    let mut c8 = vec![Rgb565::default(); (w * 8) as usize];
    let e = BandRenderer::new(&mut c8, w, 8, 8)
        .unwrap()
        .render_accumulated_share_to(&binned, raw(0), &offsets, &mut sums, two, &mut send)
        .unwrap_err();
    assert_eq!(
        e,
        BandError::Input(Error::TooFewBands { bands: 1, cores: 2 })
    );
}
