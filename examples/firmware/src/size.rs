//! The `size_*` firmwares of `cargo xtask size`: one textured triangle through the scene
//! path (mesh -> camera -> clip -> bands), each with a different set of stages, so the flash
//! of "a firmware that uses one mode" can be compared in bytes. `size_base` is the same
//! harness without fixel (its flash is subtracted to get fixel's share).

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::math::{Fx, Mat4, Vec3};
use fixel::pipeline::{Draw, DrawMode, Stages};
use fixel::prelude::{BandRenderer, Cull, Viewport};
use fixel::scene::{mesh_triangles, DirectionalLight, Mesh};
use fixel::surface::{Binned, Frame};
use fixel::texture::{MipTexture, Texture};
use fixel_scenes as demo;

use crate::data;
use crate::scenes::{Fnv1a, H, ROWS, W};

const BAND: usize = (W * ROWS) as usize;

/// The triangle every `size_*` firmware draws (model space, in front of `demo::camera`).
pub static POSITIONS: [Vec3; 3] = [
    Vec3::new(
        Fx::from_bits(-65536),
        Fx::from_bits(-65536),
        Fx::from_bits(-3 << 16),
    ),
    Vec3::new(
        Fx::from_bits(65536),
        Fx::from_bits(-65536),
        Fx::from_bits(-3 << 16),
    ),
    Vec3::new(
        Fx::from_bits(0),
        Fx::from_bits(65536),
        Fx::from_bits(-4 << 16),
    ),
];
/// Its normals (facing the camera).
pub static NORMALS: [Vec3; 3] = [Vec3::new(Fx::ZERO, Fx::ZERO, Fx::ONE); 3];
pub static UVS: [[Fx; 2]; 3] = [
    [Fx::ZERO, Fx::ZERO],
    [Fx::from_bits(2 << 16), Fx::ZERO],
    [Fx::ONE, Fx::from_bits(2 << 16)],
];
/// Its one triangle.
pub static INDICES: [[u16; 3]; 1] = [[0, 1, 2]];

/// Draws the triangle with `draw` in bands (depth band only when `depth`), lit when `LIT`;
/// returns (checksum, pixels). The light is a constant inside the geometry closure, as a
/// firmware writes it: an unlit firmware passes `None` and links no lighting.
fn frame<const LIT: bool, const CLIP: bool>(
    draw: &Draw<'_, Rgb565>,
    depth: bool,
) -> Option<(u32, u32)> {
    let mut color = [Rgb565::new(0, 0, 0); BAND];
    let mut zbuf = [0u16; BAND];
    let mut bins = [Binned::default(); 4];
    let mesh = Mesh::new(&POSITIONS, Some(&NORMALS), &UVS, &INDICES).ok()?;
    let camera = demo::camera(20);
    let sun = DirectionalLight::default();
    let mut bands = BandRenderer::new(&mut color, W, ROWS, H).ok()?;
    if depth {
        bands = bands.with_depth(&mut zbuf).ok()?;
    }
    let mut sum = Fnv1a::default();
    let stats = bands
        .render(
            &[draw],
            &mut bins,
            Rgb565::new(0, 0, 0),
            |sink| {
                let light = if LIT { Some(&sun) } else { None };
                mesh_triangles(&mesh, &Mat4::IDENTITY, &camera, light, |t| {
                    if CLIP {
                        draw.project(t, &mut |s| sink.push(0, s));
                    } else {
                        // The triangle stays in view: nothing is ever refused here.
                        draw.project_unclipped(t, &mut |s| sink.push(0, s));
                    }
                })
            },
            |band| {
                sum.pixels(band.pixels());
                Ok::<(), ()>(())
            },
        )
        .ok()?;
    Some((sum.0, stats.pixels))
}

