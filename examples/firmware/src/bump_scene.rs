//! The `bump` scenes (`cargo xtask mcu`): the brick sphere of `fixel_scenes::surface`
//! bump-mapped from the precomputed derivative map (64 x 64 bricks, nearest mip), lit per
//! pixel by the point light of frame 0, in a 240 x 240 viewport of the 320 x 240 frame.
//! `bump` draws it in 8-row bands (each band builds only the vertices of the triangles that
//! meet it, 48 bytes each, the last few kept in a small cache); `whole_bump` draws the same frame whole. The assets
//! are the firmware's flash tables (`data::BRICK_*`, baked by `build.rs`) or the host's
//! run-time copies of them. Included by the firmware binaries and by the host's checksum
//! test (outside the firmware library, so the other scenes' code is not touched).

use core::cell::Cell;

use crate::open_frame::{open_bands, open_whole};
use crate::scenes::{FrameResult, H, W};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Fx, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::scene::{LitMesh, PixelLight, Tangent};
use fixel::shading::bump::{Bumped, DerivativeMap};
use fixel::shading::lighting::Specular;
use fixel::shading::TexBinding;
use fixel::surface::BandRange;
use fixel::texture::{
    Bilinear, Lod, LodGranularity, MipTexture, NearestMipmapNearest, Repeat, Texture,
};
use fixel::Error;
use fixel_scenes::surface;

/// Side of the brick maps.
pub const SIZE: u32 = 64;
/// Mip levels of the derivative map.
pub const LEVELS: u32 = 7;
/// Built vertices kept (56 B each, on the stack): the sphere's triangles come a latitude
/// ring at a time, so neighbours find their shared corners here.
pub const VERTEX_CACHE: usize = 24;
/// Triangles of the brick sphere.
pub const TRIANGLES: usize = fixel_scenes::SPHERE_TRIANGLES;

/// The scene's data, wherever it is held (flash on the MCUs).
#[derive(Clone, Copy)]
pub struct BumpAssets<'a> {
    /// Sphere positions (model space).
    pub positions: &'a [Vec3],
    /// Sphere normals.
    pub normals: &'a [Vec3],
    /// Texture coordinates (4 x 2 repeats around).
    pub uvs: &'a [[Fx; 2]],
    /// Triangles.
    pub indices: &'a [[u16; 3]],
    /// One tangent per vertex.
    pub tangents: &'a [Tangent],
    /// The brick colours, `SIZE * SIZE`.
    pub colours: &'a [Rgb565],
    /// The derivative map's mip chain.
    pub derivs: &'a [Rgb565],
    /// The derivative map's scale.
    pub scale: Fx,
}

impl BumpAssets<'static> {
    /// The firmware's flash tables (`data::BRICK_*`).
    #[cfg(target_os = "none")]
    pub fn flash() -> Self {
        use crate::data;
        let s = core::hint::black_box(&data::BRICK_SPHERE);
        BumpAssets {
            positions: &s.positions,
            normals: &s.normals,
            uvs: &s.uvs,
            indices: &s.indices,
            tangents: &data::BRICK_TANGENTS,
            colours: &data::BRICK_COLOURS,
            derivs: &data::BRICK_DERIVS,
            scale: data::BRICK_SCALE,
        }
    }
}

/// Band buffers and one band range per triangle: 10 KiB + 4.4 KB.
pub struct BumpBuffers {
    color: [Rgb565; crate::scenes::BAND_PIXELS],
    depth: [u16; crate::scenes::BAND_PIXELS],
    ranges: [BandRange; TRIANGLES],
}

impl BumpBuffers {
    /// Zeroed buffers.
    pub const fn new() -> Self {
        BumpBuffers {
            color: [Rgb565::new(0, 0, 0); crate::scenes::BAND_PIXELS],
            depth: [0; crate::scenes::BAND_PIXELS],
            ranges: [BandRange::EMPTY; TRIANGLES],
        }
    }
}

impl Default for BumpBuffers {
    fn default() -> Self {
        Self::new()
    }
}

