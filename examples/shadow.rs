//! Shadow maps: the benchmark cube on a floor, its shadow from a 64 x 64 depth map drawn
//! from the light. Writes `target/pictures/shadow.png`, a 2 x 2 sheet (640 x 480):
//!
//! | | |
//! |---|---|
//! | high directional light, PCF 2x2 bilinear | grazing directional light, PCF 3x3 |
//! | spot light, PCF 2x2 bilinear | high light, single tap (the texels show) |
//!
//! and each panel alone (`shadow-*.png`), plus the high light's depth map (`shadow-map.png`);
//! `realtime_shadow.png`: the high light's single tap through light varyings (left) and in
//! its real-time form, the light coordinates from the texture coordinates (`ShadowedUv`,
//! right, the same shadow for fewer instructions);
//! and `shadow-teapot.png`: the Utah teapot (baked from OBJ, 1560 triangles) casting its
//! shadow on the floor under the high light (PCF 2x2) and the grazing light (PCF 3x3).
//!
//! `cargo run --release --example shadow`

#[path = "common/mod.rs"]
mod common;

#[allow(dead_code)] // positions, normals, uvs and indices only
mod teapot {
    include!("../assets/teapot/teapot_mesh.rs");
}

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::prelude::*;
use fixel::shading::pcf::{Pcf2x2, Pcf3x3, ShadowFilter, SingleTap};
use fixel::shading::shadow::{Bias, LightKind, LightSpace, Shadowed};
use fixel::shading::ModulateIntensity;
use fixel::surface::DepthMap;
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat};
use fixel_scenes as demo;
use fixel_scenes::shadow::{self as scene, SceneLight};

const W: u32 = demo::WIDTH;
const H: u32 = demo::HEIGHT;
const MAP: u32 = 64;

