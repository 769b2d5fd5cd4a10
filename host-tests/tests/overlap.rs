//! Sending a band while the next is drawn (`BandRenderer::with_buffers` and the `*_to`
//! frames through a `BandSender`):
//!
//! * the same bands, in the same order, with the same pixels as the one-buffer frame of
//!   `render`, `render_spans` and `render_accumulated`, over random meshes, band heights,
//!   storage and rings of 2 to 4 buffers;
//! * the sender's contract: no band is drawn into a buffer whose transfer is still running,
//!   at most `n - 1` transfers run while a band is drawn, and every transfer started is
//!   waited for before the frame returns, errors included;
//! * bad rings refused: fewer than two buffers, buffers of different lengths.

mod common;

use std::collections::VecDeque;

use common::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::Viewport;
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{Draw, DrawMode, KeptSetup, Projection, Shading};
use fixel::prelude::Cull;
use fixel::scene::{
    mesh_to_sink, mesh_triangles, CachedVertex, DirectionalLight, Mesh, MeshTransform,
};
use fixel::surface::{BandDraw, BandError, BandRange, BandRenderer, BandSender, Binned, Frame};
use fixel::texture::{Filter, Wrap};
use fixel::Error;
use fixel_scenes as demo;
use proptest::prelude::*;

/// A random mesh's arrays.
#[derive(Clone, Debug)]
struct MeshArrays {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    uvs: Vec<[Fx; 2]>,
    indices: Vec<[u16; 3]>,
}

impl MeshArrays {
    fn mesh(&self) -> Mesh<'_> {
        Mesh::new(
            &self.positions,
            Some(&self.normals),
            &self.uvs,
            &self.indices,
        )
        .unwrap()
    }
}

fn mesh_arrays() -> impl Strategy<Value = MeshArrays> {
    (3usize..30).prop_flat_map(|n| {
        let p = (-2.5f64..2.5, -2.0f64..2.0, -3.0f64..4.5);
        let nm = (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0);
        (
            prop::collection::vec(p, n),
            prop::collection::vec(nm, n),
            prop::collection::vec((-2.0f64..2.0, -2.0f64..2.0), n),
            prop::collection::vec([0..n as u16, 0..n as u16, 0..n as u16], 1..60),
        )
            .prop_map(|(p, nm, uv, indices)| {
                let v = |(x, y, z): (f64, f64, f64)| {
                    Vec3::new(Fx::from_num(x), Fx::from_num(y), Fx::from_num(z))
                };
                MeshArrays {
                    positions: p.into_iter().map(v).collect(),
                    normals: nm.into_iter().map(v).collect(),
                    uvs: uv
                        .into_iter()
                        .map(|(u, v)| [Fx::from_num(u), Fx::from_num(v)])
                        .collect(),
                    indices,
                }
            })
    })
}

fn mode() -> impl Strategy<Value = DrawMode> {
    (
        prop::sample::select(vec![Projection::Affine, Projection::Exact]),
        prop::sample::select(vec![Filter::Nearest, Filter::Bilinear]),
        prop::sample::select(vec![Shading::Modulate, Shading::Gouraud, Shading::Flat]),
        prop::sample::select(vec![Cull::None, Cull::Back]),
    )
        .prop_map(|(projection, filter, shading, cull)| DrawMode {
            projection,
            filter,
            shading,
            cull,
            wrap: [Wrap::Repeat, Wrap::MirroredRepeat],
            ..DrawMode::default()
        })
}

fn model(turn: u16) -> Mat4 {
    let a = Angle::from_turns(turn);
    Mat4::translation(Vec3::from_num(0, 0, -5)) * (Mat4::rotation_x(a) * Mat4::rotation_y(a))
}

/// One band as it reached the display: its first row and pixels.
type Sent = (i32, Vec<u16>);

/// A stand-in for a DMA channel that checks the renderer keeps to the contract: `start`
/// records the band and the address of its buffer, refuses a buffer still in flight and
/// more than `ring - 1` transfers running; `wait` retires the oldest. `fail_at` makes the
/// start of that band fail.
struct CheckedDma {
    ring: usize,
    in_flight: VecDeque<usize>,
    sent: Vec<Sent>,
    starts: usize,
    waits: usize,
    fail_at: Option<usize>,
}

