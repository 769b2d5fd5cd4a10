//! Property tests:
//!
//! * random triangles with clip coordinates across the whole I16F16 range (w <= 0, huge,
//!   tiny) in random modes never panic and never write outside the buffers;
//! * random meshes that tile the viewport (jittered grid, random diagonals, random w)
//!   write every pixel exactly once;
//! * band rendering equals whole-frame rendering bit for bit, with bins big enough and too
//!   small (re-walk fallback).
//!
//! Case counts are bounded so the file stays fast in debug builds.

mod common;

use common::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{ClipVertex, Cull, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection, Shading};
use fixel::surface::Binned;
use fixel::surface::{BandRenderer, Frame};
use fixel::texture::{Filter, Wrap};
use proptest::prelude::*;

fn any_bits() -> impl Strategy<Value = i32> {
    prop_oneof![
        4 => any::<i32>(),
        2 => -(1i32 << 18)..(1 << 18),
        1 => prop::sample::select(vec![
            0,
            1,
            -1,
            255,
            256,
            257,
            65535,
            65536,
            -65536,
            i32::MAX,
            i32::MIN,
            i32::MAX - 1,
            i32::MIN + 1,
            1 << 30,
            -(1 << 30),
        ]),
    ]
}

/// Clip coordinates anywhere in the I16F16 range (w <= 0, huge, tiny included).
fn wild_vertex() -> impl Strategy<Value = ClipVertex> {
    (
        [any_bits(), any_bits(), any_bits(), any_bits()],
        [any_bits(), any_bits()],
        [any::<u16>(), any::<u16>(), any::<u16>()],
    )
        .prop_map(|(p, uv, color)| ClipVertex {
            position: p.map(Fx::from_bits),
            uv: uv.map(Fx::from_bits),
            color,
        })
}

/// Near the view volume (NDC within +-3) with w from 2^-16 to 8, so that many cases reach
/// the rasterizer; uv anywhere.
fn tame_vertex() -> impl Strategy<Value = ClipVertex> {
    (
        (-3.0f64..3.0, -3.0f64..3.0, -1.5f64..1.5),
        1i32..(1 << 19),
        [any_bits(), any_bits()],
        [any::<u16>(), any::<u16>(), any::<u16>()],
    )
        .prop_map(|((x, y, z), w, uv, color)| {
            let wf = f64::from(w) / 65536.0;
            ClipVertex {
                position: [
                    Fx::saturating_from_num(x * wf),
                    Fx::saturating_from_num(y * wf),
                    Fx::saturating_from_num(z * wf),
                    Fx::from_bits(w),
                ],
                uv: uv.map(Fx::from_bits),
                color,
            }
        })
}

fn any_vertex() -> impl Strategy<Value = ClipVertex> {
    prop_oneof![wild_vertex(), tame_vertex()]
}

