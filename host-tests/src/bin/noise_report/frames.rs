//! The measured frames: the firmware scenes drawn whole (pixels, coverage, FNV-1a checksum)
//! and timed through the firmware's own band code, the flame's f64 reference, and RGB565
//! to RGB8 for the PNGs.

use std::time::Instant;

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::pipeline::{Exact, NoDepth, ProjectionStage, ShadedDraw};
use fixel::shading::noise::{FlameShader, Ramp};
use fixel::shading::Shader;
use fixel::surface::Frame;
use host_tests::reference::noise::render_flame;

use crate::{noise, scenes, H, W};

fn bits(px: &[Rgb565]) -> Vec<u16> {
    px.iter().map(|&c| RawU16::from(c).into_inner()).collect()
}

/// The sphere's triangles, from the firmware's vertex code.
pub fn sphere_tris() -> Vec<[Vertex<4>; 3]> {
    let mut verts = [None; noise::VERTS];
    noise::vertices(&mut verts);
    (0..noise::TRIS)
        .filter_map(|t| {
            let i = noise::sphere_triangle(t);
            let v = |k: usize| verts[usize::from(i[k])];
            Some([v(0)?, v(1)?, v(2)?])
        })
        .collect()
}

/// Whole-frame pixels, coverage and FNV-1a checksum of the firmware scene with `shader`,
/// and host ns/px of the firmware's band code (median of `runs`).
pub fn sphere_frame<S: Shader<Varyings = [i32; 4]>>(
    shader: S,
    tris: &[[Vertex<4>; 3]],
    runs: u32,
) -> (Vec<u16>, Vec<bool>, u32, f64) {
    sphere_frame_in::<S, Exact>(shader, tris, runs)
}

/// [`sphere_frame`] with projection `J`.
pub fn sphere_frame_in<S: Shader<Varyings = [i32; 4]>, J: ProjectionStage>(
    shader: S,
    tris: &[[Vertex<4>; 3]],
    runs: u32,
) -> (Vec<u16>, Vec<bool>, u32, f64) {
    let mut buf = Box::new(noise::NoiseBuffers::new());
    whole_frame::<S, J, 4>(shader, tris, runs, &mut || {
        noise::render_in::<S, J>(shader, &mut buf, &mut || {}, &mut || {}).unwrap()
    })
}

/// The frame of `tris` drawn whole with `shader` (pixels, coverage, FNV-1a checksum), and
/// host ns/px of `bands` (the firmware's band code, median of `runs`; its checksum must be
/// the whole frame's).
pub fn whole_frame<S: Shader<Varyings = [i32; N]>, J: ProjectionStage, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
    runs: u32,
    bands: &mut dyn FnMut() -> scenes::FrameResult,
) -> (Vec<u16>, Vec<bool>, u32, f64) {
    let draw =
        ShadedDraw::<S, J, NoDepth>::new(shader, Viewport::new(0, 0, W, H).unwrap(), Cull::Back)
            .unwrap();
    let n = (W * H) as usize;
    let mut color = vec![Rgb565::new(0, 0, 0); n];
    let mut frame = Frame::new(&mut color, W, H).unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    for t in tris {
        draw.clip_triangles(&[*t], &mut frame).unwrap();
    }
    let mut sum = scenes::Fnv1a::default();
    sum.pixels(frame.pixels());
    let px = bits(frame.pixels());
    // Coverage: the same triangles drawn flat white into a black frame.
    let marker = ShadedDraw::<_, Exact, NoDepth>::new(
        fixel::shading::Flat(0xFFFF),
        Viewport::new(0, 0, W, H).unwrap(),
        Cull::Back,
    )
    .unwrap();
    let mut mc = vec![Rgb565::new(0, 0, 0); n];
    let mut mf = Frame::new(&mut mc, W, H).unwrap();
    for t in tris {
        let flat: [Vertex<0>; 3] = t.map(|v| Vertex::new(v.position, []));
        marker.clip_triangles(&[flat], &mut mf).unwrap();
    }
    let cov: Vec<bool> = bits(mf.pixels()).iter().map(|&c| c != 0).collect();
    let mut times = Vec::new();
    let mut pixels = 1;
    for _ in 0..runs {
        let t0 = Instant::now();
        let r = bands();
        times.push(t0.elapsed().as_secs_f64());
        assert_eq!(r.checksum, sum.0, "band and whole frames differ");
        pixels = r.stats.pixels.max(1);
    }
    times.sort_by(f64::total_cmp);
    (
        px,
        cov,
        sum.0,
        times[times.len() / 2] * 1e9 / f64::from(pixels),
    )
}