impl CheckedDma {
    fn new(ring: usize, fail_at: Option<usize>) -> Self {
        CheckedDma {
            ring,
            in_flight: VecDeque::new(),
            sent: Vec::new(),
            starts: 0,
            waits: 0,
            fail_at,
        }
    }
}

#[derive(Debug, PartialEq)]
enum DmaError {
    Refused(usize),
    Broken(&'static str),
}

impl BandSender<Rgb565> for CheckedDma {
    type Error = DmaError;

    fn start(&mut self, band: &Frame<'_, Rgb565>) -> Result<(), DmaError> {
        let at = band.pixels().as_ptr() as usize;
        if self.in_flight.contains(&at) {
            return Err(DmaError::Broken("a band was drawn into a buffer in flight"));
        }
        if self.in_flight.len() >= self.ring {
            return Err(DmaError::Broken(
                "more transfers running than spare buffers",
            ));
        }
        if self.fail_at == Some(self.sent.len()) {
            return Err(DmaError::Refused(self.sent.len()));
        }
        self.starts += 1;
        self.in_flight.push_back(at);
        self.sent.push((
            band.first_row(),
            band.pixels().iter().map(|&c| bits(c)).collect(),
        ));
        Ok(())
    }

    fn wait(&mut self) -> Result<(), DmaError> {
        self.waits += 1;
        self.in_flight
            .pop_front()
            .map(|_| ())
            .ok_or(DmaError::Broken("wait with no transfer running"))
    }
}

/// The bands a one-buffer renderer flushes: `(first row, pixels)` in order.
fn collect<'v>(out: &'v mut Vec<Sent>) -> impl FnMut(&Frame<'_, Rgb565>) -> Result<(), ()> + 'v {
    move |b| {
        out.push((b.first_row(), b.pixels().iter().map(|&c| bits(c)).collect()));
        Ok(())
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(96), ..ProptestConfig::default() })]

    /// `render_to` and `render_spans_to` through a ring of 2 to 4 buffers send exactly the
    /// bands `render` and `render_spans` flush through one; the sender's checks hold.
    #[test]
    fn a_ring_sends_the_bands_of_one_buffer(
        meshes in (mesh_arrays(), mesh_arrays()),
        modes in (mode(), mode()),
        turn in any::<u16>(),
        (w, h) in (1usize..40, 1usize..70),
        rows in 1u32..12,
        ring in 2usize..5,
        bins_len in 0usize..40,
        ranges_len in prop_oneof![Just(0usize), 0usize..100, Just(1000)],
        setups_len in prop_oneof![Just(0usize), 1usize..8],
        lit in any::<bool>(),
    ) {
        let tex = noise_texture(8, 16, 5);
        let texels = host_tests::adapter::texels(&tex);
        let t = texture(&tex, &texels);
        let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
        let d0 = Draw::dynamic(modes.0, Some(t), vp).unwrap();
        let d1 = Draw::dynamic(modes.1, Some(t), vp).unwrap().with_flat_color(raw(0x07E0));
        let draws: [&dyn BandDraw<Rgb565>; 2] = [&d0, &d1];
        let (ma, mb) = (meshes.0.mesh(), meshes.1.mesh());
        let (model_a, model_b) = (model(turn), model(turn.wrapping_mul(3)));
        let camera = demo::camera(20);
        let (xf_a, xf_b) = (MeshTransform::new(&model_a, &camera), MeshTransform::new(&model_b, &camera));
        let light = DirectionalLight::default();
        let light = lit.then_some(&light);
        let clear = raw(0x1234);
        let rows = rows.min(h as u32);
        let n = w * rows as usize;
        let mut cache = vec![CachedVertex::default(); 16];
        let mut geometry_spans = |sink: &mut fixel::surface::MeshSink<'_, '_, '_, Rgb565>| {
            let next = mesh_to_sink(&d0, 0, &ma, &xf_a, light, &mut cache, 0, sink);
            mesh_to_sink(&d1, 1, &mb, &xf_b, light, &mut cache, next, sink);
        };
        let geometry_bins = |sink: &mut fixel::surface::TriangleSink<'_, '_, '_, Rgb565>| {
            mesh_triangles(&ma, &model_a, &camera, light, |t| d0.project(t, &mut |s| sink.push(0, s)));
            mesh_triangles(&mb, &model_b, &camera, light, |t| d1.project(t, &mut |s| sink.push(1, s)));
        };
        let mut dbuf = vec![0u16; n];
        let mut bins = vec![Binned::default(); bins_len];
        let mut ranges = vec![BandRange::EMPTY; ranges_len];

        // Today's frames: one buffer, flushed band by band.
        let (mut one_spans, mut one_bins) = (Vec::new(), Vec::new());
        let mut cbuf = vec![Rgb565::default(); n];
        let mut setups = vec![KeptSetup::EMPTY; setups_len];
        let mut one = BandRenderer::new(&mut cbuf, w as u32, rows, h as u32).unwrap()
            .with_depth(&mut dbuf).unwrap().with_setup_cache(&mut setups);
        let s_one = one.render_spans(&draws, &mut bins, &mut ranges, clear, &mut geometry_spans, collect(&mut one_spans)).unwrap();
        let b_one = one.render(&draws, &mut bins, clear, geometry_bins, collect(&mut one_bins)).unwrap();

        // The ring, through the checking DMA.
        let mut store = vec![vec![Rgb565::default(); n]; ring];
        let mut buffers: Vec<&mut [Rgb565]> = store.iter_mut().map(|b| &mut b[..]).collect();
        let mut setups = vec![KeptSetup::EMPTY; setups_len];
        let mut many = BandRenderer::with_buffers(&mut buffers, w as u32, rows, h as u32).unwrap()
            .with_depth(&mut dbuf).unwrap().with_setup_cache(&mut setups);
        let mut dma = CheckedDma::new(ring, None);
        let s_many = many.render_spans_to(&draws, &mut bins, &mut ranges, clear, &mut geometry_spans, &mut dma).unwrap();
        prop_assert_eq!(s_many, s_one);
        prop_assert_eq!((dma.starts, dma.waits), (s_one.bands as usize, s_one.bands as usize));
        prop_assert!(dma.sent == one_spans, "render_spans_to sent other bands");
        let mut dma = CheckedDma::new(ring, None);
        let b_many = many.render_to(&draws, &mut bins, clear, geometry_bins, &mut dma).unwrap();
        prop_assert_eq!(b_many, b_one);
        prop_assert_eq!(dma.waits, dma.starts);
        prop_assert!(dma.sent == one_bins, "render_to sent other bands");
    }

    /// A sender that fails at band `k` stops the frame there, with its error, after every
    /// transfer started has been waited for.
    #[test]
    fn a_failed_start_stops_the_frame_after_the_waits(
        ring in 2usize..5,
        rows in 1u32..9,
        fail_at in 0usize..12,
    ) {
        let (w, h) = (16u32, 40u32);
        let vp = Viewport::new(0, 0, w, h).unwrap();
        let draw = Draw::dynamic(DrawMode { shading: Shading::Flat, ..DrawMode::default() }, None, vp)
            .unwrap()
            .with_flat_color(raw(0xF800));
        let n = (w * rows) as usize;
        let mut store = vec![vec![Rgb565::default(); n]; ring];
        let mut buffers: Vec<&mut [Rgb565]> = store.iter_mut().map(|b| &mut b[..]).collect();
        let mut bands = BandRenderer::with_buffers(&mut buffers, w, rows, h).unwrap();
        let mut dma = CheckedDma::new(ring, Some(fail_at));
        let cube = demo::cube();
        let mesh = cube.mesh().unwrap();
        let r = bands.render_to(&[&draw], &mut [Binned::default(); 16], raw(0), |sink| {
            mesh_triangles(&mesh, &demo::cube_model(0), &demo::camera(20), None, |t| {
                draw.project(t, &mut |s| sink.push(0, s))
            })
        }, &mut dma);
        let bands_in_frame = h.div_ceil(rows) as usize;
        if fail_at < bands_in_frame {
            prop_assert_eq!(r, Err(BandError::Flush(DmaError::Refused(fail_at))));
            prop_assert_eq!(dma.starts, fail_at);
        } else {
            prop_assert!(r.is_ok());
            prop_assert_eq!(dma.starts, bands_in_frame);
        }
        prop_assert_eq!(dma.waits, dma.starts);
        prop_assert!(dma.in_flight.is_empty());
    }
}