fn panel<'t, K: LightKind, F: ShadowFilter, const M: usize, const UV: bool>(
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
        let shader = Shadowed::<_, K, F, M, UV>::new(
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
    if light == SceneLight::High && F::NAME == "single tap" && !UV {
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
            panel::<_, Pcf2x2, 6, false>(&high, SceneLight::High, &tex, &floor),
        ),
        (
            "grazing-pcf3x3",
            panel::<_, Pcf3x3, 6, false>(&grazing, SceneLight::Grazing, &tex, &floor),
        ),
        (
            "spot-pcf2x2",
            panel::<_, Pcf2x2, 7, false>(&spot, SceneLight::Spot, &tex, &floor),
        ),
        (
            "high-single",
            panel::<_, SingleTap, 6, false>(&high, SceneLight::High, &tex, &floor),
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

    // The single tap through light varyings and through the texture coordinates.
    let uv = panel::<_, SingleTap, 6, true>(&high, SceneLight::High, &tex, &floor);
    let mut pair = vec![Rgb565::default(); (2 * W * H) as usize];
    for (k, px) in [&panels[3].1, &uv].iter().enumerate() {
        for y in 0..H {
            for x in 0..W {
                pair[(y * 2 * W + k as u32 * W + x) as usize] = px[(y * W + x) as usize];
            }
        }
    }
    let path = common::out_dir().join("realtime_shadow.png");
    common::write_png(&path, 2 * W, H, &pair);
    println!("wrote {}", path.display());

    // The teapot on the floor, under the high and the grazing light.
    let porcelain = [Rgb565::new(29, 58, 27)];
    let white = MipTexture::single(Texture::new(&porcelain, 1, 1).unwrap());
    let mut sheet = vec![Rgb565::default(); (2 * W * H) as usize];
    for (k, px) in [
        teapot_panel::<Pcf2x2>(&high, SceneLight::High, &white, &floor),
        teapot_panel::<Pcf3x3>(&grazing, SceneLight::Grazing, &white, &floor),
    ]
    .iter()
    .enumerate()
    {
        for y in 0..H {
            for x in 0..W {
                sheet[(y * 2 * W + k as u32 * W + x) as usize] = px[(y * W + x) as usize];
            }
        }
    }
    let path = common::out_dir().join("shadow-teapot.png");
    common::write_png(&path, 2 * W, H, &sheet);
    println!("wrote {}", path.display());
}

/// A uniform scale.
fn scale(k: fixel::math::Fx) -> Mat4 {
    let (o, z) = (fixel::math::Fx::ONE, fixel::math::Fx::ZERO);
    Mat4::from_rows([[k, z, z, z], [z, k, z, z], [z, z, k, z], [z, z, z, o]])
}

/// The teapot (scaled to the cube's size, standing on the floor) and the floor, with a
/// 128 x 128 map from the directional light `space`.
fn teapot_panel<'t, F: ShadowFilter>(
    space: &LightSpace<fixel::shading::shadow::Directional>,
    light: SceneLight,
    tex: &'t MipTexture<'t>,
    floor_tex: &'t MipTexture<'t>,
) -> Vec<Rgb565> {
    use fixel::math::{fx, Angle};
    use fixel::pipeline::DepthOnlyDraw;
    use fixel::scene::{light_pass_mesh, shadowed_mesh_triangles, Mesh};
    use fixel::shading::shadow::with_light;
    use fixel::shading::Classic;
    const TMAP: u32 = 128;
    let pot = Mesh::new(
        &teapot::TEAPOT_POSITIONS,
        Some(&teapot::TEAPOT_NORMALS),
        &teapot::TEAPOT_UVS,
        &teapot::TEAPOT_INDICES,
    )
    .unwrap();
    // The baked teapot is centred (y from -1.575 to 1.575): at 0.6 x, its base 0.945 below
    // its centre stands on the floor.
    let model = Mat4::translation(Vec3::new(fx(0.4), scene::FLOOR_Y + fx(0.945), fx(-5.2)))
        * Mat4::rotation_y(Angle::from_degrees(fx(-35)))
        * scale(fx(0.6));
    let floor_mesh = scene::floor();
    let floor = floor_mesh.mesh().unwrap();
    let mut texels = vec![0u16; (TMAP * TMAP) as usize];
    let mut map = DepthMap::new(&mut texels, TMAP).unwrap();
    map.clear();
    let depth_draw = DepthOnlyDraw::new(&map, Cull::Back).unwrap();
    light_pass_mesh(&depth_draw, &pot, &model, space, &mut map).unwrap();
    light_pass_mesh(&depth_draw, &floor, &Mat4::IDENTITY, space, &mut map).unwrap();
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let view = map.view();
    let draw = |t: &'t MipTexture<'t>| {
        let binding = TexBinding::new(t, Bilinear, Repeat, Repeat, Lod::default()).unwrap();
        let shader = Shadowed::<_, fixel::shading::shadow::Directional, F, 6>::new(
            ModulateIntensity { tex: binding },
            view,
            Bias::for_filter::<F>(),
        )
        .unwrap();
        ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).unwrap()
    };
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::default(); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, W, H)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(Rgb565::new(4, 10, 14));
    let cam = scene::camera();
    let gl = scene::gouraud_light(light);
    for (mesh, m, d) in [
        (&pot, model, draw(tex)),
        (&floor, Mat4::IDENTITY, draw(floor_tex)),
    ] {
        shadowed_mesh_triangles(mesh, &m, &cam, Some(&gl), space, |cv, lv| {
            let tri = [0, 1, 2].map(|k| {
                let inner = fixel::geometry::Vertex::new(
                    cv[k].position,
                    ModulateIntensity::<Bilinear, Repeat, Repeat>::from_classic(
                        &cv[k].to_vertex().varyings,
                    ),
                );
                with_light::<3, 6>(&inner, lv[k])
            });
            d.clip_triangles(&[tri], &mut frame).unwrap();
        });
    }
    color
}
