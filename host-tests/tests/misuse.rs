//! The ways a careless program goes wrong, each with the documented outcome: an `Error`
//! that says what is wrong, or (for a viewport larger than its target) a documented crop
//! that gives exactly the pixels of the full-size target.

use core::convert::Infallible;

use fixel::math::{fx, try_fx, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ModulateIntensity, NoDepth, Pipeline, Replace};
use fixel::prelude::*;
use fixel::scene::{draw_mesh, mesh_triangles, DirectionalLight};
use fixel::surface::{BandError, Binned};
use fixel::texture::{Bilinear, Repeat};
use fixel_scenes as demo;

type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
type Unlit = Pipeline<Exact, Bilinear, Repeat, Repeat, Replace, NoDepth>;

const W: u32 = 160;
const H: u32 = 120;

fn texels() -> Vec<Rgb565> {
    let mut t = vec![Rgb565::BLACK; 64 * 64];
    demo::checker_texture(64, 64, &mut t).unwrap();
    t
}

/// The cube drawn with `draw` into a fresh `w` x `h` frame with depth, cleared or not.
fn cube_frame(draw: &Draw<'_, Rgb565>, w: u32, h: u32, clear: bool) -> Vec<Rgb565> {
    let mut color = vec![Rgb565::BLACK; (w * h) as usize];
    let mut depth = vec![0u16; (w * h) as usize];
    let mut frame = Frame::new(&mut color, w, h)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    if clear {
        frame.clear(Rgb565::BLACK);
    }
    let cube = demo::cube();
    let light = DirectionalLight::default();
    let n = draw_mesh(
        draw,
        &cube.mesh().unwrap(),
        &demo::cube_model(0),
        &demo::camera(20),
        Some(&light),
        &mut frame,
    )
    .unwrap();
    assert!(n > 1000);
    color
}

#[test]
fn depth_test_into_a_frame_without_depth_is_an_error() {
    let t = texels();
    let tex = Texture::new(&t, 64, 64).unwrap();
    let draw = Draw::new::<Lit>(Some(tex), Viewport::new(0, 0, W, H).unwrap(), Cull::Back).unwrap();
    let mut color = vec![Rgb565::BLACK; (W * H) as usize];
    let mut frame = Frame::new(&mut color, W, H).unwrap();
    let cube = demo::cube();
    let r = draw_mesh(
        &draw,
        &cube.mesh().unwrap(),
        &demo::cube_model(0),
        &demo::camera(20),
        None,
        &mut frame,
    );
    assert_eq!(r, Err(Error::NoDepthBuffer));
    assert!(
        color.iter().all(|&c| c == Rgb565::BLACK),
        "nothing is drawn"
    );
    let msg = Error::NoDepthBuffer.to_string();
    assert!(msg.contains("depth buffer"), "{msg}");

    // The same draw without a depth test is fine.
    let unlit =
        Draw::new::<Unlit>(Some(tex), Viewport::new(0, 0, W, H).unwrap(), Cull::Back).unwrap();
    let mut frame = Frame::new(&mut color, W, H).unwrap();
    let tri = [ClipVertex::default(); 3];
    assert_eq!(unlit.clip_triangles(&[tri], &mut frame), Ok(0));
}

#[test]
fn depth_test_into_bands_without_depth_is_an_error() {
    let t = texels();
    let tex = Texture::new(&t, 64, 64).unwrap();
    let draw = Draw::new::<Lit>(Some(tex), Viewport::new(0, 0, W, H).unwrap(), Cull::Back).unwrap();
    let mut buf = vec![Rgb565::BLACK; (W * 8) as usize];
    let mut bands = BandRenderer::new(&mut buf, W, 8, H).unwrap();
    let mut bins = [Binned::default(); 16];
    let mut flushed = 0;
    let r = bands.render(
        &[&draw],
        &mut bins,
        Rgb565::BLACK,
        |_| {},
        |_| {
            flushed += 1;
            Ok::<(), Infallible>(())
        },
    );
    assert_eq!(r, Err(BandError::Input(Error::NoDepthBuffer)));
    assert_eq!(flushed, 0, "refused before the first band");
    // With E = Infallible, `?` turns it into a plain fixel::Error.
    let plain: Error = r.unwrap_err().into();
    assert_eq!(plain, Error::NoDepthBuffer);
}

