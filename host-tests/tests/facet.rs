//! `ModulateFacet` (one intensity per triangle) against `ModulateIntensity` (the intensity
//! interpolated) and against the f64 reference, on the benchmark cube, whose faces carry
//! per-face normals: every triangle's three intensities are equal, so the two shaders
//! differ only where the interpolated constant's lowest bits cross a multiple of 1/256
//! (the intensity is truncated to Q8 per pixel).
//!
//! Measured (quadratic N = 32, bilinear; the printed lines): on frames 0 / 25 / 50 / 75 the
//! frames differ by 1 LSB at 15.7 / 13.4 / 20.6 / 13.9 % of the pixels, and the facet shader
//! is the closer of the two to the reference (PSNR 40.10 / 51.56 / 51.13 / 47.47 dB against
//! 39.45 / 45.92 / 42.23 / 44.78). The test holds: at most 1 LSB apart, a maximum
//! error at most 1 LSB larger, a PSNR no more than 0.1 dB lower.

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::pipeline::{
    DepthLess, Draw, ModulateFacet, ModulateIntensity, Pipeline, QuadraticBy, Stages,
};
use fixel::prelude::*;
use fixel::texture::{Bilinear, Repeat};
use host_tests::adapter::{self, clip_triangles};
use host_tests::metrics::{channel_errors, compare};
use host_tests::reference::{self, RefFilter, RefProjection};
use host_tests::scenes;

type Facet = Pipeline<QuadraticBy<5>, Bilinear, Repeat, Repeat, ModulateFacet, DepthLess>;
type Interpolated =
    Pipeline<QuadraticBy<5>, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;

/// The frame `M` draws of `tris` (raw RGB565) and the pixels it wrote.
fn draw<M: Stages + 'static>(
    tris: &[[fixel::geometry::ClipVertex; 3]],
    tex: Texture<'_>,
    w: u32,
    h: u32,
) -> (Vec<u16>, u32) {
    let n = (w * h) as usize;
    let mut color = vec![Rgb565::new(0, 0, 0); n];
    let mut depth = vec![0u16; n];
    let mut frame = Frame::new(&mut color, w, h)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    let vp = Viewport::new(0, 0, w, h).unwrap();
    let d = Draw::new::<M>(Some(tex), vp, Cull::Back)
        .unwrap()
        .with_subdivision(5)
        .unwrap();
    let written = d.clip_triangles(tris, &mut frame).unwrap();
    let px = color
        .iter()
        .map(|&c| RawU16::from(c).into_inner())
        .collect();
    (px, written)
}

#[test]
fn facet_draws_the_cube_as_the_interpolated_intensity() {
    for f in [0, 25, 50, 75] {
        let s = scenes::cube(f);
        let tris = scenes::to_ref_triangles(&s);
        let clip = clip_triangles(&tris);
        let texels = adapter::texels(&s.texture);
        let tex = Texture::new(&texels, s.texture.width, s.texture.height).unwrap();
        let (facet, wf) = draw::<Facet>(&clip, tex, s.width, s.height);
        let (interp, wi) = draw::<Interpolated>(&clip, tex, s.width, s.height);
        assert_eq!(wf, wi, "frame {f}: the same coverage");
        let (mut differ, mut max) = (0usize, 0u32);
        for (a, b) in facet.iter().zip(&interp) {
            if a != b {
                differ += 1;
                max = max.max(*channel_errors(*a, *b).iter().max().unwrap());
            }
        }
        // Against the f64 reference (exact perspective, bilinear), both.
        let mode = reference::RefMode {
            filter: RefFilter::Bilinear,
            projection: RefProjection::Perspective,
            ..s.mode
        };
        let r = reference::render(&tris, Some(&s.texture), &mode, s.width, s.height);
        let cov: Vec<bool> = r.covered.clone();
        let ef = compare(&facet, &cov, &r);
        let ei = compare(&interp, &cov, &r);
        println!(
            "cube frame {f}: {wf} pixels, {differ} differ (max {max} LSB); PSNR facet {:.2} dB, interpolated {:.2} dB; max {} / {} LSB",
            ef.psnr_db, ei.psnr_db, ef.max, ei.max
        );
        assert!(max <= 1, "frame {f}: a pixel differs by {max} LSB");
        assert!(
            ef.max <= ei.max + 1,
            "frame {f}: max error {} against {}",
            ef.max,
            ei.max
        );
        assert!(
            ef.psnr_db >= ei.psnr_db - 0.1,
            "frame {f}: PSNR {:.2} against {:.2}",
            ef.psnr_db,
            ei.psnr_db
        );
    }
}

/// `Draw::dynamic` refuses the facet shading with a message that says what to use instead.
#[test]
fn dynamic_refuses_facet() {
    let vp = Viewport::new(0, 0, 8, 8).unwrap();
    let texels = [Rgb565::new(0, 0, 0); 4];
    let tex = Texture::new(&texels, 2, 2).unwrap();
    let mode = fixel::pipeline::DrawMode {
        shading: fixel::pipeline::Shading::ModulateFacet,
        ..Default::default()
    };
    match Draw::<Rgb565>::dynamic(mode, Some(tex), vp) {
        Err(Error::BadMode(m)) => assert!(m.contains("Draw::new"), "{m}"),
        other => panic!("expected BadMode, got {:?}", other.map(|d| *d.mode())),
    }
}
