//! The `bump` scene (`cargo xtask mcu`, whole-frame layout): the brick sphere of
//! `fixel::demo::surface` bump-mapped from the precomputed derivative map (64 x 64 bricks,
//! nearest mip), lit per pixel by the point light of frame 0, in a 240 x 240 viewport of
//! the 320 x 240 frame. The assets are built at start-up with fixel's own functions (outside
//! the measured region); each sphere vertex is prepared once per frame (48 bytes each).
//! Included by the firmware binary and by the host's checksum test
//! (outside the firmware library, so the other scenes' code is not touched).

use crate::scenes::{Fnv1a, FrameResult, H, W};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::demo::surface;
use fixel::demo::{MeshData, SPHERE_TRIANGLES, SPHERE_VERTICES};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::scene::{LitMesh, Tangent};
use fixel::shading::bump::{Bumped, DerivativeMap};
use fixel::shading::lighting::Specular;
use fixel::shading::TexBinding;
use fixel::surface::{BandStats, Frame};
use fixel::texture::{
    chain_len, Bilinear, Lod, LodGranularity, MipTexture, NearestMipmapNearest, Repeat, Texture,
};
use fixel::Error;

/// Side of the brick maps.
pub const SIZE: u32 = 64;
const LEVELS: u32 = 7;
const CHAIN: usize = chain_len(SIZE, SIZE, LEVELS);

/// The scene's data: the sphere with its tangents, the brick colours and derivative map.
pub struct BumpAssets {
    sphere: MeshData<SPHERE_VERTICES, SPHERE_TRIANGLES>,
    tangents: [Tangent; SPHERE_VERTICES],
    colours: [Rgb565; (SIZE * SIZE) as usize],
    heights: [u8; CHAIN],
    derivs: [Rgb565; CHAIN],
    scale: Fx,
}

impl BumpAssets {
    /// Builds everything in place (about 80 KB).
    pub fn build(out: &mut BumpAssets) -> Result<(), Error> {
        let (sphere, tangents) = surface::sphere()?;
        out.sphere = sphere;
        out.tangents = tangents;
        out.scale = surface::brick_maps(
            SIZE,
            LEVELS,
            &mut out.colours,
            &mut out.heights,
            &mut out.derivs,
        )?;
        Ok(())
    }

    /// Zeroed (fill with [`BumpAssets::build`]).
    pub fn zeroed() -> Self {
        BumpAssets {
            sphere: MeshData {
                positions: [fixel::math::Vec3::ZERO; SPHERE_VERTICES],
                normals: [fixel::math::Vec3::ZERO; SPHERE_VERTICES],
                uvs: [[Fx::ZERO; 2]; SPHERE_VERTICES],
                indices: [[0; 3]; SPHERE_TRIANGLES],
            },
            tangents: [Tangent::default(); SPHERE_VERTICES],
            colours: [Rgb565::new(0, 0, 0); (SIZE * SIZE) as usize],
            heights: [0; CHAIN],
            derivs: [Rgb565::new(0, 0, 0); CHAIN],
            scale: Fx::ZERO,
        }
    }
}

/// Renders frame `i` into `color`/`depth` (320 x 240), with `vertices` (one per sphere
/// vertex) for the prepared vertices, and hashes it (between `pause` and
/// `resume`, outside the count).
pub fn bump(
    a: &BumpAssets,
    color: &mut [Rgb565],
    depth: &mut [u16],
    vertices: &mut [Vertex<8>],
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let mut frame = Frame::new(color, W, H)?.with_depth(depth)?;
    frame.clear(Rgb565::new(0, 0, 0));
    let mesh = LitMesh::new(
        &a.sphere.positions,
        &a.sphere.normals,
        &a.sphere.uvs,
        Some(&a.tangents),
        &a.sphere.indices,
    )?;
    // The derivative map's level once per span (the colour texture is not mipmapped).
    let lod = Lod {
        granularity: LodGranularity::Span,
        ..Lod::default()
    };
    let colour_chain = MipTexture::single(Texture::new(&a.colours, SIZE, SIZE)?);
    let tex = TexBinding::new(&colour_chain, Bilinear, Repeat, Repeat, lod)?;
    let deriv_chain = MipTexture::new(&a.derivs, SIZE, SIZE, LEVELS)?;
    let dbind = TexBinding::new(
        &deriv_chain,
        NearestMipmapNearest::default(),
        Repeat,
        Repeat,
        lod,
    )?;
    let normals = DerivativeMap::new(dbind, a.scale, Fx::from_bits(1311))?; // 0.02
    let shader = Bumped::new(
        tex,
        normals,
        (SIZE, SIZE),
        surface::material(Specular::Blinn),
    )?;
    let vp = Viewport::new((W - H) / 2, 0, H, H)?;
    let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back)?;
    mesh.bump_vertices(
        &surface::sphere_model(i),
        &surface::camera()?,
        &surface::light(i),
        vertices,
    )?;
    let pixels = mesh.draw_indexed(&draw, vertices, &mut frame)?;
    pause();
    let mut f = Fnv1a::default();
    f.pixels(frame.pixels());
    resume();
    Ok(FrameResult {
        checksum: f.0,
        stats: BandStats {
            pixels,
            bands: 1,
            ..BandStats::default()
        },
    })
}
