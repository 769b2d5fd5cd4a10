//! Solid textures from Perlin noise: a marble sphere and a wooden cube on a granite floor,
//! band-limited turbulence, lit per vertex, drawn through fixel's open fragment stage, and
//! the marble teapot (`noise_teapot.png`: the Utah teapot carved from one block), and marble
//! that changes shape over time through 4D noise (`noise_marble4d.gif`).
//! Also writes the same scene with 6 fixed octaves (aliasing on the floor) and the animated
//! flame as a GIF (48 frames, 2 s loop).
//!
//! `cargo run --release --example noise` (pictures in `target/pictures/`).

#[path = "common/mod.rs"]
mod common;
#[path = "common/light3d_cube.rs"]
#[allow(dead_code)]
mod light3d_cube;
#[allow(dead_code)] // the solid texture needs no uv or tangents
mod teapot {
    include!("../assets/teapot/teapot_mesh.rs");
}

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Fx, Mat4};
use fixel::pipeline::{DepthLess, Exact, NoDepth, ShadedDraw};
use fixel::scene::DirectionalLight;
use fixel::shading::noise::{
    BandLimit, Fixed, FlameShader, Octaves, Pattern, Ramp, Ramps, SolidMesh, SolidShader,
    FLAME_KEYS,
};
use fixel::shading::Shader;
use fixel::surface::Frame;
use fixel_scenes as demo;
use fixel_scenes::noise::{marble_sphere_model, wood_cube_model, FLOOR_SCALE, SHOWCASE_SCALE};

const W: u32 = 320;
const H: u32 = 240;

fn tris<const V: usize, const T: usize>(
    m: &demo::MeshData<V, T>,
    model: &Mat4,
    scale: Fx,
) -> Vec<[Vertex<4>; 3]> {
    let mesh = SolidMesh::new(&m.positions, Some(&m.normals), &m.indices, scale)
        .expect("the demo meshes are valid");
    let mut out = Vec::new();
    mesh.triangles(
        model,
        &demo::camera(200),
        Some(&DirectionalLight::default()),
        |t| out.push(*t),
    );
    out
}

fn draw<P: Pattern, O: Octaves>(
    shader: SolidShader<P, O>,
    tris: &[[Vertex<4>; 3]],
    frame: &mut Frame<'_, Rgb565>,
) where
    SolidShader<P, O>: Shader<Varyings = [i32; 4]>,
{
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back)
        .expect("draw")
        .clip_triangles(tris, frame)
        .expect("the frame has the depth buffer the draw tests");
}

fn render(ramps: &Ramps, fixed_octaves: Option<u8>) -> Vec<Rgb565> {
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::new(20, 40, 24); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, W, H)
        .expect("frame")
        .with_depth(&mut depth)
        .expect("depth");
    frame.clear(Rgb565::new(12, 28, 20));
    let sphere = tris(&demo::sphere(), &marble_sphere_model(), SHOWCASE_SCALE);
    let cube = tris(&demo::cube(), &wood_cube_model(), SHOWCASE_SCALE);
    let floor = tris(&demo::floor(), &Mat4::IDENTITY, FLOOR_SCALE);
    let band = BandLimit::new(6);
    match fixed_octaves {
        None => {
            draw(SolidShader::new(ramps.marble(), band), &sphere, &mut frame);
            draw(SolidShader::new(ramps.wood(), band), &cube, &mut frame);
            draw(SolidShader::new(ramps.granite(), band), &floor, &mut frame);
        }
        Some(k) => {
            draw(
                SolidShader::new(ramps.marble(), Fixed(k)),
                &sphere,
                &mut frame,
            );
            draw(SolidShader::new(ramps.wood(), Fixed(k)), &cube, &mut frame);
            draw(
                SolidShader::new(ramps.granite(), Fixed(k)),
                &floor,
                &mut frame,
            );
        }
    }
    color
}

/// The flame quad: NDC `-1..1` on both axes, flame units `x` in `-1.3..1.3`, `y` in
/// `-0.1..1.4` (bottom to top).
fn flame_quad() -> [[Vertex<2>; 3]; 2] {
    let v = |xn: f32, yn: f32, x: f32, y: f32| {
        Vertex::new(
            [Fx::from_num(xn), Fx::from_num(yn), Fx::ZERO, Fx::ONE],
            [(x * 65536.0) as i32, (y * 65536.0) as i32],
        )
    };
    let (a, b, c, d) = (
        v(-1.0, -1.0, -1.3, -0.1),
        v(1.0, -1.0, 1.3, -0.1),
        v(1.0, 1.0, 1.3, 1.4),
        v(-1.0, 1.0, -1.3, 1.4),
    );
    [[a, b, c], [a, c, d]]
}

