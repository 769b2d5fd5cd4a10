//! fixel's fixed-point Perlin noise and turbulence against the f64
//! reference (`host_tests::reference::noise`), with the hard cases: lattice
//! points, the varying limits, negative coordinates and the period boundary, continuity
//! across cells, and a view so distant that a pixel covers many cells.

use fixel::shading::noise::{
    noise3, turbulence, BandLimit, ABS_NOISE_MEAN_Q15, MAX_OCTAVES, PERIOD,
};
use host_tests::reference::noise::{
    abs_noise_mean, noise_bits, turbulence as ref_turb, RefOctaves,
};
use proptest::prelude::*;

/// Budget of `noise3` against the f64 noise, Q15 LSBs (1 LSB = 2^-15); measured 7.1.
const NOISE_BUDGET_LSB: f64 = 8.0;

/// The extremes' magnitude lies in this range (Q15); see `noise_extremes`.
const EXTREME_MIN: i32 = 30_000;
const EXTREME_MAX: i32 = 34_100;

/// A small deterministic generator (splitmix64).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn i32(&mut self) -> i32 {
        self.next() as i32
    }
    /// Within ±`cells` cells of 0.
    fn near(&mut self, cells: i32) -> i32 {
        ((self.next() % (2 * cells as u64 * 65536)) as i64 - i64::from(cells) * 65536) as i32
    }
}

fn err_lsb(x: i32, y: i32, z: i32) -> f64 {
    (f64::from(noise3(x, y, z)) - noise_bits(x, y, z) * 32768.0).abs()
}

#[test]
fn noise_within_budget_of_reference() {
    let mut rng = Rng(1);
    let (mut max, mut sum, n) = (0.0f64, 0.0, 200_000);
    for i in 0..n {
        let (x, y, z) = if i % 2 == 0 {
            (rng.near(8), rng.near(8), rng.near(8))
        } else {
            (rng.i32(), rng.i32(), rng.i32())
        };
        let e = err_lsb(x, y, z);
        max = max.max(e);
        sum += e;
    }
    println!(
        "noise3 vs f64: max {max:.2} LSB, mean {:.3} LSB (Q15)",
        sum / f64::from(n)
    );
    assert!(max <= NOISE_BUDGET_LSB, "max error {max} LSB");
}

/// Where the noise's extremes are: `noise3` at the centre of every one of the 256³ cells of
/// a period, then coordinate ascent (steps from 1/16 down to 1/65536 cell) from the 32
/// highest and 32 lowest. The extremes found are the documented range, and the f64 noise
/// agrees there.
#[test]
fn noise_extremes() {
    const HALF: i32 = 1 << 15;
    let mut hi: Vec<(i32, [i32; 3])> = Vec::new();
    let mut lo: Vec<(i32, [i32; 3])> = Vec::new();
    for x in 0..256 {
        for y in 0..256 {
            for z in 0..256 {
                let p = [(x << 16) + HALF, (y << 16) + HALF, (z << 16) + HALF];
                let n = noise3(p[0], p[1], p[2]);
                if n.abs() > 26_000 {
                    if n > 0 {
                        hi.push((n, p))
                    } else {
                        lo.push((n, p))
                    }
                }
            }
        }
    }
    hi.sort_by_key(|&(n, _)| -n);
    lo.sort_by_key(|&(n, _)| n);
    let climb = |mut p: [i32; 3], sign: i32| {
        let f = |p: [i32; 3]| sign * noise3(p[0], p[1], p[2]);
        let mut step = 4096;
        while step >= 1 {
            let mut moved = true;
            while moved {
                moved = false;
                for a in 0..3 {
                    for d in [-step, step] {
                        let mut q = p;
                        q[a] += d;
                        if f(q) > f(p) {
                            p = q;
                            moved = true;
                        }
                    }
                }
            }
            step /= 2;
        }
        p
    };
    let n3 = |p: &[i32; 3]| noise3(p[0], p[1], p[2]);
    let max_p = hi
        .iter()
        .take(32)
        .map(|&(_, p)| climb(p, 1))
        .max_by_key(n3)
        .unwrap();
    let min_p = lo
        .iter()
        .take(32)
        .map(|&(_, p)| climb(p, -1))
        .min_by_key(n3)
        .unwrap();
    let (max, min) = (n3(&max_p), n3(&min_p));
    let cells = |p: [i32; 3]| p.map(|c| f64::from(c) / 65536.0);
    println!(
        "noise3 extremes: max {max} ({:.4}) at {:?}, min {min} ({:.4}) at {:?}; f64 there: {:.4}, {:.4}",
        f64::from(max) / 32768.0,
        cells(max_p),
        f64::from(min) / 32768.0,
        cells(min_p),
        noise_bits(max_p[0], max_p[1], max_p[2]),
        noise_bits(min_p[0], min_p[1], min_p[2]),
    );
    assert!((EXTREME_MIN..=EXTREME_MAX).contains(&max), "max {max}");
    assert!((-EXTREME_MAX..=-EXTREME_MIN).contains(&min), "min {min}");
    assert!(err_lsb(max_p[0], max_p[1], max_p[2]) <= NOISE_BUDGET_LSB);
    assert!(err_lsb(min_p[0], min_p[1], min_p[2]) <= NOISE_BUDGET_LSB);
}

