//! The `async` frame (`BandRenderer::render_async` through an `AsyncBandSender`) and the
//! SPI senders (`SpiSender` over `embedded-hal` 1.0 and `embedded-hal-async` 1.0
//! `SpiDevice`s):
//!
//! * the async frame sends the bands of `render`, in order, with the same pixels, whether
//!   each transfer is finished at its first poll or keeps the frame waiting;
//! * while a transfer is pending, the frame draws the next band (it polls the transfer once,
//!   draws, then awaits it): the drawing happens between the two polls;
//! * the SPI senders put each band on the wire as big-endian RGB565, in one write or in
//!   chunks of the scratch buffer, the same bytes either way.

mod common;

use std::cell::RefCell;
use std::future::Future;
use std::pin::pin;
use std::task::{Context, Poll, Waker};

use common::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_hal::spi::{ErrorType, Operation};
use fixel::geometry::Viewport;
use fixel::pipeline::{Draw, DrawMode};
use fixel::scene::mesh_triangles;
use fixel::surface::{
    AsyncBandSender, BandRenderer, BandSender, Binned, Frame, SpiSender, TriangleSink,
};
use fixel_scenes as demo;
use proptest::prelude::*;

/// Runs a future to its end with a waker that does nothing (every test sender makes
/// progress on each poll).
fn run<F: Future>(f: F) -> F::Output {
    let mut f = pin!(f);
    let mut cx = Context::from_waker(Waker::noop());
    loop {
        if let Poll::Ready(v) = f.as_mut().poll(&mut cx) {
            return v;
        }
    }
}

/// Yields `n` times before finishing.
async fn pending(n: u32) {
    let mut left = n;
    std::future::poll_fn(|_| {
        if left == 0 {
            Poll::Ready(())
        } else {
            left -= 1;
            Poll::Pending
        }
    })
    .await
}

/// What happened, in order: `send k` when band k's transfer started (first poll), `done k`
/// when it finished, `draw k` when band k was drawn.
type Log = RefCell<Vec<String>>;

/// A sender whose transfers take `polls` polls; it logs and keeps the bands.
struct Slow<'l> {
    polls: u32,
    log: &'l Log,
    sent: Vec<(i32, Vec<u16>)>,
}

impl AsyncBandSender<Rgb565> for Slow<'_> {
    type Error = ();
    async fn send(&mut self, band: &Frame<'_, Rgb565>) -> Result<(), ()> {
        let k = self.sent.len();
        self.log.borrow_mut().push(format!("send {k}"));
        self.sent.push((
            band.first_row(),
            band.pixels().iter().map(|&c| bits(c)).collect(),
        ));
        pending(self.polls).await;
        self.log.borrow_mut().push(format!("done {k}"));
        Ok(())
    }
}

