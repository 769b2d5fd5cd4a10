extern crate std;
use super::blend::*;
use super::*;
use crate::color::rgb565;
use crate::texture::wrap::{ClampToBorder, ClampToEdge, DynWrap, MirroredRepeat, Repeat, Wrap};
use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use std::vec::Vec;
use std::{println, vec};

struct Rng(u32);
impl Rng {
    fn next(&mut self) -> u32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        self.0
    }
}

fn raw_tex(raws: &[u16]) -> Vec<Rgb565> {
    raws.iter().map(|&r| Rgb565::from(RawU16::new(r))).collect()
}

fn chans(t: u16) -> [f64; 3] {
    [(t >> 11) as f64, ((t >> 5) & 63) as f64, (t & 31) as f64]
}

/// Independent reference texel fetch: i64 indices, spec formulas with `rem_euclid`.
fn ref_texel(tex: &Texture<'_>, mode: [Wrap; 2], i: i64, j: i64) -> [f64; 3] {
    let wrap = |m: Wrap, i: i64, size: i64| -> Option<i64> {
        match m {
            Wrap::Repeat => Some(i.rem_euclid(size)),
            Wrap::MirroredRepeat => {
                let a = i.rem_euclid(2 * size) - size;
                Some((size - 1) - if a >= 0 { a } else { -(1 + a) })
            }
            Wrap::ClampToEdge => Some(i.clamp(0, size - 1)),
            Wrap::ClampToBorder => (0..size).contains(&i).then_some(i),
        }
    };
    let (w, h) = (tex.width() as i64, tex.height() as i64);
    match (wrap(mode[0], i, w), wrap(mode[1], j, h)) {
        (Some(i), Some(j)) => {
            let idx = (j * w + i) as usize;
            chans(tex.texels()[idx].into_storage())
        }
        _ => chans(tex.border_raw()),
    }
}

/// Independent float reference of the whole bilinear sample.
fn reference_bilinear(tex: &Texture<'_>, mode: [Wrap; 2], u: i32, v: i32) -> [f64; 3] {
    let uf = u as f64 / 65536.0 - 0.5;
    let vf = v as f64 / 65536.0 - 0.5;
    let (i0, j0) = (uf.floor() as i64, vf.floor() as i64);
    let (a, b) = (uf - uf.floor(), vf - vf.floor());
    let texel = |i: i64, j: i64| ref_texel(tex, mode, i, j);
    let (c00, c10, c01, c11) = (
        texel(i0, j0),
        texel(i0 + 1, j0),
        texel(i0, j0 + 1),
        texel(i0 + 1, j0 + 1),
    );
    let mut out = [0.0; 3];
    for k in 0..3 {
        out[k] = (1.0 - a) * (1.0 - b) * c00[k]
            + a * (1.0 - b) * c10[k]
            + (1.0 - a) * b * c01[k]
            + a * b * c11[k];
    }
    out
}

fn random_tex(rng: &mut Rng, w: u32, h: u32) -> Vec<Rgb565> {
    (0..w * h)
        .map(|_| Rgb565::from(RawU16::new(rng.next() as u16)))
        .collect()
}

/// Error statistics of one sampler against the float reference.
#[derive(Default)]
struct Stats {
    n: u64,
    max_abs: [f64; 3],
    // |fast - round(exact)| histogram: 0, 1, 2, >=3 LSB, per channel.
    hist: [[u64; 4]; 3],
    // |fast - exact| (unrounded) histogram in quarter-LSB bins up to 2 LSB, per channel.
    bins: [[u64; 9]; 3],
}

