//! Golden images of texture-coordinate generation, projective quads and
//! anti-aliasing, compared bit for bit with `host-tests/golden/*.png`. Bless with
//! `FIXEL_BLESS=1 cargo test -p host-tests --test mapping_goldens` after an intended change
//! (and look at the images).

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use fixel::geometry::{Cull, Viewport};
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{
    DepthLess, DepthTest, Draw, DrawMode, Exact, Projection, ShadedDraw, Shading,
};
use fixel::scene::{
    draw_mesh, draw_quad, map_mesh, map_mesh_capacity, mesh_triangles, Axis, Camera,
    DirectionalLight, Mesh, MeshStorage, SamplePattern, UvMapping,
};
use fixel::shading::triplanar::{Triplanar, TriplanarMesh};
use fixel::surface::{BandRenderer, Binned, Frame};
use fixel::texture::{Bilinear, Filter, Texture, Wrap};
use fixel::Rgb565;
use fixel_scenes as demo;
use host_tests::golden::assert_golden;

#[allow(dead_code)]
mod teapot {
    include!("../../assets/teapot/teapot_mesh.rs");
}

const W: u32 = 160;
const H: u32 = 120;

fn raw(px: &[Rgb565]) -> Vec<u16> {
    px.iter().map(|&c| RawU16::from(c).into_inner()).collect()
}

fn checker(n: u32) -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); (n * n) as usize];
    demo::checker_texture(n, n, &mut t).unwrap();
    t
}

fn camera() -> Camera {
    Camera::perspective(
        Angle::from_degrees(Fx::from_num(40)),
        Fx::from_num(4) / 3,
        Fx::from_num(0.5),
        Fx::from_num(30),
    )
    .unwrap()
}

fn model() -> Mat4 {
    Mat4::translation(Vec3::from_num(0, -0.1, -7.5))
        * Mat4::rotation_x(Angle::from_degrees(Fx::from_num(20)))
        * Mat4::rotation_y(Angle::from_degrees(Fx::from_num(-30)))
}

#[test]
fn teapot_cylindrical_and_triplanar() {
    let t = checker(64);
    let tex = Texture::new(&t, 64, 64).unwrap();
    let (p, n, ix) = (
        &teapot::TEAPOT_POSITIONS[..],
        &teapot::TEAPOT_NORMALS[..],
        &teapot::TEAPOT_INDICES[..],
    );
    let m = UvMapping::Cylindrical {
        center: Vec3::ZERO,
        axis: Axis::Y,
        top: Fx::from_num(1.6),
        bottom: Fx::from_num(-1.6),
    };
    let need = map_mesh_capacity(&m, p, ix).unwrap();
    let (mut sp, mut sn, mut su, mut si) = (
        vec![Vec3::ZERO; need],
        vec![Vec3::ZERO; need],
        vec![[Fx::ZERO; 2]; need],
        vec![[0u16; 3]; ix.len()],
    );
    let storage = MeshStorage {
        positions: &mut sp,
        normals: Some(&mut sn),
        uvs: &mut su,
        indices: &mut si,
    };
    let mesh: Mesh<'_> = map_mesh(&m, p, Some(n), ix, storage).unwrap();
    let mode = DrawMode {
        projection: Projection::Exact,
        filter: Filter::Bilinear,
        wrap: [Wrap::Repeat, Wrap::Repeat],
        shading: Shading::Modulate,
        depth: DepthTest::Less,
        cull: Cull::Back,
        ..DrawMode::default()
    };
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let (mut c, mut d) = (
        vec![Rgb565::new(0, 0, 0); (W * H) as usize],
        vec![0u16; (W * H) as usize],
    );
    let mut frame = Frame::new(&mut c, W, H)
        .unwrap()
        .with_depth(&mut d)
        .unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    let draw = Draw::dynamic(mode, Some(tex), vp).unwrap();
    draw_mesh(
        &draw,
        &mesh,
        &model(),
        &camera(),
        Some(&DirectionalLight::default()),
        &mut frame,
    )
    .unwrap();
    assert_golden("mapping_teapot_cylindrical", W, H, &raw(&c));

    let mut tris = Vec::new();
    TriplanarMesh {
        positions: p,
        normals: n,
        indices: ix,
        texels_per_unit: Fx::from_num(24),
    }
    .triangles(
        &model(),
        &camera(),
        Some(&DirectionalLight::default()),
        |t| tris.push(*t),
    );
    let mut frame = Frame::new(&mut c, W, H)
        .unwrap()
        .with_depth(&mut d)
        .unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    ShadedDraw::<_, Exact, DepthLess>::new(Triplanar::new(tex, Bilinear), vp, Cull::Back)
        .unwrap()
        .clip_triangles(&tris, &mut frame)
        .unwrap();
    assert_golden("mapping_teapot_triplanar", W, H, &raw(&c));
}

