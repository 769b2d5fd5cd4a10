//! Surface detail (seed 000 §3, seed 004): per-pixel lighting and bump mapping on a brick
//! sphere under a point light.
//!
//! * `lighting.png`: one plain sphere lit per vertex (Gouraud), per pixel with Phong, and
//!   per pixel with Blinn-Phong: the highlight's shape.
//! * `bump.png`: the brick sphere with Phong lighting only, bump-mapped from precomputed
//!   derivatives, bump-mapped from the height map per pixel, and normal-mapped; below, the
//!   derivative-mapped sphere as the light circles it.
//!
//! `cargo run --release --example surface_detail` (pictures in `target/pictures/`).

#[path = "common/mod.rs"]
mod common;

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565, RgbColor};
use fixel::demo::bricks::{brick_colours, brick_heights};
use fixel::demo::surface;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::fx;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::scene::LitMesh;
use fixel::shading::bump::{
    derivative_map, normal_map, Bumped, DerivativeMap, HeightDifferences, NormalMap, TangentNormals,
};
use fixel::shading::lighting::{Phong, Specular};
use fixel::shading::{Gouraud, Shader, TexBinding};
use fixel::surface::Frame;
use fixel::texture::{
    chain_len, full_levels, generate_height_mips, generate_mips, HeightMap, Lod, MipTexture,
    Nearest, NearestMipmapNearest, Repeat, Texture, Trilinear,
};
use fixel::Error;

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
    let (sphere, tangents) = surface::sphere()?;
    let mesh = LitMesh::new(
        &sphere.positions,
        &sphere.normals,
        &sphere.uvs,
        Some(&tangents),
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

    // bump.png: four ways on the top row, the light circling on the bottom row.
    let (w, h) = (4 * PANEL, 2 * PANEL);
    let mut px = vec![Rgb565::BLACK; (w * h) as usize];
    let mut depth = vec![0xFFFFu16; (w * h) as usize];
    let mut frame = Frame::new(&mut px, w, h)?.with_depth(&mut depth)?;
    frame.clear(Rgb565::new(3, 6, 5));
    draw(
        Phong {
            tex,
            material: blinn,
        },
        &tris,
        &mut frame,
        (0, 0),
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
    bumped(tex, dmap, size, &bump, &mut frame, (1, 0))?;
    bumped(
        tex,
        HeightDifferences::new(hmap, strength)?,
        size,
        &bump,
        &mut frame,
        (2, 0),
    )?;
    let nbind = TexBinding::new(&normal_chain, Trilinear::default(), Repeat, Repeat, lod)?;
    bumped(
        tex,
        NormalMap { map: nbind },
        size,
        &bump,
        &mut frame,
        (3, 0),
    )?;
    for (k, i) in [2u32, 0, 14, 12].into_iter().enumerate() {
        let k = k as u32;
        let mut tris = Vec::new();
        mesh.bump_triangles(
            &surface::sphere_model(0),
            &camera,
            &surface::light(i),
            |t| tris.push(*t),
        );
        bumped(tex, dmap, size, &tris, &mut frame, (k, 1))?;
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