/// Accumulation through a ring sends the averaged bands of one buffer.
#[test]
fn accumulation_through_a_ring_is_the_one_buffer_frame() {
    let (w, h, rows) = (64u32, 48u32, 8u32);
    let tex = noise_texture(16, 16, 3);
    let texels = host_tests::adapter::texels(&tex);
    let t = texture(&tex, &texels);
    let vp = Viewport::new(0, 0, w, h).unwrap();
    let draw = Draw::dynamic(DrawMode::default(), Some(t), vp).unwrap();
    let cube = demo::cube();
    let mesh = cube.mesh().unwrap();
    let cam = demo::camera(20);
    let offsets = [
        [Fx::from_num(0.25), Fx::from_num(-0.25)],
        [Fx::from_num(-0.25), Fx::from_num(0.25)],
    ];
    let geometry = |sink: &mut fixel::surface::TriangleSink<'_, '_, '_, Rgb565>| {
        mesh_triangles(&mesh, &demo::cube_model(3), &cam, None, |t| {
            draw.project(t, &mut |s| sink.push(0, s))
        })
    };
    let n = (w * rows) as usize;
    let (mut d, mut sums) = (vec![0u16; n], vec![[0u16; 3]; n]);
    let mut c = vec![Rgb565::default(); n];
    let mut one = Vec::new();
    let mut bins = [Binned::default(); 16];
    BandRenderer::new(&mut c, w, rows, h)
        .unwrap()
        .with_depth(&mut d)
        .unwrap()
        .render_accumulated(
            &[&draw],
            &mut bins,
            raw(0),
            &offsets,
            &mut sums,
            geometry,
            collect(&mut one),
        )
        .unwrap();
    let (mut a, mut b, mut e) = (
        vec![Rgb565::default(); n],
        vec![Rgb565::default(); n],
        vec![Rgb565::default(); n],
    );
    let mut buffers = [&mut a[..], &mut b[..], &mut e[..]];
    let mut dma = CheckedDma::new(3, None);
    BandRenderer::with_buffers(&mut buffers, w, rows, h)
        .unwrap()
        .with_depth(&mut d)
        .unwrap()
        .render_accumulated_to(
            &[&draw],
            &mut bins,
            raw(0),
            &offsets,
            &mut sums,
            geometry,
            &mut dma,
        )
        .unwrap();
    assert_eq!(dma.sent, one);
    assert_eq!(dma.waits, dma.starts);
}

