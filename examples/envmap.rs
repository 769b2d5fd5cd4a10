//! Environment mapping showcase: a chrome sphere and a chrome torus in a cube-mapped
//! outdoor scene (the procedural sky of `fixel::shading::env::sky`: sky, sun, a skyline of
//! windowed buildings, a checkered ground), the background drawn from the same cube map.
//!
//! ```text
//! cargo run --release --example envmap
//! ```
//!
//! Writes to `target/pictures/`:
//! * `envmap.png`: 320 x 240, per-pixel reflection, bilinear, 256-texel faces;
//! * `envmap_faces.png`: the six faces as a cross (+Y on top, -Y below, -X +Z +X -Z across);
//! * `envmap_vertex_vs_pixel.png`: the benchmark sphere (24 x 48), left per-vertex `r`,
//!   right per-pixel `r`;
//! * `envmap_cube_sphere_latlong.png`: the torus mirroring the same sky through a cube map
//!   (6 x 64²), a sphere map (128²) and a latitude-longitude map (256 x 128);
//! * `envmap_diffuse_glossy.png`: the benchmark sphere with its texture `T(256, 128)` lit
//!   by the sky (maps of 6 x 16² baked from 6 x 32² by `convolve_face`): base × irradiance,
//!   base × irradiance + 0.31 × glossy (Phong e = 16), glossy alone.

mod common;
#[path = "common/sky.rs"]
mod sky_common;
use sky_common::{background, sky_faces};

use embedded_graphics_core::pixelcolor::IntoStorage;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{fx, Angle, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::env::{
    convolve_face, sky, CubeMap, EnvLit, EnvVertices, LatLongMap, Lobe, ReflectPerPixel,
    ReflectPerVertex, SphereMap,
};
use fixel::shading::TexBinding;
use fixel::surface::Frame;
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat, Texture};
use fixel::Rgb565;

const W: u32 = 320;
const H: u32 = 240;

/// A torus about the y axis: major radius `a`, minor `b`, `nu` x `nv` quads.
fn torus(a: f64, b: f64, nu: u16, nv: u16) -> (Vec<Vec3>, Vec<Vec3>, Vec<[u16; 3]>) {
    let (mut p, mut n, mut idx) = (Vec::new(), Vec::new(), Vec::new());
    for i in 0..=nu {
        let u = 2.0 * std::f64::consts::PI * f64::from(i) / f64::from(nu);
        for j in 0..=nv {
            let v = 2.0 * std::f64::consts::PI * f64::from(j) / f64::from(nv);
            let nn = [v.cos() * u.cos(), v.sin(), -v.cos() * u.sin()];
            let c = [a * u.cos(), 0.0, -a * u.sin()];
            p.push(Vec3::from_num(
                c[0] + b * nn[0],
                c[1] + b * nn[1],
                c[2] + b * nn[2],
            ));
            n.push(Vec3::from_num(nn[0], nn[1], nn[2]));
        }
    }
    let id = |i: u16, j: u16| i * (nv + 1) + j;
    for i in 0..nu {
        for j in 0..nv {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            idx.push([a, c, b]);
            idx.push([a, d, c]);
        }
    }
    (p, n, idx)
}

fn tris<const N: usize>(
    p: &[Vec3],
    n: &[Vec3],
    idx: &[[u16; 3]],
    vert: impl Fn(Vec3, Vec3) -> Option<Vertex<N>>,
) -> Vec<[Vertex<N>; 3]> {
    idx.iter()
        .filter_map(|t| {
            let v = t.map(|i| vert(p[usize::from(i)], n[usize::from(i)]));
            Some([v[0]?, v[1]?, v[2]?])
        })
        .collect()
}