/// The cube's geometry, turned by `turn`, pushed as draw 0.
fn cube_geometry<'a>(
    draw: &'a Draw<'a, Rgb565>,
    turn: u32,
) -> impl FnMut(&mut TriangleSink<'_, '_, '_, Rgb565>) + 'a {
    let cube = demo::cube();
    move |sink| {
        let mesh = cube.mesh().unwrap();
        mesh_triangles(
            &mesh,
            &demo::cube_model(turn),
            &demo::camera(20),
            None,
            |t| draw.project(t, &mut |s| sink.push(0, s)),
        )
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(48), ..ProptestConfig::default() })]

    /// The async frame through one buffer or a ring sends the bands of `render`; with a
    /// ring, band k + 1 is drawn while band k's transfer is pending.
    #[test]
    fn the_async_frame_sends_the_bands_of_render(
        (w, h) in (1u32..48, 1u32..64),
        rows in 1u32..10,
        ring in 1usize..4,
        polls in 0u32..3,
        turn in 0u32..100,
        bins_len in prop_oneof![Just(0usize), 1usize..16],
    ) {
        let vp = Viewport::new(0, 0, w, h).unwrap();
        let tex = noise_texture(8, 8, 2);
        let texels = host_tests::adapter::texels(&tex);
        let draw = Draw::dynamic(DrawMode::default(), Some(texture(&tex, &texels)), vp).unwrap();
        let rows = rows.min(h);
        let n = (w * rows) as usize;
        let mut bins = vec![Binned::default(); bins_len];
        let mut c = vec![Rgb565::default(); n];
        let mut want = Vec::new();
        BandRenderer::new(&mut c, w, rows, h).unwrap()
            .render(&[&draw], &mut bins, raw(0x1111), cube_geometry(&draw, turn), |b| {
                want.push((b.first_row(), b.pixels().iter().map(|&c| bits(c)).collect::<Vec<u16>>()));
                Ok::<(), ()>(())
            })
            .unwrap();

        let log = Log::default();
        let mut store = vec![vec![Rgb565::default(); n]; ring.max(2)];
        let mut buffers: Vec<&mut [Rgb565]> = store.iter_mut().map(|b| &mut b[..]).collect();
        let mut one = vec![Rgb565::default(); n];
        let mut bands = if ring == 1 {
            BandRenderer::new(&mut one, w, rows, h).unwrap()
        } else {
            BandRenderer::with_buffers(&mut buffers, w, rows, h).unwrap()
        };
        let mut sender = Slow { polls, log: &log, sent: Vec::new() };
        let mut geometry = cube_geometry(&draw, turn);
        let mut band_no = 0;
        let stats = run(bands.render_async(&[&draw], &mut bins, raw(0x1111), |sink| {
            if !sink.fresh() || bins_len == 0 {
                log.borrow_mut().push(format!("draw {band_no}"));
                band_no += 1;
            }
            geometry(sink)
        }, &mut sender)).unwrap();
        prop_assert_eq!(stats.bands as usize, want.len());
        prop_assert!(sender.sent == want, "the async frame sent other bands");
        if ring > 1 && polls > 0 && bins_len == 0 {
            // Re-walked per band (no bins): each band's drawing is logged; band k + 1 is
            // drawn between the start and the end of band k's transfer.
            let log = log.borrow();
            for k in 0..want.len().saturating_sub(1) {
                let at = |s: String| log.iter().position(|l| *l == s).unwrap();
                let next = at(format!("draw {}", k + 2));
                prop_assert!(at(format!("send {k}")) < next && next < at(format!("done {k}")),
                    "band {} not drawn during band {k}'s transfer: {:?}", k + 1, log);
            }
        }
    }
}

/// Keeps every byte written, and the size of each write.
#[derive(Debug, Default)]
struct Wire {
    bytes: Vec<u8>,
    writes: Vec<usize>,
}

impl ErrorType for Wire {
    type Error = std::convert::Infallible;
}

impl embedded_hal::spi::SpiDevice for Wire {
    fn transaction(&mut self, ops: &mut [Operation<'_, u8>]) -> Result<(), Self::Error> {
        for op in ops {
            if let Operation::Write(b) = op {
                self.bytes.extend_from_slice(b);
                self.writes.push(b.len());
            }
        }
        Ok(())
    }
}

impl embedded_hal_async::spi::SpiDevice for Wire {
    async fn transaction(&mut self, ops: &mut [Operation<'_, u8>]) -> Result<(), Self::Error> {
        embedded_hal::spi::SpiDevice::transaction(self, ops)
    }
}

/// Both SPI senders put the band on the wire as big-endian RGB565, in writes of at most
/// the scratch buffer; a scratch buffer under 2 bytes is refused.
#[test]
fn spi_senders_write_big_endian_rgb565() {
    let mut pixels: Vec<Rgb565> = (0..24u16).map(|i| raw(i.wrapping_mul(0x0F1D))).collect();
    let want: Vec<u8> = pixels.iter().flat_map(|&c| bits(c).to_be_bytes()).collect();
    let band = Frame::new(&mut pixels, 6, 4).unwrap();
    for scratch_len in [2, 5, 10, 48, 100] {
        let mut scratch = vec![0u8; scratch_len];
        let mut s = SpiSender::new(Wire::default(), &mut scratch).unwrap();
        s.start(&band).unwrap();
        BandSender::<Rgb565>::wait(&mut s).unwrap();
        let w = s.into_inner();
        assert_eq!(w.bytes, want, "blocking, scratch {scratch_len}");
        assert!(w.writes.iter().all(|&n| n <= scratch_len && n % 2 == 0));
        let mut s = SpiSender::new(Wire::default(), &mut scratch).unwrap();
        run(AsyncBandSender::send(&mut s, &band)).unwrap();
        let w = s.into_inner();
        assert_eq!(w.bytes, want, "async, scratch {scratch_len}");
        assert_eq!(w.writes.len(), 48usize.div_ceil(scratch_len & !1));
    }
    let e = SpiSender::new(Wire::default(), &mut [0u8; 1]).unwrap_err();
    assert_eq!(
        e,
        fixel::Error::WrongLength {
            expected: 2,
            actual: 1
        }
    );
}