/// Draws one frame in 8-row bands of a `W`-wide colour band (and of `zbuf` as its depth
/// band, when given): `draw` draws into each band and returns the pixels it wrote. The
/// frame's checksum and pixels, or `None` when a band could not be made or drawn.
pub fn in_bands(
    mut zbuf: Option<&mut [u16]>,
    mut draw: impl FnMut(&mut Frame<'_, Rgb565>) -> Option<u32>,
) -> Option<(u32, u32)> {
    let mut color = [Rgb565::new(0, 0, 0); BAND];
    let mut sum = Fnv1a::default();
    let mut pixels = 0u32;
    for band in 0..H / ROWS {
        let f = Frame::new(&mut color, W, ROWS).ok()?.at_row(band * ROWS);
        let mut f = match zbuf.as_deref_mut() {
            Some(z) => f.with_depth(z).ok()?,
            None => f,
        };
        f.clear(Rgb565::new(0, 0, 0));
        pixels += draw(&mut f)?;
        sum.pixels(f.pixels());
    }
    Some((sum.0, pixels))
}

/// The 8 x 8 texture as a one-level chain, in flash (built at run time it would link
/// `memcpy` for its level slots).
static T8_CHAIN: MipTexture<'static> =
    MipTexture::single(Texture::from_static(&data::T8_TEXELS, 8, 8));

/// The minimal textured unlit firmware as the open stage writes it: the triangle through
/// `ShadedDraw<Replace<Nearest, Repeat, Repeat>, Affine, NoDepth>`, `u, v` from the
/// firmware's own vertex function, in bands; clipped when `CLIP`, else through
/// `ShadedDraw::project_unclipped` (the geometry stays in view). The same frame as
/// [`typed`]'s affine nearest unlit one (`size_open`, `size_open_unclipped`).
pub fn open<const CLIP: bool>() -> bool {
    use fixel::geometry::Vertex;
    use fixel::pipeline::{Affine, NoDepth, ShadedDraw};
    use fixel::shading::{Replace, TexBinding};
    use fixel::texture::{Lod, Nearest, Repeat};
    let chain = core::hint::black_box(&T8_CHAIN);
    let Ok(tex) = TexBinding::new(chain, Nearest, Repeat, Repeat, Lod::default()) else {
        return false;
    };
    let Ok(vp) = Viewport::new(0, 0, W, H) else {
        return false;
    };
    let Ok(draw) = ShadedDraw::<_, Affine, NoDepth>::new(Replace { tex }, vp, Cull::Back) else {
        return false;
    };
    // Model space is world space here: clip = projection * view * p.
    let camera = demo::camera(20);
    let mvp = camera.projection.mul(&camera.view);
    let vertex = |i: u16| {
        let i = usize::from(i);
        let p = mvp.transform_point(*POSITIONS.get(i)?)?;
        let [u, v] = *UVS.get(i)?;
        Some(Vertex::new(
            [p.x, p.y, p.z, p.w],
            [u.to_bits(), v.to_bits()],
        ))
    };
    print(in_bands(None, |frame| {
        let mut pixels = 0;
        for tri in &INDICES {
            let (a, b, c) = (vertex(tri[0])?, vertex(tri[1])?, vertex(tri[2])?);
            if CLIP {
                pixels += draw.clip_triangles(&[[a, b, c]], frame).ok()?;
            } else {
                // The triangle stays in view: nothing is ever refused here.
                draw.project_unclipped(&[a, b, c], &mut |s| {
                    pixels += draw.screen_triangle(s, frame).unwrap_or(0);
                });
            }
        }
        Some(pixels)
    }))
}

fn print(r: Option<(u32, u32)>) -> bool {
    match r {
        Some((c, p)) => {
            crate::outln!("checksum=0x{:08x} pixels={}", c, p);
            true
        }
        None => false,
    }
}

/// One draw with stages `M` (types: only that span loop is linked), lit when `LIT`, into a
/// depth band when `DEPTH`.
pub fn typed<M, const LIT: bool, const DEPTH: bool>() -> bool
where
    M: Stages + 'static,
{
    typed_clip::<M, LIT, DEPTH, true>()
}

/// [`typed`] for geometry that stays in view: triangles through
/// `Draw::project_unclipped`, so no clipper is linked.
pub fn typed_unclipped<M, const LIT: bool, const DEPTH: bool>() -> bool
where
    M: Stages + 'static,
{
    typed_clip::<M, LIT, DEPTH, false>()
}

fn typed_clip<M, const LIT: bool, const DEPTH: bool, const CLIP: bool>() -> bool
where
    M: Stages + 'static,
{
    let Ok(vp) = Viewport::new(0, 0, W, H) else {
        return false;
    };
    let Ok(draw) = Draw::new::<M>(Some(core::hint::black_box(data::T8)), vp, Cull::Back) else {
        return false;
    };
    print(frame::<LIT, CLIP>(&draw, DEPTH))
}

/// One draw whose mode is chosen at run time: every span loop is linked ("everything"),
/// and lighting too.
pub fn dynamic(mode: DrawMode, lit: bool) -> bool {
    let Ok(vp) = Viewport::new(0, 0, W, H) else {
        return false;
    };
    let mode = core::hint::black_box(mode);
    let Ok(draw) = Draw::dynamic(mode, Some(core::hint::black_box(data::T8)), vp) else {
        return false;
    };
    print(if core::hint::black_box(lit) {
        frame::<true, true>(&draw, true)
    } else {
        frame::<false, true>(&draw, true)
    })
}

/// The harness alone: the same buffers, checksum and output, no fixel.
pub fn base() -> bool {
    let mut color = [Rgb565::new(0, 0, 0); BAND];
    let mut sum = Fnv1a::default();
    let color = core::hint::black_box(&mut color);
    let mut pixels = 0u32;
    for _ in 0..H / ROWS {
        color[0] = data::T8_TEXELS[core::hint::black_box(3)];
        sum.pixels(color);
        pixels += 1;
    }
    print(Some((sum.0, pixels)))
}

/// The same triangle mirroring a cube map (six 8 x 8 faces: `T(8, 8)` each) with the
/// reflection per pixel, bilinear, exact perspective, depth-tested, in bands: the flash an
/// environment-mapped draw links (`cargo xtask size`, row "depth-tested cube-map mirror").
pub fn env() -> bool {
    use fixel::geometry::Vertex;
    use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
    use fixel::shading::env::{CubeMap, EnvVertices, ReflectPerPixel};
    use fixel::texture::Bilinear;
    let t = core::hint::black_box(data::T8);
    let (Ok(cube), Ok(vp)) = (CubeMap::new([t; 6], Bilinear), Viewport::new(0, 0, W, H)) else {
        return false;
    };
    let Ok(draw) = ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(cube), vp, Cull::Back)
    else {
        return false;
    };
    let camera = demo::camera(20);
    let setup = EnvVertices::new(
        &Mat4::IDENTITY,
        &camera.projection.mul(&camera.view),
        Vec3::ZERO,
    );
    let positions = core::hint::black_box(&POSITIONS);
    let v = |i: usize| setup.per_pixel(positions[i], NORMALS[i]);
    let (Some(a), Some(b), Some(c)) = (v(0), v(1), v(2)) else {
        return false;
    };
    let tri: [[Vertex<6>; 3]; 1] = [[a, b, c]];
    let mut zbuf = [0u16; BAND];
    print(in_bands(Some(&mut zbuf), |f| {
        draw.clip_triangles(&tri, f).ok()
    }))
}

