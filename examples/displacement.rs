//! Displacement mapping (`fixel::scene::displace`): the demo sphere as it is
//! (its texture coloured by the height map, so the detail is only painted on), the same
//! sphere subdivided once and displaced by the height map (the silhouette turns rocky and
//! the lighting follows the recomputed normals), and a water surface: a flat grid
//! subdivided once and displaced by a tiling swell, the run-time animated case (here one
//! frame of it, and `displacement_water.gif`, 32 frames of it with the swell's offset
//! moving: the base is subdivided once and only displaced again each frame).
//!
//! `displacement_vs_bump.png` sets it beside bump mapping, all three lit per pixel: the
//! smooth sphere, the smooth sphere bump-mapped by the same surface's heights (the relief is
//! shaded, the outline stays round), and the displaced sphere (the outline is the relief's).
//!
//! `cargo run --release --example displacement` (pictures in `target/pictures/`).

#[path = "common/mod.rs"]
mod common;

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use fixel::geometry::Vertex;
use fixel::geometry::{Cull, Viewport};
use fixel::math::{fx, Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection, Shading};
use fixel::scene::{
    count_edges, count_edges_words, displace, draw_mesh, subdivide, subdivide_capacity, weld,
    weld_table_words, Camera, DirectionalLight, Displacement, Mesh, MeshStorage,
};
use fixel::scene::{tangents, LitMesh, Tangent};
use fixel::shading::bump::{Bumped, HeightDifferences};
use fixel::shading::lighting::{Phong, Specular};
use fixel::shading::{Shader, TexBinding};
use fixel::surface::Frame;
use fixel::texture::{Filter, HeightMap, Lod, MipTexture, Repeat, Texture, Trilinear, Wrap};
use fixel::Error;
use fixel_scenes::displaced::{
    grid, rock_heights, rock_heights_sized, wave_heights, ROCK_HEIGHT, ROCK_WIDTH, WAVE_SIDE,
};
use fixel_scenes::surface;
use fixel_scenes::{self as demo, MeshData};

const PANEL: u32 = 280;
const H: u32 = 240;

/// The rock's colour by height: `(height, r, g, b)`.
const ROCK_KEYS: [(u8, u8, u8, u8); 4] = [
    (40, 70, 58, 52),
    (110, 128, 112, 96),
    (150, 176, 160, 140),
    (200, 232, 226, 214),
];

/// A colour ramp over height: `keys` are `(height, r, g, b)` with 8-bit channels.
fn ramp(h: u8, keys: &[(u8, u8, u8, u8)]) -> Rgb565 {
    let mut c = (keys[0].1, keys[0].2, keys[0].3);
    for w in keys.windows(2) {
        let (a, b) = (w[0], w[1]);
        if h >= a.0 && h <= b.0 {
            let t = f64::from(h - a.0) / f64::from((b.0 - a.0).max(1));
            let l = |x: u8, y: u8| (f64::from(x) + t * (f64::from(y) - f64::from(x))) as u8;
            c = (l(a.1, b.1), l(a.2, b.2), l(a.3, b.3));
        }
    }
    if h > keys[keys.len() - 1].0 {
        let k = keys[keys.len() - 1];
        c = (k.1, k.2, k.3);
    }
    Rgb565::new(c.0 >> 3, c.1 >> 2, c.2 >> 3)
}

/// Draws triangles with `shader` into panel `k` of `frame` (per-pixel shaders).
fn draw_panel<S: Shader<Varyings = [i32; 8]>>(
    shader: S,
    tris: &[[Vertex<8>; 3]],
    frame: &mut Frame<'_, Rgb565>,
    k: u32,
) -> Result<(), Error> {
    let vp = Viewport::new(k * PANEL, 0, PANEL, H)?;
    ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back)?.clip_triangles(tris, frame)?;
    Ok(())
}

