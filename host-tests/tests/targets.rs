//! Render targets: the embedded-graphics flush adapter, bands, other colour
//! formats, and the errors bad input gets.
//!
//! (a) A frame drawn in bands and flushed through `DrawTargetFlush` into an
//!     embedded-graphics `DrawTarget` equals the plain `Frame` bit for bit,
//!     both through the default `fill_contiguous` (which calls `draw_iter`)
//!     and through an override (one call per band).
//! (b) Bands of 1, 7, 16 and 240 rows equal the whole frame for the three
//!     benchmark scenes, and so does the fallback when the bins overflow.
//! (c) `Frame<Rgb888>` and `Frame<Gray8>` hold exactly
//!     `TargetColor::from_rgb565` of the RGB565 frame.
//! (d) Every constructor refuses bad input with the documented `Error`
//!     variant, and its message names the problem.

use core::convert::Infallible;

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Size};
use embedded_graphics_core::pixelcolor::{Gray8, Rgb565, Rgb888};
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::Pixel;
use fixel::color::TargetColor;
use fixel::geometry::{ClipVertex, Viewport};
use fixel::pipeline::{Draw, DrawMode, Projection, Shading};
use fixel::surface::Binned;
use fixel::surface::{BandRenderer, DrawTargetFlush, Frame};
use fixel::texture::Texture;
use fixel::Error;
use host_tests::{adapter, scenes};

const W: u32 = scenes::WIDTH;
const H: u32 = scenes::HEIGHT;
const BLACK: Rgb565 = Rgb565::new(0, 0, 0);

/// A benchmark scene ready for fixel: clip triangles, texels and mode.
struct Scene {
    tris: Vec<[ClipVertex; 3]>,
    texels: Vec<Rgb565>,
    tw: u32,
    th: u32,
    mode: DrawMode,
}

fn scene(s: &scenes::SceneDesc) -> Scene {
    Scene {
        tris: adapter::clip_triangles(&scenes::to_ref_triangles(s)),
        texels: adapter::texels(&s.texture),
        tw: s.texture.width,
        th: s.texture.height,
        mode: adapter::draw_mode(&s.mode, None, true),
    }
}

fn benchmark_scenes() -> [(&'static str, Scene); 3] {
    [
        ("cube", scene(&scenes::cube(0))),
        ("sphere", scene(&scenes::sphere(0))),
        ("floor", scene(&scenes::floor())),
    ]
}

fn draw<'a, C: TargetColor>(s: &'a Scene) -> Draw<'a, C> {
    let tex = Texture::new(&s.texels, s.tw, s.th).unwrap();
    Draw::dynamic(s.mode, Some(tex), Viewport::new(0, 0, W, H).unwrap()).unwrap()
}

/// The scene drawn whole into a `Frame<C>` with depth.
fn whole<C: TargetColor>(s: &Scene) -> Vec<C> {
    let n = (W * H) as usize;
    let mut color = vec![C::default(); n];
    let mut depth = vec![0u16; n];
    let mut frame = Frame::new(&mut color, W, H)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(C::from_rgb565(0));
    draw::<C>(s).clip_triangles(&s.tris, &mut frame).unwrap();
    color
}

/// The scene drawn in bands of `rows` through `BandRenderer` (with `bins`
/// bin slots), each band handed to `flush`. Returns the stats.
fn banded(
    s: &Scene,
    rows: u32,
    bins: usize,
    flush: &mut dyn FnMut(&Frame<'_, Rgb565>) -> Result<(), Infallible>,
) -> fixel::surface::BandStats {
    let d = draw::<Rgb565>(s);
    let mut color = vec![BLACK; (W * rows) as usize];
    let mut depth = vec![0u16; (W * rows) as usize];
    let mut br = BandRenderer::new(&mut color, W, rows, H)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    let mut bins = vec![Binned::default(); bins];
    br.render(
        &[&d],
        &mut bins,
        BLACK,
        |sink| {
            for t in &s.tris {
                d.project(t, &mut |st| sink.push(0, st));
            }
        },
        |band| flush(band),
    )
    .unwrap()
}

/// An in-memory embedded-graphics display that only implements `draw_iter`
/// (so `fill_contiguous` is embedded-graphics' default, which calls it).
struct IterDisplay {
    px: Vec<Rgb565>,
    draw_iter_calls: usize,
}

impl OriginDimensions for IterDisplay {
    fn size(&self) -> Size {
        Size::new(W, H)
    }
}

impl DrawTarget for IterDisplay {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        self.draw_iter_calls += 1;
        for Pixel(p, c) in pixels {
            if (0..W as i32).contains(&p.x) && (0..H as i32).contains(&p.y) {
                self.px[(p.y as u32 * W + p.x as u32) as usize] = c;
            }
        }
        Ok(())
    }
}

