//! Surface detail: per-pixel lighting and bump mapping on a brick
//! sphere under a point light.
//!
//! * `lighting.png`: one plain sphere lit per vertex (Gouraud), per pixel with Phong, and
//!   per pixel with Blinn-Phong: the highlight's shape.
//! * `bump.png`: the brick sphere lit per vertex (texture times the Gouraud colour), per
//!   pixel, bump-mapped from precomputed derivatives, and normal-mapped; below, a brick
//!   wall bump-mapped from its height map as a point light passes over it.
//!
//! `cargo run --release --example surface_detail` (pictures in `target/pictures/`).

#[path = "common/mod.rs"]
mod common;

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565, RgbColor};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{fx, Angle, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::scene::{tangents, LitMesh, PixelLight, Tangent};
use fixel::shading::bump::{
    derivative_map, normal_map, Bumped, DerivativeMap, HeightDifferences, NormalMap, TangentNormals,
};
use fixel::shading::lighting::{Phong, Specular};
use fixel::shading::{Gouraud, Modulate, Shader, TexBinding};
use fixel::surface::Frame;
use fixel::texture::{
    chain_len, full_levels, generate_height_mips, generate_mips, HeightMap, Lod, MipTexture,
    Nearest, NearestMipmapNearest, Repeat, Texture, Trilinear,
};
use fixel::Error;
use fixel_scenes::bricks::{brick_colours, brick_heights};
use fixel_scenes::surface;

const PANEL: u32 = 240;
const BRICKS: u32 = 128;

fn draw<S: Shader<Varyings = [i32; N]>, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
    frame: &mut Frame<'_, Rgb565>,
    panel: (u32, u32),
) -> Result<(), Error> {
    let vp = Viewport::new(panel.0 * PANEL, panel.1 * PANEL, PANEL, PANEL)?;
    ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back)?.clip_triangles(tris, frame)?;
    Ok(())
}

