//! Every way of drawing a mesh gives the same pixels: random meshes (vertices
//! behind the camera, off screen and on it; random normals, uvs and indices), two meshes
//! with two draws in random modes, drawn
//!
//! * whole-frame through `draw_mesh` (clip-space triangles, the reference path),
//! * whole-frame through the prepared-vertex walker `draw_mesh_walked`, with a vertex cache
//!   of any length (none, direct-mapped, one per vertex),
//! * in bands of any height through `BandRenderer::render_spans`, with bins, band ranges,
//!   vertex cache and kept set-ups of any length: bins big enough (geometry once), ranges
//!   big enough (re-projection per band), ranges too short (partial re-walk), none at all;
//!
//! must agree bit for bit, and the storage flags must say which rung was used. The walker
//! and the bands draw each mesh with or without baked face planes (`Mesh::with_face_planes`).

mod common;

use common::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::Viewport;
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{Draw, DrawMode, KeptSetup, Projection, Shading};
use fixel::prelude::Cull;
use fixel::scene::{
    draw_mesh, draw_mesh_walked, mesh_to_sink, write_face_planes, CachedVertex, DirectionalLight,
    FacePlane, Mesh, MeshTransform,
};
use fixel::surface::Binned;
use fixel::surface::{BandRange, BandRenderer, Frame};
use fixel::texture::{Filter, Wrap};
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

    /// The mesh's baked face planes ([`Mesh::with_face_planes`]).
    fn planes(&self) -> Vec<FacePlane> {
        let mut planes = vec![FacePlane::ZERO; self.indices.len()];
        write_face_planes(&self.positions, &self.indices, &mut planes).unwrap();
        planes
    }
}

fn mesh_arrays() -> impl Strategy<Value = MeshArrays> {
    (3usize..40).prop_flat_map(|n| {
        let p = (-2.5f64..2.5, -2.0f64..2.0, -3.0f64..4.5);
        let nm = (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0);
        (
            prop::collection::vec(p, n),
            prop::collection::vec(nm, n),
            prop::collection::vec((-2.0f64..2.0, -2.0f64..2.0), n),
            prop::collection::vec([0..n as u16, 0..n as u16, 0..n as u16], 1..90),
        )
            .prop_map(|(p, nm, uv, indices)| MeshArrays {
                positions: p
                    .into_iter()
                    .map(|(x, y, z)| Vec3::new(Fx::from_num(x), Fx::from_num(y), Fx::from_num(z)))
                    .collect(),
                normals: nm
                    .into_iter()
                    .map(|(x, y, z)| Vec3::new(Fx::from_num(x), Fx::from_num(y), Fx::from_num(z)))
                    .collect(),
                uvs: uv
                    .into_iter()
                    .map(|(u, v)| [Fx::from_num(u), Fx::from_num(v)])
                    .collect(),
                indices,
            })
    })
}

