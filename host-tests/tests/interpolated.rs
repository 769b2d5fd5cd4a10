//! `Shader::INTERPOLATED`: a shader that reads only its first varyings draws the same pixels
//! as one that reads every varying it carries, in every projection: the span loops may leave
//! the unread ones stale, never the read ones. Random triangles (perspective, clipped, of any
//! size), the unread varyings large and varied so that a loop stepping the wrong ones would
//! show.

mod common;

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{
    Adaptive, Affine, DepthLess, Exact, ProjectionStage, QuadraticBy, ShadedDraw, SubdividedBy,
};
use fixel::shading::{Fragment, Shader};
use fixel::surface::Frame;
use proptest::prelude::*;

/// Varyings 0 and 1 hashed into a colour; `LIVE` says how many varyings the span loops
/// must interpolate (2: the others are stale; `usize::MAX`: all four).
#[derive(Clone, Copy, Debug)]
struct ReadsTwo<const LIVE: usize>;

impl<const LIVE: usize> Shader for ReadsTwo<LIVE> {
    type Varyings = [i32; 4];
    type Triangle = ();
    const INTERPOLATED: usize = LIVE;
    fn triangle(&self, _: &mut [[i32; 4]; 3]) {}
    fn shade(&self, f: &Fragment<[i32; 4], ()>) -> Option<u16> {
        let [a, b, _, _] = f.varyings;
        Some(((a >> 10) as u16) ^ ((b >> 6) as u16).rotate_left(5))
    }
}

const W: u32 = 48;
const H: u32 = 40;

/// The frame's colour bits and the pixels written, `tris` drawn with `shader` under `P`.
fn frame<P: ProjectionStage, S: Shader<Varyings = [i32; 4]>>(
    shader: S,
    tris: &[[Vertex<4>; 3]],
) -> (Vec<u16>, u32) {
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
    let mut f = Frame::new(&mut color, W, H)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    f.clear(Rgb565::new(0, 0, 0));
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let draw = ShadedDraw::<_, P, DepthLess>::new(shader, vp, Cull::None).unwrap();
    let pixels = draw.clip_triangles(tris, &mut f).unwrap();
    (
        color
            .iter()
            .map(|c| RawU16::from(*c).into_inner())
            .collect(),
        pixels,
    )
}

fn same_pixels<P: ProjectionStage>(tris: &[[Vertex<4>; 3]]) -> Result<(), TestCaseError> {
    let two = frame::<P, _>(ReadsTwo::<2>, tris);
    let all = frame::<P, _>(ReadsTwo::<{ usize::MAX }>, tris);
    prop_assert!(two.1 > 0 || all.1 == 0);
    prop_assert_eq!(two, all);
    Ok(())
}

/// A clip-space vertex: `x, y` within 1.6 w (some outside the view), `w` in 0.5..8, the
/// read varyings within 2^20, the unread ones anywhere in `i32`.
fn vertex() -> impl Strategy<Value = Vertex<4>> {
    (
        (-1.6f64..1.6, -1.6f64..1.6, -0.9f64..0.9, 0.5f64..8.0),
        (-(1i32 << 20)..1 << 20, -(1i32 << 20)..1 << 20),
        (any::<i32>(), any::<i32>()),
    )
        .prop_map(|((x, y, z, w), (a, b), (c, d))| {
            Vertex::new(
                [
                    Fx::from_num(x * w),
                    Fx::from_num(y * w),
                    Fx::from_num(z * w),
                    Fx::from_num(w),
                ],
                [a, b, c, d],
            )
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(64), ..ProptestConfig::default() })]

    #[test]
    fn reading_fewer_varyings_draws_the_same_pixels_in_every_projection(
        tris in prop::collection::vec([vertex(), vertex(), vertex()], 1..6),
    ) {
        same_pixels::<Exact>(&tris)?;
        same_pixels::<Affine>(&tris)?;
        same_pixels::<SubdividedBy<3>>(&tris)?;
        same_pixels::<Adaptive>(&tris)?;
        same_pixels::<QuadraticBy<4>>(&tris)?;
    }
}
