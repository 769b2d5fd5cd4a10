//! Per-pixel lighting, bump and normal mapping on microcontrollers (`report_surface`,
//! shared with the host report): the brick sphere of `fixel_scenes::surface`, frame 0 under
//! light 0, in a 160 x 160 frame, in each lighting variant. The same code runs on the host,
//! so checksums compare bit for bit; the host measures each frame's error against the f64
//! reference. Vertices are prepared once per frame (`LitMesh::*_vertices`).

use crate::scenes::Fnv1a;
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Fx, Vec3};
use fixel::pipeline::{DepthLess, Exact, ProjectionStage, ShadedDraw, SubdividedBy};
use fixel::scene::{LitMesh, Tangent};
use fixel::shading::bump::{normal_map, Bumped, DerivativeMap, HeightDifferences, NormalMap};
use fixel::shading::lighting::{Phong, Specular};
use fixel::shading::{Gouraud, Shader, TexBinding};
use fixel::surface::Frame;
use fixel::texture::{
    chain_len, Bilinear, HeightMap, Lod, MipTexture, Nearest, NearestMipmapNearest, Repeat, Texture,
};
use fixel::Error;
use fixel_scenes::surface;
use fixel_scenes::{MeshData, SPHERE_TRIANGLES, SPHERE_VERTICES};

/// Frame side.
pub const W: u32 = 160;
/// Frame height.
pub const H: u32 = 160;
/// Side of the brick maps.
pub const SIZE: u32 = 64;
const LEVELS: u32 = 7;
const CHAIN: usize = chain_len(SIZE, SIZE, LEVELS);
/// Bump strength σ (0.02 texel widths per height step), I16F16 bits.
pub const STRENGTH: Fx = Fx::from_bits(1311);
/// The plain surface's colour (raw RGB565).
pub const PLAIN: u16 = 0xE654;

/// The variants, by report name (the host report's order).
pub const VARIANTS: [&str; 8] = [
    "gouraud",
    "phong",
    "blinn",
    "blinn-textured",
    "bump-derivatives",
    "bump-derivatives-sub8",
    "bump-heights",
    "normal-map",
];

/// The scene's data and vertex storage (about 150 KB: report layout only).
pub struct SurfaceAssets {
    sphere: MeshData<SPHERE_VERTICES, SPHERE_TRIANGLES>,
    tangents: [Tangent; SPHERE_VERTICES],
    colours: [Rgb565; (SIZE * SIZE) as usize],
    heights: [u8; CHAIN],
    derivs: [Rgb565; CHAIN],
    scale: Fx,
    normals: [Rgb565; (SIZE * SIZE) as usize],
    lit: [Vertex<8>; SPHERE_VERTICES],
    gouraud: [Vertex<3>; SPHERE_VERTICES],
}

impl SurfaceAssets {
    /// Zeroed (fill with [`SurfaceAssets::build`]).
    pub const fn zeroed() -> Self {
        SurfaceAssets {
            sphere: MeshData {
                positions: [Vec3::ZERO; SPHERE_VERTICES],
                normals: [Vec3::ZERO; SPHERE_VERTICES],
                uvs: [[Fx::ZERO; 2]; SPHERE_VERTICES],
                indices: [[0; 3]; SPHERE_TRIANGLES],
            },
            tangents: [Tangent {
                direction: Vec3::ZERO,
                handedness: 1,
            }; SPHERE_VERTICES],
            colours: [Rgb565::new(0, 0, 0); (SIZE * SIZE) as usize],
            heights: [0; CHAIN],
            derivs: [Rgb565::new(0, 0, 0); CHAIN],
            scale: Fx::ZERO,
            normals: [Rgb565::new(0, 0, 0); (SIZE * SIZE) as usize],
            lit: [Vertex::new([Fx::ZERO; 4], [0; 8]); SPHERE_VERTICES],
            gouraud: [Vertex::new([Fx::ZERO; 4], [0; 3]); SPHERE_VERTICES],
        }
    }

    /// Builds the sphere, its tangents and the brick maps with fixel's own functions.
    pub fn build(&mut self) -> Result<(), Error> {
        let (sphere, tangents) = surface::sphere()?;
        self.sphere = sphere;
        self.tangents = tangents;
        self.scale = surface::brick_maps(
            SIZE,
            LEVELS,
            &mut self.colours,
            &mut self.heights,
            &mut self.derivs,
        )?;
        let base = HeightMap::new(&self.heights[..(SIZE * SIZE) as usize], SIZE, SIZE, 1)?;
        normal_map(&base, STRENGTH, &mut self.normals)?;
        Ok(())
    }
}

