//! Palette textures against the RGB565 textures their palettes expand to: every filter and
//! wrap, plain and scaled, and mip chains, bit for bit; storage and refusals.

extern crate std;
use super::*;
use crate::test_rng::Rng;
use crate::texture::{
    chain_len, ClampToBorder, ClampToEdge, LinearMipmapNearest, MipTexture, MirroredRepeat,
    NearestMipmapNearest, Repeat, TexSampler, Texture,
};
use std::vec::Vec;

fn rgb(raw: u16) -> Rgb565 {
    Rgb565::new((raw >> 11) as u8, ((raw >> 5) & 63) as u8, (raw & 31) as u8)
}

/// Random palette and indices of a `w x h` chain of `levels` levels, with the RGB565 chain
/// they expand to.
fn random<I: IndexFormat>(
    rng: &mut Rng,
    w: u32,
    h: u32,
    levels: u32,
) -> (Vec<Rgb565>, Vec<u8>, Vec<Rgb565>) {
    let colors = 1usize << I::BITS;
    let palette: Vec<Rgb565> = (0..colors).map(|_| rgb(rng.next() as u16)).collect();
    let mut bytes = Vec::new();
    let mut expanded = Vec::new();
    for k in 0..levels {
        let n = (level_side(w, k) * level_side(h, k)) as usize;
        let idx: Vec<usize> = (0..n).map(|_| rng.next() as usize % colors).collect();
        if I::BITS == 8 {
            bytes.extend(idx.iter().map(|&i| i as u8));
        } else {
            for pair in idx.chunks(2) {
                bytes.push(pair[0] as u8 | (*pair.get(1).unwrap_or(&0) as u8) << 4);
            }
        }
        expanded.extend(idx.iter().map(|&i| palette[i]));
    }
    (palette, bytes, expanded)
}

fn coord(rng: &mut Rng) -> i32 {
    match rng.next() % 4 {
        // Anywhere.
        0 => rng.next() as i32,
        // Within a few repeats of the texture, any fraction.
        _ => (rng.next() as i32) >> 10,
    }
}

fn check_level<I: IndexFormat, F: PaletteFilter, WU: WrapMode, WV: WrapMode>(
    p: &PaletteTexture<'_, I>,
    t: &Texture<'_>,
    rng: &mut Rng,
) {
    for _ in 0..400 {
        let (u, v) = (coord(rng), coord(rng));
        let i = (rng.next() % 300) as u16;
        assert_eq!(
            p.sample::<F, _, _>(WU::default(), WV::default(), u, v),
            F::sample(t, WU::default(), WV::default(), u, v),
            "{:?} {:?} {:?} ({u}, {v})",
            F::FILTER,
            WU::MODE,
            WV::MODE
        );
        assert_eq!(
            p.sample_scaled::<F, _, _>(WU::default(), WV::default(), u, v, i),
            F::sample_scaled(t, WU::default(), WV::default(), u, v, i),
        );
    }
}

fn every_mode<I: IndexFormat>(seed: u64) {
    let mut rng = Rng(seed);
    for (w, h) in [(8, 4), (1, 1), (16, 2), (2, 32), (64, 64)] {
        let (pal, idx, exp) = random::<I>(&mut rng, w, h, 1);
        let border = rgb(0x1234);
        macro_rules! palette {
            ($p:expr) => {
                PaletteTexture::<I>::new(&idx, $p, w, h)
                    .unwrap()
                    .with_border(border)
            };
        }
        let t = Texture::new(&exp, w, h).unwrap().with_border(border);
        let run = |p: &PaletteTexture<'_, I>, rng: &mut Rng| {
            macro_rules! wraps {
                ($f:ty) => {
                    check_level::<I, $f, Repeat, Repeat>(p, &t, rng);
                    check_level::<I, $f, MirroredRepeat, ClampToEdge>(p, &t, rng);
                    check_level::<I, $f, ClampToEdge, MirroredRepeat>(p, &t, rng);
                    check_level::<I, $f, ClampToBorder, ClampToBorder>(p, &t, rng);
                    check_level::<I, $f, Repeat, ClampToBorder>(p, &t, rng);
                };
            }
            wraps!(Nearest);
            wraps!(Bilinear);
        };
        if I::BITS == 8 {
            let mut a = [Rgb565::new(0, 0, 0); 256];
            a.copy_from_slice(&pal);
            // SAFETY-free cast: `I::Palette` is `[Rgb565; 256]` here.
            let p: &I::Palette = (&a as &dyn core::any::Any).downcast_ref().unwrap();
            run(&palette!(p), &mut rng);
        } else {
            let mut a = [Rgb565::new(0, 0, 0); 16];
            a.copy_from_slice(&pal);
            let p: &I::Palette = (&a as &dyn core::any::Any).downcast_ref().unwrap();
            run(&palette!(p), &mut rng);
        }
    }
}

