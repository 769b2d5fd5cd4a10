//! The real-time modes beside the accurate ones they stand in for, on the benchmark
//! sphere (frame 0, 320 x 240 each panel):
//!
//! ```text
//! cargo run --release --example realtime
//! ```
//!
//! Writes to `target/pictures/`:
//! * `realtime_env.png`: left, the per-pixel reflection in the 64-texel sky cube map
//!   (`ReflectPerPixel`); middle, sphere-map coordinates per vertex and that cube map baked
//!   into a 128 x 128 sphere map (`bake_sphere_map`), a plain textured draw (`SphereMapUvs`, the `env_matcap` scene);
//!   right, the same cube map through one face per triangle and its coordinates per vertex
//!   (`CubeVertex`, the `env_cube_vertex` scene);
//! * `realtime_noise.png`: left, the marble solid texture per pixel (`SolidShader`,
//!   band-limited to 6 octaves); right, the same marble baked into a 256 x 128 texture for
//!   the sphere's own coordinates (`noise::bake`) and drawn as the textured sphere is (the
//!   `noise_baked` scene);
//! * `realtime_wood.png`, `realtime_granite.png`: the same pair for the wood and the granite
//!   (the `noise_baked_wood` and `noise_baked_granite` scenes);
//! * `realtime_flame.png`: the flame at t = 0, 1/8, 2/8, 3/8 s, top per pixel
//!   (`FlameShader`, 5 octaves), bottom from two baked tileable layers (`BakedFlame`, the
//!   `noise_flame_baked` scene), each pixel shown as 2 x 2;
//! * `realtime_bump.png`: left, the brick sphere bump-mapped per pixel (`Bumped`, height
//!   differences, a directional light); right, the same lighting resolved into a 256 x 128
//!   texture for that light fixed in object space (`bump::resolve_sphere`) and drawn unlit
//!   (the `bump_fast` scene).

mod common;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Vec3;
use fixel::pipeline::{
    DepthLess, Draw, Exact, ModulateIntensity, Pipeline, Replace, ShadedDraw, SubdividedBy,
};
use fixel::scene::{draw_mesh_walked, CachedVertex, DirectionalLight, MeshTransform, SphereMapUvs};
use fixel::shading::env::{sky, CubeMap, CubeVertex, EnvVertices, ReflectPerPixel};
use fixel::shading::noise::{bake, BandLimit, Pattern, Ramps, SolidMesh, SolidShader};
use fixel::surface::Frame;
use fixel::texture::{Bilinear, ClampToEdge, Lod, MipTexture, Repeat, Texture};
use fixel_scenes as demo;

const W: u32 = 320;
const H: u32 = 240;

type Matcap = Pipeline<SubdividedBy<6>, Bilinear, ClampToEdge, ClampToEdge, Replace, DepthLess>;
type Lit = Pipeline<SubdividedBy<6>, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;

/// A fresh frame's buffers.
fn buffers() -> (Vec<Rgb565>, Vec<u16>) {
    let n = (W * H) as usize;
    (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n])
}

/// Two frames side by side.
fn pair(a: &[Rgb565], b: &[Rgb565]) -> Vec<Rgb565> {
    row(&[a, b])
}

/// Frames side by side, left to right.
fn row(frames: &[&[Rgb565]]) -> Vec<Rgb565> {
    let w = W as usize;
    (0..H as usize)
        .flat_map(|y| frames.iter().flat_map(move |f| &f[y * w..(y + 1) * w]))
        .copied()
        .collect()
}

/// The benchmark sphere drawn with a classic draw through the mesh walker.
fn walked<G: fixel::scene::VertexUv>(
    draw: &Draw<'_, Rgb565>,
    t: MeshTransform<G>,
    lit: bool,
) -> Vec<Rgb565> {
    let s = demo::sphere();
    let mesh = s.mesh().expect("mesh");
    let (mut c, mut z) = buffers();
    let mut f = Frame::new(&mut c, W, H)
        .expect("frame")
        .with_depth(&mut z)
        .expect("depth");
    f.clear(Rgb565::new(0, 0, 0));
    let mut cache = vec![CachedVertex::EMPTY; s.positions.len()];
    let light = DirectionalLight::default();
    draw_mesh_walked(draw, &mesh, &t, lit.then_some(&light), &mut cache, &mut f).expect("drawn");
    c
}

