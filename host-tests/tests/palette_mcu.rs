//! Palette textures on the benchmark floor and cube (`examples/firmware/src/palette_scene.rs`,
//! the frames of the firmwares `floor_palette4`, `floor_palette8`, `cube_palette4`,
//! `cube_palette8` and their RGB565 twins `floor_rgb565`, `cube_rgb565`), rendered on the
//! host through the very same code.
//!
//! `cargo xtask mcu` compares the `mcu-expected` lines printed here with the firmwares'.
//! The test checks, per scene: the bands equal a whole-frame draw; a palette frame equals
//! the RGB565 path's frame on the texture the palette expands to (the palette costs colour
//! error only, no pixel of its own); the frames equal their goldens. It prints the error of
//! each palette frame against the RGB565 frame (the report rows' error column).

#[path = "../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "../../examples/firmware/src/palette_scene.rs"]
mod palette_scene;

#[allow(dead_code)]
mod palette {
    include!("../../assets/palette/t64_p8.rs");
    include!("../../assets/palette/t64_p4.rs");
    include!("../../assets/palette/t128_p8.rs");
    include!("../../assets/palette/t128_p4.rs");
}

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::Vertex;
use fixel::pipeline::{DepthLess, ProjectionStage, QuadraticBy, ShadedDraw, SubdividedBy};
use fixel::prelude::*;
use fixel::shading::{
    ModulateIntensity, PaletteBinding, PaletteModulateIntensity, PaletteReplace, Replace, Shader,
    TexBinding,
};
use fixel::texture::{
    Bilinear, Index4, Index8, IndexFormat, Lod, MipTexture, Nearest, PaletteTexture, Repeat,
};
use fixel_scenes as demo;
use host_tests::golden::assert_golden;
use scenes::{Fnv1a, FrameResult, SmallBuffers};

fn checker(w: u32, h: u32) -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    demo::checker_texture(w, h, &mut t).unwrap();
    t
}

/// The RGB565 texels a palette texture expands to.
fn expand<I: IndexFormat>(t: &PaletteTexture<'_, I>) -> Vec<Rgb565> {
    (0..t.width() * t.height())
        .map(|k| {
            let raw = t.texel_at(k);
            Rgb565::new((raw >> 11) as u8, ((raw >> 5) & 63) as u8, (raw & 31) as u8)
        })
        .collect()
}

/// `tris` drawn with `draw` into one whole frame: its raw pixels and checksum.
fn whole<S, P, const N: usize>(
    draw: &ShadedDraw<S, P, DepthLess>,
    tris: &[[Vertex<N>; 3]],
) -> (Vec<u16>, u32)
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
{
    let (w, h) = (scenes::W, scenes::H);
    let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    let mut depth = vec![0u16; (w * h) as usize];
    let mut frame = Frame::new(&mut color, w, h)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    draw.clip_triangles(tris, &mut frame).unwrap();
    let mut f = Fnv1a::default();
    f.pixels(frame.pixels());
    (
        frame.pixels().iter().map(|c| c.into_storage()).collect(),
        f.0,
    )
}

fn bands(run: impl FnOnce(&mut SmallBuffers) -> FrameResult) -> FrameResult {
    let mut buf = Box::new(SmallBuffers::with_storage());
    run(&mut buf)
}

/// PSNR (dB, 8-bit channels) of `b` against `a`, both raw RGB565.
fn psnr(a: &[u16], b: &[u16]) -> f64 {
    let ch = |c: u16| {
        let (r, g, b) = (c >> 11, (c >> 5) & 63, c & 31);
        [
            (r << 3) | (r >> 2),
            (g << 2) | (g >> 4),
            (b << 3) | (b >> 2),
        ]
        .map(f64::from)
    };
    let se: f64 = a
        .iter()
        .zip(b)
        .map(|(&x, &y)| {
            let (x, y) = (ch(x), ch(y));
            (0..3).map(|k| (x[k] - y[k]).powi(2)).sum::<f64>()
        })
        .sum();
    10.0 * (255.0f64.powi(2) * 3.0 * a.len() as f64 / se).log10()
}

fn print(scene: &str, r: &FrameResult) {
    println!(
        "mcu-expected scene={scene} checksum=0x{:08x} pixels={}",
        r.checksum, r.stats.pixels
    );
}

fn floor_shaders<I: IndexFormat>(t: PaletteTexture<'_, I>) -> (Vec<u16>, u32, Vec<u16>) {
    let (tris, n) = palette_scene::floor_tris().unwrap();
    let tris = &tris[..n];
    let vp = Viewport::new(0, 0, scenes::W, scenes::H).unwrap();
    let pal = PaletteReplace {
        tex: PaletteBinding::new(t, Nearest, Repeat, Repeat),
    };
    let d = ShadedDraw::<_, SubdividedBy<6>, DepthLess>::new(pal, vp, Cull::Back).unwrap();
    let (px, sum) = whole(&d, tris);
    let texels = expand(&t);
    let m = MipTexture::single(Texture::new(&texels, t.width(), t.height()).unwrap());
    let tex = TexBinding::new(&m, Nearest, Repeat, Repeat, Lod::default()).unwrap();
    let d =
        ShadedDraw::<_, SubdividedBy<6>, DepthLess>::new(Replace { tex }, vp, Cull::Back).unwrap();
    let (expanded, _) = whole(&d, tris);
    (px, sum, expanded)
}