/// Hard case: every lattice point is a zero, up to the varying format's limits.
#[test]
fn lattice_points_are_exact_zeros() {
    let mut rng = Rng(3);
    let edges = [
        i32::MIN >> 16,
        (i32::MIN >> 16) + 1,
        -1,
        0,
        1,
        255,
        256,
        i32::MAX >> 16,
    ];
    for &x in &edges {
        for &y in &edges {
            for &z in &edges {
                assert_eq!(noise3(x << 16, y << 16, z << 16), 0, "({x}, {y}, {z})");
            }
        }
    }
    for _ in 0..10_000 {
        let (x, y, z) = (rng.i32() >> 16, rng.i32() >> 16, rng.i32() >> 16);
        assert_eq!(noise3(x << 16, y << 16, z << 16), 0);
        for k in 0..MAX_OCTAVES {
            assert_eq!(turbulence([x << 16, y << 16, z << 16], k), 0);
        }
    }
}

/// Hard case: coordinates at ±the varying limits. The noise has period 256 cells and
/// 2^32 raw units are 256 periods, so a shift by any multiple of the period, wrapping in
/// `i32`, gives bit-identical noise: near `i32::MIN` / `i32::MAX` as near the origin,
/// with no overflow; turbulence's octave shifts wrap the same way.
#[test]
fn varying_limits_give_the_same_noise_as_the_origin() {
    let mut rng = Rng(11);
    let period = PERIOD << 16;
    for _ in 0..50_000 {
        let p = [rng.near(2), rng.near(2), rng.near(2)];
        let n = noise3(p[0], p[1], p[2]);
        // The far copies: i32::MIN + p (exact multiple of the period away) and the top.
        let lo = p.map(|c| c.wrapping_add(i32::MIN));
        let hi = p.map(|c| c.wrapping_add(i32::MAX - period + 1));
        assert_eq!(noise3(lo[0], lo[1], lo[2]), n);
        assert_eq!(noise3(hi[0], hi[1], hi[2]), n);
        assert_eq!(turbulence(lo, 6), turbulence(p, 6));
        assert_eq!(turbulence(hi, 6), turbulence(p, 6));
        // And the f64 noise agrees at the true (unwrapped) far point.
        let far = noise_bits(lo[0], lo[1], lo[2]) * 32768.0;
        assert!((far - f64::from(n)).abs() <= NOISE_BUDGET_LSB);
    }
}