/// The textured triangle bump-mapped from an 8 x 8 derivative map (its texels: the `T(8, 8)`
/// checker read as derivative pairs), lit per pixel by a point light, bilinear, exact,
/// depth: what a bump-mapped draw links (`size_bump`).
pub fn bump() -> bool {
    use fixel::geometry::Vertex;
    use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
    use fixel::scene::{LitMesh, PixelLight};
    use fixel::shading::bump::{Bumped, DerivativeMap};
    use fixel::shading::lighting::{Material, Specular, SpecularTable};
    use fixel::shading::TexBinding;
    use fixel::texture::{Bilinear, Lod, Nearest, Repeat};
    static SHINY: SpecularTable = match SpecularTable::new(24) {
        Ok(t) => t,
        Err(_) => panic!("24 is a valid exponent"),
    };
    let t = core::hint::black_box(data::T8);
    let chain = MipTexture::single(t);
    let lod = Lod::default();
    let (Ok(tex), Ok(dmap)) = (
        TexBinding::new(&chain, Bilinear, Repeat, Repeat, lod),
        TexBinding::new(&chain, Nearest, Repeat, Repeat, lod),
    ) else {
        return false;
    };
    let material = Material {
        ambient: 51,
        diffuse: 218,
        specular: 128,
        model: Specular::Blinn,
        shininess: &SHINY,
    };
    let Ok(normals) = DerivativeMap::new(dmap, Fx::ONE, Fx::from_bits(1311)) else {
        return false;
    };
    let (Ok(shader), Ok(vp)) = (
        Bumped::new(tex, normals, (8, 8), material),
        Viewport::new(0, 0, W, H),
    ) else {
        return false;
    };
    let Ok(draw) = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back) else {
        return false;
    };
    let positions = core::hint::black_box(&POSITIONS);
    let Ok(mesh) = LitMesh::new(positions, &NORMALS, &UVS, None, &INDICES) else {
        return false;
    };
    let light = PixelLight::Point(Vec3::new(Fx::ZERO, Fx::ZERO, Fx::from_bits(-2 << 16)));
    let mut tri = [[Vertex::new([Fx::ZERO; 4], [0; 8]); 3]; 1];
    mesh.bump_triangles(&Mat4::IDENTITY, &demo::camera(20), &light, |t| tri[0] = *t);
    let mut zbuf = [0u16; BAND];
    print(in_bands(Some(&mut zbuf), |f| {
        draw.clip_triangles(&tri, f).ok()
    }))
}