/// Fewer than two buffers, buffers of different lengths, a band taller than the buffers:
/// refused, each with a message that names the problem.
#[test]
fn bad_rings_are_refused() {
    let (mut a, mut b) = ([Rgb565::default(); 64], [Rgb565::default(); 48]);
    let e = BandRenderer::<Rgb565>::with_buffers(&mut [], 8, 4, 16).unwrap_err();
    assert_eq!(e, Error::TooFewBandBuffers { given: 0 });
    assert!(e.to_string().contains("at least two"), "{e}");
    let e = BandRenderer::with_buffers(&mut [&mut a[..]], 8, 4, 16).unwrap_err();
    assert_eq!(e, Error::TooFewBandBuffers { given: 1 });
    let e = BandRenderer::with_buffers(&mut [&mut a[..], &mut b[..]], 8, 4, 16).unwrap_err();
    assert_eq!(
        e,
        Error::BandBuffersDiffer {
            index: 1,
            len: 48,
            first: 64
        }
    );
    assert!(e.to_string().contains("one length"), "{e}");
    let e = BandRenderer::with_buffers(&mut [&mut a[..], &mut b[..48]], 8, 4, 16).unwrap_err();
    assert_eq!(
        e,
        Error::BandBuffersDiffer {
            index: 1,
            len: 48,
            first: 64
        }
    );
    let e = BandRenderer::with_buffers(&mut [&mut a[..48], &mut b[..]], 8, 7, 16).unwrap_err();
    assert_eq!(
        e,
        Error::BandTooTall {
            rows: 7,
            capacity: 6
        }
    );
}