/// Mean, variance and a spectral figure (mean squared difference at lags of 1/8, 1/2 and
/// 2 cells, the structure function: the spectrum's integral transform) of `noise3` on
/// 2^16 points in a 16-cell box at the origin and in boxes at the varying limits.
#[test]
fn statistics_far_from_the_origin_match_the_origin() {
    let stats = |base: [i32; 3]| {
        let mut rng = Rng(5);
        let (mut s, mut s2) = (0.0, 0.0);
        let mut sf = [0.0; 3];
        let n = 1 << 16;
        for _ in 0..n {
            let p = [0, 1, 2].map(|a| base[a].wrapping_add(rng.near(8)));
            let v = f64::from(noise3(p[0], p[1], p[2])) / 32768.0;
            s += v;
            s2 += v * v;
            for (k, lag) in [8192, 32768, 131072].into_iter().enumerate() {
                let w = f64::from(noise3(p[0].wrapping_add(lag), p[1], p[2])) / 32768.0;
                sf[k] += (w - v) * (w - v);
            }
        }
        let n = f64::from(n);
        (s / n, s2 / n - (s / n) * (s / n), sf.map(|x| x / n))
    };
    let origin = stats([0, 0, 0]);
    println!(
        "origin: mean {:.4} var {:.4} structure {:?}",
        origin.0, origin.1, origin.2
    );
    for base in [
        [i32::MAX - (16 << 16); 3],
        [i32::MIN + (16 << 16); 3],
        [0x4000_0123, -0x3FFF_F00F, 0x7000_0000],
    ] {
        let far = stats(base);
        println!(
            "{base:?}: mean {:.4} var {:.4} structure {:?}",
            far.0, far.1, far.2
        );
        assert!((far.0 - origin.0).abs() < 0.01, "mean");
        assert!((far.1 / origin.1 - 1.0).abs() < 0.05, "variance");
        for k in 0..3 {
            assert!(
                (far.2[k] / origin.2[k] - 1.0).abs() < 0.05,
                "structure at lag {k}"
            );
        }
    }
    assert!(origin.0.abs() < 0.01);
}

/// Hard case: negative coordinates and the period boundary. `noise3` floors negative
/// coordinates (arithmetic shift) as the f64 `floor` does, so it matches the reference
/// there, and it is continuous across 0 and ±256 cells (the wrap of the permutation).
#[test]
fn negative_coordinates_and_the_period_boundary() {
    let mut rng = Rng(13);
    for _ in 0..50_000 {
        let p = [-rng.near(300).abs(), -rng.near(300).abs(), rng.near(300)];
        assert!(err_lsb(p[0], p[1], p[2]) <= NOISE_BUDGET_LSB, "{p:?}");
    }
    for b in [0, 256 << 16, -256 << 16, 255 << 16, -1 << 16] {
        for _ in 0..2_000 {
            let (y, z) = (rng.near(4), rng.near(4));
            let jump = (noise3(b, y, z) - noise3(b - 1, y, z)).abs();
            assert!(jump <= 4, "jump {jump} at x = {b}");
        }
    }
}

/// Hard case: continuity across lattice cells. At a cell face the value may jump by at
/// most 4 Q15 LSBs between neighbouring inputs (1/65536 cell apart), and the one-sided
/// slopes over 1/256 cell (f64 noise: C², so no jump) differ by at most 24 LSB per 1/256
/// cell (the slope itself is up to ~4000 LSB per 1/256 cell: the kink is within 0.6 %).
#[test]
fn continuity_across_cells() {
    let mut rng = Rng(17);
    let (mut worst_jump, mut worst_kink) = (0, 0);
    for _ in 0..20_000 {
        let face = (rng.i32() >> 16) << 16;
        let (y, z) = (rng.near(50), rng.near(50));
        for axis in 0..3 {
            let at = |x: i32| {
                let mut p = [y, z, y ^ z];
                p[axis] = x;
                noise3(p[0], p[1], p[2])
            };
            let h = 256;
            let jump = (at(face) - at(face - 1)).abs();
            let left = at(face) - at(face - h);
            let right = at(face + h) - at(face);
            worst_jump = worst_jump.max(jump);
            worst_kink = worst_kink.max((right - left).abs());
        }
    }
    println!("across cell faces: value jump {worst_jump} LSB, slope change {worst_kink} LSB per 1/256 cell");
    assert!(worst_jump <= 4);
    assert!(worst_kink <= 24);
}

