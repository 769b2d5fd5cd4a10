//! Inputs at the fixed-point and size limits: each is drawn right or refused with an
//! `Error` that says what is wrong, never drawn wrong with `Ok` (and never overflowed in an
//! overflow-checked build).

use core::convert::Infallible;

use fixel::prelude::*;
use fixel::shading::shadow::{Directional, LightSpace};
use fixel::surface::Binned;
use fixel::texture::{Lod, MipFilter, MipTexture};
use proptest::prelude::*;

/// A 2048 x 2048 band renderer drawing 1025 full-viewport quads writes more than 2^32
/// pixels: the count saturates at `u32::MAX` instead of wrapping. Ignored by default: it
/// writes 2^32 pixels (run it with `--ignored`).
#[test]
#[ignore = "writes 2^32 pixels"]
fn band_pixel_count_saturates() {
    const S: u32 = 2048;
    let mode = DrawMode {
        shading: Shading::Flat,
        cull: Cull::None,
        ..DrawMode::default()
    };
    let vp = Viewport::new(0, 0, S, S).unwrap();
    let draw = Draw::dynamic(mode, None, vp)
        .unwrap()
        .with_flat_color(Rgb565::WHITE);
    let at = |x: i32, y: i32| ClipVertex::new([x, y, 0, 1].map(Fx::from_num), [Fx::ZERO; 2]);
    let quad = [
        [at(-1, -1), at(1, -1), at(1, 1)],
        [at(-1, -1), at(1, 1), at(-1, 1)],
    ];
    let rows = 256;
    let mut buf = vec![Rgb565::BLACK; (S * rows) as usize];
    let mut bands = BandRenderer::new(&mut buf, S, rows, S).unwrap();
    let mut bins = vec![Binned::default(); 2 * 1025];
    let stats = bands
        .render(
            &[&draw],
            &mut bins,
            Rgb565::BLACK,
            |sink| {
                for _ in 0..1025 {
                    for t in &quad {
                        draw.project(t, &mut |s| sink.push(0, s));
                    }
                }
            },
            |_| Ok::<(), Infallible>(()),
        )
        .unwrap();
    assert_eq!(stats.triangles, 2050);
    assert_eq!(stats.pixels, u32::MAX);
}

/// The depth row `(m[2][2], m[2][3])` of a directional light looking down -z from the
/// origin: `(-2 / (far - near), -(far + near) / (far - near))`.
fn depth_row(near: Fx, far: Fx) -> Result<(f64, f64), Error> {
    let l = LightSpace::<Directional>::directional(
        Vec3::ZERO,
        Vec3::from_num(0, 0, -1),
        Vec3::from_num(0, 1, 0),
        Fx::from_num(10),
        near,
        far,
    )?;
    let m = l.matrix().m;
    Ok((m[2][2].to_num(), m[2][3].to_num()))
}

/// Near 20000, far 30000 (`far + near` past I16F16) and near -20000, far 20000
/// (`far - near` past it): the depth rows are right, not wrapped.
#[test]
fn directional_light_with_large_depths() {
    let l = LightSpace::<Directional>::directional(
        Vec3::from_num(0, 0, 10),
        Vec3::ZERO,
        Vec3::from_num(0, 1, 0),
        Fx::from_num(10),
        Fx::from_num(20000),
        Fx::from_num(30000),
    )
    .unwrap();
    let m = l.matrix().m;
    // -k z' - c with z' = z - 10 in view space: -0.0002 z + (0.002 - 5).
    assert!((m[2][3].to_num::<f64>() + 4.998).abs() < 1e-3, "{m:?}");
    let (k, c) = depth_row(Fx::from_num(-20000), Fx::from_num(20000)).unwrap();
    assert!(
        k < 0.0 && (k + 5e-5).abs() < 2e-5 && c.abs() < 1e-4,
        "{k} {c}"
    );
    // A thin range far from the light: (far + near) / (far - near) = 65535 is refused.
    let e = depth_row(Fx::from_num(32767), Fx::from_num(32767) + Fx::DELTA * 2).unwrap_err();
    assert!(matches!(e, Error::BadProjection(_)), "{e:?}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]
    /// Any near < far: the depth row within one I16F16 step of the exact one, or refused
    /// only when `(far + near) / (far - near)` is outside I16F16.
    #[test]
    fn directional_depth_row_is_exact_or_refused(a in any::<i32>(), b in any::<i32>()) {
        prop_assume!(a != b);
        let (n, f) = (a.min(b), a.max(b));
        let (near, far) = (Fx::from_bits(n), Fx::from_bits(f));
        let (fe, ne) = (far.to_num::<f64>(), near.to_num::<f64>());
        let (k, c) = (2.0 / (fe - ne), (fe + ne) / (fe - ne));
        let step = 1.0 / 65536.0;
        match depth_row(near, far) {
            Ok((mk, mc)) => {
                prop_assert!((mk + k).abs() <= step && (mc + c).abs() <= step, "{mk} {mc} vs {k} {c}");
            }
            Err(e) => prop_assert!(c.abs() >= 32767.0 || k >= 32767.0, "{e:?} for {ne}..{fe}"),
        }
    }
}

/// `Lod` clamps at `i32::MAX` (and `i32::MIN`): every level arithmetic saturates or stays
/// in `u32`, the draw picks the last level (or level 0), in every mipmapped filter.
#[test]
fn extreme_lod_clamps_draw_the_last_level() {
    let mut chain = vec![Rgb565::BLACK; fixel::texture::chain_len(8, 8, 4)];
    chain[..64].fill(Rgb565::RED);
    fixel::texture::generate_mips(&mut chain, 8, 8, 4).unwrap();
    let n = chain.len();
    chain[n - 1] = Rgb565::GREEN;
    let mip = MipTexture::new(&chain, 8, 8, 4).unwrap();
    for (lambda, want) in [(i32::MAX, Rgb565::GREEN), (i32::MIN, Rgb565::RED)] {
        for mip_filter in [MipFilter::Nearest, MipFilter::Linear] {
            for filter in [Filter::Nearest, Filter::Bilinear] {
                let mode = DrawMode {
                    mip: mip_filter,
                    filter,
                    shading: Shading::Replace,
                    cull: Cull::None,
                    ..DrawMode::default()
                };
                let lod = Lod {
                    bias: lambda,
                    min: lambda,
                    max: lambda,
                    ..Lod::default()
                };
                let vp = Viewport::new(0, 0, 16, 16).unwrap();
                let draw = Draw::dynamic_mip(mode, Some(mip), vp)
                    .unwrap()
                    .with_lod(lod);
                let mut px = vec![Rgb565::BLACK; 256];
                let mut frame = Frame::new(&mut px, 16, 16).unwrap();
                let at = |x: i32, y: i32| {
                    ClipVertex::new([x, y, 0, 1].map(Fx::from_num), [x, y].map(Fx::from_num))
                };
                let tri = [[at(-1, -1), at(1, -1), at(1, 1)]];
                let written = draw.clip_triangles(&tri, &mut frame).unwrap();
                assert!(written > 100, "{written}");
                assert!(
                    px.iter().all(|&c| c == want || c == Rgb565::BLACK),
                    "{lambda} {mode:?}"
                );
            }
        }
    }
}