fn any_mode() -> impl Strategy<Value = DrawMode> {
    let wrap = prop::sample::select(vec![
        Wrap::Repeat,
        Wrap::MirroredRepeat,
        Wrap::ClampToEdge,
        Wrap::ClampToBorder,
    ]);
    (
        prop::sample::select(vec![
            Projection::Affine,
            Projection::Exact,
            Projection::Subdivided { log2_n: 1 },
            Projection::Subdivided { log2_n: 4 },
            Projection::Subdivided { log2_n: 6 },
            Projection::Quadratic { log2_n: 1 },
            Projection::Quadratic { log2_n: 4 },
            Projection::Quadratic { log2_n: 6 },
        ]),
        prop::sample::select(vec![Filter::Nearest, Filter::Bilinear]),
        [wrap.clone(), wrap],
        prop::sample::select(vec![
            Shading::Replace,
            Shading::Modulate,
            Shading::ModulateIntensity,
            Shading::Gouraud,
            Shading::Flat,
        ]),
        prop::sample::select(vec![DepthTest::Off, DepthTest::Less]),
        prop::sample::select(vec![Cull::None, Cull::Back, Cull::Front]),
    )
        .prop_map(
            |(projection, filter, wrap, shading, depth, cull)| DrawMode {
                projection,
                filter,
                wrap,
                shading,
                depth,
                cull,
                ..DrawMode::default()
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Any clip-space input, any mode, any viewport placement inside the target: no panic,
    /// guard untouched, no row outside the target requested, pixel count consistent.
    #[test]
    fn any_triangle_is_safe(
        tris in prop::collection::vec([any_vertex(), any_vertex(), any_vertex()], 1..4),
        mode in any_mode(),
        (w, h) in (1usize..48, 1usize..40),
        tex_log2 in (0u32..6, 0u32..6),
        vp_off in (0u32..8, 0u32..8, 1u32..64, 1u32..64),
    ) {
        let tex = noise_texture(1 << tex_log2.0, 1 << tex_log2.1, 11);
        let texels = host_tests::adapter::texels(&tex);
        let t = texture(&tex, &texels);
        // A viewport that may stick out of the target on the right and bottom.
        let vp = Viewport::new(vp_off.0, vp_off.1, vp_off.2, vp_off.3).unwrap();
        let draw = Draw::dynamic(mode, Some(t), vp).unwrap();
        let mut g = Guarded::new(w, h, mode.depth == DepthTest::Less);
        let n = draw.clip_triangles(&tris, &mut g).unwrap();
        g.check("any triangle");
        prop_assert!(n as usize <= 4 * w * h * tris.len());
        if mode.depth == DepthTest::Off {
            // Without a depth test every rasterized pixel is written: n counts them.
            let written = g.pixels().iter().filter(|&&p| p != 0).count();
            prop_assert!(written <= n as usize);
        }
    }
}

/// A jittered `nx` x `ny` grid over NDC `[-e, e]^2`, two triangles per cell along a random
/// diagonal, counter-clockwise in NDC, with per-vertex `w`.
fn tiling(
    nx: usize,
    ny: usize,
    e: f64,
    jitter: &[(f64, f64)],
    diag: &[bool],
    ws: &[f64],
) -> Vec<[ClipVertex; 3]> {
    let idx = |i: usize, j: usize| j * (nx + 1) + i;
    let vert = |i: usize, j: usize| {
        let (jx, jy) = jitter[idx(i, j)];
        // Border vertices slide only along their border.
        let jx = if i == 0 || i == nx { 0.0 } else { jx };
        let jy = if j == 0 || j == ny { 0.0 } else { jy };
        let x = -e + 2.0 * e * (i as f64 + jx) / nx as f64;
        let y = -e + 2.0 * e * (j as f64 + jy) / ny as f64;
        let w = ws[idx(i, j)];
        ClipVertex::new(
            [
                Fx::from_num(x * w),
                Fx::from_num(y * w),
                Fx::from_num(0.5 * w * (x * 0.3 - 0.1)),
                Fx::from_num(w),
            ],
            [Fx::ZERO; 2],
        )
    };
    let mut out = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            // NDC y up: (i, j) bottom-left, counter-clockwise is bl, br, tr, tl.
            let (bl, br, tr, tl) = (
                vert(i, j),
                vert(i + 1, j),
                vert(i + 1, j + 1),
                vert(i, j + 1),
            );
            if diag[j * nx + i] {
                out.push([bl, br, tr]);
                out.push([bl, tr, tl]);
            } else {
                out.push([bl, br, tl]);
                out.push([br, tr, tl]);
            }
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    /// A random mesh tiling the whole viewport writes every pixel exactly once (front faces
    /// with back-face culling: every triangle is kept; front-face culling keeps none).
    #[test]
    fn tiling_meshes_write_every_pixel_once(
        (nx, ny) in (1usize..9, 1usize..9),
        (w, h) in (1usize..48, 1usize..40),
        e in prop_oneof![Just(1.0), 1.0f64..2.5],
        // |jitter| < 1/6 of a cell keeps every cell's two triangles counter-clockwise for
        // either diagonal: the orientation of (bl, br, tr) is at least 1 - 6|jitter|. With
        // 0.3 a cell could fold (a clockwise, culled triangle over its neighbour), which is
        // not a tiling; CI's proptest found one (the regression file keeps the seed).
        jitter in prop::collection::vec((-0.16f64..0.16, -0.16f64..0.16), 100),
        diag in prop::collection::vec(any::<bool>(), 64),
        ws in prop::collection::vec(prop_oneof![Just(1.0), 0.25f64..4.0], 100),
    ) {
        let mesh = tiling(nx, ny, e, &jitter, &diag, &ws);
        let counts = write_counts(&mesh, Cull::Back, w, h);
        let bad = counts.iter().filter(|&&c| c != 1).count();
        prop_assert_eq!(bad, 0, "{} of {} pixels not written exactly once", bad, w * h);
        let culled = write_counts(&mesh, Cull::Front, w, h);
        prop_assert!(culled.iter().all(|&c| c == 0));
    }
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

/// Draws `tris` (each tagged with its draw) whole-frame through `Frame`.
fn whole(
    draws: &[&Draw<'_, Rgb565>],
    tris: &[(u8, [ClipVertex; 3])],
    w: usize,
    h: usize,
) -> Vec<u16> {
    let mut color = vec![Rgb565::default(); w * h];
    let mut depth = vec![0u16; w * h];
    let mut f = Frame::new(&mut color, w as u32, h as u32)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    f.clear(raw(0x1234));
    for (d, t) in tris {
        draws[usize::from(*d)]
            .clip_triangles(std::slice::from_ref(t), &mut f)
            .unwrap();
    }
    color.iter().map(|&c| bits(c)).collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    /// Band rendering (any band height, bins big enough or too small) gives the same frame
    /// as whole-frame rendering, bit for bit.
    #[test]
    fn bands_equal_whole_frame(
        tris in prop::collection::vec((0u8..2, [scene_vertex(), scene_vertex(), scene_vertex()]), 1..12),
        modes in (any_mode(), any_mode()),
        (w, h) in (1usize..48, 1usize..40),
        rows in 1u32..40,
        small_bins in any::<bool>(),
    ) {
        let tex = noise_texture(8, 16, 21);
        let texels = host_tests::adapter::texels(&tex);
        let t = texture(&tex, &texels);
        let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
        let d0 = Draw::dynamic(modes.0, Some(t), vp).unwrap();
        let d1 = Draw::dynamic(modes.1, Some(t), vp).unwrap().with_flat_color(raw(0xF81F));
        let draws = [&d0, &d1];
        let expected = whole(&draws, &tris, w, h);

        let mut screen = 0usize;
        for (d, tri) in &tris {
            draws[usize::from(*d)].project(tri, &mut |_| screen += 1);
        }
        let nbins = if small_bins { screen.saturating_sub(1) } else { screen + 3 };
        let mut bins = vec![Binned::default(); nbins];
        let rows = rows.min(h as u32);
        let mut cbuf = vec![Rgb565::default(); w * rows as usize];
        let mut dbuf = vec![0u16; w * rows as usize];
        let mut band = BandRenderer::new(&mut cbuf, w as u32, rows, h as u32)
            .unwrap()
            .with_depth(&mut dbuf)
            .unwrap();
        let mut got = vec![0u16; w * h];
        let stats = band
            .render(
                &[&d0, &d1],
                &mut bins,
                raw(0x1234),
                |sink| {
                    for (d, tri) in &tris {
                        draws[usize::from(*d)].project(tri, &mut |s| sink.push(*d, s));
                    }
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
        prop_assert_eq!(stats.rewalked, screen > nbins);
        prop_assert_eq!(stats.bands as usize, h.div_ceil(rows as usize));
        prop_assert!(got == expected, "band frame differs from whole frame ({:?})", stats);
    }
}

/// The draw of the depth-floor properties: the run-time draw in `mode`, or a typed one
/// (`typed` 1: affine or adaptive, whose short spans are drawn inline; 2: exact).
fn floor_draw<'a>(
    mode: DrawMode,
    adaptive: bool,
    typed: u8,
    t: fixel::texture::Texture<'a>,
    vp: Viewport,
) -> Draw<'a, Rgb565> {
    use fixel::pipeline::{Adaptive, Affine, DepthLess, Exact, ModulateIntensity, Pipeline};
    use fixel::texture::{Bilinear, Repeat};
    type TypedAffine = Pipeline<Affine, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
    type TypedAdaptive = Pipeline<Adaptive, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
    type TypedExact = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
    let mode = DrawMode {
        depth: DepthTest::Less,
        projection: if adaptive {
            Projection::Adaptive { budget: 64 }
        } else {
            mode.projection
        },
        ..mode
    };
    match (typed, adaptive) {
        (1, false) => Draw::new::<TypedAffine>(Some(t), vp, Cull::None).unwrap(),
        (1, true) => Draw::new::<TypedAdaptive>(Some(t), vp, Cull::None).unwrap(),
        (2, _) => Draw::new::<TypedExact>(Some(t), vp, Cull::None).unwrap(),
        _ => Draw::dynamic(mode, Some(t), vp).unwrap(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(128), ..ProptestConfig::default() })]

    /// The frame's depth floor stays at or below every stored depth after each triangle,
    /// in every projection, for the run-time draw and for typed ones (whose short spans are
    /// drawn inline and leave the bound to the triangle: see `depth_lower_bound`).
    #[test]
    fn depth_floor_stays_below_every_stored_depth(
        tris in prop::collection::vec([tame_vertex(), tame_vertex(), tame_vertex()], 1..12),
        mode in any_mode(),
        adaptive in any::<bool>(),
        typed in 0u8..3,
        (w, h) in (1usize..48, 1usize..40),
    ) {
        use fixel::surface::RenderTarget;
        let tex = noise_texture(8, 8, 5);
        let texels = host_tests::adapter::texels(&tex);
        let t = texture(&tex, &texels);
        let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
        let draw = floor_draw(mode, adaptive, typed, t, vp);
        let mut color = vec![Rgb565::new(0, 0, 0); w * h];
        let mut depth = vec![0u16; w * h];
        let mut frame = Frame::new(&mut color, w as u32, h as u32)
            .unwrap()
            .with_depth(&mut depth)
            .unwrap();
        for tri in &tris {
            draw.clip_triangles(core::slice::from_ref(tri), &mut frame).unwrap();
            let floor = frame.depth_floor();
            let lowest = frame.depth().unwrap().iter().copied().min().unwrap();
            prop_assert!(floor <= lowest, "floor {} above a stored depth {}", floor, lowest);
        }
    }

    /// The depth floor is only a shortcut: a frame drawn with it (`with_depth`, the floor
    /// known from the clear) equals the frame drawn over the same cleared depth with the
    /// floor unknown (`with_depth_kept`), colour and depth, for triangles anywhere in the
    /// clip-space format; and every depth a triangle changes, it lowers (`GL_LESS`).
    #[test]
    fn depth_floor_changes_no_pixel(
        tris in prop::collection::vec([any_vertex(), any_vertex(), any_vertex()], 1..10),
        mode in any_mode(),
        adaptive in any::<bool>(),
        typed in 0u8..3,
        (w, h) in (1usize..48, 1usize..40),
    ) {
        let tex = noise_texture(8, 8, 5);
        let texels = host_tests::adapter::texels(&tex);
        let t = texture(&tex, &texels);
        let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
        let draw = floor_draw(mode, adaptive, typed, t, vp);
        let black = Rgb565::new(0, 0, 0);
        let (mut ca, mut da) = (vec![black; w * h], vec![0u16; w * h]);
        let (mut cb, mut db) = (vec![black; w * h], vec![u16::MAX; w * h]);
        let mut a = Frame::new(&mut ca, w as u32, h as u32).unwrap().with_depth(&mut da).unwrap();
        let mut b = Frame::new(&mut cb, w as u32, h as u32)
            .unwrap()
            .with_depth_kept(&mut db)
            .unwrap();
        for tri in &tris {
            let before = a.depth().unwrap().to_vec();
            let na = draw.clip_triangles(core::slice::from_ref(tri), &mut a).unwrap();
            let nb = draw.clip_triangles(core::slice::from_ref(tri), &mut b).unwrap();
            prop_assert_eq!(na, nb);
            let after = a.depth().unwrap();
            for (i, (&old, &new)) in before.iter().zip(after).enumerate() {
                prop_assert!(new <= old, "pixel {} depth {} raised to {}", i, old, new);
            }
            prop_assert!(a.depth() == b.depth(), "depth differs with the floor");
            prop_assert!(a.pixels() == b.pixels(), "colour differs with the floor");
        }
    }
}