fn mode() -> impl Strategy<Value = DrawMode> {
    (
        prop::sample::select(vec![Projection::Affine, Projection::Exact]),
        prop::sample::select(vec![Filter::Nearest, Filter::Bilinear]),
        prop::sample::select(vec![
            Shading::Replace,
            Shading::Modulate,
            Shading::ModulateIntensity,
            Shading::Gouraud,
            Shading::Flat,
        ]),
        prop::sample::select(vec![Cull::None, Cull::Back, Cull::Front]),
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

proptest! {
    #![proptest_config(ProptestConfig { cases: 160, ..ProptestConfig::default() })]

    #[test]
    fn every_path_draws_the_same_pixels(
        meshes in (mesh_arrays(), mesh_arrays()),
        modes in (mode(), mode()),
        turn in any::<u16>(),
        (w, h) in (1usize..40, prop_oneof![3 => 1usize..60, 1 => 250usize..300]),
        rows in prop_oneof![2 => Just(1u32), 3 => 1u32..20],
        bins_len in 0usize..24,
        ranges_len in prop_oneof![Just(0usize), 0usize..200, Just(10_000)],
        cache_len in prop_oneof![Just(0usize), 1usize..70, Just(100)],
        setups_len in prop_oneof![Just(0usize), 1usize..8, Just(64)],
        lit in any::<bool>(),
        baked in (any::<bool>(), any::<bool>()),
    ) {
        let tex = noise_texture(8, 16, 5);
        let texels = host_tests::adapter::texels(&tex);
        let t = texture(&tex, &texels);
        let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
        let d0 = Draw::dynamic(modes.0, Some(t), vp).unwrap();
        let d1 = Draw::dynamic(modes.1, Some(t), vp).unwrap().with_flat_color(raw(0x07E0));
        let draws: [&dyn fixel::surface::BandDraw<Rgb565>; 2] = [&d0, &d1];
        let (ma, mb) = (meshes.0.mesh(), meshes.1.mesh());
        // The walker and the bands draw each mesh with or without baked face planes; the
        // reference never.
        let (planes_a, planes_b) = (meshes.0.planes(), meshes.1.planes());
        let wa = if baked.0 { ma.with_face_planes(&planes_a).unwrap() } else { ma };
        let wb = if baked.1 { mb.with_face_planes(&planes_b).unwrap() } else { mb };
        let (model_a, model_b) = (model(turn), model(turn.wrapping_mul(3)));
        let camera = demo::camera(20);
        let (xf_a, xf_b) = (
            MeshTransform::new(&model_a, &camera),
            MeshTransform::new(&model_b, &camera),
        );
        let light = DirectionalLight::default();
        let light = lit.then_some(&light);
        let clear = raw(0x1234);

        // Reference: clip-space triangles, whole frame.
        let mut color = vec![Rgb565::default(); w * h];
        let mut depth = vec![0u16; w * h];
        let mut f = Frame::new(&mut color, w as u32, h as u32).unwrap().with_depth(&mut depth).unwrap();
        f.clear(clear);
        let px_ref = draw_mesh(&d0, &ma, &model_a, &camera, light, &mut f).unwrap()
            + draw_mesh(&d1, &mb, &model_b, &camera, light, &mut f).unwrap();
        let expected: Vec<u16> = color.iter().map(|&c| bits(c)).collect();

        // The walker, whole frame.
        let mut cache = vec![CachedVertex::default(); cache_len];
        let mut color = vec![Rgb565::default(); w * h];
        let mut depth = vec![0u16; w * h];
        let mut f = Frame::new(&mut color, w as u32, h as u32).unwrap().with_depth(&mut depth).unwrap();
        f.clear(clear);
        let px_walk = draw_mesh_walked(&d0, &wa, &xf_a, light, &mut cache, &mut f).unwrap()
            + draw_mesh_walked(&d1, &wb, &xf_b, light, &mut cache, &mut f).unwrap();
        let walked: Vec<u16> = color.iter().map(|&c| bits(c)).collect();
        prop_assert_eq!(px_walk, px_ref);
        prop_assert!(walked == expected, "walker differs from draw_mesh");

        // Bands through render_spans.
        let rows = rows.min(h as u32);
        let mut bins = vec![Binned::default(); bins_len];
        let mut ranges = vec![BandRange::EMPTY; ranges_len];
        let mut cbuf = vec![Rgb565::default(); w * rows as usize];
        let mut dbuf = vec![0u16; w * rows as usize];
        let mut setups = vec![KeptSetup::EMPTY; setups_len];
        let mut band = BandRenderer::new(&mut cbuf, w as u32, rows, h as u32)
            .unwrap()
            .with_depth(&mut dbuf)
            .unwrap()
            .with_setup_cache(&mut setups);
        let mut got = vec![0u16; w * h];
        let stats = band
            .render_spans(
                &draws,
                &mut bins,
                &mut ranges,
                clear,
                |sink| {
                    let next = mesh_to_sink(&d0, 0, &wa, &xf_a, light, &mut cache, 0, sink);
                    mesh_to_sink(&d1, 1, &wb, &xf_b, light, &mut cache, next, sink);
                },
                |b| {
                    let start = b.first_row() as usize * w;
                    for (o, &c) in got[start..start + b.pixels().len()].iter_mut().zip(b.pixels()) {
                        *o = bits(c);
                    }
                    Ok::<(), ()>(())
                },
            )
            .unwrap();
        let ids = ma.triangles() + mb.triangles();
        prop_assert_eq!(stats.pixels, px_ref);
        prop_assert_eq!(stats.reprojected, stats.triangles as usize > bins_len);
        // Re-walk only with some triangle id past the stored ranges, and only off the bins.
        prop_assert!(!stats.rewalked || (stats.reprojected && ranges_len < ids));
        prop_assert!(got == expected, "bands differ from the whole frame ({:?})", stats);
    }
}

/// A mesh whose index points past its vertices, or with more vertices than a `u16` index
/// reaches, is refused when it is built, with a message saying what is wrong.
#[test]
fn bad_meshes_are_errors() {
    let p = [Vec3::ZERO; 3];
    let uv = [[Fx::ZERO; 2]; 3];
    let e = Mesh::new(&p, None, &uv, &[[0, 1, 3]]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "index 3 at position 2 is out of range for 3 vertices"
    );
    let big = vec![Vec3::ZERO; 65537];
    let big_uv = vec![[Fx::ZERO; 2]; 65537];
    let e = Mesh::new(&big, None, &big_uv, &[[0, 1, 2]]).unwrap_err();
    assert!(e.to_string().contains("65537 vertices"), "{e}");
}

/// Vertices whose position or normal overflows the fixed-point range skip their triangles
/// on every path, also when a later triangle meets such a vertex again through the walker's
/// cache (the walker marks it with an outcode bit): the walker draws what `draw_mesh`
/// draws, and the triangles without such a vertex are still drawn.
#[test]
fn overflowing_vertices_skip_their_triangles_on_every_path() {
    let f = |x: f64, y: f64, z: f64| Vec3::new(Fx::from_num(x), Fx::from_num(y), Fx::from_num(z));
    // 0..4: an ordinary quad; 4: a position that overflows clip space; 5: a normal that
    // overflows view space (its position is ordinary).
    let positions = [
        f(-1.5, -1.0, 0.0),
        f(1.5, -1.0, 0.0),
        f(1.5, 1.0, 0.0),
        f(-1.5, 1.0, 0.0),
        f(30000.0, 30000.0, -30000.0),
        f(0.0, 1.8, 0.0),
    ];
    // Turned by an eighth about y below, so one view-space component reaches 42,426.
    let big = f(30000.0, 0.0, 30000.0);
    let normals = [
        f(0.0, 0.0, 1.0),
        f(0.0, 0.0, 1.0),
        f(0.0, 0.0, 1.0),
        f(0.0, 0.0, 1.0),
        f(0.0, 0.0, 1.0),
        big,
    ];
    let uvs = [
        [Fx::ZERO; 2],
        [Fx::ONE, Fx::ZERO],
        [Fx::ONE; 2],
        [Fx::ZERO, Fx::ONE],
        [Fx::ONE; 2],
        [Fx::ONE; 2],
    ];
    // The overflowing vertices are each used twice, so the second use comes from the cache.
    let indices = [
        [0, 1, 4],
        [0, 1, 2],
        [4, 2, 3],
        [2, 3, 5],
        [0, 2, 3],
        [5, 1, 2],
    ];
    let mesh = Mesh::new(&positions, Some(&normals), &uvs, &indices).unwrap();
    let tex = noise_texture(8, 16, 5);
    let texels = host_tests::adapter::texels(&tex);
    let (w, h) = (64usize, 48usize);
    let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
    let camera = demo::camera(20);
    let model =
        Mat4::translation(Vec3::from_num(0, 0, -5)) * Mat4::rotation_y(Angle::from_turns(8192));
    let xf = MeshTransform::new(&model, &camera);
    let light = DirectionalLight::default();
    for shading in [Shading::Modulate, Shading::ModulateIntensity] {
        let mode = DrawMode {
            shading,
            cull: Cull::None,
            ..DrawMode::default()
        };
        let d = Draw::dynamic(mode, Some(texture(&tex, &texels)), vp).unwrap();
        for lit in [false, true] {
            let light = lit.then_some(&light);
            let (px_ref, expected) =
                drawn(w, h, |fr| draw_mesh(&d, &mesh, &model, &camera, light, fr));
            assert!(px_ref > 0, "the ordinary triangles are drawn");
            // The marked vertices do overflow: their triangles alone draw nothing (vertex
            // 5 only when lit; unlit, its triangle is ordinary).
            let only = |tris: &[[u16; 3]]| {
                let m = Mesh::new(&positions, Some(&normals), &uvs, tris).unwrap();
                drawn(w, h, |fr| draw_mesh(&d, &m, &model, &camera, light, fr)).0
            };
            assert_eq!(only(&[[0, 1, 4], [4, 2, 3]]), 0);
            assert_eq!(only(&[[2, 3, 5]]) == 0, lit, "lit {lit}");
            for cache_len in [0usize, 1, 4, 8] {
                let mut cache = vec![CachedVertex::default(); cache_len];
                let (px, walked) = drawn(w, h, |fr| {
                    draw_mesh_walked(&d, &mesh, &xf, light, &mut cache, fr)
                });
                assert_eq!(px, px_ref, "{shading:?} lit {lit} cache {cache_len}");
                assert!(
                    walked == expected,
                    "{shading:?} lit {lit} cache {cache_len}"
                );
            }
        }
    }
}

/// A sliver whose projection rounds to the other orientation (found by the property test
/// above in CI): 0.3 pixels wide and 200 tall, front-facing in exact arithmetic, so the
/// model-space test culls it under `Cull::Front`, but its rounded sub-pixel corners turn it
/// the other way, so the screen-space test alone would keep it. Drawn after the same
/// corners in the other order (which prepares them all in the walker's cache), it is still
/// culled: the model-space test decides on every path, whatever the cache holds.
#[test]
fn a_sliver_that_rounds_to_the_other_orientation_is_culled_on_every_path() {
    let f = |x: f64, y: f64, z: f64| Vec3::new(Fx::from_num(x), Fx::from_num(y), Fx::from_num(z));
    let positions = [
        f(-0.0938, -1.08614, -2.06349),
        f(0.52956, -1.42546, -2.97656),
        f(-2.19147, -1.31825, 0.77948),
    ];
    let normals = [f(0.0, 0.0, 1.0); 3];
    let uvs = [[Fx::ZERO; 2], [Fx::ONE, Fx::ZERO], [Fx::ONE; 2]];
    let (w, h) = (2usize, 250usize);
    let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
    let camera = demo::camera(20);
    let model = model(10025);
    let xf = MeshTransform::new(&model, &camera);
    let tex = noise_texture(8, 16, 5);
    let texels = host_tests::adapter::texels(&tex);
    let mode = DrawMode {
        cull: Cull::Front,
        ..DrawMode::default()
    };
    let d = Draw::dynamic(mode, Some(texture(&tex, &texels)), vp).unwrap();
    // The screen-space test alone keeps the sliver.
    let sliver = Mesh::new(&positions, Some(&normals), &uvs, &[[0, 1, 2]]).unwrap();
    let mut pieces = 0;
    fixel::scene::mesh_triangles(&sliver, &model, &camera, None, |t| {
        d.project(t, &mut |_| pieces += 1);
    });
    assert_eq!(pieces, 1, "the rounded sliver passes the screen-space test");
    // Every path culls it, also after its corners were prepared by the reversed triangle.
    let orders: [&[[u16; 3]]; 2] = [&[[0, 1, 2]], &[[0, 2, 1], [0, 1, 2]]];
    for indices in orders {
        let mesh = Mesh::new(&positions, Some(&normals), &uvs, indices).unwrap();
        let (px_ref, expected) = drawn(w, h, |fr| draw_mesh(&d, &mesh, &model, &camera, None, fr));
        assert_eq!(px_ref, 0, "draw_mesh culls the sliver and its reverse");
        for cache_len in [0usize, 1, 3, 8] {
            let mut cache = vec![CachedVertex::default(); cache_len];
            let (px, walked) = drawn(w, h, |fr| {
                draw_mesh_walked(&d, &mesh, &xf, None, &mut cache, fr)
            });
            assert_eq!(px, 0, "{indices:?} cache {cache_len}");
            assert!(walked == expected);
        }
    }
}

/// Draws with `draw` into a cleared `w` x `h` frame with depth; returns the pixel count it
/// reports and the frame's RGB565 bits.
fn drawn(
    w: usize,
    h: usize,
    draw: impl FnOnce(&mut Frame<'_, Rgb565>) -> Result<u32, fixel::Error>,
) -> (u32, Vec<u16>) {
    let mut color = vec![Rgb565::default(); w * h];
    let mut depth = vec![0u16; w * h];
    let mut fr = Frame::new(&mut color, w as u32, h as u32)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    fr.clear(raw(0x1234));
    let px = draw(&mut fr).unwrap();
    (px, color.iter().map(|&c| bits(c)).collect())
}

/// A triangle crossing several bands, kept from band to band, is projected only in
/// the first band it meets (its band range then ends there); without kept set-ups, in
/// every band it meets. The pixels are the whole frame's either way.
#[test]
fn a_kept_triangle_is_projected_in_its_first_band_only() {
    use fixel::geometry::{Cull, Vertex};
    use fixel::math::Fx;
    use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
    use fixel::shading::Gouraud;
    use fixel::surface::BandDraw;
    let (w, h, rows) = (24u32, 40u32, 4u32);
    let vp = Viewport::new(0, 0, w, h).expect("a viewport");
    let draw = ShadedDraw::<_, Exact, NoDepth>::new(Gouraud, vp, Cull::None).expect("a draw");
    let one = 256 << 16;
    let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
    let tri = [
        Vertex::new(p(-0.8, -0.9), [one, 0, 0]),
        Vertex::new(p(0.9, -0.3), [0, one, 0]),
        Vertex::new(p(-0.2, 0.95), [0, 0, one]),
    ];
    let mut whole = [Rgb565::default(); (24 * 40) as usize];
    let mut frame = Frame::new(&mut whole, w, h).expect("a frame");
    draw.clip_triangles(&[tri], &mut frame).expect("drawn");
    let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
    for kept in [0usize, 1, 3] {
        let mut color = [Rgb565::default(); (24 * 4) as usize];
        let mut setups = [KeptSetup::EMPTY; 3];
        let mut bands = BandRenderer::new(&mut color, w, rows, h)
            .expect("bands")
            .with_setup_cache(&mut setups[..kept]);
        let mut ranges = [BandRange::EMPTY; 1];
        let (mut projected, mut got) = (0, Vec::new());
        bands
            .render_spans(
                &draws,
                &mut [],
                &mut ranges,
                Rgb565::default(),
                |sink| {
                    if sink.wants(0) {
                        projected += usize::from(!sink.fresh());
                        draw.project(&tri, &mut |s| sink.push(0, 0, s));
                    }
                },
                |band| {
                    got.extend_from_slice(band.pixels());
                    Ok::<(), core::convert::Infallible>(())
                },
            )
            .expect("a frame");
        assert!(got[..] == whole[..], "{kept} kept");
        let met = (0..h / rows).filter(|&b| ranges[0].covers(b)).count();
        if kept == 0 {
            assert!(projected >= 5 && met == projected, "{projected} of {met}");
        } else {
            assert_eq!((projected, met), (1, 1), "{kept} kept");
        }
    }
}
