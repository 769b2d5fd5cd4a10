//! The shadow firmware's frames (`examples/firmware/src/shadow.rs`, the same code, band by
//! band) rendered on the host: their checksums must be what the firmware printed under
//! QEMU on both cores (pinned below, measured with `cargo build` + QEMU `mps2-an386`), and
//! the banded lit pass must give exactly the pixels of one whole-frame draw.

#[path = "../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;
#[path = "../../examples/firmware/src/shadow.rs"]
#[allow(dead_code)]
mod shadow;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::prelude::*;
use fixel::shading::pcf::{Pcf2x2, Pcf3x3, ShadowFilter, SingleTap};
use fixel::shading::shadow::{Bias, LightKind, LightSpace, Shadowed};
use fixel::shading::ModulateIntensity;
use fixel::surface::ShadowMap;
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat};
use fixel_scenes as demo;
use fixel_scenes::shadow::{self as scene, SceneLight};
use scenes::Fnv1a;
use shadow::ShadowBuffers;

fn texture(w: u32, h: u32) -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    demo::checker_texture(w, h, &mut t).unwrap();
    t
}

/// Checksums printed by the firmware (identical on Cortex-M4F and Cortex-M0+).
const FIRMWARE: [(&str, u32); 8] = [
    ("shadow_light", 0x89313f10),
    ("shadow_none", 0x1d0baf22),
    ("shadow_single", 0xd32ba043),
    ("shadow_single_uv", 0x383f159b),
    ("shadow_pcf2x2", 0x7ac488c8),
    ("shadow_pcf3x3", 0x4f3ec924),
    ("shadow_spot", 0x08120866),
    ("shadow_grazing", 0x98872624),
];

/// The banded firmware frame and the same frame drawn whole: (banded, whole) checksums and
/// the pixels written.
fn frames<K: LightKind, F: ShadowFilter, const M: usize, const UV: bool>(
    space: &LightSpace<K>,
    light: SceneLight,
    cull: Cull,
) -> (u32, u32, u32)
where
    fixel::geometry::ScreenTriangle<M>: fixel::surface::Binnable,
{
    let (t128, t64) = (texture(128, 128), texture(64, 64));
    let (c, f) = (
        Texture::new(&t128, 128, 128).unwrap(),
        Texture::new(&t64, 64, 64).unwrap(),
    );
    let mut buf = Box::new(ShadowBuffers::new());
    shadow::light_pass_culling(space, &mut buf.map, cull).unwrap();
    let banded =
        shadow::lit_pass::<K, F, M, UV>(&mut buf, space, light, c, f, &mut || (), &mut || ())
            .unwrap();
    // Whole frame, through the demo's own lit pass.
    let map = ShadowMap::new(&buf.map, shadow::MAP).unwrap();
    let (ct, ft) = (MipTexture::single(c), MipTexture::single(f));
    let vp = Viewport::new(0, 0, 320, 240).unwrap();
    let draw = |t| {
        let tex = TexBinding::new(t, Bilinear, Repeat, Repeat, Lod::default()).unwrap();
        let s = Shadowed::<_, K, F, M, UV>::new(
            ModulateIntensity { tex },
            map,
            Bias::for_filter::<F>(),
        )
        .unwrap();
        ShadedDraw::<_, Exact, DepthLess>::new(s, vp, Cull::Back).unwrap()
    };
    let (dc, df) = (draw(&ct), draw(&ft));
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); 320 * 240], vec![0u16; 320 * 240]);
    let mut frame = Frame::new(&mut color, 320, 240)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(Rgb565::new(4, 10, 14));
    let px = scene::lit_pass([&dc, &df], space, light, &mut frame).unwrap();
    assert_eq!(px, banded.stats.pixels);
    let mut h = Fnv1a::default();
    h.pixels(frame.pixels());
    (banded.checksum, h.0, banded.stats.pixels)
}

#[test]
fn firmware_checksums_and_bands_equal_whole_frame() {
    let high = scene::directional(SceneLight::High).unwrap();
    let mut map = vec![0u16; shadow::MAP_TEXELS];
    shadow::light_pass(&high, &mut map).unwrap();
    let sum = map
        .iter()
        .fold(0u32, |h, &t| (h ^ u32::from(t)).wrapping_mul(16_777_619));
    let (t128, t64) = (texture(128, 128), texture(64, 64));
    let (c, f) = (
        Texture::new(&t128, 128, 128).unwrap(),
        Texture::new(&t64, 64, 64).unwrap(),
    );
    let mut buf = Box::new(ShadowBuffers::new());
    let none = shadow::unshadowed_pass(
        &mut buf,
        &high,
        SceneLight::High,
        c,
        f,
        &mut || (),
        &mut || (),
    )
    .unwrap();
    let mut got = vec![("shadow_light", sum), ("shadow_none", none.checksum)];
    let mut pixels = vec![shadow::MAP_TEXELS as u32, none.stats.pixels];
    for (name, (banded, whole, px)) in [
        (
            "shadow_single",
            frames::<_, SingleTap, 6, false>(&high, SceneLight::High, Cull::Back),
        ),
        (
            "shadow_single_uv",
            frames::<_, SingleTap, 6, true>(&high, SceneLight::High, Cull::Back),
        ),
        (
            "shadow_pcf2x2",
            frames::<_, Pcf2x2, 6, false>(&high, SceneLight::High, Cull::Back),
        ),
        (
            "shadow_pcf3x3",
            frames::<_, Pcf3x3, 6, false>(&high, SceneLight::High, Cull::Back),
        ),
        (
            "shadow_spot",
            frames::<_, Pcf2x2, 7, false>(&scene::spot().unwrap(), SceneLight::Spot, Cull::Back),
        ),
        (
            "shadow_grazing",
            frames::<_, Pcf3x3, 6, false>(
                &scene::directional(SceneLight::Grazing).unwrap(),
                SceneLight::Grazing,
                Cull::Front,
            ),
        ),
    ] {
        assert_eq!(banded, whole, "{name}: bands differ from the whole frame");
        got.push((name, banded));
        pixels.push(px);
    }
    // The format `cargo xtask mcu` reads (the light pass's "pixels" are the map's texels).
    for ((name, c), px) in got.iter().zip(&pixels) {
        println!("mcu-expected scene={name} checksum=0x{c:08x} pixels={px}");
    }
    assert_eq!(got, FIRMWARE);
    // The whole-frame firmwares' own path (`whole_shadow_single`, `whole_shadow_single_uv`).
    let mut map = vec![0u16; shadow::MAP_TEXELS];
    shadow::light_pass_culling(&high, &mut map, Cull::Back).unwrap();
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); 320 * 240], vec![0u16; 320 * 240]);
    let mut whole = |uv: bool| {
        let w = if uv {
            shadow::lit_pass_whole::<_, SingleTap, 6, true>
        } else {
            shadow::lit_pass_whole::<_, SingleTap, 6, false>
        };
        w(
            &mut color,
            &mut depth,
            &map,
            &high,
            SceneLight::High,
            c,
            f,
            &mut || (),
            &mut || (),
        )
        .unwrap()
    };
    for (k, name, uv) in [
        (2, "whole_shadow_single", false),
        (3, "whole_shadow_single_uv", true),
    ] {
        let w = whole(uv);
        assert_eq!(
            (w.checksum, w.stats.pixels),
            (got[k].1, pixels[k]),
            "{name}"
        );
        println!(
            "mcu-expected scene={name} checksum=0x{:08x} pixels={}",
            w.checksum, w.stats.pixels
        );
    }
}