fn cube_shaders<I: IndexFormat>(t: PaletteTexture<'_, I>) -> (Vec<u16>, u32, Vec<u16>) {
    let (tris, n) = palette_scene::cube_tris().unwrap();
    let tris = &tris[..n];
    let vp = Viewport::new(0, 0, scenes::W, scenes::H).unwrap();
    let pal = PaletteModulateIntensity {
        tex: PaletteBinding::new(t, Bilinear, Repeat, Repeat),
    };
    let d = ShadedDraw::<_, QuadraticBy<4>, DepthLess>::new(pal, vp, Cull::Back).unwrap();
    let (px, sum) = whole(&d, tris);
    let texels = expand(&t);
    let m = MipTexture::single(Texture::new(&texels, t.width(), t.height()).unwrap());
    let tex = TexBinding::new(&m, Bilinear, Repeat, Repeat, Lod::default()).unwrap();
    let d =
        ShadedDraw::<_, QuadraticBy<4>, DepthLess>::new(ModulateIntensity { tex }, vp, Cull::Back)
            .unwrap();
    let (expanded, _) = whole(&d, tris);
    (px, sum, expanded)
}

#[test]
fn floor_frames() {
    let t64 = checker(64, 64);
    let m = MipTexture::single(Texture::new(&t64, 64, 64).unwrap());
    let rgb = bands(|b| palette_scene::floor_rgb565(b, &m, &mut || {}, &mut || {}).unwrap());
    print("floor_rgb565", &rgb);
    // The RGB565 frame, whole, through the same shader.
    let (tris, n) = palette_scene::floor_tris().unwrap();
    let tex = TexBinding::new(&m, Nearest, Repeat, Repeat, Lod::default()).unwrap();
    let vp = Viewport::new(0, 0, scenes::W, scenes::H).unwrap();
    let d =
        ShadedDraw::<_, SubdividedBy<6>, DepthLess>::new(Replace { tex }, vp, Cull::Back).unwrap();
    let (rgb_px, rgb_sum) = whole(&d, &tris[..n]);
    assert_eq!(
        rgb.checksum, rgb_sum,
        "floor_rgb565: bands differ from whole"
    );
    let p8 =
        PaletteTexture::<Index8>::new(&palette::T64_P8_INDICES, &palette::T64_P8_PALETTE, 64, 64)
            .unwrap();
    let p4 =
        PaletteTexture::<Index4>::new(&palette::T64_P4_INDICES, &palette::T64_P4_PALETTE, 64, 64)
            .unwrap();
    let r8 = bands(|b| palette_scene::floor_palette(b, p8, &mut || {}, &mut || {}).unwrap());
    let r4 = bands(|b| palette_scene::floor_palette(b, p4, &mut || {}, &mut || {}).unwrap());
    print("floor_palette8", &r8);
    print("floor_palette4", &r4);
    for (name, r, (px, sum, expanded)) in [
        ("floor_palette8", r8, floor_shaders(p8)),
        ("floor_palette4", r4, floor_shaders(p4)),
    ] {
        assert_eq!(r.checksum, sum, "{name}: bands differ from whole");
        assert_eq!(r.stats.pixels, rgb.stats.pixels, "{name}: pixels drawn");
        assert!(px == expanded, "{name}: differs from the expanded texture");
        println!(
            "palette-error scene={name} psnr_vs_rgb565={:.2}",
            psnr(&rgb_px, &px)
        );
        assert_golden(&format!("palette/{name}"), scenes::W, scenes::H, &px);
    }
}

#[test]
fn cube_frames() {
    let t128 = checker(128, 128);
    let m = MipTexture::single(Texture::new(&t128, 128, 128).unwrap());
    let rgb = bands(|b| palette_scene::cube_rgb565(b, &m, &mut || {}, &mut || {}).unwrap());
    print("cube_rgb565", &rgb);
    let (tris, n) = palette_scene::cube_tris().unwrap();
    let tex = TexBinding::new(&m, Bilinear, Repeat, Repeat, Lod::default()).unwrap();
    let vp = Viewport::new(0, 0, scenes::W, scenes::H).unwrap();
    let d =
        ShadedDraw::<_, QuadraticBy<4>, DepthLess>::new(ModulateIntensity { tex }, vp, Cull::Back)
            .unwrap();
    let (rgb_px, rgb_sum) = whole(&d, &tris[..n]);
    assert_eq!(
        rgb.checksum, rgb_sum,
        "cube_rgb565: bands differ from whole"
    );
    let p8 = PaletteTexture::<Index8>::new(
        &palette::T128_P8_INDICES,
        &palette::T128_P8_PALETTE,
        128,
        128,
    )
    .unwrap();
    let p4 = PaletteTexture::<Index4>::new(
        &palette::T128_P4_INDICES,
        &palette::T128_P4_PALETTE,
        128,
        128,
    )
    .unwrap();
    let r8 = bands(|b| palette_scene::cube_palette(b, p8, &mut || {}, &mut || {}).unwrap());
    let r4 = bands(|b| palette_scene::cube_palette(b, p4, &mut || {}, &mut || {}).unwrap());
    print("cube_palette8", &r8);
    print("cube_palette4", &r4);
    for (name, r, (px, sum, expanded)) in [
        ("cube_palette8", r8, cube_shaders(p8)),
        ("cube_palette4", r4, cube_shaders(p4)),
    ] {
        assert_eq!(r.checksum, sum, "{name}: bands differ from whole");
        assert_eq!(r.stats.pixels, rgb.stats.pixels, "{name}: pixels drawn");
        assert!(px == expanded, "{name}: differs from the expanded texture");
        println!(
            "palette-error scene={name} psnr_vs_rgb565={:.2}",
            psnr(&rgb_px, &px)
        );
        assert_golden(&format!("palette/{name}"), scenes::W, scenes::H, &px);
    }
}