fn draw<S, P, const N: usize>(
    shader: S,
    mesh: &LitMesh<'_>,
    vertices: &[Vertex<N>],
    frame: &mut Frame<'_, Rgb565>,
) -> Result<u32, Error>
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
{
    let draw = ShadedDraw::<_, P, DepthLess>::new(shader, Viewport::new(0, 0, W, H)?, Cull::Back)?;
    mesh.draw_indexed(&draw, vertices, frame)
}

/// Draws variant `k` of [`VARIANTS`] into `color`/`depth` (`W x H`, cleared first) and
/// returns the pixels written. Everything from the vertices on is the measured work.
#[inline(never)]
pub fn render(
    k: usize,
    a: &mut SurfaceAssets,
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Result<u32, Error> {
    let mut frame = Frame::new(color, W, H)?.with_depth(depth)?;
    frame.clear(Rgb565::new(0, 0, 0));
    let mesh = LitMesh::new(
        &a.sphere.positions,
        &a.sphere.normals,
        &a.sphere.uvs,
        Some(&a.tangents),
        &a.sphere.indices,
    )?;
    let (model, camera, light) = (
        surface::sphere_model(0),
        surface::camera()?,
        surface::light(0),
    );
    let lod = Lod::default();
    let plain = [Rgb565::from(
        embedded_graphics_core::pixelcolor::raw::RawU16::new(PLAIN),
    )];
    let plain_chain = MipTexture::single(Texture::new(&plain, 1, 1)?);
    let flat = TexBinding::new(&plain_chain, Nearest, Repeat, Repeat, lod)?;
    let colour_chain = MipTexture::single(Texture::new(&a.colours, SIZE, SIZE)?);
    let tex = TexBinding::new(&colour_chain, Bilinear, Repeat, Repeat, lod)?;
    let size = (SIZE, SIZE);
    let blinn = surface::material(Specular::Blinn);
    let name = VARIANTS.get(k).copied().unwrap_or("");
    if name == "gouraud" {
        mesh.gouraud_vertices(&model, &camera, &light, &blinn, PLAIN, &mut a.gouraud)?;
        return draw::<_, Exact, 3>(Gouraud, &mesh, &a.gouraud, &mut frame);
    }
    let bump = name.starts_with("bump") || name == "normal-map";
    if bump {
        mesh.bump_vertices(&model, &camera, &light, &mut a.lit)?;
    } else {
        mesh.phong_vertices(&model, &camera, &light, &mut a.lit)?;
    }
    let v = &a.lit;
    let deriv_chain = MipTexture::new(&a.derivs, SIZE, SIZE, LEVELS)?;
    let dbind = TexBinding::new(
        &deriv_chain,
        NearestMipmapNearest::default(),
        Repeat,
        Repeat,
        lod,
    )?;
    match name {
        "phong" => {
            let material = surface::material(Specular::Phong);
            draw::<_, Exact, 8>(
                Phong {
                    tex: flat,
                    material,
                },
                &mesh,
                v,
                &mut frame,
            )
        }
        "blinn" => draw::<_, Exact, 8>(
            Phong {
                tex: flat,
                material: blinn,
            },
            &mesh,
            v,
            &mut frame,
        ),
        "blinn-textured" => draw::<_, Exact, 8>(
            Phong {
                tex,
                material: blinn,
            },
            &mesh,
            v,
            &mut frame,
        ),
        "bump-derivatives" | "bump-derivatives-sub8" => {
            let n = DerivativeMap::new(dbind, a.scale, STRENGTH)?;
            let s = Bumped::new(tex, n, size, blinn)?;
            if name.ends_with("sub8") {
                draw::<_, SubdividedBy<3>, 8>(s, &mesh, v, &mut frame)
            } else {
                draw::<_, Exact, 8>(s, &mesh, v, &mut frame)
            }
        }
        "bump-heights" => {
            let map = HeightMap::new(&a.heights, SIZE, SIZE, LEVELS)?;
            let n = HeightDifferences::new(map, STRENGTH)?;
            draw::<_, Exact, 8>(Bumped::new(tex, n, size, blinn)?, &mesh, v, &mut frame)
        }
        _ => {
            let chain = MipTexture::single(Texture::new(&a.normals, SIZE, SIZE)?);
            let b = TexBinding::new(&chain, Bilinear, Repeat, Repeat, lod)?;
            let n = NormalMap { map: b };
            draw::<_, Exact, 8>(Bumped::new(tex, n, size, blinn)?, &mesh, v, &mut frame)
        }
    }
}

/// FNV-1a of a frame.
pub fn checksum(px: &[Rgb565]) -> u32 {
    let mut f = Fnv1a::default();
    f.pixels(px);
    let _ = px.first().map(|c| c.into_storage());
    f.0
}