/// The animated flame: 48 frames of 120 x 160 at 24 fps, 5 octaves.
fn flame_gif(path: &std::path::Path) {
    let (w, h) = (120u32, 160u32);
    let ramp = Ramp::from_keys(&FLAME_KEYS).expect("flame ramp");
    let file = std::fs::File::create(path).expect("create GIF");
    let mut enc = gif::Encoder::new(file, w as u16, h as u16, &[]).expect("GIF header");
    enc.set_repeat(gif::Repeat::Infinite).expect("GIF loop");
    let vp = Viewport::new(0, 0, w, h).expect("viewport");
    for i in 0..48 {
        let shader = FlameShader {
            ramp: &ramp,
            t: i * 65536 / 24,
            octaves: 5,
        };
        let draw = ShadedDraw::<_, Exact, NoDepth>::new(shader, vp, Cull::None).expect("draw");
        let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
        let mut frame = Frame::new(&mut color, w, h).expect("frame");
        draw.clip_triangles(&flame_quad(), &mut frame)
            .expect("the flame draw tests no depth");
        let rgb: Vec<u8> = color
            .iter()
            .flat_map(|p| {
                let (r, g, b) = (p.r(), p.g(), p.b());
                [
                    (r << 3) | (r >> 2),
                    (g << 2) | (g >> 4),
                    (b << 3) | (b >> 2),
                ]
            })
            .collect();
        let mut f = gif::Frame::from_rgb_speed(w as u16, h as u16, &rgb, 10);
        f.delay = 4; // 1/100 s units: 25 fps
        enc.write_frame(&f).expect("GIF frame");
        if i == 0 {
            common::write_png(&path.with_extension("png"), w, h, &color);
        }
    }
}

/// The wooden cube twice: per-vertex light (left) and the baked 3D light map (right, two
/// point lights in the cube's own space, `examples/common/light3d_cube.rs`).
fn light_map_picture(ramps: &Ramps) -> Vec<Rgb565> {
    use fixel::math::{Angle, Vec3};
    use fixel::shading::noise::{LightMap3d, LitSolid};
    use fixel::texture::LodGranularity;
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, W, H)
        .expect("frame")
        .with_depth(&mut depth)
        .expect("depth");
    frame.clear(Rgb565::new(6, 12, 10));
    let model = |x: f32| {
        Mat4::translation(Vec3::new(Fx::from_num(x), Fx::ZERO, Fx::from_num(-5.5)))
            * (Mat4::rotation_x(Angle::from_turns(5000))
                * Mat4::rotation_y(Angle::from_turns(7000)))
    };
    let band = BandLimit::new(6);
    let left = tris(&demo::cube(), &model(-1.7), SHOWCASE_SCALE);
    draw(SolidShader::new(ramps.wood(), band), &left, &mut frame);
    let right: Vec<[Vertex<3>; 3]> = tris(&demo::cube(), &model(1.7), SHOWCASE_SCALE)
        .iter()
        .map(|t| t.map(|v| Vertex::new(v.position, [v.varyings[0], v.varyings[1], v.varyings[2]])))
        .collect();
    let light = LightMap3d::new(
        &light3d_cube::CUBE_LIGHT_TEXELS,
        light3d_cube::CUBE_LIGHT_SIDE,
        light3d_cube::CUBE_LIGHT_ORIGIN,
        light3d_cube::CUBE_LIGHT_LOG2_TEXEL,
    )
    .expect("light map");
    let shader = LitSolid {
        pattern: ramps.wood(),
        octaves: band,
        light,
        granularity: LodGranularity::Span,
    };
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back)
        .expect("draw")
        .clip_triangles(&right, &mut frame)
        .expect("the frame has the depth buffer the draw tests");
    color
}