/// [`ABS_NOISE_MEAN_Q15`], the mean of `|noise|` band-limiting substitutes for dropped
/// octaves, is the f64 reference's measured mean within 1 %.
#[test]
fn abs_noise_mean_constant() {
    let m = abs_noise_mean() * 32768.0;
    println!("mean |noise|: f64 {m:.1} (Q15), constant {ABS_NOISE_MEAN_Q15}");
    assert!((f64::from(ABS_NOISE_MEAN_Q15) - m).abs() < 0.01 * m);
}

/// Turbulence of 1 to 8 octaves against the f64 sum: each octave adds at most one noise
/// budget (scaled by 2^-k) plus one LSB of truncation.
#[test]
fn turbulence_within_budget_of_reference() {
    let mut rng = Rng(19);
    for k in 1..=MAX_OCTAVES {
        let mut max = 0.0f64;
        for _ in 0..20_000 {
            let p = [rng.near(20), rng.near(20), rng.i32()];
            let r =
                ref_turb(p.map(|c| f64::from(c) / 65536.0), RefOctaves::Fixed(k), 0.0) * 32768.0;
            max = max.max((f64::from(turbulence(p, k)) - r).abs());
        }
        println!("turbulence {k} octaves: max {max:.2} LSB");
        assert!(
            max <= 2.0 * NOISE_BUDGET_LSB + f64::from(k),
            "{k} octaves: {max}"
        );
    }
}

/// Band-limited turbulence: the weights follow the seeds' truncation, and a pixel that
/// covers many cells gets exactly the mean, whatever the point (a view so distant that
/// one pixel covers many lattice cells: the mean, not noise).
#[test]
fn band_limit_goes_to_the_mean_when_distant() {
    let b = BandLimit::new(6);
    let tail: i32 = (0..6).map(|k| ABS_NOISE_MEAN_Q15 >> k).sum();
    let mut rng = Rng(23);
    for _ in 0..10_000 {
        let p = [rng.i32(), rng.i32(), rng.i32()];
        for lambda in [256, 1000, 5 * 256, i32::MAX] {
            assert_eq!(b.turbulence(p, lambda), tail);
        }
        // Footprint of 1/64 cell: all six octaves at full weight, as the fixed sum.
        assert_eq!(b.turbulence(p, -6 * 256), turbulence(p, 6));
        assert_eq!(b.turbulence(p, i32::MIN), turbulence(p, 6));
    }
    // The seeds' rule: at a footprint of 2^-m cells, octaves 0..=m are summed in full.
    for m in 0..5 {
        let lambda = -(m << 8);
        for k in 0..6u32 {
            let w = b.weight(lambda, k);
            assert_eq!(w, if k as i32 <= m { 256 } else { 0 }, "m {m} k {k}");
        }
    }
}

proptest! {
    /// Any i32 point: noise within budget of the f64 noise and inside the measured range.
    #[test]
    fn noise_anywhere(x in any::<i32>(), y in any::<i32>(), z in any::<i32>()) {
        prop_assert!(err_lsb(x, y, z) <= NOISE_BUDGET_LSB);
        prop_assert!(noise3(x, y, z).abs() <= EXTREME_MAX);
    }

    /// Any point and footprint: band-limited turbulence in 0..2.0 and between the fixed
    /// sums' envelope and the mean.
    #[test]
    fn band_turbulence_anywhere(x in any::<i32>(), y in any::<i32>(), z in any::<i32>(), lambda in any::<i32>(), max in 1u8..=8) {
        let t = BandLimit::new(max).turbulence([x, y, z], lambda);
        prop_assert!((0..65_536).contains(&t));
    }
}