#[test]
fn a_frame_drawn_without_clear_is_depth_tested_correctly() {
    let t = texels();
    let tex = Texture::new(&t, 64, 64).unwrap();
    let draw = Draw::new::<Lit>(Some(tex), Viewport::new(0, 0, W, H).unwrap(), Cull::Back).unwrap();
    // `with_depth` fills the depth buffer with the far plane: forgetting `clear` (the
    // colour was already black) gives the same frame.
    assert_eq!(
        cube_frame(&draw, W, H, false),
        cube_frame(&draw, W, H, true)
    );
}

#[test]
fn a_draw_index_past_the_draws_is_an_error() {
    let t = texels();
    let tex = Texture::new(&t, 64, 64).unwrap();
    let draw =
        Draw::new::<Unlit>(Some(tex), Viewport::new(0, 0, W, H).unwrap(), Cull::Back).unwrap();
    let mut buf = vec![Rgb565::BLACK; (W * 8) as usize];
    let mut bands = BandRenderer::new(&mut buf, W, 8, H).unwrap();
    let cube = demo::cube();
    let mesh = cube.mesh().unwrap();
    for nbins in [16, 0] {
        // Enough bins, and none (the fallback that re-runs the geometry per band).
        let mut bins = vec![Binned::default(); nbins];
        let mut flushed = 0;
        let r = bands.render(
            &[&draw],
            &mut bins,
            Rgb565::BLACK,
            |sink| {
                mesh_triangles(&mesh, &demo::cube_model(0), &demo::camera(20), None, |t| {
                    draw.project(t, &mut |s| sink.push(1, s))
                })
            },
            |_| {
                flushed += 1;
                Ok::<(), Infallible>(())
            },
        );
        let e = Error::BadDrawIndex { index: 1, draws: 1 };
        assert_eq!(r, Err(BandError::Input(e)), "{nbins} bins");
        assert_eq!(flushed, 0);
        assert!(e.to_string().contains("draw index 1"), "{e}");
    }
}

#[test]
fn a_viewport_larger_than_its_target_is_cropped_exactly() {
    let t = texels();
    let tex = Texture::new(&t, 64, 64).unwrap();
    // A 2W x 2H viewport drawn into a W x H frame: the frame holds the top-left quarter of
    // the 2W x 2H picture, pixel for pixel.
    let big = Viewport::new(0, 0, 2 * W, 2 * H).unwrap();
    let draw = Draw::new::<Lit>(Some(tex), big, Cull::Back).unwrap();
    let full = cube_frame(&draw, 2 * W, 2 * H, true);
    let cropped = cube_frame(&draw, W, H, true);
    for y in 0..H {
        for x in 0..W {
            let (a, b) = (
                cropped[(y * W + x) as usize],
                full[(y * 2 * W + x) as usize],
            );
            assert_eq!(a, b, "pixel ({x}, {y})");
        }
    }
    assert!(cropped.iter().any(|&c| c != Rgb565::BLACK));
}

#[test]
fn a_zero_light_direction_is_an_error() {
    let e = DirectionalLight::new(Vec3::ZERO, fx(0.3), fx(0.7));
    assert_eq!(e, Err(Error::ZeroVector("light direction")));
    assert!(DirectionalLight::new(Vec3::from_num(0, 0, 1), fx(0.3), fx(0.7)).is_ok());
}

#[test]
fn numbers_into_fixed_point_saturate_or_are_refused() {
    assert_eq!(fx(40000), Fx::MAX);
    assert_eq!(fx(-40000.0f64), Fx::MIN);
    assert_eq!(fx(f32::NAN), Fx::ZERO);
    assert_eq!(fx(f32::INFINITY), Fx::MAX);
    assert_eq!(fx(1.25f32), Fx::from_bits(5 << 14));
    assert_eq!(try_fx(40000), Err(Error::OutOfRange { what: "number" }));
    assert_eq!(try_fx(f64::NAN), Err(Error::OutOfRange { what: "number" }));
    assert_eq!(try_fx(-3), Ok(Fx::from_bits(-3 << 16)));
    // Mixed argument types; components saturate one by one.
    let v = Vec3::from_num(1, 0.5f32, 1e9f64);
    assert_eq!(v, Vec3::new(Fx::ONE, Fx::from_bits(1 << 15), Fx::MAX));
    // A camera built from saturated numbers does not wrap into a mirrored scene.
    let m = Mat4::translation(Vec3::from_num(40000, 0, 0));
    assert_eq!(m.transform_point(Vec3::ZERO).map(|p| p.x), Some(Fx::MAX));
}