/// A display that streams `fill_contiguous` itself and counts the calls.
struct StreamDisplay {
    px: Vec<Rgb565>,
    fills: Vec<Rectangle>,
}

impl OriginDimensions for StreamDisplay {
    fn size(&self) -> Size {
        Size::new(W, H)
    }
}

impl DrawTarget for StreamDisplay {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, _: I) -> Result<(), Infallible> {
        panic!("StreamDisplay expects fill_contiguous only");
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        self.fills.push(*area);
        let (x0, y0) = (area.top_left.x as u32, area.top_left.y as u32);
        let mut it = colors.into_iter();
        for y in y0..y0 + area.size.height {
            for x in x0..x0 + area.size.width {
                self.px[(y * W + x) as usize] = it.next().expect("enough colours");
            }
        }
        assert!(it.next().is_none(), "more colours than the area holds");
        Ok(())
    }
}

fn differing(a: &[Rgb565], b: &[Rgb565]) -> usize {
    a.iter().zip(b).filter(|(x, y)| x != y).count()
}

#[test]
fn draw_target_flush_equals_frame() {
    let s = scene(&scenes::cube(0));
    let reference = whole::<Rgb565>(&s);
    assert!(
        reference.iter().any(|&c| c != BLACK),
        "the cube drew nothing"
    );
    for rows in [16, 240] {
        let bands = H.div_ceil(rows) as usize;
        let mut iter = IterDisplay {
            px: vec![Rgb565::new(1, 2, 3); (W * H) as usize],
            draw_iter_calls: 0,
        };
        let stats = banded(&s, rows, 64, &mut |b| DrawTargetFlush(&mut iter).flush(b));
        assert_eq!(stats.bands as usize, bands);
        assert_eq!(
            iter.draw_iter_calls, bands,
            "default fill_contiguous -> draw_iter per band"
        );
        assert_eq!(
            differing(&iter.px, &reference),
            0,
            "draw_iter display, {rows}-row bands"
        );

        let mut stream = StreamDisplay {
            px: vec![Rgb565::new(1, 2, 3); (W * H) as usize],
            fills: Vec::new(),
        };
        banded(&s, rows, 64, &mut |b| DrawTargetFlush(&mut stream).flush(b));
        assert_eq!(stream.fills.len(), bands, "one fill_contiguous per band");
        for (i, r) in stream.fills.iter().enumerate() {
            let y0 = i as u32 * rows;
            assert_eq!(
                *r,
                Rectangle::new(
                    embedded_graphics_core::geometry::Point::new(0, y0 as i32),
                    Size::new(W, rows.min(H - y0))
                )
            );
        }
        assert_eq!(
            differing(&stream.px, &reference),
            0,
            "fill_contiguous display, {rows}-row bands"
        );
    }
}

#[test]
fn bands_equal_whole_frames() {
    for (name, s) in benchmark_scenes() {
        let reference = whole::<Rgb565>(&s);
        for rows in [1, 7, 16, 240] {
            // Enough bins, and (rows 16) a single bin: the re-walk fallback.
            let bin_sizes: &[usize] = if rows == 16 { &[4096, 1] } else { &[4096] };
            for &bins in bin_sizes {
                let mut out = vec![Rgb565::new(1, 2, 3); (W * H) as usize];
                let stats = banded(&s, rows, bins, &mut |b| {
                    let y0 = b.first_row() as usize * W as usize;
                    out[y0..y0 + b.pixels().len()].copy_from_slice(b.pixels());
                    Ok(())
                });
                assert_eq!(stats.rewalked, bins == 1, "{name}");
                assert_eq!(
                    differing(&out, &reference),
                    0,
                    "{name}: {rows}-row bands ({bins} bins) differ from the whole frame"
                );
            }
        }
    }
}

