//! The span loops' paths against each other: the short path draws what the general loop draws.

extern crate std;
use super::SHORT_PATH;
use crate::geometry::{ClipVertex, Cull, Viewport};
use crate::math::Fx;
use crate::pipeline::{
    Affine, DepthLess, Draw, ModulateIntensity, Pipeline, QuadraticBy, RenderTarget, Replace, Rows,
    Stages, SubdividedBy,
};
use crate::texture::{Bilinear, Nearest, Repeat, Texture};
use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::Rgb565;
use std::vec::Vec;

use crate::test_rng::Rng;

/// A whole frame of colour and depth, as plain as a target gets (the surface stage's frames
/// and bands are tested against the span loops in the host tests).
struct Plain<'a> {
    color: &'a mut [Rgb565],
    depth: &'a mut [u16],
    width: u32,
}

impl RenderTarget for Plain<'_> {
    type Color = Rgb565;
    fn width(&self) -> u32 {
        self.width
    }
    fn row_range(&self) -> (i32, i32) {
        (0, (self.color.len() / self.width as usize) as i32)
    }
    fn rows_mut(&mut self) -> Rows<'_, Rgb565> {
        let w = self.width as usize;
        Rows {
            height: self.color.len() / w,
            color: self.color,
            depth: Some(self.depth),
            width: w,
            stride: w,
            y0: 0,
        }
    }
    fn has_depth(&self) -> bool {
        true
    }
}

/// Uniform in `lo..hi` (I16F16).
fn fx(rng: &mut Rng, lo: f64, hi: f64) -> Fx {
    Fx::from_num(lo + rng.unit01() * (hi - lo))
}

/// Random triangles, small (spans of a few pixels) and large (spans past one chunk),
/// in front of the camera at varying depth, drawn with `M` twice: with and without the
/// short-span path. Colour and depth must be the same bits, and so must the counts.
fn same_pixels<M: Stages + 'static>() {
    let texels: Vec<Rgb565> = (0..64 * 32u32)
        .map(|i| Rgb565::from(RawU16::new((i.wrapping_mul(0x9E37) >> 3) as u16)))
        .collect();
    let tex = Texture::new(&texels, 64, 32).unwrap();
    let (w, h) = (96u32, 72u32);
    let vp = Viewport::new(0, 0, w, h).unwrap();
    let draw = Draw::new::<M>(Some(tex), vp, Cull::None).unwrap();
    let mut rng = Rng(0x5DEE_CE66_D1CE_4E5B);
    let mut drawn = 0u32;
    for round in 0..300 {
        let size = if round % 3 == 0 { 1.6 } else { 0.12 };
        let (cx, cy) = (
            fx(&mut rng, -0.9, 0.9).to_num::<f64>(),
            fx(&mut rng, -0.9, 0.9).to_num::<f64>(),
        );
        let tri: [ClipVertex; 3] = core::array::from_fn(|_| {
            let wv = fx(&mut rng, 1.0, 6.0);
            let x =
                Fx::from_num((cx + fx(&mut rng, -size, size).to_num::<f64>()) * wv.to_num::<f64>());
            let y =
                Fx::from_num((cy + fx(&mut rng, -size, size).to_num::<f64>()) * wv.to_num::<f64>());
            let z = Fx::from_num(fx(&mut rng, -0.9, 0.9).to_num::<f64>() * wv.to_num::<f64>());
            let mut v = ClipVertex::new(
                [x, y, z, wv],
                [fx(&mut rng, -2.0, 3.0), fx(&mut rng, -2.0, 3.0)],
            );
            let c = (rng.next() % 257) as u16;
            v.color = [c; 3];
            v
        });
        let frames: Vec<(Vec<Rgb565>, Vec<u16>, u32)> = [true, false]
            .into_iter()
            .map(|short| {
                SHORT_PATH.with(|c| c.set(short));
                let mut color = std::vec![Rgb565::new(0, 0, 0); (w * h) as usize];
                let mut depth = std::vec![0xFFFF_u16; (w * h) as usize];
                let mut f = Plain {
                    color: &mut color,
                    depth: &mut depth,
                    width: w,
                };
                let n = draw.clip_triangles(&[tri], &mut f).unwrap();
                (color, depth, n)
            })
            .collect();
        SHORT_PATH.with(|c| c.set(true));
        assert!(frames[0] == frames[1], "round {round}: {tri:?}");
        drawn += frames[0].2;
    }
    assert!(drawn > 20_000, "only {drawn} pixels drawn");
}

#[test]
fn short_spans_draw_what_the_general_loop_draws() {
    same_pixels::<Pipeline<SubdividedBy<6>, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>>(
    );
    same_pixels::<Pipeline<SubdividedBy<4>, Nearest, Repeat, Repeat, Replace, DepthLess>>();
    same_pixels::<Pipeline<Affine, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>>();
    same_pixels::<Pipeline<QuadraticBy<4>, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>>(
    );
}