/// `displacement_vs_bump.png`: the rocky sphere lit per pixel (Blinn-Phong, the point light
/// of `fixel_scenes::surface`) three ways: smooth, bump-mapped from the same heights (per-pixel
/// differences, on a 4x finer grid of the same surface) at the
/// strength that matches the displacement (σ = scale / 256 steps over a texel's 0.0736
/// units), and displaced. Bump mapping shades the bumps but keeps the round outline.
fn versus_bump<const V: usize, const T: usize>(
    sphere: &MeshData<V, T>,
    base: &Base,
    rock: &Displacement<'_>,
    rock_px: &[Rgb565],
) -> Result<(), Error> {
    let w = 3 * PANEL;
    let sky = Rgb565::new(4, 9, 8);
    let mut color = vec![sky; (w * H) as usize];
    let mut depth = vec![0u16; (w * H) as usize];
    let mut frame = Frame::new(&mut color, w, H)?.with_depth(&mut depth)?;
    frame.clear(sky);
    let camera = Camera::perspective(
        Angle::from_degrees(fx(34)),
        fx(PANEL) / fx(H),
        fx(0.5),
        fx(40),
    )?;
    let light = surface::light(0);
    let model = Mat4::translation(Vec3::from_num(0, 0, -6.2))
        * Mat4::rotation_x(Angle::from_degrees(fx(18)))
        * Mat4::rotation_y(Angle::from_degrees(fx(-40)));
    let material = surface::material(Specular::Blinn);
    let chain = MipTexture::single(Texture::new(rock_px, ROCK_WIDTH, ROCK_HEIGHT)?);
    let tex = TexBinding::new(&chain, Trilinear::default(), Repeat, Repeat, Lod::default())?;
    let mut t = vec![Tangent::default(); V];
    tangents(
        &sphere.positions,
        &sphere.normals,
        &sphere.uvs,
        &sphere.indices,
        &mut t,
    )?;
    let smooth = LitMesh::new(
        &sphere.positions,
        &sphere.normals,
        &sphere.uvs,
        Some(&t),
        &sphere.indices,
    )?;
    let mut tris = Vec::new();
    smooth.phong_triangles(&model, &camera, &light, |t| tris.push(*t));
    draw_panel(Phong { tex, material }, &tris, &mut frame, 0)?;
    let mut tris = Vec::new();
    smooth.bump_triangles(&model, &camera, &light, |t| tris.push(*t));
    // Texel width: 2 pi 1.5 / 128 = pi 1.5 / 64 = 0.0736 units.
    let sigma = rock.scale / 256 / fx(0.0736);
    // Per-pixel height differences pick the nearest texel: the same surface's heights on a
    // 4x finer grid (`rock_heights_sized`) keep the texels smaller than the pixels.
    let (fw, fh) = (4 * ROCK_WIDTH, 4 * ROCK_HEIGHT);
    let mut fine = vec![0u8; (fw * fh) as usize];
    rock_heights_sized(fw, fh, &mut fine)?;
    let fine_px: Vec<Rgb565> = fine.iter().map(|&h| ramp(h, &ROCK_KEYS)).collect();
    let fine_chain = MipTexture::single(Texture::new(&fine_px, fw, fh)?);
    let fine_tex = TexBinding::new(
        &fine_chain,
        Trilinear::default(),
        Repeat,
        Repeat,
        Lod::default(),
    )?;
    let normals = HeightDifferences::new(HeightMap::new(&fine, fw, fh, 1)?, sigma * 4)?;
    let size = (fw, fh);
    draw_panel(
        Bumped::new(fine_tex, normals, size, material)?,
        &tris,
        &mut frame,
        1,
    )?;
    let n = base.positions.len();
    let (mut dp, mut dn) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    displace(rock, &base.mesh()?, Some(&base.twins), &mut dp, &mut dn)?;
    let mut t = vec![Tangent::default(); n];
    tangents(&dp, &dn, &base.uvs, &base.indices, &mut t)?;
    let rough = LitMesh::new(&dp, &dn, &base.uvs, Some(&t), &base.indices)?;
    let mut tris = Vec::new();
    rough.phong_triangles(&model, &camera, &light, |t| tris.push(*t));
    draw_panel(Phong { tex, material }, &tris, &mut frame, 2)?;
    let path = common::out_dir().join("displacement_vs_bump.png");
    common::write_png(&path, w, H, &color);
    println!("wrote {}", path.display());
    Ok(())
}

/// `uvs` plus `offset`: where the displacement read its heights.
fn shifted(uvs: &[[Fx; 2]], offset: [Fx; 2]) -> Vec<[Fx; 2]> {
    uvs.iter()
        .map(|c| [c[0] + offset[0], c[1] + offset[1]])
        .collect()
}