#[test]
fn rgb888_and_gray8_frames() {
    let s = scene(&scenes::cube(0));
    let rgb565 = whole::<Rgb565>(&s);
    let raw: Vec<u16> = rgb565
        .iter()
        .map(|&c| embedded_graphics_core::pixelcolor::IntoStorage::into_storage(c))
        .collect();
    let rgb888 = whole::<Rgb888>(&s);
    let gray8 = whole::<Gray8>(&s);
    let want888: Vec<Rgb888> = raw.iter().map(|&p| Rgb888::from_rgb565(p)).collect();
    let want8: Vec<Gray8> = raw.iter().map(|&p| Gray8::from_rgb565(p)).collect();
    assert_eq!(rgb888, want888);
    assert_eq!(gray8, want8);
    // Spot-check the conversions themselves (bit replication, BT.601 luma).
    assert_eq!(Rgb888::from_rgb565(0xFFFF), Rgb888::new(255, 255, 255));
    assert_eq!(Rgb888::from_rgb565(0xF800), Rgb888::new(255, 0, 0));
    assert_eq!(Gray8::from_rgb565(0xFFFF), Gray8::new(255));
    assert_eq!(Gray8::from_rgb565(0), Gray8::new(0));
}

/// Asserts `r` failed with `want`, and that its message contains every
/// fragment of `says`.
fn assert_error<T: core::fmt::Debug>(r: Result<T, Error>, want: Error, says: &[&str]) {
    let e = r.expect_err("expected an error");
    assert_eq!(e, want);
    let msg = e.to_string();
    for s in says {
        assert!(
            msg.contains(s),
            "{want:?}: message {msg:?} should mention {s:?}"
        );
    }
}

#[test]
fn bad_input_gives_the_documented_errors() {
    let texels = vec![BLACK; 64];
    assert_error(
        Texture::new(&texels[..48], 6, 8),
        Error::NotPowerOfTwo(6),
        &["6", "power of two"],
    );
    assert_error(
        Texture::new(&texels[..48], 8, 6),
        Error::NotPowerOfTwo(6),
        &["6", "power of two"],
    );
    assert_error(
        Texture::new(&texels[..60], 8, 8),
        Error::WrongLength {
            expected: 64,
            actual: 60,
        },
        &["60", "64"],
    );
    assert_error(Texture::new(&texels, 0, 8), Error::BadSize(0), &["0"]);
    assert_error(
        Texture::new(&texels, 8192, 8),
        Error::BadSize(8192),
        &["8192"],
    );
    assert!(Texture::new(&texels, 8, 8).is_ok());

    let mut band = vec![BLACK; 320 * 16];
    assert_error(
        BandRenderer::new(&mut band, 320, 17, 240),
        Error::BandTooTall {
            rows: 17,
            capacity: 16,
        },
        &["17", "16"],
    );
    assert_error(
        BandRenderer::new(&mut band, 320, 0, 240),
        Error::BandTooTall {
            rows: 0,
            capacity: 16,
        },
        &["0", "16"],
    );
    let mut short_depth = vec![0u16; 320 * 15];
    assert_error(
        BandRenderer::new(&mut band, 320, 16, 240)
            .unwrap()
            .with_depth(&mut short_depth),
        Error::WrongLength {
            expected: 320 * 16,
            actual: 320 * 15,
        },
        &["4800", "5120"],
    );

    let mut color = vec![BLACK; 320 * 240];
    assert_error(
        Frame::new(&mut color[..1000], 320, 240),
        Error::WrongLength {
            expected: 76800,
            actual: 1000,
        },
        &["1000", "76800"],
    );
    assert_error(Frame::new(&mut color, 0, 240), Error::BadSize(0), &["0"]);
    let mut depth = vec![0u16; 320 * 239];
    assert_error(
        Frame::new(&mut color, 320, 240)
            .unwrap()
            .with_depth(&mut depth),
        Error::WrongLength {
            expected: 76800,
            actual: 76480,
        },
        &["76480", "76800"],
    );

    let bad_vp = |w, h| Error::BadViewport {
        width: w,
        height: h,
    };
    assert_error(Viewport::new(0, 0, 0, 240), bad_vp(0, 240), &["0x240"]);
    assert_error(Viewport::new(0, 0, 320, 0), bad_vp(320, 0), &["320x0"]);
    assert_error(
        Viewport::new(0, 0, 4096, 240),
        bad_vp(4096, 240),
        &["4096x240", "2048"],
    );
    let out = |axis, offset, size| Error::ViewportOutOfBounds {
        axis,
        offset,
        size,
        limit: 2048,
    };
    assert_error(
        Viewport::new(2000, 0, 100, 100),
        out("x", 2000, 100),
        &["x offset 2000", "2048"],
    );
    // The offset is named, not the (valid) size.
    assert_error(
        Viewport::new(u32::MAX, 0, 10, 10),
        out("x", u32::MAX, 10),
        &["x offset 4294967295", "at most 2048"],
    );
    assert_error(
        Viewport::new(0, 2040, 10, 10),
        out("y", 2040, 10),
        &["y offset 2040", "at most 2048"],
    );
    assert!(Viewport::new(0, 0, 2048, 2048).is_ok());

    let vp = Viewport::new(0, 0, 320, 240).unwrap();
    for shading in [
        Shading::Replace,
        Shading::Modulate,
        Shading::ModulateIntensity,
    ] {
        let mode = DrawMode {
            shading,
            ..DrawMode::default()
        };
        assert_error(
            Draw::<Rgb565>::dynamic(mode, None, vp),
            Error::BadMode("textured shading needs a texture"),
            &["texture"],
        );
    }
    for shading in [Shading::Gouraud, Shading::Flat] {
        let mode = DrawMode {
            shading,
            ..DrawMode::default()
        };
        assert!(Draw::<Rgb565>::dynamic(mode, None, vp).is_ok());
    }
    let tex = Texture::new(&texels, 8, 8).unwrap();
    let sub_err = Error::BadMode("subdivision log2_n must be in 1..=6 (N = 2..64)");
    for log2_n in [0, 7, 255] {
        let mode = DrawMode {
            projection: Projection::Subdivided { log2_n },
            ..DrawMode::default()
        };
        assert_error(
            Draw::<Rgb565>::dynamic(mode, Some(tex), vp),
            sub_err,
            &["log2_n", "1..=6"],
        );
    }
    let mode = DrawMode {
        projection: Projection::Subdivided { log2_n: 4 },
        ..DrawMode::default()
    };
    for log2_n in 1..=6 {
        let d = Draw::<Rgb565>::dynamic(mode, Some(tex), vp).unwrap();
        assert!(d.with_subdivision(log2_n).is_ok());
    }
    for log2_n in [0, 7] {
        let d = Draw::<Rgb565>::dynamic(mode, Some(tex), vp).unwrap();
        assert_error(d.with_subdivision(log2_n), sub_err, &["log2_n"]);
    }
}