#[test]
fn index8_samples_equal_the_expanded_texture_in_every_filter_and_wrap() {
    every_mode::<Index8>(0x9a1e_0008);
}

#[test]
fn index4_samples_equal_the_expanded_texture_in_every_filter_and_wrap() {
    every_mode::<Index4>(0x9a1e_0004);
}

#[test]
fn nibbles_are_low_first_and_a_single_texel_takes_a_byte() {
    let mut pal = [Rgb565::new(0, 0, 0); 16];
    for (k, c) in pal.iter_mut().enumerate() {
        *c = rgb(k as u16 * 1000);
    }
    let t = PaletteTexture::<Index4>::new(&[0x21, 0x43], &pal, 4, 1).unwrap();
    let got: Vec<u16> = (0..4).map(|i| t.texel_raw(i, 0)).collect();
    assert_eq!(got, [1000, 2000, 3000, 4000]);
    assert!(PaletteTexture::<Index4>::new(&[0x05], &pal, 1, 1).is_ok());
    assert_eq!(palette_chain_bytes::<Index4>(4, 2, 3), 4 + 1 + 1);
    assert_eq!(palette_chain_bytes::<Index8>(4, 2, 3), 8 + 2 + 1);
}

#[test]
fn bad_sizes_and_lengths_are_refused() {
    let pal = [Rgb565::new(0, 0, 0); 256];
    let idx = [0u8; 64];
    assert_eq!(
        PaletteTexture::<Index8>::new(&idx, &pal, 6, 8).unwrap_err(),
        Error::NotPowerOfTwo(6)
    );
    assert_eq!(
        PaletteTexture::<Index8>::new(&idx, &pal, 0, 8).unwrap_err(),
        Error::BadSize(0)
    );
    assert_eq!(
        PaletteTexture::<Index8>::new(&idx[..63], &pal, 8, 8).unwrap_err(),
        Error::WrongLength {
            expected: 64,
            actual: 63
        }
    );
    let pal4 = [Rgb565::new(0, 0, 0); 16];
    assert_eq!(
        PaletteTexture::<Index4>::new(&idx, &pal4, 8, 8).unwrap_err(),
        Error::WrongLength {
            expected: 32,
            actual: 64
        }
    );
    assert_eq!(
        PaletteMips::<Index8>::new(&idx, &pal, 8, 8, 0).unwrap_err(),
        Error::BadSize(0)
    );
    assert_eq!(
        PaletteMips::<Index8>::new(&idx, &pal, 8, 8, 5).unwrap_err(),
        Error::BadSize(5)
    );
    assert_eq!(
        PaletteMips::<Index8>::new(&idx, &pal, 8, 8, 2).unwrap_err(),
        Error::WrongLength {
            expected: 80,
            actual: 64
        }
    );
}

/// The chain samples as `MipTexture` does with `*_MIPMAP_NEAREST` on the expanded chain.
#[test]
fn mips_pick_the_levels_mip_texture_picks() {
    let mut rng = Rng(0x9a1e_0a1b);
    let (w, h) = (32, 8);
    let levels = full_levels(w, h);
    let (pal, idx, exp) = random::<Index4>(&mut rng, w, h, levels);
    assert_eq!(exp.len(), chain_len(w, h, levels));
    let mut a = [Rgb565::new(0, 0, 0); 16];
    a.copy_from_slice(&pal);
    let p = PaletteMips::<Index4>::new(&idx, &a, w, h, levels).unwrap();
    let m = MipTexture::new(&exp, w, h, levels).unwrap();
    for _ in 0..4000 {
        let (u, v) = (coord(&mut rng), coord(&mut rng));
        let lambda = (rng.next() % 2200) as i32 - 200;
        assert_eq!(
            p.sample_mip::<Nearest, _, _>(Repeat, MirroredRepeat, u, v, lambda),
            NearestMipmapNearest::default().sample_mip(&m, Repeat, MirroredRepeat, u, v, lambda),
            "({u}, {v}) lambda {lambda}"
        );
        assert_eq!(
            p.sample_mip::<Bilinear, _, _>(ClampToEdge, Repeat, u, v, lambda),
            LinearMipmapNearest::default().sample_mip(&m, ClampToEdge, Repeat, u, v, lambda),
            "({u}, {v}) lambda {lambda}"
        );
    }
}