fn main() -> Result<(), Error> {
    let (sphere, sphere_tangents) = surface::sphere()?;
    let mesh = LitMesh::new(
        &sphere.positions,
        &sphere.normals,
        &sphere.uvs,
        Some(&sphere_tangents),
        &sphere.indices,
    )?;
    let camera = surface::camera()?;
    let model = surface::sphere_model(0);
    let light = surface::light(0);

    // Assets: brick colours (trilinear), heights, derivatives and normals with mip chains.
    let levels = full_levels(BRICKS, BRICKS);
    let n = chain_len(BRICKS, BRICKS, levels);
    let base = (BRICKS * BRICKS) as usize;
    let mut colours = vec![Rgb565::BLACK; n];
    brick_colours(BRICKS, &mut colours[..base])?;
    generate_mips(&mut colours, BRICKS, BRICKS, levels)?;
    let mut heights = vec![0u8; n];
    brick_heights(BRICKS, &mut heights[..base])?;
    generate_height_mips(&mut heights, BRICKS, BRICKS, levels)?;
    let hmap = HeightMap::new(&heights, BRICKS, BRICKS, levels)?;
    let mut derivs = vec![Rgb565::BLACK; n];
    let scale = derivative_map(&hmap, &mut derivs)?;
    let strength = fx(0.02);
    let mut normals = vec![Rgb565::BLACK; n];
    normal_map(&hmap, strength, &mut normals)?;
    let colour_chain = MipTexture::new(&colours, BRICKS, BRICKS, levels)?;
    let deriv_chain = MipTexture::new(&derivs, BRICKS, BRICKS, levels)?;
    let normal_chain = MipTexture::new(&normals, BRICKS, BRICKS, levels)?;
    let lod = Lod::default();
    let tex = TexBinding::new(&colour_chain, Trilinear::default(), Repeat, Repeat, lod)?;
    let size = (BRICKS, BRICKS);

    // lighting.png: Gouraud, Phong, Blinn-Phong on a plain sphere.
    let (w, h) = (3 * PANEL, PANEL);
    let mut px = vec![Rgb565::new(4, 8, 6); (w * h) as usize];
    let mut depth = vec![0xFFFFu16; (w * h) as usize];
    let mut frame = Frame::new(&mut px, w, h)?.with_depth(&mut depth)?;
    frame.clear(Rgb565::new(4, 8, 6));
    let plain = Rgb565::new(28, 50, 20);
    let white = [plain];
    let plain_chain = MipTexture::single(Texture::new(&white, 1, 1)?);
    let flat = TexBinding::new(&plain_chain, Nearest, Repeat, Repeat, lod)?;
    let mut tris3 = Vec::new();
    let blinn = surface::material(Specular::Blinn);
    mesh.gouraud_triangles(&model, &camera, &light, &blinn, plain.into_storage(), |t| {
        tris3.push(*t)
    });
    draw(Gouraud, &tris3, &mut frame, (0, 0))?;
    let mut tris = Vec::new();
    mesh.phong_triangles(&model, &camera, &light, |t| tris.push(*t));
    let phong = surface::material(Specular::Phong);
    draw(
        Phong {
            tex: flat,
            material: phong,
        },
        &tris,
        &mut frame,
        (1, 0),
    )?;
    draw(
        Phong {
            tex: flat,
            material: blinn,
        },
        &tris,
        &mut frame,
        (2, 0),
    )?;
    let path = common::out_dir().join("lighting.png");
    common::write_png(&path, w, h, &px);
    println!("wrote {}", path.display());

    // bump.png, top row: the brick sphere lit per vertex (texture x Gouraud colour), per
    // pixel, bump-mapped from the derivative map and normal-mapped.
    let (w, h) = (4 * PANEL, 2 * PANEL);
    let mut px = vec![Rgb565::BLACK; (w * h) as usize];
    let mut depth = vec![0xFFFFu16; (w * h) as usize];
    let mut frame = Frame::new(&mut px, w, h)?.with_depth(&mut depth)?;
    frame.clear(Rgb565::new(3, 6, 5));
    let nv = sphere.positions.len();
    let mut lit = vec![Vertex::new([fx(0); 4], [0; 8]); nv];
    let mut col = vec![Vertex::new([fx(0); 4], [0; 3]); nv];
    mesh.phong_vertices(&model, &camera, &light, &mut lit)?;
    mesh.gouraud_vertices(&model, &camera, &light, &blinn, 0xFFFF, &mut col)?;
    let classic: Vec<Vertex<5>> = lit
        .iter()
        .zip(&col)
        .map(|(l, c)| {
            let [u, v, ..] = l.varyings;
            let [r, g, b] = c.varyings;
            Vertex::new(l.position, [u, v, r, g, b])
        })
        .collect();
    let mut tris5 = Vec::new();
    mesh.indexed(&classic, |t| tris5.push(*t));
    draw(Modulate { tex }, &tris5, &mut frame, (0, 0))?;
    draw(
        Phong {
            tex,
            material: blinn,
        },
        &tris,
        &mut frame,
        (1, 0),
    )?;
    let mut bump = Vec::new();
    mesh.bump_triangles(&model, &camera, &light, |t| bump.push(*t));
    let dbind = TexBinding::new(
        &deriv_chain,
        NearestMipmapNearest::default(),
        Repeat,
        Repeat,
        lod,
    )?;
    let dmap = DerivativeMap::new(dbind, scale, strength)?;
    bumped(tex, dmap, size, &bump, &mut frame, (2, 0))?;
    let nbind = TexBinding::new(&normal_chain, Trilinear::default(), Repeat, Repeat, lod)?;
    bumped(
        tex,
        NormalMap { map: nbind },
        size,
        &bump,
        &mut frame,
        (3, 0),
    )?;
    // Bottom row: a brick wall, turned 30 degrees, bump-mapped, as a point light passes
    // over it from left to right (the per-pixel height differences here).
    let wall_p = [
        Vec3::from_num(-1.6, 1.6, 0),
        Vec3::from_num(1.6, 1.6, 0),
        Vec3::from_num(1.6, -1.6, 0),
        Vec3::from_num(-1.6, -1.6, 0),
    ];
    let wall_n = [Vec3::from_num(0, 0, 1); 4];
    let wall_uv = [
        [fx(0), fx(0)],
        [fx(1), fx(0)],
        [fx(1), fx(1)],
        [fx(0), fx(1)],
    ];
    let wall_i = [[0u16, 3, 2], [0, 2, 1]];
    let mut wall_t = [Tangent::default(); 4];
    tangents(&wall_p, &wall_n, &wall_uv, &wall_i, &mut wall_t)?;
    let wall = LitMesh::new(&wall_p, &wall_n, &wall_uv, Some(&wall_t), &wall_i)?;
    let wall_model = Mat4::translation(Vec3::from_num(0, 0, -5.6))
        * Mat4::rotation_y(Angle::from_degrees(fx(-30)));
    for k in 0..4u32 {
        let x = -2.4 + 1.6 * f64::from(k);
        let light = PixelLight::point(Vec3::from_num(x, 0.6, -4.2))?;
        let mut tris = Vec::new();
        wall.bump_triangles(&wall_model, &camera, &light, |t| tris.push(*t));
        let heights = HeightDifferences::new(hmap, fx(0.03))?;
        bumped(tex, heights, size, &tris, &mut frame, (k, 1))?;
    }
    let path = common::out_dir().join("bump.png");
    common::write_png(&path, w, h, &px);
    println!("wrote {}", path.display());
    Ok(())
}

fn bumped<N: TangentNormals>(
    tex: TexBinding<'_, Trilinear, Repeat, Repeat>,
    normals: N,
    size: (u32, u32),
    tris: &[[Vertex<8>; 3]],
    frame: &mut Frame<'_, Rgb565>,
    panel: (u32, u32),
) -> Result<(), Error> {
    let material = surface::material(Specular::Blinn);
    draw(
        Bumped::new(tex, normals, size, material)?,
        tris,
        frame,
        panel,
    )
}
