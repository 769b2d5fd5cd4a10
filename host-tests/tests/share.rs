//! One frame's bands split between cores (`BinnedFrame` built once, `render_share_to` on
//! each core with its `BandShare`):
//!
//! * the bands of all the shares, put in row order, are the bands of the one-core
//!   `render`, bit for bit, over random turns of the cube and the sphere, frame and band
//!   sizes, core counts and band rings;
//! * the binning pass split in two parts (`BinnedFrame::join`) gives the same frame;
//! * each core draws exactly the bands `k` with `k mod cores = core`, top to bottom;
//! * bad splits are refused: a core past the cores, no cores, fewer bands than cores, bins
//!   too small for the frame.

mod common;

use common::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::Viewport;
use fixel::pipeline::{Draw, DrawMode, Shading};
use fixel::scene::{mesh_triangles, DirectionalLight};
use fixel::surface::{
    BandDraw, BandError, BandRenderer, BandShare, Binned, BinnedFrame, Blocking, Dma, Frame,
    TriangleSink,
};
use fixel::Error;
use fixel_scenes as demo;
use proptest::prelude::*;

type Sent = (i32, Vec<u16>);

fn keep(out: &mut Vec<Sent>, b: &Frame<'_, Rgb565>) {
    out.push((b.first_row(), b.pixels().iter().map(|&c| bits(c)).collect()));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(64), ..ProptestConfig::default() })]

    #[test]
    fn the_shares_together_are_the_one_core_frame(
        sphere in any::<bool>(),
        turn in 0u32..200,
        (w, h) in (1u32..64, 1u32..80),
        rows in 1u32..12,
        cores in 1u32..5,
        ring in 1usize..4,
        split in prop_oneof![Just(None), (0.0f64..1.0).prop_map(Some)],
    ) {
        let rows = rows.min(h);
        prop_assume!(h.div_ceil(rows) >= cores);
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
        let n = (w * rows) as usize;
        let mut bins = vec![Binned::default(); 2400];
        let (mut c, mut d) = (vec![Rgb565::default(); n], vec![0u16; n]);
        let mut want = Vec::new();
        let one = BandRenderer::new(&mut c, w, rows, h).unwrap().with_depth(&mut d).unwrap()
            .render(&draws, &mut bins, raw(0x0821), geometry, |b| { keep(&mut want, b); Ok::<(), ()>(()) })
            .unwrap();

        let frame = match split {
            None => BinnedFrame::new(&draws, &mut bins, geometry).unwrap(),
            Some(at) => {
                // The binning pass in two parts (as two cores would run it), joined.
                let (pos, nrm, uv, idx): (&[_], &[_], &[_], &[_]) = if sphere {
                    (&ball.positions, &ball.normals, &ball.uvs, &ball.indices)
                } else {
                    (&cube.positions, &cube.normals, &cube.uvs, &cube.indices)
                };
                let k = (idx.len() as f64 * at) as usize;
                let (draw, light, model) = (&draw, &light, &model);
                let part = |range: std::ops::Range<usize>| {
                    let m = fixel::scene::Mesh::new(pos, Some(nrm), uv, &idx[range]).unwrap();
                    move |sink: &mut TriangleSink<'_, '_, '_, Rgb565>| {
                        mesh_triangles(&m, model, &demo::camera(20), Some(light), |t| {
                            draw.project(t, &mut |s| sink.push(0, s))
                        })
                    }
                };
                let (first, later) = bins.split_at_mut(1200);
                let a = BinnedFrame::new(&draws, first, part(0..k)).unwrap();
                let b = BinnedFrame::new(&draws, later, part(k..idx.len())).unwrap();
                a.join(b).unwrap()
            }
        };
        prop_assert_eq!(frame.triangles() as u32, one.triangles);
        let mut got: Vec<Sent> = Vec::new();
        let mut pixels = 0;
        for core in 0..cores {
            let share = BandShare::new(core, cores).unwrap();
            let mut store = vec![vec![Rgb565::default(); n]; ring.max(2)];
            let mut buffers: Vec<&mut [Rgb565]> = store.iter_mut().map(|b| &mut b[..]).collect();
            let mut single = vec![Rgb565::default(); n];
            let mut d = vec![0u16; n];
            let bands = if ring == 1 {
                BandRenderer::new(&mut single, w, rows, h).unwrap()
            } else {
                BandRenderer::with_buffers(&mut buffers, w, rows, h).unwrap()
            };
            let mut bands = bands.with_depth(&mut d).unwrap();
            let mut mine = Vec::new();
            let mut waits = 0;
            let mut dma = Dma::new(|b: &Frame<'_, Rgb565>| { keep(&mut mine, b); Ok::<(), ()>(()) }, || { waits += 1; Ok(()) });
            let stats = bands.render_share_to(&frame, raw(0x0821), share, &mut dma).unwrap();
            prop_assert_eq!(stats.bands as usize, mine.len());
            prop_assert_eq!(waits, mine.len());
            for (i, (row, _)) in mine.iter().enumerate() {
                prop_assert_eq!(*row as u32, (core + i as u32 * cores) * rows, "core {} band {}", core, i);
            }
            pixels += stats.pixels;
            got.extend(mine);
        }
        got.sort_by_key(|(row, _)| *row);
        prop_assert_eq!(pixels, one.pixels);
        prop_assert!(got == want, "the shares differ from the one-core frame");
    }
}