impl Stats {
    fn add(&mut self, got: u16, exact: [f64; 3]) {
        self.n += 1;
        let g = chans(got);
        for k in 0..3 {
            let e = (g[k] - exact[k]).abs();
            if e > self.max_abs[k] {
                self.max_abs[k] = e;
            }
            let r = (g[k] - (exact[k] + 0.5).floor()).abs() as usize;
            self.hist[k][r.min(3)] += 1;
            self.bins[k][((e * 4.0) as usize).min(8)] += 1;
        }
    }
    fn print(&self, name: &str) {
        println!("{name}: {} samples", self.n);
        for (k, ch) in ["R", "G", "B"].iter().enumerate() {
            println!(
                "  {ch}: max|got-exact| = {:.4} LSB; |got-round(exact)| 0:{} 1:{} 2:{} >=3:{}; \
                 |got-exact| quarter-LSB bins {:?}",
                self.max_abs[k],
                self.hist[k][0],
                self.hist[k][1],
                self.hist[k][2],
                self.hist[k][3],
                self.bins[k]
            );
        }
    }
    fn within_one(&self) -> f64 {
        let ok: u64 = (0..3).map(|k| self.hist[k][0] + self.hist[k][1]).sum();
        ok as f64 / (3 * self.n) as f64
    }
}

fn measure(samples: usize) -> (Stats, Stats) {
    let mut rng = Rng(0xDEAD_BEEF);
    let (mut acc, mut fast) = (Stats::default(), Stats::default());
    for &(w, h) in &[(8u32, 8u32), (16, 4), (1, 8), (8, 1), (32, 32)] {
        let texels = random_tex(&mut rng, w, h);
        let tex = Texture::new(&texels, w, h).unwrap().with_border_raw(0xFFFF);
        for _ in 0..samples {
            let u = (rng.next() % ((3 * w) << 16)) as i32 - (w << 16) as i32;
            let v = (rng.next() % ((3 * h) << 16)) as i32 - (h << 16) as i32;
            let exact = reference_bilinear(&tex, [Wrap::Repeat, Wrap::Repeat], u, v);
            acc.add(Bilinear::sample(&tex, Repeat, Repeat, u, v), exact);
            fast.add(BilinearFast::sample(&tex, Repeat, Repeat, u, v), exact);
        }
    }
    (acc, fast)
}

#[test]
fn bilinear_error_distribution() {
    let (acc, fast) = measure(200_000);
    acc.print("Bilinear (Q8 four-weight, 9 mul)");
    fast.print("BilinearFast (Q5 packed lerps, 6 mul)");
    println!(
        "within 1 LSB of round(exact): accurate {:.6}, fast {:.6}",
        acc.within_one(),
        fast.within_one()
    );
    for k in 0..3 {
        // Never more than 1 LSB from the exact value rounded to nearest.
        assert_eq!(acc.hist[k][2] + acc.hist[k][3], 0, "channel {k}");
        assert!(acc.max_abs[k] < 1.0, "channel {k}: {}", acc.max_abs[k]);
    }
    assert!(acc.within_one() >= 0.995);
}

/// Worst cases that random sampling may miss: extreme texel pairs at every Q16 fraction
/// step of 16 (all 4096 alpha x a set of betas).
#[test]
fn bilinear_worst_case_sweep() {
    let pairs: [[u16; 4]; 4] = [
        [0x0000, 0xFFFF, 0xFFFF, 0x0000],
        [0xFFFF, 0x0000, 0x0000, 0xFFFF],
        [0x0000, 0x0000, 0x0000, 0xFFFF],
        [0xFFFF, 0xFFFF, 0xFFFF, 0x0000],
    ];
    for p in pairs {
        let texels = raw_tex(&p);
        let tex = Texture::new(&texels, 2, 2).unwrap();
        for fu in (0..0x10000).step_by(16) {
            for fv in (0..0x10000).step_by(1021) {
                // Sample point inside the 2x2 block: u = 0.5 + frac.
                let (u, v) = (0x8000 + fu, 0x8000 + fv);
                let exact = reference_bilinear(&tex, [Wrap::Repeat, Wrap::Repeat], u, v);
                let got = chans(Bilinear::sample(&tex, Repeat, Repeat, u, v));
                for k in 0..3 {
                    assert!(
                        (got[k] - exact[k]).abs() < 1.0,
                        "{p:?} fu {fu} fv {fv} ch {k}: {} vs {}",
                        got[k],
                        exact[k]
                    );
                }
            }
        }
    }
}

