//! Palette textures, properties over random textures, palettes, coordinates, filters and
//! wraps: a palette texture samples as the RGB565 texture its palette expands to, bit for
//! bit, and its bilinear sample is within 1 LSB per channel of the f64 bilinear blend of
//! the four palette colours (the budget `Bilinear` has against the f64 reference).

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::texture::{
    Bilinear, DynWrap, Index4, Index8, IndexFormat, Nearest, PaletteTexture, Sampler, Texture,
    Wrap, WrapMode,
};
use proptest::prelude::*;

fn rgb(raw: u16) -> Rgb565 {
    Rgb565::new((raw >> 11) as u8, ((raw >> 5) & 63) as u8, (raw & 31) as u8)
}

fn wrap(k: u8) -> Wrap {
    [
        Wrap::Repeat,
        Wrap::MirroredRepeat,
        Wrap::ClampToEdge,
        Wrap::ClampToBorder,
    ][usize::from(k % 4)]
}

/// One case: sides `2^lw x 2^lh`, palette seed colours, index seed, coordinates, wraps.
#[derive(Debug, Clone)]
struct Case {
    lw: u32,
    lh: u32,
    palette: Vec<u16>,
    indices: Vec<u8>,
    u: i32,
    v: i32,
    wu: u8,
    wv: u8,
}

fn case() -> impl Strategy<Value = Case> {
    (
        0u32..7,
        0u32..7,
        any::<u64>(),
        any::<i32>(),
        any::<i32>(),
        any::<u8>(),
        any::<u8>(),
        any::<bool>(),
    )
        .prop_map(|(lw, lh, seed, u, v, wu, wv, near)| {
            let mut s = seed | 1;
            let mut next = move || {
                s ^= s << 13;
                s ^= s >> 7;
                s ^= s << 17;
                s
            };
            let n = 1usize << (lw + lh);
            let palette = (0..256).map(|_| next() as u16).collect();
            let indices = (0..n).map(|_| next() as u8).collect();
            // Half the cases within a few repeats of the texture (where the wraps differ).
            let (u, v) = if near { (u >> 9, v >> 9) } else { (u, v) };
            Case {
                lw,
                lh,
                palette,
                indices,
                u,
                v,
                wu,
                wv,
            }
        })
}

/// The palette texture of `c` in format `I` and the RGB565 texels it expands to.
fn check<I: IndexFormat>(c: &Case, pal: &I::Palette, packed: &[u8], expanded: &[Rgb565]) {
    let (w, h) = (1 << c.lw, 1 << c.lh);
    let border = rgb(0xA5A5);
    let p = PaletteTexture::<I>::new(packed, pal, w, h)
        .unwrap()
        .with_border(border);
    let t = Texture::new(expanded, w, h).unwrap().with_border(border);
    let (wu, wv) = (DynWrap(wrap(c.wu)), DynWrap(wrap(c.wv)));
    assert_eq!(
        p.sample::<Nearest, _, _>(wu, wv, c.u, c.v),
        Nearest::sample(&t, wu, wv, c.u, c.v)
    );
    let got = p.sample::<Bilinear, _, _>(wu, wv, c.u, c.v);
    assert_eq!(got, Bilinear::sample(&t, wu, wv, c.u, c.v));
    // The f64 reference: GL's bilinear blend of the four palette colours.
    let (fu, fv) = (
        f64::from(c.u) / 65536.0 - 0.5,
        f64::from(c.v) / 65536.0 - 0.5,
    );
    let (i0, j0) = (fu.floor(), fv.floor());
    let (a, b) = (fu - i0, fv - j0);
    let texel = |i: f64, j: f64| -> [f64; 3] {
        let (iw, jw) = (wu.wrap(i as i32, c.lw), wv.wrap(j as i32, c.lh));
        let raw = match (iw, jw) {
            (Some(i), Some(j)) => p.texel_raw(i, j),
            _ => 0xA5A5,
        };
        [
            f64::from(raw >> 11),
            f64::from((raw >> 5) & 63),
            f64::from(raw & 31),
        ]
    };
    let (c00, c10, c01, c11) = (
        texel(i0, j0),
        texel(i0 + 1.0, j0),
        texel(i0, j0 + 1.0),
        texel(i0 + 1.0, j0 + 1.0),
    );
    let got = [got >> 11, (got >> 5) & 63, got & 31];
    for k in 0..3 {
        let want = (1.0 - a) * (1.0 - b) * c00[k]
            + a * (1.0 - b) * c10[k]
            + (1.0 - a) * b * c01[k]
            + a * b * c11[k];
        assert!(
            (f64::from(got[k]) - want).abs() <= 1.0,
            "channel {k}: {} against {want:.3} ({c:?})",
            got[k]
        );
    }
}

/// 512 cases, or `PROPTEST_CASES` when set (for long local runs).
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(512)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn index8_equals_expanded_and_the_f64_blend(c in case()) {
        let pal: [Rgb565; 256] = core::array::from_fn(|k| rgb(c.palette[k]));
        let expanded: Vec<Rgb565> = c.indices.iter().map(|&i| pal[usize::from(i)]).collect();
        check::<Index8>(&c, &pal, &c.indices, &expanded);
    }

    #[test]
    fn index4_equals_expanded_and_the_f64_blend(c in case()) {
        let pal: [Rgb565; 16] = core::array::from_fn(|k| rgb(c.palette[k]));
        let idx: Vec<u8> = c.indices.iter().map(|&i| i & 15).collect();
        let packed: Vec<u8> = idx
            .chunks(2)
            .map(|p| p[0] | p.get(1).copied().unwrap_or(0) << 4)
            .collect();
        let expanded: Vec<Rgb565> = idx.iter().map(|&i| pal[usize::from(i)]).collect();
        check::<Index4>(&c, &pal, &packed, &expanded);
    }
}