/// The benchmark sphere's triangles, each vertex from its position and normal by `vertex`.
fn sphere_triangles<const N: usize>(
    s: &demo::MeshData<{ demo::SPHERE_VERTICES }, { demo::SPHERE_TRIANGLES }>,
    vertex: impl Fn(Vec3, Vec3) -> Option<Vertex<N>>,
) -> Vec<[Vertex<N>; 3]> {
    s.indices
        .iter()
        .map(|t| {
            t.map(|i| {
                vertex(s.positions[usize::from(i)], s.normals[usize::from(i)]).expect("vertex")
            })
        })
        .collect()
}

/// A cleared, depth-tested whole frame drawn by `draw`: its colours.
fn draw_whole(draw: impl FnOnce(&mut Frame<'_, Rgb565>)) -> Vec<Rgb565> {
    let (mut c, mut z) = buffers();
    let mut f = Frame::new(&mut c, W, H)
        .expect("frame")
        .with_depth(&mut z)
        .expect("depth");
    f.clear(Rgb565::new(0, 0, 0));
    draw(&mut f);
    c
}

fn env(out: &std::path::Path) {
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    let faces: Vec<Vec<Rgb565>> = (0..6)
        .map(|k| {
            let mut t = vec![Rgb565::new(0, 0, 0); 64 * 64];
            sky::sky_face(k, 64, &mut t).expect("face");
            t
        })
        .collect();
    let cube = CubeMap::new(
        core::array::from_fn(|i| Texture::new(&faces[i], 64, 64).expect("face")),
        Bilinear,
    )
    .expect("cube");
    let s = demo::sphere();
    let cam = demo::camera(20);
    let model = demo::sphere_model(0);
    let setup = EnvVertices::new(&model, &cam.projection.mul(&cam.view), Vec3::ZERO);
    let tris = sphere_triangles(&s, |p, n| setup.per_pixel(p, n));
    let c = draw_whole(|f| {
        ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(cube), vp, Cull::Back)
            .expect("draw")
            .clip_triangles(&tris, f)
            .expect("drawn");
    });
    let mut map = vec![Rgb565::new(0, 0, 0); 128 * 128];
    fixel::shading::env::bake_sphere_map(&cube, 128, &mut map).expect("sphere map");
    let tex = Texture::new(&map, 128, 128).expect("texture");
    let draw = Draw::new::<Matcap>(Some(tex), vp, Cull::Back).expect("draw");
    let fast = walked(
        &draw,
        MeshTransform::new(&model, &cam).with_uvs(SphereMapUvs),
        false,
    );
    let chains: [MipTexture<'_>; 6] = core::array::from_fn(|i| {
        MipTexture::single(Texture::new(&faces[i], 64, 64).expect("face"))
    });
    let per_vertex = sphere_triangles(&s, |p, n| setup.per_vertex(p, n));
    let shader = CubeVertex::new(&chains, Bilinear, Lod::default()).expect("faces");
    let cv = draw_whole(|f| {
        ShadedDraw::<_, SubdividedBy<6>, DepthLess>::new(shader, vp, Cull::Back)
            .expect("draw")
            .clip_triangles(&per_vertex, f)
            .expect("drawn");
    });
    common::write_png(
        &out.join("realtime_env.png"),
        3 * W,
        H,
        &row(&[&c, &fast, &cv]),
    );
}