/// The flame firmware's frames (`noise::flame_frames_with`: 4 frames of 80 x 96, t = i/8
/// s) drawn whole with `octaves`: all frames' pixels in order, coverage (all), the FNV-1a
/// checksum over them, and host ns/px of the firmware's code (median of `runs`).
pub fn flame_frames(octaves: u8, runs: u32) -> (Vec<u16>, Vec<bool>, u32, f64) {
    let ramp = Ramp::from_keys(&fixel::shading::noise::FLAME_KEYS).unwrap();
    let vp = Viewport::new(0, 0, noise::FLAME_W, noise::FLAME_H).unwrap();
    let mut px = Vec::new();
    let mut sum = scenes::Fnv1a::default();
    for i in 0..4 {
        let shader = FlameShader {
            ramp: &ramp,
            t: i << 13,
            octaves,
        };
        let draw = ShadedDraw::<_, Exact, NoDepth>::new(shader, vp, Cull::None).unwrap();
        let mut color = vec![Rgb565::new(0, 0, 0); noise::FLAME_PIXELS];
        let mut frame = Frame::new(&mut color, noise::FLAME_W, noise::FLAME_H).unwrap();
        draw.clip_triangles(&flame_quad(), &mut frame).unwrap();
        sum.pixels(frame.pixels());
        px.extend(bits(frame.pixels()));
    }
    let mut color = Box::new([Rgb565::new(0, 0, 0); noise::FLAME_PIXELS]);
    let mut times = Vec::new();
    let mut pixels = 1;
    for _ in 0..runs {
        let t0 = Instant::now();
        let r = noise::flame_frames_with(&mut color, 4, octaves, &mut || {}, &mut || {}).unwrap();
        times.push(t0.elapsed().as_secs_f64());
        assert_eq!(r.checksum, sum.0, "flame frames differ");
        pixels = r.stats.pixels.max(1);
    }
    times.sort_by(f64::total_cmp);
    let cov = vec![true; px.len()];
    (
        px,
        cov,
        sum.0,
        times[times.len() / 2] * 1e9 / f64::from(pixels),
    )
}

/// The flame firmware's quad (NDC `-1..1`, [`noise::FLAME_QUAD`] flame units).
fn flame_quad() -> [[Vertex<2>; 3]; 2] {
    let (x0, x1, y0, y1) = noise::FLAME_QUAD;
    let v = |xn: i32, yn: i32, x: i32, y: i32| {
        Vertex::new(
            [
                fixel::math::Fx::from_num(xn),
                fixel::math::Fx::from_num(yn),
                fixel::math::Fx::ZERO,
                fixel::math::Fx::ONE,
            ],
            [x, y],
        )
    };
    let (a, b, c, d) = (
        v(-1, -1, x0, y0),
        v(1, -1, x1, y0),
        v(1, 1, x1, y1),
        v(-1, 1, x0, y1),
    );
    [[a, b, c], [a, c, d]]
}

