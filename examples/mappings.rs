//! Texture-coordinate generation on the Utah teapot, baked from its public
//! patch data (`cargo xtask teapot`, then `cargo xtask bake-obj`): the same teapot and UV
//! test grid under the planar, cylindrical and spherical generators of
//! `fixel::scene::map_mesh`, and the cylindrical one without the per-triangle seam fix (the
//! column of triangles across the seam shows the whole texture squeezed backwards), and
//! triplanar mapping per pixel (`fixel::shading::triplanar`), which needs no coordinates.
//! Also `two_stage.png`: two-stage mapping (Bier & Sloan 1986), a row per intermediate surface
//! (plane, cylinder, sphere, box) and a column per O-mapping rule (reflected ray, object
//! normal, centroid, surface normal).
//!
//! `cargo run --release --example mappings` (pictures in `target/pictures/`).

#[path = "common/mod.rs"]
mod common;

#[allow(dead_code)] // the example regenerates the coordinates and needs no tangents
mod teapot {
    include!("../assets/teapot/teapot_mesh.rs");
}

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Viewport};
use fixel::math::{fx, Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection, Shading};
use fixel::scene::{
    draw_mesh, map_mesh, map_mesh_capacity, map_mesh_capacity_with, map_mesh_with, Axis, Camera,
    DirectionalLight, Intermediate, Mesh, MeshStorage, OMapping, TwoStage, UvMapping,
};
use fixel::shading::triplanar::{Triplanar, TriplanarMesh};
use fixel::surface::Frame;
use fixel::texture::Bilinear;
use fixel::texture::{Filter, Texture, Wrap};
use fixel::Error;

const PANEL: u32 = 200;
const H: u32 = 150;

/// A UV test grid: 8 x 8 cells of hue by column and brightness by row, with dark lines,
/// and a white dot in each cell's corner showing which way is up.
fn grid_texture(n: u32) -> Vec<Rgb565> {
    let hues: [(u8, u8, u8); 8] = [
        (31, 8, 8),
        (31, 40, 4),
        (28, 60, 4),
        (6, 52, 8),
        (4, 50, 28),
        (6, 24, 31),
        (18, 10, 31),
        (30, 12, 26),
    ];
    let cell = n / 8;
    (0..n * n)
        .map(|k| {
            let (x, y) = (k % n, k / n);
            let (cx, cy) = (x / cell, y / cell);
            let (fx_, fy) = (x % cell, y % cell);
            if fx_ == 0 || fy == 0 {
                return Rgb565::new(2, 4, 2);
            }
            if fx_ <= 3 && fy <= 3 {
                return Rgb565::new(31, 63, 31);
            }
            let (r, g, b) = hues[cx as usize];
            let k = 4 + (8 - cy) as u16; // brighter at the top
            let s = |c: u8, max: u16| ((u16::from(c) * k / 12).min(max)) as u8;
            Rgb565::new(s(r, 31), s(g, 63), s(b, 31))
        })
        .collect()
}

fn mapped(mapping: &UvMapping, storage: &mut Storage) -> Result<usize, Error> {
    let out = MeshStorage {
        positions: &mut storage.0,
        normals: Some(&mut storage.1),
        uvs: &mut storage.2,
        indices: &mut storage.3,
    };
    Ok(map_mesh(
        mapping,
        &teapot::TEAPOT_POSITIONS,
        Some(&teapot::TEAPOT_NORMALS),
        &teapot::TEAPOT_INDICES,
        out,
    )?
    .vertices())
}

type Storage = (Vec<Vec3>, Vec<Vec3>, Vec<[Fx; 2]>, Vec<[u16; 3]>);