/// `pattern` per pixel (left) and baked (right) into `out/name`.
fn noise(out: &std::path::Path, pattern: impl Pattern, name: &str) {
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    let s = demo::sphere();
    let cam = demo::camera(20);
    let model = demo::sphere_model(0);
    let mesh = SolidMesh::new(
        &s.positions,
        Some(&s.normals),
        &s.indices,
        fixel_scenes::noise::SHOWCASE_SCALE,
    )
    .expect("mesh");
    let mut tris = Vec::new();
    mesh.triangles(&model, &cam, Some(&DirectionalLight::default()), |t| {
        tris.push(*t)
    });
    let (mut c, mut z) = buffers();
    let mut f = Frame::new(&mut c, W, H)
        .expect("frame")
        .with_depth(&mut z)
        .expect("depth");
    f.clear(Rgb565::new(0, 0, 0));
    ShadedDraw::<_, Exact, DepthLess>::new(
        SolidShader::new(pattern, BandLimit::new(6)),
        vp,
        Cull::Back,
    )
    .expect("draw")
    .clip_triangles(&tris, &mut f)
    .expect("drawn");
    let mut t = vec![Rgb565::new(0, 0, 0); 256 * 128];
    bake(
        &pattern,
        &BandLimit::new(6),
        &fixel_scenes::noise::baked_sphere_surface(),
        256,
        128,
        &mut t,
    )
    .expect("bake");
    let tex = Texture::new(&t, 256, 128).expect("texture");
    let draw = Draw::new::<Lit>(Some(tex), vp, Cull::Back).expect("draw");
    let fast = walked(&draw, MeshTransform::new(&model, &cam), true);
    common::write_png(&out.join(name), 2 * W, H, &pair(&c, &fast));
}

/// The flame at t = 0, 1/8, 2/8, 3/8 s on the flame firmware's 80 x 96 quad: top, per
/// pixel (`FlameShader`, 5 octaves); bottom, from the two baked layers (`BakedFlame`); every
/// pixel shown as 2 x 2.
fn flame(out: &std::path::Path) {
    use fixel::pipeline::NoDepth;
    use fixel::shading::noise::{
        bake_flame_layer, BakedFlame, FlameShader, Ramp, FLAME_KEYS, FLAME_LAYERS, FLAME_LAYER_SIDE,
    };
    const FW: u32 = 80;
    const FH: u32 = 96;
    let ramp = Ramp::from_keys(&FLAME_KEYS).expect("ramp");
    let n = (FLAME_LAYER_SIDE * FLAME_LAYER_SIDE) as usize;
    let (mut l0, mut l1) = (vec![0u16; n], vec![0u16; n]);
    bake_flame_layer(&FLAME_LAYERS[0], FLAME_LAYER_SIDE, &mut l0).expect("layer 0");
    bake_flame_layer(&FLAME_LAYERS[1], FLAME_LAYER_SIDE, &mut l1).expect("layer 1");
    // The firmware's quad: x in -1.3..1.3, y in -0.1..1.4 flame units.
    let (x0, x1, y0, y1) = (-85_197, 85_197, -6_554, 91_750);
    let v = |xn: i32, yn: i32, x: i32, y: i32| {
        Vertex::new(
            [
                fixel::math::Fx::from_num(xn),
                fixel::math::Fx::from_num(yn),
                fixel::math::Fx::ZERO,
                fixel::math::Fx::ONE,
            ],
            [x, y],
        )
    };
    let (a, b, c, d) = (
        v(-1, -1, x0, y0),
        v(1, -1, x1, y0),
        v(1, 1, x1, y1),
        v(-1, 1, x0, y1),
    );
    let quad = [[a, b, c], [a, c, d]];
    let vp = Viewport::new(0, 0, FW, FH).expect("viewport");
    let (iw, ih) = (4 * FW * 2, 2 * FH * 2);
    let mut img = vec![Rgb565::new(0, 0, 0); (iw * ih) as usize];
    for i in 0..4u32 {
        let t = (i as i32) << 13;
        let mut frames = [
            vec![Rgb565::new(0, 0, 0); (FW * FH) as usize],
            vec![Rgb565::new(0, 0, 0); (FW * FH) as usize],
        ];
        let shader = FlameShader {
            ramp: &ramp,
            t,
            octaves: 5,
        };
        let mut f = Frame::new(&mut frames[0], FW, FH).expect("frame");
        ShadedDraw::<_, Exact, NoDepth>::new(shader, vp, Cull::None)
            .expect("draw")
            .clip_triangles(&quad, &mut f)
            .expect("drawn");
        let baked =
            BakedFlame::new(&ramp, &FLAME_LAYERS, [&l0, &l1], FLAME_LAYER_SIDE, t).expect("layers");
        let mut f = Frame::new(&mut frames[1], FW, FH).expect("frame");
        ShadedDraw::<_, Exact, NoDepth>::new(baked, vp, Cull::None)
            .expect("draw")
            .clip_triangles(&quad, &mut f)
            .expect("drawn");
        for (row, px) in frames.iter().enumerate() {
            for (k, &c) in px.iter().enumerate() {
                let (x, y) = (k as u32 % FW, k as u32 / FW);
                let (ox, oy) = (2 * (i * FW + x), 2 * (row as u32 * FH + y));
                for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    img[((oy + dy) * iw + ox + dx) as usize] = c;
                }
            }
        }
    }
    common::write_png(&out.join("realtime_flame.png"), iw, ih, &img);
}

