//! Solid textures from Perlin noise: a marble sphere and a wooden cube on a granite floor,
//! band-limited turbulence, lit per vertex, drawn through fixel's open fragment stage.
//! Also writes the aliasing comparison (6 fixed octaves against band-limited) of the floor.
//!
//! `cargo run --release --example noise` (pictures in `target/pictures/`).

#[path = "common/mod.rs"]
mod common;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::demo;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Fx, Mat4};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::scene::DirectionalLight;
use fixel::shading::noise::presets::{
    marble_sphere_model, wood_cube_model, FLOOR_SCALE, SHOWCASE_SCALE,
};
use fixel::shading::noise::{BandLimit, Fixed, Octaves, Pattern, Ramps, SolidMesh, SolidShader};
use fixel::shading::Shader;
use fixel::surface::Frame;

const W: u32 = 320;
const H: u32 = 240;

fn tris<const V: usize, const T: usize>(
    m: &demo::MeshData<V, T>,
    model: &Mat4,
    scale: Fx,
) -> Vec<[Vertex<4>; 3]> {
    let mesh = SolidMesh {
        positions: &m.positions,
        normals: Some(&m.normals),
        indices: &m.indices,
        scale,
    };
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
        .clip_triangles(tris, frame);
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

fn main() {
    let ramps = Ramps::new().expect("ramps");
    let dir = common::out_dir();
    let band = render(&ramps, None);
    common::write_png(&dir.join("noise.png"), W, H, &band);
    let fixed = render(&ramps, Some(6));
    common::write_png(&dir.join("noise_fixed6.png"), W, H, &fixed);
    println!("wrote {}", dir.join("noise.png").display());
}
