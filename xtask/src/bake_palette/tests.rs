//! Tests of the palette baker: lossless when the colours fit, fixel's storage layout, the
//! error falling with more bits, and the committed benchmark bakes.

use super::*;
use fixel::texture::{Index4, Index8, IndexFormat, PaletteMips};

fn checker(w: u32, h: u32, levels: u32) -> Vec<C565> {
    let (w0, h0, base) = read_source(&format!("checker:{w}x{h}")).unwrap();
    assert_eq!((w0, h0), (w, h));
    chain(&base, w, h, levels)
}

#[test]
fn few_colours_are_kept_exactly() {
    let px: Vec<C565> = (0..64)
        .map(|i| [(i % 5) as u8 * 6, (i % 3) as u8 * 20, 7])
        .collect();
    let q = quantise_chain(&px, 8, 8, 1, 4, false);
    assert!(q.total.0.is_infinite(), "{:?}", q.total);
    assert_eq!(q.total.1, 0.0);
    assert_eq!(q.palette.len(), 16);
}

/// The chain `m` gives `q`'s colours at every texel.
fn check_mips<I: IndexFormat>(m: &PaletteMips<'_, I>, q: &Quantised) {
    for l in 0..q.levels {
        let t = m.level(l).unwrap();
        for (k, &ix) in q.indices[l as usize].iter().enumerate() {
            let c = q.palette[ix as usize];
            let raw = (u16::from(c[0]) << 11) | (u16::from(c[1]) << 5) | u16::from(c[2]);
            assert_eq!(t.texel_at(k as u32), raw, "level {l} texel {k}");
        }
    }
}

/// The packed indices, read through fixel's `PaletteMips`, give the quantised colours.
fn layout(bits: u32) {
    let (w, h) = (16, 8);
    let levels = full_levels(w, h);
    let src = checker(w, h, levels);
    let q = quantise_chain(&src, w, h, levels, bits, false);
    let packed = pack(&q.indices, bits);
    let pal: Vec<fixel::Rgb565> = q
        .palette
        .iter()
        .map(|c| fixel::Rgb565::new(c[0], c[1], c[2]))
        .collect();
    if bits == 8 {
        let a: [fixel::Rgb565; 256] = pal.try_into().unwrap();
        check_mips(
            &PaletteMips::<Index8>::new(&packed, &a, w, h, levels).unwrap(),
            &q,
        );
    } else {
        let a: [fixel::Rgb565; 16] = pal.try_into().unwrap();
        check_mips(
            &PaletteMips::<Index4>::new(&packed, &a, w, h, levels).unwrap(),
            &q,
        );
    }
}

#[test]
fn packed_indices_are_fixels_layout() {
    layout(8);
    layout(4);
}

#[test]
fn more_bits_less_error_and_dithering_runs() {
    let src = checker(64, 64, 1);
    let q4 = quantise_chain(&src, 64, 64, 1, 4, false);
    let q8 = quantise_chain(&src, 64, 64, 1, 8, false);
    assert!(
        q8.total.0 > q4.total.0 + 6.0,
        "{:?} {:?}",
        q4.total,
        q8.total
    );
    assert!(q4.total.0 > 20.0, "{:?}", q4.total);
    let d = quantise_chain(&src, 64, 64, 1, 4, true);
    assert!(d.total.0.is_finite() && d.indices != q4.indices);
}

/// The committed benchmark bakes (`assets/palette/`, read by the palette firmwares and
/// host-tests) are what `bake-palette` makes today.
#[test]
fn committed_benchmark_bakes_are_current() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    for (side, bits) in [(64, 8), (64, 4), (128, 8), (128, 4)] {
        let name = format!("T{side}_P{bits}");
        let out = format!("assets/palette/t{side}_p{bits}.rs");
        let src = checker(side, side, 1);
        let q = quantise_chain(&src, side, side, 1, bits, false);
        let cmd = format!("--bits {bits} --name {name} checker:{side}x{side} {out}");
        let want = source(&q, &cmd, &name, DEFAULT_RGB565);
        let got = std::fs::read_to_string(root.join(&out)).unwrap_or_default();
        assert!(
            got == want,
            "{out} is stale: run `cargo xtask bake-palette {cmd}`"
        );
    }
}