fn bump(out: &std::path::Path) {
    use fixel::math::Fx;
    use fixel::scene::{LitMesh, PixelLight};
    use fixel::shading::bump::{resolve_sphere, Bumped, HeightDifferences};
    use fixel::shading::lighting::{Material, Specular};
    use fixel::shading::TexBinding;
    use fixel::texture::{chain_len, HeightMap, Lod, MipTexture};
    use fixel_scenes::surface;
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    let (n, levels) = (64, 7);
    let mut colours = vec![Rgb565::new(0, 0, 0); 64 * 64];
    let mut heights = vec![0u8; chain_len(n, n, levels)];
    let mut derivs = vec![Rgb565::new(0, 0, 0); chain_len(n, n, levels)];
    surface::brick_maps(n, levels, &mut colours, &mut heights, &mut derivs).expect("bricks");
    let material = Material {
        specular: 0,
        ..surface::material(Specular::None)
    };
    let hm = HeightMap::new(&heights, n, n, levels).expect("heights");
    let normals =
        HeightDifferences::new(hm, Fx::from_bits(surface::RESOLVE_STRENGTH)).expect("normals");
    // Per pixel.
    let (sphere, tangents) = surface::sphere().expect("sphere");
    let mesh = LitMesh::new(
        &sphere.positions,
        &sphere.normals,
        &sphere.uvs,
        Some(&tangents),
        &sphere.indices,
    )
    .expect("mesh");
    let chain = MipTexture::single(Texture::new(&colours, n, n).expect("tile"));
    let tex = TexBinding::new(&chain, Bilinear, Repeat, Repeat, Lod::default()).expect("binding");
    let shader = Bumped::new(tex, normals, (n, n), material).expect("shader");
    let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).expect("draw");
    let mut vertices = vec![Vertex::new([Fx::ZERO; 4], [0; 8]); sphere.positions.len()];
    let light = PixelLight::directional(surface::resolve_light()).expect("light");
    mesh.bump_vertices(
        &demo::sphere_model(0),
        &demo::camera(20),
        &light,
        &mut vertices,
    )
    .expect("vertices");
    let (mut c, mut z) = buffers();
    let mut f = Frame::new(&mut c, W, H)
        .expect("frame")
        .with_depth(&mut z)
        .expect("depth");
    f.clear(Rgb565::new(0, 0, 0));
    mesh.draw_indexed(&draw, &vertices, &mut f).expect("drawn");
    // Resolved once, then a plain unlit textured draw.
    let tile = Texture::new(&colours, n, n).expect("tile");
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
    .expect("resolve");
    let tex = Texture::new(&t, 256, 128).expect("texture");
    type Unlit = Pipeline<SubdividedBy<6>, Bilinear, Repeat, Repeat, Replace, DepthLess>;
    let draw = Draw::new::<Unlit>(Some(tex), vp, Cull::Back).expect("draw");
    let cam = demo::camera(20);
    let fast = walked(
        &draw,
        MeshTransform::new(&demo::sphere_model(0), &cam),
        false,
    );
    common::write_png(&out.join("realtime_bump.png"), 2 * W, H, &pair(&c, &fast));
}

fn main() {
    let out = common::out_dir();
    env(&out);
    let ramps = Ramps::new().expect("ramps");
    noise(&out, ramps.marble(), "realtime_noise.png");
    noise(&out, ramps.wood(), "realtime_wood.png");
    noise(&out, ramps.granite(), "realtime_granite.png");
    flame(&out);
    bump(&out);
    println!(
        "wrote realtime_env.png, realtime_noise.png, realtime_wood.png, realtime_granite.png, \
         realtime_flame.png, realtime_bump.png to {}",
        out.display()
    );
}
