//! Shadow maps: the benchmark cube on a floor, its shadow from a 64 x 64 depth map drawn
//! from the light. Writes `target/pictures/shadow.png`, a 2 x 2 sheet (640 x 480):
//!
//! | | |
//! |---|---|
//! | high directional light, PCF 2x2 bilinear | grazing directional light, PCF 3x3 |
//! | spot light, PCF 2x2 bilinear | high light, single tap (the texels show) |
//!
//! and each panel alone (`shadow-*.png`), plus the high light's depth map (`shadow-map.png`).
//!
//! `cargo run --release --example shadow`

#[path = "common/mod.rs"]
mod common;

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::demo;
use fixel::demo::shadow::{self as scene, SceneLight};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::prelude::*;
use fixel::shading::pcf::{Pcf2x2, Pcf3x3, ShadowFilter, SingleTap};
use fixel::shading::shadow::{Bias, LightKind, LightSpace, Shadowed};
use fixel::shading::ModulateIntensity;
use fixel::surface::DepthMap;
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat};

const W: u32 = demo::WIDTH;
const H: u32 = demo::HEIGHT;
const MAP: u32 = 64;

fn panel<'t, K: LightKind, F: ShadowFilter, const M: usize>(
    space: &LightSpace<K>,
    light: SceneLight,
    tex: &'t MipTexture<'t>,
    floor: &'t MipTexture<'t>,
) -> Vec<Rgb565> {
    let mut texels = vec![0u16; (MAP * MAP) as usize];
    let mut map = DepthMap::new(&mut texels, MAP).unwrap();
    let written = scene::light_pass(space, &mut map).unwrap();
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let view = map.view();
    let draw = |t: &'t MipTexture<'t>| {
        let binding = TexBinding::new(t, Bilinear, Repeat, Repeat, Lod::default()).unwrap();
        let shader = Shadowed::<_, K, F, M>::new(
            ModulateIntensity { tex: binding },
            view,
            Bias::for_filter::<F>(),
        )
        .unwrap();
        ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).unwrap()
    };
    let (cube_draw, floor_draw) = (draw(tex), draw(floor));
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::default(); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, W, H)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(Rgb565::new(4, 10, 14));
    let px = scene::lit_pass([&cube_draw, &floor_draw], space, light, &mut frame).unwrap();
    println!(
        "{:?} {} {}: light pass {written} texels of {}, lit pass {px} pixels",
        light,
        K::NAME,
        F::NAME,
        MAP * MAP
    );
    if light == SceneLight::High && F::NAME == "single tap" {
        // The depth map itself, nearest = bright, scaled up 4x.
        let s = MAP as usize;
        let mut img = vec![Rgb565::default(); s * s * 16];
        for (i, p) in img.iter_mut().enumerate() {
            let (x, y) = ((i % (4 * s)) / 4, (i / (4 * s)) / 4);
            let d = map.texels()[y * s + x];
            let g = 255 - (d >> 8) as u8;
            *p = Rgb565::from(RawU16::new(fixel::color::rgb888_to_565(g, g, g)));
        }
        common::write_png(
            &common::out_dir().join("shadow-map.png"),
            4 * MAP,
            4 * MAP,
            &img,
        );
    }
    color
}

fn main() {
    let mut texels = vec![Rgb565::default(); 128 * 128];
    demo::checker_texture(128, 128, &mut texels).unwrap();
    let tex = MipTexture::single(Texture::new(&texels, 128, 128).unwrap());
    let mut floor_texels = vec![Rgb565::default(); 64 * 64];
    scene::floor_texture(&mut floor_texels).unwrap();
    let floor = MipTexture::single(Texture::new(&floor_texels, 64, 64).unwrap());
    let high = scene::directional(SceneLight::High).unwrap();
    let grazing = scene::directional(SceneLight::Grazing).unwrap();
    let spot = scene::spot().unwrap();
    let panels = [
        (
            "high-pcf2x2",
            panel::<_, Pcf2x2, 6>(&high, SceneLight::High, &tex, &floor),
        ),
        (
            "grazing-pcf3x3",
            panel::<_, Pcf3x3, 6>(&grazing, SceneLight::Grazing, &tex, &floor),
        ),
        (
            "spot-pcf2x2",
            panel::<_, Pcf2x2, 7>(&spot, SceneLight::Spot, &tex, &floor),
        ),
        (
            "high-single",
            panel::<_, SingleTap, 6>(&high, SceneLight::High, &tex, &floor),
        ),
    ];
    let mut sheet = vec![Rgb565::default(); (4 * W * H) as usize];
    for (k, (name, px)) in panels.iter().enumerate() {
        common::write_png(
            &common::out_dir().join(format!("shadow-{name}.png")),
            W,
            H,
            px,
        );
        let (ox, oy) = ((k as u32 % 2) * W, (k as u32 / 2) * H);
        for y in 0..H {
            for x in 0..W {
                sheet[((oy + y) * 2 * W + ox + x) as usize] = px[(y * W + x) as usize];
            }
        }
    }
    let path = common::out_dir().join("shadow.png");
    common::write_png(&path, 2 * W, 2 * H, &sheet);
    println!("wrote {}", path.display());
}