#[test]
fn projective_quad() {
    let t = checker(64);
    let tex = Texture::new(&t, 64, 64).unwrap();
    let mode = DrawMode {
        projection: Projection::Exact,
        filter: Filter::Bilinear,
        cull: Cull::None,
        ..DrawMode::default()
    };
    let draw = Draw::dynamic(mode, Some(tex), Viewport::new(0, 0, W, H).unwrap()).unwrap();
    let mut c = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    let mut frame = Frame::new(&mut c, W, H).unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    let p = |x: f64, y: f64| [Fx::from_num(x), Fx::from_num(y)];
    draw_quad(
        &draw,
        [
            p(30.0, 12.0),
            p(140.0, 30.0),
            p(150.0, 100.0),
            p(8.0, 112.0),
        ],
        &mut frame,
    )
    .unwrap();
    assert_golden("mapping_quad", W, H, &raw(&c));
}

#[test]
fn cube_rotated_grid_in_bands() {
    let t = checker(128);
    let tex = Texture::new(&t, 128, 128).unwrap();
    let (w, h) = (320u32, 240u32);
    let mode = DrawMode {
        projection: Projection::Exact,
        filter: Filter::Bilinear,
        depth: DepthTest::Less,
        cull: Cull::Back,
        ..DrawMode::default()
    };
    let draw = Draw::dynamic(mode, Some(tex), Viewport::new(0, 0, w, h).unwrap()).unwrap();
    let (mut c, mut d) = (
        vec![Rgb565::new(0, 0, 0); (w * 8) as usize],
        vec![0u16; (w * 8) as usize],
    );
    let mut sums = vec![[0u16; 3]; (w * 8) as usize];
    let mut bins = vec![Binned::default(); 16];
    let mut offsets = [[Fx::ZERO; 2]; 4];
    SamplePattern::RotatedGrid4.offsets(&mut offsets).unwrap();
    let cube = demo::cube();
    let mesh = cube.mesh().unwrap();
    let cam = demo::camera(20);
    let light = DirectionalLight::default();
    let mut out = Vec::new();
    let mut bands = BandRenderer::new(&mut c, w, 8, h)
        .unwrap()
        .with_depth(&mut d)
        .unwrap();
    bands
        .render_accumulated(
            &[&draw],
            &mut bins,
            Rgb565::new(0, 0, 0),
            &offsets,
            &mut sums,
            |sink| {
                mesh_triangles(&mesh, &demo::cube_model(20), &cam, Some(&light), |t| {
                    draw.project(t, &mut |s| sink.push(0, s))
                })
            },
            |band| {
                out.extend_from_slice(band.pixels());
                Ok::<(), ()>(())
            },
        )
        .unwrap();
    assert_golden("aa_cube_rotated_grid", w, h, &raw(&out));
}