#[test]
fn blend_q8_exhaustive_weights_extremes() {
    // Every Q8 (a, b) with the hardest texels: results never leave the channel range and
    // are within 1 LSB of exact.
    let sets: [[u16; 4]; 3] = [
        [0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF],
        [0x0000, 0xFFFF, 0xFFFF, 0x0000],
        [0xF81F, 0x07E0, 0x07E0, 0xF81F],
    ];
    for c in sets {
        for a in 0..=256u32 {
            for b in 0..=256u32 {
                let got = chans(blend_q8(c, a, b));
                let (af, bf) = (a as f64 / 256.0, b as f64 / 256.0);
                let cs: Vec<[f64; 3]> = c.iter().map(|&t| chans(t)).collect();
                for k in 0..3 {
                    let e = (1.0 - af) * (1.0 - bf) * cs[0][k]
                        + af * (1.0 - bf) * cs[1][k]
                        + (1.0 - af) * bf * cs[2][k]
                        + af * bf * cs[3][k];
                    assert!((got[k] - e).abs() < 1.0, "{c:?} {a} {b} {k}");
                }
            }
        }
        assert_eq!(blend_q8(c, 0, 0), c[0]);
        assert_eq!(blend_q8(c, 256, 0), c[1]);
        assert_eq!(blend_q8(c, 0, 256), c[2]);
        assert_eq!(blend_q8(c, 256, 256), c[3]);
    }
}

#[test]
fn texel_centres_are_exact() {
    let mut rng = Rng(42);
    let (w, h) = (8u32, 4u32);
    let texels = random_tex(&mut rng, w, h);
    let tex = Texture::new(&texels, w, h).unwrap();
    for j in 0..h {
        for i in 0..w {
            let want = tex.texel_raw(i, j);
            let (u, v) = (((i << 16) + 0x8000) as i32, ((j << 16) + 0x8000) as i32);
            assert_eq!(Nearest::sample(&tex, Repeat, Repeat, u, v), want);
            assert_eq!(Bilinear::sample(&tex, Repeat, Repeat, u, v), want);
            assert_eq!(BilinearFast::sample(&tex, Repeat, Repeat, u, v), want);
            // Nearest anywhere inside the texel.
            for (du, dv) in [(0, 0), (0xFFFF, 0xFFFF), (1, 0x7FFF)] {
                let (u, v) = (((i << 16) + du) as i32, ((j << 16) + dv) as i32);
                assert_eq!(Nearest::sample(&tex, Repeat, Repeat, u, v), want);
            }
            // Same texel one tile away, negative side.
            let (u, v) = (u - (w << 16) as i32, v - ((3 * h) << 16) as i32);
            assert_eq!(Nearest::sample(&tex, Repeat, Repeat, u, v), want);
            assert_eq!(Bilinear::sample(&tex, Repeat, Repeat, u, v), want);
        }
    }
}

#[test]
fn bilinear_halfway() {
    // Two texels side by side, sample exactly between their centres: round half up of
    // the average per channel.
    let mut rng = Rng(7);
    for _ in 0..2000 {
        let (a, b) = (rng.next() as u16, rng.next() as u16);
        let texels = raw_tex(&[a, b]);
        let tex = Texture::new(&texels, 2, 1).unwrap();
        let got = Bilinear::sample(&tex, ClampToEdge, ClampToEdge, 0x10000, 0x8000);
        let (ca, cb) = (chans(a), chans(b));
        let want = rgb565(
            ((ca[0] + cb[0] + 1.0) / 2.0).floor() as u8,
            ((ca[1] + cb[1] + 1.0) / 2.0).floor() as u8,
            ((ca[2] + cb[2] + 1.0) / 2.0).floor() as u8,
        );
        assert_eq!(got, want, "{a:#06x} {b:#06x}");
        // Vertical pair (1x2) likewise.
        let tex = Texture::new(&texels, 1, 2).unwrap();
        let got = Bilinear::sample(&tex, ClampToEdge, ClampToEdge, 0x8000, 0x10000);
        assert_eq!(got, want);
    }
    // Quarter way between black and white red channel: 31 * 0.25 = 7.75 -> 8.
    let texels = raw_tex(&[0x0000, 0xF800]);
    let tex = Texture::new(&texels, 2, 1).unwrap();
    let got = Bilinear::sample(&tex, ClampToEdge, ClampToEdge, 0x8000 + 0x4000, 0x8000);
    assert_eq!(got, rgb565(8, 0, 0));
}