/// A mesh subdivided `levels` times and welded: the displacement's base.
struct Base {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    uvs: Vec<[Fx; 2]>,
    indices: Vec<[u16; 3]>,
    twins: Vec<u16>,
}

impl Base {
    fn new<const V: usize, const T: usize>(
        src: &MeshData<V, T>,
        levels: u32,
    ) -> Result<Self, Error> {
        let mut table = vec![0u32; count_edges_words(T)];
        let edges = count_edges(&src.indices, &mut table)?;
        let cap = subdivide_capacity(V, T, edges, levels);
        let mut b = Base {
            positions: vec![Vec3::ZERO; cap.vertices],
            normals: vec![Vec3::ZERO; cap.vertices],
            uvs: vec![[Fx::ZERO; 2]; cap.vertices],
            indices: vec![[0; 3]; cap.triangles],
            twins: vec![0; cap.vertices],
        };
        let mut table = vec![0u32; cap.edge_words.max(weld_table_words(cap.vertices))];
        let out = MeshStorage {
            positions: &mut b.positions,
            normals: Some(&mut b.normals),
            uvs: &mut b.uvs,
            indices: &mut b.indices,
        };
        let n = subdivide(&src.mesh()?, levels, out, &mut table)?.vertices();
        b.positions.truncate(n);
        b.normals.truncate(n);
        b.uvs.truncate(n);
        b.twins.truncate(n);
        weld(&b.positions, &mut table, &mut b.twins)?;
        println!(
            "{V} vertices, {T} triangles -> {n} vertices, {} triangles",
            b.indices.len()
        );
        Ok(b)
    }

    fn mesh(&self) -> Result<Mesh<'_>, Error> {
        Mesh::new(
            &self.positions,
            Some(&self.normals),
            &self.uvs,
            &self.indices,
        )
    }
}