#[test]
fn bad_splits_are_refused() {
    for (core, cores) in [(0, 0), (2, 2), (5, 3), (0, 256)] {
        let e = BandShare::new(core, cores).unwrap_err();
        assert_eq!(e, Error::BadBandShare { core, cores });
        assert!(e.to_string().contains("below the cores"), "{e}");
    }
    assert_eq!(
        BandShare::new(1, 2).map(|s| (s.core(), s.cores())),
        Ok((1, 2))
    );
    let vp = Viewport::new(0, 0, 8, 8).unwrap();
    let flat = DrawMode {
        shading: Shading::Flat,
        ..DrawMode::default()
    };
    let draw = Draw::dynamic(flat, None, vp).unwrap();
    let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
    let cube = demo::cube();
    let mesh = cube.mesh().unwrap();
    let geometry = |sink: &mut TriangleSink<'_, '_, '_, Rgb565>| {
        mesh_triangles(&mesh, &demo::cube_model(0), &demo::camera(20), None, |t| {
            draw.project(t, &mut |s| sink.push(0, s))
        })
    };
    // Bins too small: the cores would each have to run the geometry.
    let e = BinnedFrame::new(&draws, &mut [Binned::default(); 2], geometry).unwrap_err();
    assert_eq!(e, Error::CapacityExceeded { capacity: 2 });
    let mut bins = [Binned::default(); 16];
    let frame = BinnedFrame::new(&draws, &mut bins, geometry).unwrap();
    // Two bands of 4 rows: three cores cannot share them.
    let mut c = [Rgb565::default(); 32];
    let mut bands = BandRenderer::new(&mut c, 8, 4, 8).unwrap();
    let mut sent = 0;
    let mut send = Blocking(|_: &Frame<'_, Rgb565>| {
        sent += 1;
        Ok::<(), ()>(())
    });
    let e = bands
        .render_share_to(&frame, raw(0), BandShare::new(2, 3).unwrap(), &mut send)
        .unwrap_err();
    assert_eq!(
        e,
        BandError::Input(Error::TooFewBands { bands: 2, cores: 3 })
    );
    assert!(Error::TooFewBands { bands: 2, cores: 3 }
        .to_string()
        .contains("cannot be split between 3 cores"));
    let ok = bands.render_share_to(&frame, raw(0), BandShare::new(1, 2).unwrap(), &mut send);
    assert_eq!(ok.map(|s| s.bands), Ok(1));
    assert_eq!(sent, 1);
}