#[test]
fn thin_textures() {
    let row = raw_tex(&[1, 2, 3, 4, 5, 6, 7, 8]);
    let wide = Texture::new(&row, 8, 1).unwrap();
    let tall = Texture::new(&row, 1, 8).unwrap();
    let one = Texture::new(&row[..1], 1, 1).unwrap();
    let mut rng = Rng(99);
    for k in 0..8i32 {
        let c = (k << 16) + 0x8000;
        let any = rng.next() as i32;
        assert_eq!(Nearest::sample(&wide, Repeat, Repeat, c, any), row_raw(k));
        assert_eq!(Bilinear::sample(&wide, Repeat, Repeat, c, any), row_raw(k));
        assert_eq!(Nearest::sample(&tall, Repeat, Repeat, any, c), row_raw(k));
        assert_eq!(Bilinear::sample(&tall, Repeat, Repeat, any, c), row_raw(k));
    }
    for _ in 0..1000 {
        let (u, v) = (rng.next() as i32, rng.next() as i32);
        assert_eq!(Nearest::sample(&one, Repeat, MirroredRepeat, u, v), 1);
        assert_eq!(Bilinear::sample(&one, ClampToEdge, Repeat, u, v), 1);
    }
    // 1x1 with border: inside [0,1)^2 nearest is the texel, outside the border.
    let one = one.with_border_raw(0xFFFF);
    assert_eq!(
        Nearest::sample(&one, ClampToBorder, ClampToBorder, 0, 0xFFFF),
        1
    );
    assert_eq!(
        Nearest::sample(&one, ClampToBorder, ClampToBorder, -1, 0),
        0xFFFF
    );
    assert_eq!(
        Nearest::sample(&one, ClampToBorder, ClampToBorder, 0, 0x10000),
        0xFFFF
    );

    fn row_raw(k: i32) -> u16 {
        k as u16 + 1
    }
}

#[test]
fn border_colour() {
    let texels = raw_tex(&[0x0000; 16]);
    let tex = Texture::new(&texels, 4, 4)
        .unwrap()
        .with_border(Rgb565::new(31, 0, 31));
    let border = rgb565(31, 0, 31);
    let b = ClampToBorder;
    for (u, v) in [
        (-1, 0),
        (0, -1),
        (4 << 16, 0),
        (0, 4 << 16),
        (i32::MIN, i32::MAX),
    ] {
        assert_eq!(Nearest::sample(&tex, b, b, u, v), border, "{u} {v}");
    }
    // Only one axis clamps to border: the other repeats.
    assert_eq!(Nearest::sample(&tex, Repeat, b, -1, 0), 0);
    assert_eq!(Nearest::sample(&tex, b, Repeat, -1, 0), border);
    // Bilinear at the left edge (u = 0): half texel, half border.
    let got = Bilinear::sample(&tex, b, b, 0, 0x8000);
    assert_eq!(got, rgb565(16, 0, 16));
    // At a corner: a quarter texel, three quarters border: 31 * 0.75 = 23.25 -> 23.
    let got = Bilinear::sample(&tex, b, b, 0, 0);
    assert_eq!(got, rgb565(23, 0, 23));
    // Far outside: all border.
    assert_eq!(Bilinear::sample(&tex, b, b, -(10 << 16), 0x8000), border);
    // Inside at centres: no border bleed.
    assert_eq!(Bilinear::sample(&tex, b, b, 0x8000, 0x8000), 0);
}