fn main() -> Result<(), Error> {
    let w = 3 * PANEL;
    let sky = Rgb565::new(4, 9, 8);
    let mut color = vec![sky; (w * H) as usize];
    let mut depth = vec![0u16; (w * H) as usize];
    let mut frame = Frame::new(&mut color, w, H)?.with_depth(&mut depth)?;
    frame.clear(sky);
    let camera = Camera::perspective(
        Angle::from_degrees(fx(34)),
        fx(PANEL) / fx(H),
        fx(0.5),
        fx(40),
    )?;
    let light = DirectionalLight::new(Vec3::from_num(-0.6, 0.5, 0.7), fx(0.12), fx(0.95))?;
    let mode = DrawMode {
        projection: Projection::Exact,
        filter: Filter::Bilinear,
        wrap: [Wrap::Repeat, Wrap::Repeat],
        shading: Shading::Modulate,
        depth: DepthTest::Less,
        cull: Cull::Back,
        ..DrawMode::default()
    };

    // The rock: heights, and the same heights as a texture.
    let mut heights = vec![0u8; (ROCK_WIDTH * ROCK_HEIGHT) as usize];
    rock_heights(&mut heights)?;
    let rock_px: Vec<Rgb565> = heights.iter().map(|&h| ramp(h, &ROCK_KEYS)).collect();
    let rock_tex = Texture::new(&rock_px, ROCK_WIDTH, ROCK_HEIGHT)?;
    let sphere = demo::sphere();
    let model = Mat4::translation(Vec3::from_num(0, 0, -6.2))
        * Mat4::rotation_x(Angle::from_degrees(fx(18)))
        * Mat4::rotation_y(Angle::from_degrees(fx(-40)));
    let vp = Viewport::new(0, 0, PANEL, H)?;
    draw_mesh(
        &Draw::dynamic(mode, Some(rock_tex), vp)?,
        &sphere.mesh()?,
        &model,
        &camera,
        Some(&light),
        &mut frame,
    )?;
    let base = Base::new(&sphere, 1)?;
    let rock_base = Base::new(&sphere, 1)?;
    let rock = Displacement {
        map: HeightMap::new(&heights, ROCK_WIDTH, ROCK_HEIGHT, 1)?,
        scale: fx(0.45),
        bias: fx(0.5),
        offset: [Fx::ZERO; 2],
    };
    let n = base.positions.len();
    let (mut dp, mut dn) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let moved = displace(&rock, &base.mesh()?, Some(&base.twins), &mut dp, &mut dn)?;
    let vp = Viewport::new(PANEL, 0, PANEL, H)?;
    draw_mesh(
        &Draw::dynamic(mode, Some(rock_tex), vp)?,
        &moved,
        &model,
        &camera,
        Some(&light),
        &mut frame,
    )?;

    // The water: a 24 x 24 grid subdivided once, displaced by the swell.
    let mut swell = vec![0u8; (WAVE_SIDE * WAVE_SIDE) as usize];
    wave_heights(&mut swell)?;
    let water_keys = [
        (40, 8, 34, 70),
        (128, 20, 90, 140),
        (190, 60, 160, 190),
        (230, 220, 240, 245),
    ];
    let water_px: Vec<Rgb565> = swell.iter().map(|&h| ramp(h, &water_keys)).collect();
    let water_tex = Texture::new(&water_px, WAVE_SIDE, WAVE_SIDE)?;
    let flat: MeshData<{ 25 * 25 }, { 2 * 24 * 24 }> = grid(24, fx(2.4));
    let base = Base::new(&flat, 1)?;
    let water = Displacement {
        map: HeightMap::new(&swell, WAVE_SIDE, WAVE_SIDE, 1)?,
        scale: fx(0.6),
        bias: fx(0.5),
        offset: [fx(0.1), fx(0.3)],
    };
    let n = base.positions.len();
    let (mut dp, mut dn) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    displace(&water, &base.mesh()?, Some(&base.twins), &mut dp, &mut dn)?;
    // The texture is coloured by the same heights: shift its coordinates with the offset.
    let uvs = shifted(&base.uvs, water.offset);
    let moved = Mesh::new(&dp, Some(&dn), &uvs, &base.indices)?;
    let sea = Mat4::translation(Vec3::from_num(0, 0.1, -9.2))
        * Mat4::rotation_x(Angle::from_degrees(fx(26)))
        * Mat4::rotation_y(Angle::from_degrees(fx(45)));
    let vp = Viewport::new(2 * PANEL, 0, PANEL, H)?;
    draw_mesh(
        &Draw::dynamic(mode, Some(water_tex), vp)?,
        &moved,
        &sea,
        &camera,
        Some(&light),
        &mut frame,
    )?;

    let path = common::out_dir().join("displacement.png");
    common::write_png(&path, w, H, &color);
    println!("wrote {}", path.display());
    versus_bump(&sphere, &rock_base, &rock, &rock_px)?;

    // The same water animated: the offset moves one whole map (a whole number of periods
    // of every wave) in 32 frames, so the loop is seamless; only the displacement is redone
    // per frame, the subdivided base stays.
    let path = common::out_dir().join("displacement_water.gif");
    let file = std::fs::File::create(&path).expect("create GIF");
    let mut enc = gif::Encoder::new(file, PANEL as u16, H as u16, &[]).expect("GIF header");
    enc.set_repeat(gif::Repeat::Infinite).expect("GIF loop");
    let base_mesh = base.mesh()?;
    for i in 0..32 {
        let d = Displacement {
            offset: [fx(i) / 32, fx(2 * i) / 32],
            ..water
        };
        displace(&d, &base_mesh, Some(&base.twins), &mut dp, &mut dn)?;
        let uvs = shifted(&base.uvs, d.offset);
        let moved = Mesh::new(&dp, Some(&dn), &uvs, &base.indices)?;
        let mut color = vec![sky; (PANEL * H) as usize];
        let mut depth = vec![0u16; (PANEL * H) as usize];
        let mut frame = Frame::new(&mut color, PANEL, H)?.with_depth(&mut depth)?;
        frame.clear(sky);
        let vp = Viewport::new(0, 0, PANEL, H)?;
        draw_mesh(
            &Draw::dynamic(mode, Some(water_tex), vp)?,
            &moved,
            &sea,
            &camera,
            Some(&light),
            &mut frame,
        )?;
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
        let mut f = gif::Frame::from_rgb_speed(PANEL as u16, H as u16, &rgb, 10);
        f.delay = 5; // 1/100 s units: 20 fps
        enc.write_frame(&f).expect("GIF frame");
    }
    println!("wrote {}", path.display());
    Ok(())
}
