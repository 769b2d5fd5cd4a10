//! The per-triangle modes of [`Shadowed`]: a triangle wholly inside a directional light's
//! frustum skips the per-pixel frustum test (and, in its own shade, the map), with the same
//! lit fraction at every pixel as the general path.

use super::*;
use crate::shading::pcf::{Pcf2x2, Pcf3x3, SingleTap};
use crate::shading::Flat;
use crate::test_rng::Rng;

/// A map of side 64 with random depths in blocks (edges inside the map), and random
/// single texels.
fn random_map(rng: &mut Rng) -> [u16; 64 * 64] {
    let mut t = [0u16; 64 * 64];
    let block = 1 + (rng.next() % 8) as usize;
    let mut level = 0u16;
    for (i, v) in t.iter_mut().enumerate() {
        if i.is_multiple_of(block) || rng.next().is_multiple_of(5) {
            level = (rng.next() >> 48) as u16;
        }
        *v = level;
    }
    t
}

/// `v` with differences from `base` where the span loop leaves them (the light varyings
/// after the inner shader's, here after none).
fn rebased(p: [i32; 3], base: [i32; 4]) -> [i32; 3] {
    [0, 1, 2].map(|k| p[k].wrapping_sub(base[k]))
}

fn check<F: ShadowFilter>(seed: u64, rounds: usize) -> [usize; 3] {
    let mut rng = Rng(seed);
    let mut modes = [0usize; 3];
    for _ in 0..rounds {
        let texels = random_map(&mut rng);
        let map = ShadowMap::new(&texels, 64).unwrap();
        let bias = Bias {
            constant: (rng.next() % 64) as i32,
            slope: (rng.next() % 512) as i32,
            max: (rng.next() % 100_000) as i32,
        };
        // Dark 0 and a white flat colour: the colour's green is `lit * 63 / 256` rounded.
        let shader = Shadowed::<_, Directional, F, 3>::new(Flat(0xFFFF), map, bias)
            .unwrap()
            .with_darkness(0)
            .unwrap();
        // Vertices mostly inside the frustum, some near or past its edges.
        let coord = |rng: &mut Rng, hi: i32| {
            let span = i64::from(hi) + 8192;
            ((rng.next() % span as u64) as i64 - 4096) as i32
        };
        let mut v: [[i32; 3]; 3] = core::array::from_fn(|_| {
            [
                coord(&mut rng, ST_ONE),
                coord(&mut rng, ST_ONE),
                coord(&mut rng, 65535 * DEPTH_STEP),
            ]
        });
        let original = v;
        let tri = shader.triangle(&mut v);
        let st = tri.1;
        modes[usize::from(st.mode)] += 1;
        let general = ShadowTriangle {
            mode: GENERAL,
            ..st
        };
        for _ in 0..32 {
            // A point of the triangle (barycentric weights in 1/1024), off by the
            // interpolation's rounding (a few units).
            let (a, b) = ((rng.next() % 1025) as i64, (rng.next() % 1025) as i64);
            let (a, b) = if a + b > 1024 {
                (1024 - a, 1024 - b)
            } else {
                (a, b)
            };
            let p: [i32; 3] = core::array::from_fn(|k| {
                let w = i64::from(original[0][k]) * (1024 - a - b)
                    + i64::from(original[1][k]) * a
                    + i64::from(original[2][k]) * b;
                (w / 1024) as i32 + (rng.next() % 33) as i32 - 16
            });
            let varyings = rebased(p, st.base);
            let frag = |t: ShadowTriangle| Fragment {
                varyings,
                x: 0,
                y: 0,
                depth: 0,
                lambda: 0,
                triangle: ((), t),
            };
            assert_eq!(
                shader.shade(&frag(st)),
                shader.shade(&frag(general)),
                "{} mode {} vertices {original:?} point {p:?} bias {bias:?}",
                F::NAME,
                st.mode
            );
        }
    }
    modes
}

/// At random points of random triangles over random maps, each filter's lit fraction in
/// the per-triangle mode (lookup without the frustum test, or own shade without the map)
/// is the general path's.
#[test]
fn triangle_modes_shade_as_the_general_path() {
    let rounds = 4000;
    for modes in [
        check::<SingleTap>(0x9E37_79B9_7F4A_7C15, rounds),
        check::<Pcf2x2>(0xD1B5_4A32_D192_ED03, rounds),
        check::<Pcf3x3>(0x8CB9_2BA7_2F3D_8DD7, rounds),
    ] {
        // Each mode is reached often.
        assert!(modes.iter().all(|&m| m > rounds / 20), "{modes:?}");
    }
}

/// A triangle facing the light takes the lookup; the same triangle turned away, its own
/// shade; a triangle with a vertex outside the map, or a bias too large to fold into the
/// depth, the general path.
#[test]
fn triangle_mode_of_each_case() {
    let texels = [u16::MAX; 16 * 16];
    let map = ShadowMap::new(&texels, 16).unwrap();
    let mode = |bias: Bias, v: [[i32; 3]; 3]| {
        let shader =
            Shadowed::<_, Directional, SingleTap, 3>::new(Flat(0xFFFF), map, bias).unwrap();
        shader.triangle(&mut v.clone()).1.mode
    };
    let h = ST_ONE / 2;
    let d = 30_000 * DEPTH_STEP;
    // Counter-clockwise in GL's clip space (t points down): faces the light.
    let front = [[h, h, d], [h, h - 1000, d], [h - 1000, h, d]];
    let back = [front[0], front[2], front[1]];
    let b = Bias::for_filter::<SingleTap>();
    assert_eq!(mode(b, front), LOOKUP);
    assert_eq!(mode(b, back), IN_SHADE);
    let mut out = front;
    out[1][0] = ST_ONE + 5;
    assert_eq!(mode(b, out), GENERAL);
    let mut edge = front;
    edge[2][1] = INSIDE_MARGIN - 1;
    assert_eq!(mode(b, edge), GENERAL);
    let huge = Bias {
        constant: i32::MAX,
        ..b
    };
    assert_eq!(mode(huge, front), GENERAL);
}