#[test]
fn all_modes_match_reference_any_input() {
    let mut rng = Rng(0x5EED);
    let modes = [
        Wrap::Repeat,
        Wrap::MirroredRepeat,
        Wrap::ClampToEdge,
        Wrap::ClampToBorder,
    ];
    let extremes = [
        i32::MIN,
        i32::MIN + 1,
        -1,
        0,
        1,
        0x7FFF,
        0x8000,
        i32::MAX - 1,
        i32::MAX,
    ];
    for &(w, h) in &[(1u32, 1u32), (1, 8), (8, 1), (4, 16), (32, 2)] {
        let texels = random_tex(&mut rng, w, h);
        let tex = Texture::new(&texels, w, h).unwrap().with_border_raw(0x1234);
        for mu in modes {
            for mv in modes {
                let mut coords: Vec<(i32, i32)> = vec![];
                for &a in &extremes {
                    for &b in &extremes {
                        coords.push((a, b));
                    }
                }
                for _ in 0..2000 {
                    coords.push((rng.next() as i32, rng.next() as i32));
                    // Near the texture: within +-8 tiles.
                    let nu = (rng.next() % (w << 20)) as i32 - (w << 19) as i32;
                    let nv = (rng.next() % (h << 20)) as i32 - (h << 19) as i32;
                    coords.push((nu, nv));
                }
                for (u, v) in coords {
                    let exact = reference_bilinear(&tex, [mu, mv], u, v);
                    let got = chans(tex.sample_dyn(Filter::Bilinear, mu, mv, u, v));
                    for k in 0..3 {
                        assert!(
                            (got[k] - exact[k]).abs() < 1.0,
                            "{mu:?}/{mv:?} {w}x{h} u {u} v {v}"
                        );
                    }
                    // Nearest: the texel containing (u, v), floor in f64.
                    let iu = (u as f64 / 65536.0).floor() as i64;
                    let iv = (v as f64 / 65536.0).floor() as i64;
                    let want = ref_texel(&tex, [mu, mv], iu, iv);
                    let got = chans(tex.sample_dyn(Filter::Nearest, mu, mv, u, v));
                    assert_eq!(got, want, "nearest {mu:?}/{mv:?} u {u} v {v}");
                }
            }
        }
    }
}

#[test]
fn dyn_matches_markers() {
    let mut rng = Rng(3);
    let texels = random_tex(&mut rng, 16, 8);
    let tex = Texture::new(&texels, 16, 8)
        .unwrap()
        .with_border_raw(0xABCD);
    for _ in 0..20_000 {
        let (u, v) = (
            (rng.next() % (64 << 16)) as i32 - (32 << 16),
            (rng.next() % (32 << 16)) as i32 - (16 << 16),
        );
        assert_eq!(
            tex.sample_dyn(
                Filter::Bilinear,
                Wrap::MirroredRepeat,
                Wrap::ClampToBorder,
                u,
                v
            ),
            Bilinear::sample(&tex, MirroredRepeat, ClampToBorder, u, v)
        );
        assert_eq!(
            tex.sample_dyn(Filter::Nearest, Wrap::ClampToEdge, Wrap::Repeat, u, v),
            Nearest::sample(&tex, DynWrap(Wrap::ClampToEdge), Repeat, u, v)
        );
    }
    assert_eq!(Nearest::FILTER, Filter::Nearest);
    assert_eq!(Bilinear::FILTER, Filter::Bilinear);
    assert_eq!(Filter::default(), Filter::Nearest);
}

/// The packed weights are the four Q8 weights packed, for every pair of fractions.
#[test]
fn packed_weights_match_the_four_weights() {
    for a in 0..=256 {
        for b in 0..=256 {
            let w = q8_weights(a, b);
            assert_eq!(
                packed_q8_weights(a, b),
                (w[1] | w[0] << 16, w[3] | w[2] << 16),
                "a = {a}, b = {b}"
            );
        }
    }
}