/// Transparency: a fence cut-out and a translucent window (alpha plane, over) and a glow
/// (additive) over the textured floor.
#[test]
fn transparency() {
    use fixel::geometry::Vertex;
    use fixel::shading::alpha::{AlphaBlend, AlphaSource, AlphaTest, BlendMode};
    use fixel::texture::Nearest;
    let (w, h) = (W, H);
    let t64 = checker(64);
    let floor_tex = Texture::new(&t64, 64, 64).unwrap();
    let t8 = checker(8);
    let q = Texture::new(&t8, 8, 8).unwrap();
    let vp = Viewport::new(0, 0, w, h).unwrap();
    let cam = Camera::perspective(
        Angle::from_degrees(Fx::from_num(45)),
        Fx::from_num(4) / 3,
        Fx::from_num(0.5),
        Fx::from_num(200),
    )
    .unwrap();
    let (mut c, mut d) = (
        vec![Rgb565::new(0, 0, 0); (w * h) as usize],
        vec![0u16; (w * h) as usize],
    );
    let mut frame = Frame::new(&mut c, w, h)
        .unwrap()
        .with_depth(&mut d)
        .unwrap();
    frame.clear(Rgb565::new(14, 30, 22));
    let mode = DrawMode {
        projection: Projection::Exact,
        filter: Filter::Bilinear,
        depth: DepthTest::Less,
        cull: Cull::Back,
        ..DrawMode::default()
    };
    let floor = demo::floor();
    draw_mesh(
        &Draw::dynamic(mode, Some(floor_tex), vp).unwrap(),
        &floor.mesh().unwrap(),
        &Mat4::IDENTITY,
        &cam,
        None,
        &mut frame,
    )
    .unwrap();
    let quad = |model: Mat4| -> Vec<[Vertex<3>; 3]> {
        let mvp = cam.projection.mul(&cam.view).mul(&model);
        let v = |x: i32, y: i32, u: i32, t: i32| {
            let p = mvp.transform_point(Vec3::from_num(x, y, 0)).unwrap();
            Vertex::new([p.x, p.y, p.z, p.w], [u << 16, t << 16, 256 << 16])
        };
        let (a, b, cc, dd) = (
            v(-1, -1, 0, 1),
            v(1, -1, 1, 1),
            v(1, 1, 1, 0),
            v(-1, 1, 0, 0),
        );
        vec![[a, b, cc], [a, cc, dd]]
    };
    let fence_a: Vec<u8> = (0..64).map(|k| if k % 4 == 3 { 0 } else { 255 }).collect();
    let glass_a: Vec<u8> = (0..64)
        .map(|k| if k % 8 == 0 || k / 8 == 0 { 255 } else { 120 })
        .collect();
    let glow_a: Vec<u8> = (0..64u32)
        .map(|k| {
            let (x, y) = (f64::from(k % 8) - 3.5, f64::from(k / 8) - 3.5);
            ((1.0 - x.hypot(y) / 4.5).max(0.0) * 255.0) as u8
        })
        .collect();
    ShadedDraw::<_, Exact, DepthLess>::new(
        AlphaTest::new(q, AlphaSource::Plane(&fence_a), 128, Nearest).unwrap(),
        vp,
        Cull::None,
    )
    .unwrap()
    .clip_triangles(
        &quad(Mat4::translation(Vec3::from_num(-1.2, -0.2, -5))),
        &mut frame,
    )
    .unwrap();
    ShadedDraw::<_, Exact, DepthLess>::new(
        AlphaBlend::new(
            q,
            AlphaSource::Plane(&glass_a),
            255,
            BlendMode::Over,
            Bilinear,
        )
        .unwrap(),
        vp,
        Cull::None,
    )
    .unwrap()
    .clip_triangles(
        &quad(Mat4::translation(Vec3::from_num(1, 0, -6))),
        &mut frame,
    )
    .unwrap();
    ShadedDraw::<_, Exact, DepthLess>::new(
        AlphaBlend::new(
            q,
            AlphaSource::Plane(&glow_a),
            200,
            BlendMode::Add,
            Bilinear,
        )
        .unwrap(),
        vp,
        Cull::None,
    )
    .unwrap()
    .clip_triangles(
        &quad(Mat4::translation(Vec3::from_num(0, 1, -4))),
        &mut frame,
    )
    .unwrap();
    assert_golden("alpha_transparency", w, h, &raw(&c));
}