fn main() -> Result<(), fixel::Error> {
    let out = common::out_dir();
    let size = 256;
    let faces = sky_faces(size);
    let textures: [Texture<'_>; 6] =
        core::array::from_fn(|i| Texture::new(&faces[i], size, size).expect("face"));
    let cube = CubeMap::new(textures, Bilinear)?;
    let proj = Mat4::perspective(Angle::from_degrees(fx(45)), fx(4.0 / 3.0), fx(0.5), fx(20))?;
    let vp = Viewport::new(0, 0, W, H)?;

    // The main picture: the camera looks a little down, from slightly above.
    let view = Mat4::rotation_x(Angle::from_degrees(fx(8)));
    let vproj = proj.mul(&view);
    let mut color = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    let mut depth = vec![0u16; (W * H) as usize];
    background(&cube, &mut color, W, H, &view);
    {
        let mut frame = Frame::new(&mut color, W, H)?.with_depth(&mut depth)?;
        let draw = ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(cube), vp, Cull::Back)?;
        let eye = Vec3::ZERO;
        let sphere = fixel_scenes::sphere();
        let model = Mat4::translation(Vec3::from_num(-1.05, -0.35, -5.2));
        let s = EnvVertices::new(&model, &vproj, eye);
        let st = tris(
            &sphere.positions,
            &sphere.normals,
            &sphere.indices,
            |p, n| s.per_pixel(Vec3::new(p.x * fx(0.75), p.y * fx(0.75), p.z * fx(0.75)), n),
        );
        draw.clip_triangles(&st, &mut frame)?;
        let (tp, tn, ti) = torus(0.85, 0.32, 64, 24);
        let model = Mat4::translation(Vec3::from_num(1.25, -0.2, -5.6))
            * Mat4::rotation_x(Angle::from_degrees(fx(62)))
            * Mat4::rotation_z(Angle::from_degrees(fx(-18)));
        let s = EnvVertices::new(&model, &vproj, eye);
        let tt = tris(&tp, &tn, &ti, |p, n| s.per_pixel(p, n));
        draw.clip_triangles(&tt, &mut frame)?;
    }
    common::write_png(&out.join("envmap.png"), W, H, &color);

    // The faces as a cross.
    let (cw, ch) = (4 * size, 3 * size);
    let mut cross = vec![Rgb565::new(0, 0, 0); (cw * ch) as usize];
    // Layout: +Y above +Z; row 1: -X +Z +X -Z; -Y below +Z.
    for (face, (ox, oy)) in [
        (0, (2, 1)),
        (1, (0, 1)),
        (2, (1, 0)),
        (3, (1, 2)),
        (4, (1, 1)),
        (5, (3, 1)),
    ] {
        for j in 0..size {
            for i in 0..size {
                cross[((oy * size + j) * cw + ox * size + i) as usize] =
                    faces[face][(j * size + i) as usize];
            }
        }
    }
    common::write_png(&out.join("envmap_faces.png"), cw, ch, &cross);

    // Per-vertex vs per-pixel r on the benchmark sphere (radius 1.5 at z = -5).
    let mut pair = vec![Rgb565::new(0, 0, 0); (2 * W * H) as usize];
    let sphere = fixel_scenes::sphere();
    let s = EnvVertices::new(
        &Mat4::translation(Vec3::from_num(0, 0, -5)),
        &proj,
        Vec3::ZERO,
    );
    for (k, per_pixel) in [false, true].into_iter().enumerate() {
        let mut color = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        let mut depth = vec![0u16; (W * H) as usize];
        background(&cube, &mut color, W, H, &Mat4::IDENTITY);
        {
            let mut frame = Frame::new(&mut color, W, H)?.with_depth(&mut depth)?;
            if per_pixel {
                let d =
                    ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(cube), vp, Cull::Back)?;
                let t = tris(
                    &sphere.positions,
                    &sphere.normals,
                    &sphere.indices,
                    |p, n| s.per_pixel(p, n),
                );
                d.clip_triangles(&t, &mut frame)?;
            } else {
                let d =
                    ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerVertex(cube), vp, Cull::Back)?;
                let t = tris(
                    &sphere.positions,
                    &sphere.normals,
                    &sphere.indices,
                    |p, n| s.per_vertex(p, n),
                );
                d.clip_triangles(&t, &mut frame)?;
            }
        }
        for y in 0..H {
            for x in 0..W {
                pair[(y * 2 * W + k as u32 * W + x) as usize] = color[(y * W + x) as usize];
            }
        }
    }
    common::write_png(&out.join("envmap_vertex_vs_pixel.png"), 2 * W, H, &pair);
    // The three lookups side by side on the torus.
    let f64s = sky_faces(64);
    let cube64 = CubeMap::new(
        core::array::from_fn(|i| Texture::new(&f64s[i], 64, 64).expect("face")),
        Bilinear,
    )?;
    let mut st = vec![Rgb565::new(0, 0, 0); 128 * 128];
    sky::sky_spheremap(128, &mut st)?;
    let mut lt = vec![Rgb565::new(0, 0, 0); 256 * 128];
    sky::sky_latlong(256, 128, &mut lt)?;
    let sm = SphereMap::new(Texture::new(&st, 128, 128)?, Bilinear);
    let ll = LatLongMap::new(Texture::new(&lt, 256, 128)?, Bilinear);
    let (tp, tn, ti) = torus(1.0, 0.4, 64, 24);
    let model = Mat4::translation(Vec3::from_num(0, 0, -4.2))
        * Mat4::rotation_x(Angle::from_degrees(fx(55)))
        * Mat4::rotation_z(Angle::from_degrees(fx(-15)));
    let s = EnvVertices::new(&model, &proj, Vec3::ZERO);
    let tt = tris(&tp, &tn, &ti, |p, n| s.per_pixel(p, n));
    let mut three = vec![Rgb565::new(0, 0, 0); (3 * W * H) as usize];
    for k in 0..3 {
        let mut color = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        let mut depth = vec![0u16; (W * H) as usize];
        background(&cube64, &mut color, W, H, &Mat4::IDENTITY);
        {
            let mut frame = Frame::new(&mut color, W, H)?.with_depth(&mut depth)?;
            match k {
                0 => {
                    ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(cube64), vp, Cull::Back)?
                        .clip_triangles(&tt, &mut frame)?
                }
                1 => ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(sm), vp, Cull::Back)?
                    .clip_triangles(&tt, &mut frame)?,
                _ => ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(ll), vp, Cull::Back)?
                    .clip_triangles(&tt, &mut frame)?,
            };
        }
        for y in 0..H {
            for x in 0..W {
                three[(y * 3 * W + k * W + x) as usize] = color[(y * W + x) as usize];
            }
        }
    }
    common::write_png(
        &out.join("envmap_cube_sphere_latlong.png"),
        3 * W,
        H,
        &three,
    );

    // Diffuse + glossy on the textured benchmark sphere.
    let src: Vec<Vec<u16>> = sky_faces(32)
        .iter()
        .map(|f| f.iter().map(|c| c.into_storage()).collect())
        .collect();
    let srcs: [&[u16]; 6] = core::array::from_fn(|i| &src[i][..]);
    let bake = |lobe| -> Result<Vec<Vec<Rgb565>>, fixel::Error> {
        (0..6)
            .map(|f| {
                let mut o = vec![Rgb565::new(0, 0, 0); 16 * 16];
                convolve_face(srcs, 32, lobe, f, 16, &mut o)?;
                Ok(o)
            })
            .collect()
    };
    let (diff, glos) = (bake(Lobe::Cosine)?, bake(Lobe::Phong(16))?);
    let dcube = CubeMap::new(
        core::array::from_fn(|i| Texture::new(&diff[i], 16, 16).expect("face")),
        Bilinear,
    )?;
    let gcube = CubeMap::new(
        core::array::from_fn(|i| Texture::new(&glos[i], 16, 16).expect("face")),
        Bilinear,
    )?;
    let mut base = vec![Rgb565::new(0, 0, 0); 256 * 128];
    fixel_scenes::checker_texture(256, 128, &mut base)?;
    let black = [Rgb565::new(0, 0, 0); 1];
    let none = CubeMap::new([Texture::new(&black, 1, 1)?; 6], Bilinear)?;
    let mip = MipTexture::single(Texture::new(&base, 256, 128)?);
    let binding = TexBinding::new(&mip, Bilinear, Repeat, Repeat, Lod::default())?;
    let sphere = fixel_scenes::sphere();
    let s = EnvVertices::new(&fixel_scenes::sphere_model(0), &proj, Vec3::ZERO);
    let t8: Vec<[Vertex<8>; 3]> = sphere
        .indices
        .iter()
        .filter_map(|t| {
            let v = t.map(|i| {
                let i = usize::from(i);
                let v = s.per_pixel(sphere.positions[i], sphere.normals[i])?;
                let a = v.varyings;
                let uv = sphere.uvs[i].map(|c| c.to_bits());
                Some(Vertex::new(
                    v.position,
                    [a[0], a[1], a[2], a[3], a[4], a[5], uv[0], uv[1]],
                ))
            });
            Some([v[0]?, v[1]?, v[2]?])
        })
        .collect();
    let mut dg = vec![Rgb565::new(0, 0, 0); (3 * W * H) as usize];
    for k in 0..3u32 {
        let mut color = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        let mut depth = vec![0u16; (W * H) as usize];
        background(&cube, &mut color, W, H, &Mat4::IDENTITY);
        {
            let mut frame = Frame::new(&mut color, W, H)?.with_depth(&mut depth)?;
            let shader = match k {
                0 => EnvLit {
                    base: binding,
                    diffuse: dcube,
                    glossy: none,
                    specular: 256,
                },
                1 => EnvLit {
                    base: binding,
                    diffuse: dcube,
                    glossy: gcube,
                    specular: 80,
                },
                _ => EnvLit {
                    base: binding,
                    diffuse: none,
                    glossy: gcube,
                    specular: 256,
                },
            };
            ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back)?
                .clip_triangles(&t8, &mut frame)?;
        }
        for y in 0..H {
            for x in 0..W {
                dg[(y * 3 * W + k * W + x) as usize] = color[(y * W + x) as usize];
            }
        }
    }
    common::write_png(&out.join("envmap_diffuse_glossy.png"), 3 * W, H, &dg);
    println!(
        "wrote envmap.png, envmap_faces.png, envmap_vertex_vs_pixel.png, envmap_cube_sphere_latlong.png, envmap_diffuse_glossy.png to {}",
        out.display()
    );
    Ok(())
}