/// The marble teapot: the Utah teapot (`assets/teapot`, 1,560 triangles) carved from one
/// block of marble. The veins run through the body, spout and handle without a seam:
/// the texture is a function of the point, not of a uv layout.
fn marble_teapot(ramps: &Ramps) -> Vec<Rgb565> {
    use fixel::math::{Angle, Vec3};
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, W, H)
        .expect("frame")
        .with_depth(&mut depth)
        .expect("depth");
    frame.clear(Rgb565::new(5, 10, 6));
    let model = Mat4::translation(Vec3::new(
        Fx::from_num(-0.45),
        Fx::from_num(0.1),
        Fx::from_num(-7.0),
    )) * (Mat4::rotation_x(Angle::from_degrees(Fx::from_num(18)))
        * Mat4::rotation_y(Angle::from_degrees(Fx::from_num(-30))));
    let mesh = SolidMesh::new(
        &teapot::TEAPOT_POSITIONS,
        Some(&teapot::TEAPOT_NORMALS),
        &teapot::TEAPOT_INDICES,
        TEAPOT_SCALE,
    )
    .expect("the baked teapot is valid");
    let mut tris = Vec::new();
    mesh.triangles(
        &model,
        &demo::camera(200),
        Some(&DirectionalLight::default()),
        |t| tris.push(*t),
    );
    draw(
        SolidShader::new(ramps.marble(), BandLimit::new(6)),
        &tris,
        &mut frame,
    );
    color
}

/// Marble that changes shape over time (4D noise, `Animated`): the sphere, 160 x 120, 24
/// frames an eighth of a cell of time apart, played forwards then backwards so the GIF
/// loops.
fn animated_marble_gif(ramps: &Ramps, path: &std::path::Path) {
    use fixel::math::Vec3;
    use fixel::shading::noise::Animated;
    let (w, h) = (160u32, 120u32);
    let model = Mat4::translation(Vec3::new(Fx::ZERO, Fx::ZERO, Fx::from_num(-4.6)))
        * Mat4::rotation_y(fixel::math::Angle::from_turns(4172));
    let sphere = demo::sphere();
    let mesh = SolidMesh::new(
        &sphere.positions,
        Some(&sphere.normals),
        &sphere.indices,
        SHOWCASE_SCALE,
    )
    .expect("the demo sphere is valid");
    let mut tris = Vec::new();
    mesh.triangles(
        &model,
        &demo::camera(200),
        Some(&DirectionalLight::default()),
        |t| tris.push(*t),
    );
    let file = std::fs::File::create(path).expect("create GIF");
    let mut enc = gif::Encoder::new(file, w as u16, h as u16, &[]).expect("GIF header");
    enc.set_repeat(gif::Repeat::Infinite).expect("GIF loop");
    let vp = Viewport::new(0, 0, w, h).expect("viewport");
    let order: Vec<i32> = (0..24).chain((1..23).rev()).collect();
    for (k, &i) in order.iter().enumerate() {
        let shader = SolidShader::new(
            ramps.marble(),
            Animated {
                octaves: 5,
                t: i << 13,
            },
        );
        let draw = ShadedDraw::<_, Exact, NoDepth>::new(shader, vp, Cull::Back).expect("draw");
        let mut color = vec![Rgb565::new(5, 10, 6); (w * h) as usize];
        let mut frame = Frame::new(&mut color, w, h).expect("frame");
        draw.clip_triangles(&tris, &mut frame)
            .expect("the draw tests no depth");
        let rgb: Vec<u8> = color
            .iter()
            .flat_map(|p| {
                let (r, g, b) = (p.r(), p.g(), p.b());
                [
                    (r << 3) | (r >> 2),
                    (g << 2) | (g >> 4),
                    (b << 3) | (b >> 2),
                ]
            })
            .collect();
        let mut f = gif::Frame::from_rgb_speed(w as u16, h as u16, &rgb, 10);
        f.delay = 8; // 1/100 s units: 12.5 fps
        enc.write_frame(&f).expect("GIF frame");
        if k == 0 {
            common::write_png(&path.with_extension("png"), w, h, &color);
        }
    }
}

/// Lattice cells per teapot unit (the teapot is 6.4 units long).
const TEAPOT_SCALE: Fx = Fx::from_bits(91_750); // 1.4

fn main() {
    let ramps = Ramps::new().expect("ramps");
    let dir = common::out_dir();
    let band = render(&ramps, None);
    common::write_png(&dir.join("noise.png"), W, H, &band);
    let fixed = render(&ramps, Some(6));
    common::write_png(&dir.join("noise_fixed6.png"), W, H, &fixed);
    flame_gif(&dir.join("flame.gif"));
    animated_marble_gif(&ramps, &dir.join("noise_marble4d.gif"));
    let pot = marble_teapot(&ramps);
    common::write_png(&dir.join("noise_teapot.png"), W, H, &pot);
    let lit = light_map_picture(&ramps);
    common::write_png(&dir.join("noise_lightmap.png"), W, H, &lit);
    println!("wrote {} and flame.gif", dir.join("noise.png").display());
}