/// The frame's depth floor (a one-value hierarchical depth buffer) lets spans wholly nearer
/// than everything stored skip reading depth; it must never let a farther span through.
#[test]
fn depth_floor_never_lets_a_farther_span_through() {
    use fixel::math::Fx;
    use fixel::pipeline::DepthTest;
    use fixel::surface::RenderTarget;
    let quad = |z: f32| -> [[ClipVertex; 3]; 2] {
        let v = |x: f32, y: f32| {
            ClipVertex::new(
                [Fx::from_num(x), Fx::from_num(y), Fx::from_num(z), Fx::ONE],
                [Fx::ZERO; 2],
            )
        };
        let (a, b, c, d) = (v(-0.9, -0.9), v(0.9, -0.9), v(0.9, 0.9), v(-0.9, 0.9));
        [[a, b, c], [a, c, d]]
    };
    let mode = DrawMode {
        shading: Shading::Flat,
        depth: DepthTest::Less,
        ..DrawMode::default()
    };
    let vp = Viewport::new(0, 0, 40, 30).unwrap();
    let draw = Draw::<Rgb565>::dynamic(mode, None, vp).unwrap();
    let (mut color, mut depth) = ([Rgb565::new(0, 0, 0); 40 * 30], [0u16; 40 * 30]);
    let mut frame = Frame::new(&mut color, 40, 30)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    // Attaching depth fills it with the far plane: the bound is known from the start.
    assert_eq!(frame.depth_floor(), u16::MAX);
    assert!(frame.depth().unwrap().iter().all(|&d| d == u16::MAX));
    frame.clear(Rgb565::new(0, 0, 0));
    assert_eq!(frame.depth_floor(), u16::MAX);
    let near = draw.clip_triangles(&quad(-0.5), &mut frame).unwrap();
    assert!(near > 800, "{near}");
    let floor = frame.depth_floor();
    assert!(floor < u16::MAX && floor > 0, "{floor}");
    // Farther than what is stored: every pixel fails, though the floor is below it.
    assert_eq!(draw.clip_triangles(&quad(0.5), &mut frame).unwrap(), 0);
    // Nearer than everything: all pass (the skipped-read path), and the floor drops.
    assert_eq!(draw.clip_triangles(&quad(-0.8), &mut frame).unwrap(), near);
    assert!(frame.depth_floor() < floor);
    assert_eq!(draw.clip_triangles(&quad(-0.5), &mut frame).unwrap(), 0);
}
