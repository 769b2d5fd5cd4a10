//! Inputs at the fixed-point and size limits: each is drawn right or refused with an
//! `Error` that says what is wrong, never drawn wrong with `Ok` (and never overflowed in an
//! overflow-checked build).

use core::convert::Infallible;

use fixel::math::Fx;
use fixel::pipeline::Shading;
use fixel::prelude::*;
use fixel::surface::Binned;

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
