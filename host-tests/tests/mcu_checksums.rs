//! The frames the MCU firmware renders (`examples/firmware`), rendered on the host through
//! the very same code (`examples/firmware/src/scenes.rs`, band by band), and their checksums.
//!
//! `cargo xtask mcu` runs this test with `--nocapture` and compares the `mcu-expected` lines
//! it prints with what each firmware prints under QEMU: any difference fails the command.
//! The test itself checks that the band path gives the same frame as one whole-frame draw.

#[path = "../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::prelude::*;
use fixel::scene::{draw_mesh, DirectionalLight, Mesh};
use fixel::texture::MipTexture;
use fixel_scenes as demo;
#[path = "../../examples/firmware/src/aa_scene.rs"]
mod aa_scene;

#[path = "../../examples/firmware/src/edge_scene.rs"]
#[allow(dead_code)] // EDGE_RAM: the aa report's
mod edge_scene;

#[path = "../../examples/firmware/src/alpha_scene.rs"]
mod alpha_scene;

#[path = "../../examples/firmware/src/bump_scene.rs"]
mod bump_scene;

#[path = "../../examples/firmware/src/open_frame.rs"]
mod open_frame;

#[allow(dead_code)] // the scene needs no tangents
mod teapot {
    include!("../../assets/teapot/teapot_mesh.rs");
}

use scenes::{Fnv1a, FrameResult, SmallBuffers, SphereBuffers, Target, Whole, WholeTarget};

fn texture(w: u32, h: u32) -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    demo::checker_texture(w, h, &mut t).unwrap();
    t
}

/// The footprints of `tex` (the firmwares keep them in flash: `data::T128_FP`).
fn footprints(tex: &Texture<'_>) -> Vec<u64> {
    let mut p = vec![0u64; tex.texels().len()];
    fixel::texture::write_footprints(tex, &mut p).unwrap();
    p
}

/// The same frame drawn whole (one 320x240 frame, no bands), hashed the same way.
fn whole<M>(tex: Texture<'_>, mesh: &Mesh<'_>, model: &Mat4, far: i32, lit: bool) -> (u32, u32)
where
    M: fixel::pipeline::Stages + 'static,
{
    let (w, h) = (scenes::W, scenes::H);
    let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    let mut depth = vec![0u16; (w * h) as usize];
    let mut frame = Frame::new(&mut color, w, h)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    let draw = Draw::new::<M>(Some(tex), Viewport::new(0, 0, w, h).unwrap(), Cull::Back).unwrap();
    let light = DirectionalLight::default();
    let px = draw_mesh(
        &draw,
        mesh,
        model,
        &demo::camera(far),
        lit.then_some(&light),
        &mut frame,
    )
    .unwrap();
    let mut f = Fnv1a::default();
    f.pixels(frame.pixels());
    (f.0, px)
}

fn print(scene: &str, r: &FrameResult) {
    println!(
        "mcu-expected scene={scene} checksum=0x{:08x} pixels={}",
        r.checksum, r.stats.pixels
    );
}

/// The whole-frame firmware (`whole_<scene>`) must give the band firmware's frame.
fn print_whole(scene: &str, r: &FrameResult, w: &FrameResult) {
    assert_eq!(
        (w.checksum, w.stats.pixels),
        (r.checksum, r.stats.pixels),
        "{scene}: the whole-frame walker differs from the bands"
    );
    print(&format!("whole_{scene}"), w);
}

/// The sphere's frame 0 drawn by the whole-frame firmware's path in mode `M`.
fn whole_sphere<M: fixel::pipeline::Stages + 'static>(
    buf: &mut Whole,
    tex: Texture<'_>,
    mesh: &fixel::scene::Mesh<'_>,
) -> FrameResult {
    whole_sphere_mip::<M>(buf, MipTexture::single(tex), mesh)
}

