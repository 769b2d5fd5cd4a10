//! The flame from baked layers (`fixel::shading::noise::BakedFlame`, the
//! `noise_flame_baked` scene): the layers against their f64 definition (the tiled
//! turbulence at each texel's centre), the four frames of the flame firmware against the f64
//! flame of the same definition (nearest texel centres, then the point itself), against the
//! per-pixel flame (five octaves, time as the third noise axis) for scale, a golden, and
//! properties of the tiled noise.
//!
//! | what (80 x 96, t = 0, 1/8, 2/8, 3/8 s, two 64 x 64 layers) | measured |
//! |---|---|
//! | texels vs the f64 layers, Q15 | layer 0: mean 1.64, max 7.1 LSB; layer 1: 1.27 / 3.8 |
//! | frames vs f64 from nearest texel centres | mean 0.084, max 16 LSB, 41.5 dB |
//! | frames vs f64 at the point (the definition) | mean 0.199, max 9 LSB, 37.2 dB |
//! | frames vs the f64 per-pixel flame (5 octaves, 3D) | mean 1.62, max 47 LSB, 20.3 dB |
//!
//! The largest errors against the nearest-texel reference are single pixels on a texel
//! boundary, where the fixed-point scroll and the f64 one pick neighbouring texels. The
//! distance to the per-pixel flame is that of two definitions: the layers rise, where the
//! per-pixel flame also changes shape along its time axis.

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
use fixel::shading::noise::{
    bake_flame_layer, noise3, noise3_tiled, BakedFlame, Ramp, FLAME_KEYS, FLAME_LAYERS,
    FLAME_LAYER_SIDE,
};
use fixel::surface::Frame;
use host_tests::metrics::compare_rgb565;
use host_tests::reference::noise::{
    flame_layers, layer_turbulence, noise_tiled, render_flame, render_quad_with, LayerSampling,
};
use proptest::prelude::*;

mod common;

const W: u32 = 80;
const H: u32 = 96;
/// The flame firmware's quad corners, flame units (Q16): `x0, x1, y0, y1`.
const QUAD: (i32, i32, i32, i32) = (-85_197, 85_197, -6_554, 91_750);
/// The tiled noise's budget against the f64 one, Q15 LSBs: `noise3`'s (`tests/noise.rs`),
/// the same arithmetic.
const NOISE_BUDGET_LSB: f64 = 8.0;

fn layers() -> [Vec<u16>; 2] {
    let n = (FLAME_LAYER_SIDE * FLAME_LAYER_SIDE) as usize;
    core::array::from_fn(|l| {
        let mut t = vec![0u16; n];
        bake_flame_layer(&FLAME_LAYERS[l], FLAME_LAYER_SIDE, &mut t).unwrap();
        t
    })
}