/// The draw, the mesh and the light of frame `i`, handed to `frame` (the band or whole
/// loop) with a triangle builder.
fn with_scene<R>(
    a: &BumpAssets<'_>,
    i: u32,
    frame: impl FnOnce(
        &ShadedDraw<BumpShader<'_>, Exact, DepthLess>,
        &dyn Fn(usize, bool) -> Option<[Vertex<8>; 3]>,
    ) -> Result<R, Error>,
) -> Result<R, Error> {
    let mesh = LitMesh::new(a.positions, a.normals, a.uvs, Some(a.tangents), a.indices)?;
    // The derivative map's level once per span (the colour texture is not mipmapped).
    let lod = Lod {
        granularity: LodGranularity::Span,
        ..Lod::default()
    };
    let colour_chain = MipTexture::single(Texture::new(a.colours, SIZE, SIZE)?);
    let tex = TexBinding::new(&colour_chain, Bilinear, Repeat, Repeat, lod)?;
    let deriv_chain = MipTexture::new(a.derivs, SIZE, SIZE, LEVELS)?;
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
    let light: PixelLight = surface::light(i);
    let camera = surface::camera()?;
    let model = surface::sphere_model(i);
    let build = mesh.bump_vertex(&model, &camera, &light);
    // A direct-mapped cache of built vertices (index mod VERTEX_CACHE): neighbouring
    // triangles share vertices, and each one costs a model-view transform, a tangent frame
    // and two normalisations.
    let cache: [Cell<(u16, Vertex<8>)>; VERTEX_CACHE] =
        core::array::from_fn(|_| Cell::new((u16::MAX, Vertex::new([Fx::ZERO; 4], [0; 8]))));
    let vertex = |i: usize| -> Option<Vertex<8>> {
        let slot = cache.get(i % VERTEX_CACHE)?;
        let (k, v) = slot.get();
        if usize::from(k) == i {
            return Some(v);
        }
        let v = build(i)?;
        slot.set((u16::try_from(i).ok()?, v));
        Some(v)
    };
    let mvp = camera.projection.mul(&camera.view.mul(&model));
    let (indices, positions) = (mesh.indices(), mesh.positions());
    // The binning pass needs the rows only: clip positions, no varyings.
    let triangle = |k: usize, attributes: bool| -> Option<[Vertex<8>; 3]> {
        let t = indices.get(k)?;
        let v = |i: u16| {
            let i = usize::from(i);
            if attributes {
                vertex(i)
            } else {
                let c = mvp.transform_point(*positions.get(i)?)?;
                Some(Vertex::new([c.x, c.y, c.z, c.w], [0; 8]))
            }
        };
        Some([v(t[0])?, v(t[1])?, v(t[2])?])
    };
    frame(&draw, &triangle)
}

/// The scene's shader type.
type BumpShader<'a> =
    Bumped<'a, DerivativeMap<'a, NearestMipmapNearest, Repeat, Repeat>, Bilinear, Repeat, Repeat>;

/// Renders frame `i` in bands through `buf` and hashes each band (between `pause` and
/// `resume`, outside the count).
pub fn bump(
    a: &BumpAssets<'_>,
    buf: &mut BumpBuffers,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    with_scene(a, i, |draw, triangle| {
        open_bands(
            &mut buf.color,
            &mut buf.depth,
            &mut buf.ranges,
            draw,
            a.indices.len(),
            triangle,
            Rgb565::new(0, 0, 0),
            pause,
            resume,
        )
    })
}

/// [`bump`]'s frame drawn whole into `color` / `depth` (320 x 240): the same checksum.
pub fn bump_whole(
    a: &BumpAssets<'_>,
    color: &mut [Rgb565],
    depth: &mut [u16],
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    with_scene(a, i, |draw, triangle| {
        open_whole(
            color,
            depth,
            draw,
            a.indices.len(),
            triangle,
            Rgb565::new(0, 0, 0),
            pause,
            resume,
        )
    })
}
