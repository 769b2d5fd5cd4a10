//! Shadow maps on microcontrollers for the report (`report_shadow`, shared with the host's
//! `shadow_report`): the demo scene (cube on a floor, 320 x 240, whole frame) under the high
//! directional light and the spot light, each map size (32, 64, 128) and filter (single
//! tap, PCF 2x2 bilinear, PCF 3x3): the light pass per map texel and the lit pass (textured,
//! lit, exact) per pixel, as separate modes. The same code runs on the host, so checksums
//! compare bit for bit.

use crate::scenes::Fnv1a;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Viewport};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::pcf::{Pcf2x2, Pcf3x3, ShadowFilter, SingleTap};
use fixel::shading::shadow::{Bias, LightKind, LightSpace, Shadowed};
use fixel::shading::{ModulateIntensity, TexBinding};
use fixel::surface::{DepthMap, Frame, ShadowMap};
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat, Texture};
use fixel::Error;
use fixel_scenes::shadow::{self as scene, SceneLight};

/// Frame width and height.
pub const W: u32 = 320;
/// Frame height.
pub const H: u32 = 240;
/// Map sizes.
pub const SIZES: [u32; 3] = [32, 64, 128];
/// Largest map, in texels.
pub const MAP_TEXELS: usize = 128 * 128;
/// Lights, by report name.
pub const LIGHTS: [&str; 2] = ["directional", "spot"];
/// Filters, by report name.
pub const FILTERS: [&str; 3] = ["single", "pcf2x2", "pcf3x3"];

/// `light` (index into [`LIGHTS`]) and its light space.
fn light_of(light: usize) -> SceneLight {
    if light == 0 {
        SceneLight::High
    } else {
        SceneLight::Spot
    }
}

/// The light pass of light `light` into the first `size²` texels of `map`; returns the
/// texels written.
#[inline(never)]
pub fn light_pass(light: usize, size: u32, map: &mut [u16]) -> Result<u32, Error> {
    let n = (size * size) as usize;
    let texels = map.get_mut(..n).ok_or(Error::BadSize(size))?;
    let mut m = DepthMap::new(texels, size)?;
    if light == 0 {
        scene::light_pass(&scene::directional(SceneLight::High)?, &mut m)
    } else {
        scene::light_pass(&scene::spot()?, &mut m)
    }
}

fn lit<K: LightKind, F: ShadowFilter, const M: usize>(
    space: &LightSpace<K>,
    light: SceneLight,
    map: ShadowMap<'_>,
    tex: [Texture<'_>; 2],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Result<u32, Error> {
    let (ct, ft) = (MipTexture::single(tex[0]), MipTexture::single(tex[1]));
    let vp = Viewport::new(0, 0, W, H)?;
    let draw = |t| -> Result<_, Error> {
        let tb = TexBinding::new(t, Bilinear, Repeat, Repeat, Lod::default())?;
        let s = Shadowed::<_, K, F, M>::new(
            ModulateIntensity { tex: tb },
            map,
            Bias::for_filter::<F>(),
        )?;
        ShadedDraw::<_, Exact, DepthLess>::new(s, vp, Cull::Back)
    };
    let (dc, df) = (draw(&ct)?, draw(&ft)?);
    let mut frame = Frame::new(color, W, H)?.with_depth(depth)?;
    frame.clear(Rgb565::new(4, 10, 14));
    scene::lit_pass([&dc, &df], space, light, &mut frame)
}

/// The lit pass of light `light` with filter `filter` (indices into [`LIGHTS`],
/// [`FILTERS`]) over the `size x size` map in `map` (from [`light_pass`]), the cube
/// textured with `tex[0]` and the floor with `tex[1]`; returns the pixels written.
#[inline(never)]
pub fn lit_pass(
    light: usize,
    filter: usize,
    size: u32,
    map: &[u16],
    tex: [Texture<'_>; 2],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Result<u32, Error> {
    let n = (size * size) as usize;
    let m = ShadowMap::new(map.get(..n).ok_or(Error::BadSize(size))?, size)?;
    let l = light_of(light);
    if light == 0 {
        let s = scene::directional(l)?;
        match filter {
            0 => lit::<_, SingleTap, 6>(&s, l, m, tex, color, depth),
            1 => lit::<_, Pcf2x2, 6>(&s, l, m, tex, color, depth),
            _ => lit::<_, Pcf3x3, 6>(&s, l, m, tex, color, depth),
        }
    } else {
        let s = scene::spot()?;
        match filter {
            0 => lit::<_, SingleTap, 7>(&s, l, m, tex, color, depth),
            1 => lit::<_, Pcf2x2, 7>(&s, l, m, tex, color, depth),
            _ => lit::<_, Pcf3x3, 7>(&s, l, m, tex, color, depth),
        }
    }
}

/// FNV-1a of a frame or a map.
pub fn checksum(px: &[Rgb565]) -> u32 {
    let mut f = Fnv1a::default();
    f.pixels(px);
    f.0
}

/// FNV-1a of a map's texels.
pub fn map_checksum(map: &[u16]) -> u32 {
    map.iter().fold(0x811C_9DC5u32, |h, &t| {
        (h ^ u32::from(t)).wrapping_mul(16_777_619)
    })
}