/// The two- and four-texels-per-multiply blends equal the per-texel form on every texel
/// and weight set, unscaled and scaled alike.
#[test]
fn blend_pair_form_matches_per_texel_form() {
    let mut rng = Rng(0x2545_F491);
    for _ in 0..200_000 {
        let c = [0; 4].map(|_: u16| rng.next() as u16);
        let a = rng.next() % 257;
        let b = rng.next() % 257;
        let i = rng.next() % 257;
        let w11 = (a * b + 128) >> 8;
        let w = [256 + w11 - a - b, a - w11, b - w11, w11];
        let ai = (a * i + 128) >> 8;
        let bi = (b * i + 128) >> 8;
        let w11 = (a * b * i + 32768) >> 16;
        let ws = [(i + w11).saturating_sub(ai + bi), ai - w11, bi - w11, w11];
        for w in [w, ws] {
            let want = blend_weights_masks(c, w);
            assert_eq!(blend_pairs_u32(c, w, Round), want);
            assert_eq!(blend_pairs_u64(c, w, Round), want);
            assert_eq!(
                blend_pairs_u32(c, w, Scale(i)),
                blend_pairs_u64(c, w, Scale(i))
            );
        }
    }
    for c in [[0xFFFF; 4], [0; 4], [0xF800, 0x07E0, 0x001F, 0xFFFF]] {
        for w in [[256, 0, 0, 0], [64; 4], [0, 0, 0, 256], [255, 1, 0, 0]] {
            let want = blend_weights_masks(c, w);
            assert_eq!(blend_pairs_u32(c, w, Round), want);
            assert_eq!(blend_pairs_u64(c, w, Round), want);
            for i in [0, 1, 255, 256] {
                assert_eq!(
                    blend_pairs_u32(c, w, Scale(i)),
                    blend_pairs_u64(c, w, Scale(i))
                );
            }
        }
    }
}

/// The lit blend is the single rounding of `sum w c i / 65536`, channel by channel,
/// with the sums taken texel by texel here.
#[test]
fn scaled_blend_rounds_once() {
    let mut rng = Rng(0x5EED_1234);
    let chans = |t: u16| [(t >> 11) as u32, ((t >> 5) & 63) as u32, (t & 31) as u32];
    for n in 0..300_000 {
        let c = [0; 4].map(|_: u16| rng.next() as u16);
        let (a, b, i) = if n < 8 {
            (
                [0, 256, 255, 0, 256, 1, 128, 255][n],
                [0, 256, 0, 255, 256, 1, 128, 255][n],
                256,
            )
        } else {
            (rng.next() % 257, rng.next() % 257, rng.next() % 257)
        };
        let w = q8_weights(a, b);
        let mut want = [0u32; 3];
        for (k, out) in want.iter_mut().enumerate() {
            let sum: u64 = (0..4).map(|t| u64::from(w[t] * chans(c[t])[k])).sum();
            *out = ((sum * u64::from(i) + 32768) >> 16) as u32;
        }
        let want = ((want[0] << 11) | (want[1] << 5) | want[2]) as u16;
        assert_eq!(
            blend_q8_scaled(c, a, b, i),
            want,
            "c {c:?} a {a} b {b} i {i}"
        );
    }
}

#[test]
fn split_half_matches_float() {
    let mut rng = Rng(11);
    let mut cs: Vec<i32> = vec![i32::MIN, i32::MIN + 1, i32::MAX, -1, 0, 1, 0x8000, 0x7FFF];
    cs.extend((0..100_000).map(|_| rng.next() as i32));
    for c in cs {
        let (i0, f) = split_half(c);
        let x = c as i64 - 0x8000;
        assert_eq!(i0 as i64, x.div_euclid(0x10000), "c = {c}");
        assert_eq!(f as i64, x.rem_euclid(0x10000), "c = {c}");
    }
}