fn main() -> Result<(), Error> {
    let tex_px = grid_texture(128);
    let tex = Texture::new(&tex_px, 128, 128)?;
    let mappings = [
        (
            "planar",
            UvMapping::Planar {
                origin: Vec3::from_num(-3, 1.6, 0),
                s: Vec3::from_num(1.0 / 6.5, 0, 0),
                t: Vec3::from_num(0, -1.0 / 3.2, 0),
            },
        ),
        (
            "cylindrical",
            UvMapping::Cylindrical {
                center: Vec3::ZERO,
                axis: Axis::Y,
                top: fx(1.6),
                bottom: fx(-1.6),
            },
        ),
        (
            "spherical",
            UvMapping::Spherical {
                center: Vec3::ZERO,
                axis: Axis::Y,
            },
        ),
    ];
    let panels = mappings.len() as u32 + 2;
    let w = PANEL * panels;
    let mut color = vec![Rgb565::new(26, 54, 28); (w * H) as usize];
    let mut depth = vec![0u16; (w * H) as usize];
    let mut frame = Frame::new(&mut color, w, H)?.with_depth(&mut depth)?;
    frame.clear(Rgb565::new(26, 54, 28));
    let camera = Camera::perspective(Angle::from_degrees(fx(32)), fx(4) / 3, fx(0.5), fx(30))?;
    let light = DirectionalLight::default();
    let model = Mat4::translation(Vec3::from_num(-0.1, 0.1, -10.5))
        * Mat4::rotation_x(Angle::from_degrees(fx(20)))
        * Mat4::rotation_y(Angle::from_degrees(fx(-30)));
    let n = teapot::TEAPOT_POSITIONS.len();
    let mode = DrawMode {
        projection: Projection::Exact,
        filter: Filter::Bilinear,
        wrap: [Wrap::Repeat, Wrap::Repeat],
        shading: Shading::Modulate,
        depth: DepthTest::Less,
        cull: Cull::Back,
        ..DrawMode::default()
    };
    for (k, (name, mapping)) in mappings.iter().enumerate() {
        let need = map_mesh_capacity(mapping, &teapot::TEAPOT_POSITIONS, &teapot::TEAPOT_INDICES)?;
        let mut s: Storage = (
            vec![Vec3::ZERO; need],
            vec![Vec3::ZERO; need],
            vec![[Fx::ZERO; 2]; need],
            vec![[0; 3]; teapot::TEAPOT_INDICES.len()],
        );
        let used = mapped(mapping, &mut s)?;
        println!("{name}: {n} vertices -> {used} (seam and pole copies)");
        let mesh = Mesh::new(&s.0[..used], Some(&s.1[..used]), &s.2[..used], &s.3)?;
        let vp = Viewport::new(k as u32 * PANEL, 0, PANEL, H)?;
        let draw = Draw::dynamic(mode, Some(tex), vp)?;
        draw_mesh(&draw, &mesh, &model, &camera, Some(&light), &mut frame)?;
    }
    // The cylindrical coordinates per vertex, without the seam rule.
    let mut plain = vec![[Fx::ZERO; 2]; n];
    mappings[1]
        .1
        .generate(&teapot::TEAPOT_POSITIONS, &mut plain)?;
    let mesh = Mesh::new(
        &teapot::TEAPOT_POSITIONS,
        Some(&teapot::TEAPOT_NORMALS),
        &plain,
        &teapot::TEAPOT_INDICES,
    )?;
    let back = Mat4::translation(Vec3::from_num(-0.1, 0.1, -10.5))
        * Mat4::rotation_x(Angle::from_degrees(fx(20)))
        * Mat4::rotation_y(Angle::from_degrees(fx(150)));
    let vp = Viewport::new(3 * PANEL, 0, PANEL, H)?;
    let draw = Draw::dynamic(mode, Some(tex), vp)?;
    draw_mesh(&draw, &mesh, &back, &camera, Some(&light), &mut frame)?;
    // Triplanar: no texture coordinates at all, three projections blended by the normal.
    let mut tris = Vec::new();
    TriplanarMesh {
        positions: &teapot::TEAPOT_POSITIONS,
        normals: &teapot::TEAPOT_NORMALS,
        indices: &teapot::TEAPOT_INDICES,
        texels_per_unit: fx(40),
    }
    .triangles(&model, &camera, Some(&light), |t| tris.push(*t));
    let vp = Viewport::new(4 * PANEL, 0, PANEL, H)?;
    ShadedDraw::<_, Exact, DepthLess>::new(Triplanar::new(tex, Bilinear), vp, Cull::Back)?
        .clip_triangles(&tris, &mut frame)?;
    let path = common::out_dir().join("mappings.png");
    common::write_png(&path, w, H, &color);
    println!("wrote {}", path.display());
    two_stage(tex, &model, &camera, &light, mode)
}

/// The 4 x 4 gallery of two-stage mappings.
fn two_stage(
    tex: Texture<'_>,
    model: &Mat4,
    camera: &Camera,
    light: &DirectionalLight,
    mode: DrawMode,
) -> Result<(), Error> {
    let (pw, ph) = (PANEL, H);
    let (w, h) = (4 * pw, 4 * ph);
    let mut color = vec![Rgb565::new(26, 54, 28); (w * h) as usize];
    let mut depth = vec![0u16; (w * h) as usize];
    let mut frame = Frame::new(&mut color, w, h)?.with_depth(&mut depth)?;
    frame.clear(Rgb565::new(26, 54, 28));
    let surfaces = [
        Intermediate::Plane {
            origin: Vec3::from_num(-3, 1.75, 4),
            s: Vec3::from_num(1.0 / 6.0, 0, 0),
            t: Vec3::from_num(0, -1.0 / 3.5, 0),
        },
        Intermediate::Cylinder {
            center: Vec3::ZERO,
            axis: Axis::Y,
            radius: fx(4),
            top: fx(2),
            bottom: fx(-2),
        },
        Intermediate::Sphere {
            center: Vec3::ZERO,
            axis: Axis::Y,
            radius: fx(4),
        },
        Intermediate::Box {
            center: Vec3::ZERO,
            half: Vec3::from_num(3.6, 2, 2.2),
        },
    ];
    // The eye in model space (the camera sits at the origin of view space).
    let eye = Vec3::from_num(0, 3, 10);
    let rules = [
        OMapping::ReflectedRay { eye },
        OMapping::ObjectNormal,
        OMapping::Centroid(Vec3::from_num(0.2, 0, 0)),
        OMapping::SurfaceNormal,
    ];
    let (pos, nrm, ix) = (
        &teapot::TEAPOT_POSITIONS,
        &teapot::TEAPOT_NORMALS,
        &teapot::TEAPOT_INDICES,
    );
    for (r, &surface) in surfaces.iter().enumerate() {
        for (c, &rule) in rules.iter().enumerate() {
            let two = TwoStage { surface, rule };
            let need = map_mesh_capacity_with(&two, pos, Some(nrm), ix)?;
            let mut s: Storage = (
                vec![Vec3::ZERO; need],
                vec![Vec3::ZERO; need],
                vec![[Fx::ZERO; 2]; need],
                vec![[0; 3]; ix.len()],
            );
            let out = MeshStorage {
                positions: &mut s.0,
                normals: Some(&mut s.1),
                uvs: &mut s.2,
                indices: &mut s.3,
            };
            let mesh = map_mesh_with(&two, pos, Some(nrm), ix, out)?;
            let vp = Viewport::new(c as u32 * pw, r as u32 * ph, pw, ph)?;
            let draw = Draw::dynamic(mode, Some(tex), vp)?;
            draw_mesh(&draw, &mesh, model, camera, Some(light), &mut frame)?;
        }
    }
    let path = common::out_dir().join("two_stage.png");
    common::write_png(&path, w, h, &color);
    println!("wrote {}", path.display());
    Ok(())
}
