//! Scenes `noise_flame_baked` and `flame_plain`: the flame quad of `noise_flame` (80 x 96,
//! four frames t = 0, 1/8, 2/8, 3/8 s, 8-row bands, 1.25 KB of colour) drawn from the two
//! baked flame layers (`fixel::shading::noise::BakedFlame`, 64 x 64 `u16` each, baked into
//! flash by `build.rs`), and the same quad as a plain bilinear textured draw of `T(64, 64)`
//! (`Replace`, about one texel per pixel), the draw it is compared with. Shared with the host
//! test `host-tests/tests/mcu_checksums.rs`, which bakes the layers at run time.

use crate::noise::{FLAME_BAND_PIXELS, FLAME_H, FLAME_QUAD, FLAME_W};
use crate::scenes::{Fnv1a, FrameResult, ROWS};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
use fixel::shading::noise::{BakedFlame, Ramp, FLAME_KEYS, FLAME_LAYERS, FLAME_LAYER_SIDE};
use fixel::shading::{Replace, Shader, TexBinding};
use fixel::surface::{BandRenderer, BandStats, Binned};
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat, Texture};
use fixel::Error;

/// Scene `noise_flame_baked`: `frames` frames of the flame from `layers` (the two tiles of
/// [`FLAME_LAYERS`], [`FLAME_LAYER_SIDE`]² texels each) in bands through `band`.
pub fn flame_baked_bands(
    band: &mut [Rgb565; FLAME_BAND_PIXELS],
    layers: [&[u16]; 2],
    frames: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let ramp = Ramp::from_keys(&FLAME_KEYS)?;
    let (x0, x1, y0, y1) = FLAME_QUAD;
    let quad = quad([x0, x1, y0, y1]);
    quad_bands(band, frames, &quad, pause, resume, |i| {
        BakedFlame::new(
            &ramp,
            &FLAME_LAYERS,
            layers,
            FLAME_LAYER_SIDE,
            (i as i32) << 13,
        )
    })
}

/// Texture coordinates of the plain quad's corners (`u0, u1, v0, v1`, I16F16): 1.25 x 1.5
/// repeats of the 64-texel texture over 80 x 96 pixels, one texel per pixel.
pub const PLAIN_UV: [i32; 4] = [0, 81_920, 0, 98_304];

/// Scene `flame_plain`: `frames` frames of the flame quad as a plain textured draw of
/// `tex` (`T(64, 64)`, bilinear, repeat) in bands through `band`.
pub fn flame_plain_bands(
    band: &mut [Rgb565; FLAME_BAND_PIXELS],
    tex: Texture<'_>,
    frames: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let mip = MipTexture::single(tex);
    let quad = quad(PLAIN_UV);
    quad_bands(band, frames, &quad, pause, resume, |_| {
        let tex = TexBinding::new(&mip, Bilinear, Repeat, Repeat, Lod::default())?;
        Ok(Replace { tex })
    })
}

/// The quad over the whole viewport as two triangles, varyings `(a, b)` from
/// `[a0, a1, b0, b1]` (`b0` at the bottom row).
fn quad(c: [i32; 4]) -> [[Vertex<2>; 3]; 2] {
    let v = |xn: i32, yn: i32, a: i32, b: i32| {
        Vertex::new(
            [Fx::from_num(xn), Fx::from_num(yn), Fx::ZERO, Fx::ONE],
            [a, b],
        )
    };
    let [a0, a1, b0, b1] = c;
    let (p, q, r, s) = (
        v(-1, -1, a0, b0),
        v(1, -1, a1, b0),
        v(1, 1, a1, b1),
        v(-1, 1, a0, b1),
    );
    [[p, q, r], [p, r, s]]
}

/// `frames` frames of `quad` drawn with the shader `shader(i)` of frame `i`, each binned
/// once and drawn band by band; FNV-1a over every band in order.
fn quad_bands<S: Shader<Varyings = [i32; 2]>>(
    band: &mut [Rgb565; FLAME_BAND_PIXELS],
    frames: u32,
    quad: &[[Vertex<2>; 3]; 2],
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
    shader: impl Fn(u32) -> Result<S, Error>,
) -> Result<FrameResult, Error> {
    let vp = Viewport::new(0, 0, FLAME_W, FLAME_H)?;
    let mut sum = Fnv1a::default();
    let mut stats = BandStats::default();
    for i in 0..frames {
        let draw = ShadedDraw::<_, Exact, NoDepth>::new(shader(i)?, vp, Cull::None)?;
        let mut bins = [Binned::EMPTY; 4];
        let mut bands = BandRenderer::new(&mut band[..], FLAME_W, ROWS, FLAME_H)?;
        let s = bands.render(
            &[&draw],
            &mut bins,
            Rgb565::new(0, 0, 0),
            |sink| {
                for t in quad {
                    draw.project(t, &mut |s| sink.push(0, s));
                }
                if sink.fresh() {
                    crate::scenes::geometry_done();
                }
            },
            sum.band_flush::<core::convert::Infallible>(pause, resume),
        )?;
        stats.pixels = stats.pixels.saturating_add(s.pixels);
        stats.bands = stats.bands.saturating_add(s.bands);
    }
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}