/// The flame from baked layers (`noise_flame_baked`: 4 frames of 80 x 96, t = i/8 s,
/// layers baked here at run time) drawn whole: pixels in order, coverage (all), the FNV-1a
/// checksum, and host ns/px of the firmware's band code (median of `runs`).
pub fn flame_baked_frames(runs: u32) -> (Vec<u16>, Vec<bool>, u32, f64) {
    use fixel::shading::noise::{
        bake_flame_layer, BakedFlame, FLAME_KEYS, FLAME_LAYERS, FLAME_LAYER_SIDE,
    };
    let ramp = Ramp::from_keys(&FLAME_KEYS).unwrap();
    let n = (FLAME_LAYER_SIDE * FLAME_LAYER_SIDE) as usize;
    let (mut l0, mut l1) = (vec![0u16; n], vec![0u16; n]);
    bake_flame_layer(&FLAME_LAYERS[0], FLAME_LAYER_SIDE, &mut l0).unwrap();
    bake_flame_layer(&FLAME_LAYERS[1], FLAME_LAYER_SIDE, &mut l1).unwrap();
    let vp = Viewport::new(0, 0, noise::FLAME_W, noise::FLAME_H).unwrap();
    let mut px = Vec::new();
    let mut sum = scenes::Fnv1a::default();
    for i in 0..4 {
        let shader =
            BakedFlame::new(&ramp, &FLAME_LAYERS, [&l0, &l1], FLAME_LAYER_SIDE, i << 13).unwrap();
        let draw = ShadedDraw::<_, Exact, NoDepth>::new(shader, vp, Cull::None).unwrap();
        let mut color = vec![Rgb565::new(0, 0, 0); noise::FLAME_PIXELS];
        let mut frame = Frame::new(&mut color, noise::FLAME_W, noise::FLAME_H).unwrap();
        draw.clip_triangles(&flame_quad(), &mut frame).unwrap();
        sum.pixels(frame.pixels());
        px.extend(bits(frame.pixels()));
    }
    let mut band = Box::new([Rgb565::new(0, 0, 0); noise::FLAME_BAND_PIXELS]);
    let mut times = Vec::new();
    let mut pixels = 1;
    for _ in 0..runs {
        let t0 = Instant::now();
        let r = crate::flame_baked_scene::flame_baked_bands(
            &mut band,
            [&l0, &l1],
            4,
            &mut || {},
            &mut || {},
        )
        .unwrap();
        times.push(t0.elapsed().as_secs_f64());
        assert_eq!(r.checksum, sum.0, "baked flame frames differ");
        pixels = r.stats.pixels.max(1);
    }
    times.sort_by(f64::total_cmp);
    let cov = vec![true; px.len()];
    (
        px,
        cov,
        sum.0,
        times[times.len() / 2] * 1e9 / f64::from(pixels),
    )
}

/// The f64 flame from the baked layers' definition over the 4 frames, read at the nearest
/// texel centres as the draw reads them: raw RGB565 in order.
pub fn flame_baked_reference() -> Vec<u16> {
    use fixel::shading::noise::{FLAME_LAYERS, FLAME_LAYER_SIDE};
    use host_tests::reference::noise::{flame_layers, render_quad_with, LayerSampling};
    (0..4)
        .flat_map(|i| {
            let t = f64::from(i) / 8.0;
            render_quad_with(&flame_quad(), 1, noise::FLAME_W, noise::FLAME_H, |x, y| {
                flame_layers(
                    &FLAME_LAYERS,
                    x,
                    y,
                    t,
                    LayerSampling::Nearest(FLAME_LAYER_SIDE),
                )
            })
            .rgb565()
        })
        .collect()
}

/// The f64 flame over the 4 frames, `ss × ss` samples per pixel: raw RGB565 in order.
pub fn flame_reference(octaves: u32, ss: u32) -> Vec<u16> {
    (0..4)
        .flat_map(|i| {
            render_flame(
                &flame_quad(),
                f64::from(i) / 8.0,
                octaves,
                ss,
                noise::FLAME_W,
                noise::FLAME_H,
            )
            .rgb565()
        })
        .collect()
}

pub fn rgb8(px: &[u16]) -> Vec<u8> {
    px.iter()
        .flat_map(|&c| {
            let (r, g, b) = ((c >> 11) & 31, (c >> 5) & 63, c & 31);
            [
                ((r << 3) | (r >> 2)) as u8,
                ((g << 2) | (g >> 4)) as u8,
                ((b << 3) | (b >> 2)) as u8,
            ]
        })
        .collect()
}