/// [`whole_sphere`] from a mip chain (one with footprints, for the footprint samplers).
fn whole_sphere_mip<M: fixel::pipeline::Stages + 'static>(
    buf: &mut Whole,
    tex: MipTexture<'_>,
    mesh: &fixel::scene::Mesh<'_>,
) -> FrameResult {
    let (mut nop1, mut nop2) = (|| {}, || {});
    scenes::sphere_mip_as::<M, 0, 0, 0, 0>(
        WholeTarget::Whole(buf),
        tex,
        mesh,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap()
}

#[test]
fn mcu_frames() {
    let mut buf = Box::new(SphereBuffers::with_storage());
    let mut small = Box::new(SmallBuffers::with_storage());
    let mut whole_buf = Box::new(Whole::new());
    let (mut nop1, mut nop2) = (|| {}, || {});

    let t128 = texture(128, 128);
    let plain = Texture::new(&t128, 128, 128).unwrap();
    let f128 = footprints(&plain);
    let tex = MipTexture::single(plain).with_footprints(&f128).unwrap();
    let r = scenes::cube(Target::Bands(&mut *small), tex, 0, &mut nop1, &mut nop2).unwrap();
    print("cube", &r);
    let wr = scenes::cube(
        WholeTarget::Whole(&mut whole_buf),
        tex,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print_whole("cube", &r, &wr);
    assert!(!r.stats.rewalked);
    // The cube with silhouette anti-aliasing on each band: the same pass over the whole
    // frame gives the same pixels.
    let mut edge = Box::new(edge_scene::EdgeBuffers::new());
    let ra =
        edge_scene::aa_edge(&mut small, &mut edge, tex, 0, None, &mut nop1, &mut nop2).unwrap();
    print("aa_edge", &ra);
    assert_eq!(ra.stats.pixels, r.stats.pixels);
    {
        let mut frame = Frame::new(&mut whole_buf.color, scenes::W, scenes::H)
            .unwrap()
            .with_depth(&mut whole_buf.depth)
            .unwrap();
        frame.clear(Rgb565::new(0, 0, 0));
        let cube = demo::cube();
        let draw = Draw::new_mip::<scenes::LitFootprint>(
            Some(tex),
            Viewport::new(0, 0, scenes::W, scenes::H).unwrap(),
            Cull::Back,
        )
        .unwrap();
        let light = DirectionalLight::default();
        draw_mesh(
            &draw,
            &cube.mesh().unwrap(),
            &demo::cube_model(0),
            &demo::camera(20),
            Some(&light),
            &mut frame,
        )
        .unwrap();
        let w = scenes::W as usize;
        let (mut hc, mut hd) = (vec![Rgb565::new(0, 0, 0); 2 * w], vec![0u16; 2 * w]);
        let mut aa =
            fixel::surface::EdgeAa::new(scenes::W, edge_scene::THRESHOLD, &mut hc, &mut hd)
                .unwrap();
        let mut out = vec![Rgb565::new(0, 0, 0); frame.pixels().len()];
        let n = aa
            .band_into(frame.pixels(), frame.depth().unwrap(), true, &mut out)
            .unwrap();
        let mut f = Fnv1a::default();
        f.pixels(&out[..n]);
        assert_eq!(
            f.0, ra.checksum,
            "aa_edge: bands differ from the whole frame"
        );
    }
    let cube = demo::cube();
    // `Lit` reads the plain texels: the footprint draw gives its pixels.
    let w = whole::<scenes::Lit>(plain, &cube.mesh().unwrap(), &demo::cube_model(0), 20, true);
    assert_eq!(
        w,
        (r.checksum, r.stats.pixels),
        "cube: bands differ from the whole frame"
    );

    let t256 = texture(256, 128);
    let tex = Texture::new(&t256, 256, 128).unwrap();
    let sphere = Box::new(demo::sphere());
    let mesh = sphere.mesh().unwrap();
    let r = scenes::sphere(
        Target::Bands(&mut *buf),
        tex,
        &mesh,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print("sphere", &r);
    assert!(r.stats.reprojected && !r.stats.rewalked, "{:?}", r.stats);
    let wr = whole_sphere::<scenes::LitSphere>(&mut whole_buf, tex, &mesh);
    print_whole("sphere", &r, &wr);
    let w = whole::<scenes::LitSphere>(tex, &mesh, &demo::sphere_model(0), 20, true);
    assert_eq!(
        w,
        (r.checksum, r.stats.pixels),
        "sphere: bands differ from the whole frame"
    );
    // The same frame in the adaptive projection (whole frame only).
    let wa = whole_sphere::<scenes::LitSphereAdaptive>(&mut whole_buf, tex, &mesh);
    let w = whole::<scenes::LitSphereAdaptive>(tex, &mesh, &demo::sphere_model(0), 20, true);
    assert_eq!(
        w,
        (wa.checksum, wa.stats.pixels),
        "sphere, adaptive: the whole-frame walker differs from the plain draw"
    );
    print("whole_sphere_adaptive", &wa);
    // The same from the texture's bilinear footprints: the same pixels.
    let f256 = footprints(&tex);
    let fp = MipTexture::single(tex).with_footprints(&f256).unwrap();
    let wf = whole_sphere_mip::<scenes::LitSphereFootprint>(&mut whole_buf, fp, &mesh);
    assert_eq!(
        (wf.checksum, wf.stats.pixels),
        (wa.checksum, wa.stats.pixels),
        "sphere: footprints differ from plain bilinear"
    );
    print("whole_sphere_footprint", &wf);
    // The same with the texture's size fixed at compile time: the same pixels.
    let ws = whole_sphere_mip::<scenes::LitSphereSized>(&mut whole_buf, fp, &mesh);
    assert_eq!(
        (ws.checksum, ws.stats.pixels),
        (wf.checksum, wf.stats.pixels),
        "sphere: the sized footprints differ from the footprints"
    );
    // And in bands (the `sphere_sized` firmware, with its buffers: the set-ups it keeps).
    let mut sized_buf = Box::new(scenes::SizedSphereBuffers::with_storage());
    let rs = scenes::sphere_mip_as::<scenes::LitSphereSized, _, _, _, _>(
        Target::Bands(&mut *sized_buf),
        fp,
        &mesh,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print("sphere_sized", &rs);
    print_whole("sphere_sized", &rs, &ws);

    // Anti-aliasing (rotated grid through 4-row bands) and transparency.
    let t128b = texture(128, 128);
    let r = aa_scene::aa_cube(
        Texture::new(&t128b, 128, 128).unwrap(),
        0,
        &mut Box::new(aa_scene::AaCubeBuffers::new()),
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print("aa_cube", &r);
    // One band holding the whole frame (the whole-frame firmware; its 750 KB of buffers are
    // built on a thread with the stack for them).
    let w = std::thread::Builder::new()
        .stack_size(16 << 20)
        .spawn(|| {
            let t128 = texture(128, 128);
            let mut buf = Box::new(aa_scene::AaCubeBuffers::<{ aa_scene::WHOLE }>::sized());
            aa_scene::aa_cube(
                Texture::new(&t128, 128, 128).unwrap(),
                0,
                &mut buf,
                &mut || {},
                &mut || {},
            )
            .unwrap()
        })
        .unwrap()
        .join()
        .unwrap();
    print_whole("aa_cube", &r, &w);
    let (t64a, t8a) = (texture(64, 64), texture(8, 8));
    let r = alpha_scene::transparency(
        Texture::new(&t64a, 64, 64).unwrap(),
        Texture::new(&t8a, 8, 8).unwrap(),
        &mut Box::new(alpha_scene::AlphaBuffers::new()),
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print("transparency", &r);
    let (mut wc, mut wd) = (vec![Rgb565::new(0, 0, 0); 320 * 240], vec![0u16; 320 * 240]);
    let w = alpha_scene::transparency_in(
        Texture::new(&t64a, 64, 64).unwrap(),
        Texture::new(&t8a, 8, 8).unwrap(),
        alpha_scene::AlphaTarget::Whole(&mut wc, &mut wd),
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print_whole("transparency", &r, &w);

    // Per-pixel lighting with bump mapping: the firmware's flash tables, built here at run
    // time by the same functions.
    let (sphere, tangents) = fixel_scenes::surface::sphere().unwrap();
    let sphere = Box::new(sphere);
    let chain = fixel::texture::chain_len(bump_scene::SIZE, bump_scene::SIZE, bump_scene::LEVELS);
    let mut colours = vec![Rgb565::new(0, 0, 0); (bump_scene::SIZE * bump_scene::SIZE) as usize];
    let (mut heights, mut derivs) = (vec![0u8; chain], vec![Rgb565::new(0, 0, 0); chain]);
    let scale = fixel_scenes::surface::brick_maps(
        bump_scene::SIZE,
        bump_scene::LEVELS,
        &mut colours,
        &mut heights,
        &mut derivs,
    )
    .unwrap();
    let assets = bump_scene::BumpAssets {
        positions: &sphere.positions,
        normals: &sphere.normals,
        uvs: &sphere.uvs,
        indices: &sphere.indices,
        tangents: &tangents,
        colours: &colours,
        derivs: &derivs,
        scale,
    };
    let mut bump_buf = Box::new(bump_scene::BumpBuffers::new());
    let r = bump_scene::bump(&assets, &mut bump_buf, 0, &mut nop1, &mut nop2).unwrap();
    print("bump", &r);
    let w = bump_scene::bump_whole(
        &assets,
        &mut whole_buf.color,
        &mut whole_buf.depth,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print_whole("bump", &r, &w);

    // The teapot baked from OBJ (the firmware's `data::teapot`, the same generated file).
    let mesh = Mesh::new(
        &teapot::TEAPOT_POSITIONS,
        Some(&teapot::TEAPOT_NORMALS),
        &teapot::TEAPOT_UVS,
        &teapot::TEAPOT_INDICES,
    )
    .unwrap();
    let r = scenes::teapot(
        Target::Bands(&mut *buf),
        tex,
        &mesh,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print("teapot", &r);
    let wr = scenes::teapot(
        WholeTarget::Whole(&mut whole_buf),
        tex,
        &mesh,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print_whole("teapot", &r, &wr);
    let w = whole::<scenes::LitSphere>(tex, &mesh, &scenes::teapot_model(0), 20, true);
    assert_eq!(
        w,
        (r.checksum, r.stats.pixels),
        "teapot: bands differ from the whole frame"
    );

    let t64 = texture(64, 64);
    let tex = Texture::new(&t64, 64, 64).unwrap();
    let floor = demo::floor();
    let fm = floor.mesh().unwrap();
    let r = scenes::floor::<scenes::FloorNearest, _, _, _, _>(
        Target::Bands(&mut *small),
        MipTexture::single(tex),
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print("floor", &r);
    let wr = scenes::floor::<scenes::FloorNearest, _, _, _, _>(
        WholeTarget::Whole(&mut whole_buf),
        MipTexture::single(tex),
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print_whole("floor", &r, &wr);
    let w = whole::<scenes::FloorNearest>(tex, &fm, &Mat4::IDENTITY, 200, false);
    assert_eq!(
        w,
        (r.checksum, r.stats.pixels),
        "floor: bands differ from the whole frame"
    );

    let f64s = footprints(&tex);
    let fp = MipTexture::single(tex).with_footprints(&f64s).unwrap();
    let r = scenes::floor::<scenes::FloorBilinearFootprint, _, _, _, _>(
        Target::Bands(&mut *small),
        fp,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print("floor_bilinear", &r);
    let wr = scenes::floor::<scenes::FloorBilinearFootprint, _, _, _, _>(
        WholeTarget::Whole(&mut whole_buf),
        fp,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print_whole("floor_bilinear", &r, &wr);
    // `FloorBilinear` reads the plain texels: the footprint draw gives its pixels.
    let w = whole::<scenes::FloorBilinear>(tex, &fm, &Mat4::IDENTITY, 200, false);
    assert_eq!(
        w,
        (r.checksum, r.stats.pixels),
        "floor_bilinear: bands differ from the whole frame"
    );
    // Printed from this test, in order: a parallel test's line could follow the quiet
    // harness's progress dots and not start with `mcu-expected`.
    mcu_noise_frame();
    mcu_noise_flame();
    mcu_noise_light3d();
}

#[path = "../../examples/firmware/src/noise.rs"]
#[allow(dead_code)]
mod noise;

/// The solid-texture firmware (`examples/firmware/src/bin/noise.rs`): the same band code.
fn mcu_noise_frame() {
    use fixel::shading::noise::{BandLimit, Ramps, SolidShader};
    let ramps = Ramps::new().unwrap();
    let mut buf = Box::new(noise::NoiseBuffers::new());
    let shader = SolidShader::new(ramps.marble(), BandLimit::new(6));
    let r = noise::render(shader, &mut buf, &mut || {}, &mut || {}).unwrap();
    print("noise", &r);
    let mut color = vec![Rgb565::new(0, 0, 0); 320 * 240];
    let mut verts = Box::new([None; noise::VERTS]);
    let w = noise::render_whole(shader, &mut color, &mut verts, &mut || {}, &mut || {}).unwrap();
    print_whole("noise", &r, &w);
}

/// The flame firmware (`examples/firmware/src/bin/noise_flame.rs`).
fn mcu_noise_flame() {
    let mut color = Box::new([Rgb565::new(0, 0, 0); noise::FLAME_PIXELS]);
    let w = noise::flame_frames(&mut color, 4, &mut || {}, &mut || {}).unwrap();
    let mut band = Box::new([Rgb565::new(0, 0, 0); noise::FLAME_BAND_PIXELS]);
    let r = noise::flame_bands(&mut band, 4, &mut || {}, &mut || {}).unwrap();
    print("noise_flame", &r);
    print_whole("noise_flame", &r, &w);
}

#[path = "../../examples/firmware/src/flame_baked_scene.rs"]
mod flame_baked_scene;

/// The `noise_flame_baked` firmware (`examples/firmware/src/bin/noise_flame_baked.rs`): the
/// flame from the two layers baked here at run time (the firmware's are baked by its
/// `build.rs` with the same function); and `flame_plain`, the same quad textured.
#[test]
fn mcu_noise_flame_baked() {
    use fixel::shading::noise::{bake_flame_layer, FLAME_LAYERS, FLAME_LAYER_SIDE};
    let n = (FLAME_LAYER_SIDE * FLAME_LAYER_SIDE) as usize;
    let (mut l0, mut l1) = (vec![0u16; n], vec![0u16; n]);
    bake_flame_layer(&FLAME_LAYERS[0], FLAME_LAYER_SIDE, &mut l0).unwrap();
    bake_flame_layer(&FLAME_LAYERS[1], FLAME_LAYER_SIDE, &mut l1).unwrap();
    let mut band = Box::new([Rgb565::new(0, 0, 0); noise::FLAME_BAND_PIXELS]);
    let r = flame_baked_scene::flame_baked_bands(&mut band, [&l0, &l1], 4, &mut || {}, &mut || {})
        .unwrap();
    print("noise_flame_baked", &r);
    let t = texture(64, 64);
    let tex = Texture::new(&t, 64, 64).unwrap();
    let r =
        flame_baked_scene::flame_plain_bands(&mut band, tex, 4, &mut || {}, &mut || {}).unwrap();
    print("flame_plain", &r);
}

#[path = "../../examples/firmware/src/light3d_scene.rs"]
#[allow(dead_code, unused_imports)]
mod light3d_scene;

/// The 3D light-map firmware (`examples/firmware/src/bin/noise_light3d.rs`): the wooden
/// cube lit by the baked light map, the same band code.
fn mcu_noise_light3d() {
    use fixel::shading::noise::{BandLimit, LitSolid, Ramps};
    use fixel::texture::LodGranularity;
    let ramps = Ramps::new().unwrap();
    let mut buf = Box::new(light3d_scene::Light3dBuffers::new());
    let shader = LitSolid {
        pattern: ramps.wood(),
        octaves: BandLimit::new(6),
        light: light3d_scene::light_map().unwrap(),
        granularity: LodGranularity::Span,
    };
    let r = light3d_scene::render_light_map(shader, &mut buf, &mut || {}, &mut || {}).unwrap();
    print("noise_light3d", &r);
    let mut whole = Box::new(light3d_scene::Light3dBuffers::<{ light3d_scene::WHOLE }>::sized());
    let w = light3d_scene::render_light_map(shader, &mut whole, &mut || {}, &mut || {}).unwrap();
    print_whole("noise_light3d", &r, &w);
}

// The environment-mapping frames: `env_pixel`, `env_vertex`.
mod env_mcu;

// The run-time displacement frame: `water`.
#[path = "../../examples/firmware/src/water_scene.rs"]
#[allow(dead_code)]
mod water_scene;

#[allow(dead_code)]
mod water_base {
    include!("../../assets/displaced/water_base.rs");
}

/// The water firmware (`examples/firmware/src/bin/water.rs`, frame 3): the baked flat grid
/// displaced by the moving swell, then drawn in bands.
#[test]
fn mcu_water() {
    let mesh = Mesh::new(
        &water_base::WATER_POSITIONS,
        Some(&water_base::WATER_NORMALS),
        &water_base::WATER_UVS,
        &water_base::WATER_INDICES,
    )
    .unwrap();
    let t64 = texture(64, 64);
    let tex = Texture::new(&t64, 64, 64).unwrap();
    let mut buf = Box::new(water_scene::WaterBuffers::with_storage());
    let n = water_scene::WATER_VERTICES;
    let (mut p, mut nm) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let r = water_scene::water(
        Target::Bands(&mut *buf),
        tex,
        &mesh,
        &water_base::WATER_HEIGHTS,
        &mut p,
        &mut nm,
        3,
        &mut || {},
        &mut || {},
    )
    .unwrap();
    print("water", &r);
    let mut whole_buf = Box::new(Whole::new());
    let w = water_scene::water(
        WholeTarget::Whole(&mut whole_buf),
        tex,
        &mesh,
        &water_base::WATER_HEIGHTS,
        &mut p,
        &mut nm,
        3,
        &mut || {},
        &mut || {},
    )
    .unwrap();
    print_whole("water", &r, &w);
    // The whole frame of the same displaced mesh gives the same picture.
    let d = water_scene::water_displacement(&water_base::WATER_HEIGHTS, 3).unwrap();
    let moved = fixel::scene::displace(&d, &mesh, None, &mut p, &mut nm).unwrap();
    let w = whole::<scenes::LitSphere>(tex, &moved, &water_scene::water_model(), 20, true);
    assert_eq!(
        w,
        (r.checksum, r.stats.pixels),
        "water: bands differ from the whole frame"
    );
}

// The sphere-map (matcap) frame: `env_matcap`.
#[path = "../../examples/firmware/src/matcap_scene.rs"]
mod matcap_scene;

/// The `env_matcap` firmware (`examples/firmware/src/bin/env_matcap.rs`, frame 0): the
/// sphere through its per-vertex sphere-map coordinates and the 128 x 128 sky sphere map,
/// in bands; the whole frame of the same walk gives the same picture.
#[test]
fn mcu_env_matcap() {
    let map = host_tests::env_scene::sky_sphere_map(128);
    let tex = Texture::new(&map, 128, 128).unwrap();
    let sphere = demo::sphere();
    let planes = fixel::scene::face_planes(&sphere.positions, &sphere.indices);
    let mesh = sphere.mesh().unwrap().with_face_planes(&planes).unwrap();
    let mut buf = Box::new(SphereBuffers::with_storage());
    let (mut nop1, mut nop2) = (|| {}, || {});
    let r = matcap_scene::env_matcap(
        Target::Bands(&mut *buf),
        tex,
        &mesh,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print("env_matcap", &r);
    let mut whole_buf = Box::new(Whole::new());
    let w = matcap_scene::env_matcap(
        WholeTarget::Whole(&mut whole_buf),
        tex,
        &mesh,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    assert_eq!(
        (w.checksum, w.stats.pixels),
        (r.checksum, r.stats.pixels),
        "env_matcap: bands differ from the whole frame"
    );
}

/// The `noise_baked` firmware (`examples/firmware/src/bin/noise_baked.rs`, frame 0): the
/// sphere scene with the marble baked here at run time into the sphere's texture (the
/// firmware's is baked by its `build.rs` with the same function: equal checksums show the
/// two bakes equal).
#[test]
fn mcu_noise_baked() {
    let ramps = fixel::shading::noise::Ramps::new().unwrap();
    noise_baked("noise_baked", &ramps.marble());
}

/// The `noise_baked_wood` firmware: [`mcu_noise_baked`] with the wood.
#[test]
fn mcu_noise_baked_wood() {
    let ramps = fixel::shading::noise::Ramps::new().unwrap();
    noise_baked("noise_baked_wood", &ramps.wood());
}

/// The `noise_baked_granite` firmware: [`mcu_noise_baked`] with the granite.
#[test]
fn mcu_noise_baked_granite() {
    let ramps = fixel::shading::noise::Ramps::new().unwrap();
    noise_baked("noise_baked_granite", &ramps.granite());
}

/// The sphere scene with `pattern` baked at run time into its 256 x 128 texture (at most 6
/// octaves), in bands and whole: prints the banded checksum as `scene`.
fn noise_baked(scene: &str, pattern: &impl fixel::shading::noise::Pattern) {
    use fixel::shading::noise::{bake, BandLimit};
    let mut t = vec![Rgb565::new(0, 0, 0); 256 * 128];
    let surface = fixel_scenes::noise::baked_sphere_surface();
    bake(pattern, &BandLimit::new(6), &surface, 256, 128, &mut t).unwrap();
    let tex = Texture::new(&t, 256, 128).unwrap();
    let sphere = demo::sphere();
    let planes = fixel::scene::face_planes(&sphere.positions, &sphere.indices);
    let mesh = sphere.mesh().unwrap().with_face_planes(&planes).unwrap();
    let mut buf = Box::new(SphereBuffers::with_storage());
    let (mut nop1, mut nop2) = (|| {}, || {});
    let r = scenes::sphere(
        Target::Bands(&mut *buf),
        tex,
        &mesh,
        0,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print(scene, &r);
    assert_eq!(
        whole::<scenes::LitSphere>(tex, &mesh, &demo::sphere_model(0), 20, true),
        (r.checksum, r.stats.pixels),
        "{scene}: bands differ from the whole frame"
    );
}

/// The `bump_fast` firmware (`examples/firmware/src/bin/bump_fast.rs`, frame 0): the
/// sphere, unlit, with the brick lighting resolved here at run time into its texture (the
/// firmware's is resolved by its `build.rs` with the same function).
#[test]
fn mcu_bump_fast() {
    use fixel::shading::bump::{resolve_sphere, HeightDifferences};
    use fixel::shading::lighting::{Material, Specular};
    use fixel::texture::{chain_len, HeightMap};
    use fixel_scenes::surface;
    let (n, levels) = (64, 7);
    let mut colours = vec![Rgb565::new(0, 0, 0); 64 * 64];
    let mut heights = vec![0u8; chain_len(n, n, levels)];
    let mut derivs = vec![Rgb565::new(0, 0, 0); chain_len(n, n, levels)];
    surface::brick_maps(n, levels, &mut colours, &mut heights, &mut derivs).unwrap();
    let tile = Texture::new(&colours, n, n).unwrap();
    let map = HeightMap::new(&heights, n, n, levels).unwrap();
    let normals = HeightDifferences::new(map, Fx::from_bits(surface::RESOLVE_STRENGTH)).unwrap();
    let material = Material {
        specular: 0,
        ..surface::material(Specular::None)
    };
    let mut t = vec![Rgb565::new(0, 0, 0); 256 * 128];
    resolve_sphere(
        &tile,
        &normals,
        &material,
        surface::resolve_light(),
        256,
        128,
        &mut t,
    )
    .unwrap();
    let tex = Texture::new(&t, 256, 128).unwrap();
    let sphere = demo::sphere();
    let planes = fixel::scene::face_planes(&sphere.positions, &sphere.indices);
    let mesh = sphere.mesh().unwrap().with_face_planes(&planes).unwrap();
    let mut buf = Box::new(SphereBuffers::with_storage());
    let (mut nop1, mut nop2) = (|| {}, || {});
    let r = scenes::render::<
        scenes::FloorBilinear,
        { scenes::RANGES },
        { scenes::CACHE },
        0,
        { scenes::SETUPS },
    >(
        Target::Bands(&mut *buf),
        MipTexture::single(tex),
        &mesh,
        &demo::sphere_model(0),
        20,
        false,
        &mut nop1,
        &mut nop2,
    )
    .unwrap();
    print("bump_fast", &r);
    assert_eq!(
        whole::<scenes::FloorBilinear>(tex, &mesh, &demo::sphere_model(0), 20, false),
        (r.checksum, r.stats.pixels),
        "bump_fast: bands differ from the whole frame"
    );
}