fn quad() -> [[Vertex<2>; 3]; 2] {
    let (x0, x1, y0, y1) = QUAD;
    let v = |xn: i32, yn: i32, x: i32, y: i32| {
        Vertex::new(
            [Fx::from_num(xn), Fx::from_num(yn), Fx::ZERO, Fx::ONE],
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

/// fixel's four frames (t = i/8 s), raw RGB565 in order.
fn fixel_frames() -> Vec<u16> {
    let ramp = Ramp::from_keys(&FLAME_KEYS).unwrap();
    let [l0, l1] = layers();
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let mut px = Vec::new();
    for i in 0..4 {
        let shader =
            BakedFlame::new(&ramp, &FLAME_LAYERS, [&l0, &l1], FLAME_LAYER_SIDE, i << 13).unwrap();
        let draw = ShadedDraw::<_, Exact, NoDepth>::new(shader, vp, Cull::None).unwrap();
        let mut color = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        let mut frame = Frame::new(&mut color, W, H).unwrap();
        draw.clip_triangles(&quad(), &mut frame).unwrap();
        px.extend(frame.pixels().iter().map(|c| c.into_storage()));
    }
    px
}

/// The f64 frames of the flame from layers, sampled as `sampling` says.
fn reference_frames(sampling: LayerSampling) -> Vec<u16> {
    (0..4)
        .flat_map(|i| {
            let t = f64::from(i) / 8.0;
            render_quad_with(&quad(), 1, W, H, |x, y| {
                flame_layers(&FLAME_LAYERS, x, y, t, sampling)
            })
            .rgb565()
        })
        .collect()
}

/// Every texel of both layers against the f64 partial turbulence at its centre.
#[test]
fn layers_match_reference() {
    let side = FLAME_LAYER_SIDE;
    for (l, texels) in layers().iter().enumerate() {
        let layer = &FLAME_LAYERS[l];
        let texel = f64::from(1u32 << layer.period_log2) / f64::from(side);
        let (mut max, mut sum) = (0.0f64, 0.0);
        for (k, &t) in texels.iter().enumerate() {
            let (i, j) = ((k as u32 % side) as f64, (k as u32 / side) as f64);
            let want = layer_turbulence(layer, (i + 0.5) * texel, (j + 0.5) * texel) * 32768.0;
            let e = (f64::from(t) - want).abs();
            max = max.max(e);
            sum += e;
        }
        let mean = sum / texels.len() as f64;
        println!("flame layer {l} vs f64: mean {mean:.2}, max {max:.1} Q15 LSB");
        assert!(
            max <= 40.0 && mean <= 8.0,
            "layer {l}: max {max} mean {mean}"
        );
    }
}

/// The four frames against the f64 flame of the same definition: read at the nearest
/// texel's centre (what the draw does, so the error is the bake's and the colour
/// arithmetic's), and at the point itself; golden of all four frames.
#[test]
fn frames_match_reference() {
    let got = fixel_frames();
    let cov = vec![true; got.len()];
    let nearest = reference_frames(LayerSampling::Nearest(FLAME_LAYER_SIDE));
    let e = compare_rgb565(&got, &cov, &nearest, &cov);
    println!("baked flame vs f64 from nearest texel centres: {e}");
    let exact = reference_frames(LayerSampling::Continuous);
    let ec = compare_rgb565(&got, &cov, &exact, &cov);
    println!("baked flame vs f64 at the point: {ec}");
    assert!(e.mean <= 0.15 && e.psnr_db >= 39.0, "{e}");
    assert!(ec.mean <= 0.3 && ec.psnr_db >= 35.0, "{ec}");
    // The four frames stacked, one golden.
    host_tests::golden::assert_golden("noise_flame_baked", W, 4 * H, &got);
}

/// The baked flame against the f64 per-pixel flame (five octaves, time as the third noise
/// axis) at the same times: how far the layered definition is from the 3D one.
#[test]
fn frames_against_per_pixel_flame() {
    let got = fixel_frames();
    let cov = vec![true; got.len()];
    let want: Vec<u16> = (0..4)
        .flat_map(|i| render_flame(&quad(), f64::from(i) / 8.0, 5, 1, W, H).rgb565())
        .collect();
    let e = compare_rgb565(&got, &cov, &want, &cov);
    println!("baked flame vs f64 per-pixel flame: {e}");
    assert!(e.psnr_db >= 19.0, "{e}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(512), ..ProptestConfig::default() })]

    /// The tiled noise repeats every `2^p` cells in x and y, and is `noise3` at 256.
    #[test]
    fn tiled_noise_tiles(x in any::<i32>(), y in any::<i32>(), z in any::<i32>(), p in 0u32..=8, kx in -4i32..=4, ky in -4i32..=4) {
        let mask = (1u32 << p) - 1;
        let n = noise3_tiled(x, y, z, mask);
        let step = (1i32 << p).wrapping_shl(16);
        prop_assert_eq!(noise3_tiled(x.wrapping_add(step.wrapping_mul(kx)), y.wrapping_add(step.wrapping_mul(ky)), z, mask), n);
        prop_assert_eq!(noise3_tiled(x, y, z, 255), noise3(x, y, z));
    }

    /// The tiled noise against its f64 definition, anywhere in one tile.
    #[test]
    fn tiled_noise_matches_reference(x in 0i32..(16 << 16), y in 0i32..(16 << 16), z in -(1i32 << 24)..(1 << 24), p in 0u32..=4) {
        let got = f64::from(noise3_tiled(x, y, z, (1 << p) - 1)) / 32768.0;
        let c = |v: i32| f64::from(v) / 65536.0;
        let want = noise_tiled(c(x), c(y), c(z), 1 << p);
        prop_assert!((got - want).abs() <= NOISE_BUDGET_LSB / 32768.0, "{} {}", got, want);
    }

    /// The baked flame's colour exists for any point and time (no panic, no overflow).
    #[test]
    fn baked_flame_anywhere(x in any::<i32>(), y in any::<i32>(), t in any::<i32>()) {
        let ramp = Ramp::from_keys(&FLAME_KEYS).unwrap();
        let l = vec![u16::MAX; 16];
        let f = BakedFlame::new(&ramp, &FLAME_LAYERS, [&l, &l], 4, t).unwrap();
        let _ = f.color(x, y);
    }
}
