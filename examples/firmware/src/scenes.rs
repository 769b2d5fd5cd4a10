//! The benchmark frames, band by band: shared word for word by the firmware and the host
//! test `host-tests/tests/mcu_checksums.rs` (included there with `#[path]`), so the checksum
//! printed by a microcontroller and the one computed on the host come from the same code.
//!
//! Only `fixel` and `core` are used here: no allocation, no platform code.

use core::convert::Infallible;
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::pipeline::KeptSetup;
use fixel::pipeline::{
    Adaptive, DepthLess, ModulateFacet, ModulateIntensity, Pipeline, QuadraticBy, Replace,
    SubdividedBy,
};
use fixel::prelude::*;
use fixel::scene::{
    draw_mesh_walked, mesh_to_sink, CachedVertex, DirectionalLight, Mesh, MeshTransform, VertexUv,
};
use fixel::surface::BandRange;
use fixel::surface::{BandStats, Binned};
use fixel::texture::{
    Bilinear, BilinearFootprint, BilinearFootprintSized, MipTexture, Nearest, Repeat,
};
use fixel_scenes as demo;

/// Marks the end of a banded frame's binning pass for `cargo xtask mcu`'s geometry share
/// (call it from the geometry closure when its sink is in the binning pass). Nothing on the
/// host.
#[inline(always)]
pub fn geometry_done() {
    #[cfg(target_os = "none")]
    crate::bench_geometry();
}

/// Frame size of every scene.
pub const W: u32 = demo::WIDTH;
/// Frame height.
pub const H: u32 = demo::HEIGHT;
/// Rows per band: colour + depth band = 320 * 8 * 4 B = 10 KiB.
pub const ROWS: u32 = 8;
/// Binned screen triangles (168 B each). The cube and floor fit; the sphere overflows and
/// the renderer keeps a 2-byte band range per triangle instead (`reprojected`).
pub const BINS: usize = 16;
/// Band ranges of the sphere firmware: one per sphere triangle (2 B each, 4.4 KB).
pub const RANGES: usize = demo::SPHERE_TRIANGLES;
/// Prepared-vertex cache of the sphere band firmware (32 B each, direct-mapped, kept across
/// the band passes). 64 entries, 2 KB: the 2 KB that 128 entries took hold 20 more kept
/// set-ups ([`SETUPS`]), which save more. 32 entries cannot hold the front half of two
/// rings of the sphere (25 vertices each) that consecutive bands share.
pub const CACHE: usize = 64;
/// Triangles kept from one band for the next (`BandRenderer::with_setup_cache`, 100 B
/// each, 3.1 KB) in the firmwares that re-project their mesh per band: a triangle that
/// crosses into the next band is drawn there from its kept set-up, without being
/// projected again. Up to 40 sphere triangles cross a band boundary (34 on most); the
/// first 31 are kept.
pub const SETUPS: usize = 31;
/// Pixels in a band buffer.
pub const BAND_PIXELS: usize = (W * ROWS) as usize;

/// `cube`: lit, bilinear, perspective-correct, repeat, depth-tested. Its faces have
/// per-face normals, so the Gouraud intensity is one per triangle: `ModulateFacet` reads it
/// once (one interpolant fewer per pixel, and closer to the f64 reference than the
/// interpolated constant: `docs/report` 45.8 dB exact against 42.8). A parabola through
/// exact values every 16 pixels: the cheapest mode within 0.5 dB of exact (45.8 dB; N = 32
/// is 44.9).
pub type Lit = Pipeline<QuadraticBy<4>, Bilinear, Repeat, Repeat, ModulateFacet, DepthLess>;
/// The `cube` scene's draw: [`Lit`] reading the texture's bilinear footprints
/// (`BilinearFootprint`: the same pixels, two loads per sample instead of four).
pub type LitFootprint =
    Pipeline<QuadraticBy<4>, BilinearFootprint, Repeat, Repeat, ModulateFacet, DepthLess>;
/// The anti-aliasing scenes' cube (`aa`, `aa_scene`): [`Lit`] as it was when their figures
/// in `docs/report/aa.md` and the README were measured, exact every 4 pixels.
pub type LitSub4 =
    Pipeline<SubdividedBy<2>, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
/// `sphere`: the same, exact every 64 pixels (its spans are short: one segment each; 45.2 dB
/// against exact's 45.3 in `docs/report`).
pub type LitSphere =
    Pipeline<SubdividedBy<6>, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
/// `sphere` in the adaptive projection (per triangle affine when a bound on the affine error
/// is within a quarter texel, exact otherwise): `whole_sphere_adaptive`, the report's
/// balanced mode for the sphere.
pub type LitSphereAdaptive =
    Pipeline<Adaptive, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
/// [`LitSphereAdaptive`] reading the texture's bilinear footprints (`BilinearFootprint`:
/// the same pixels, two loads per sample instead of four; 256 KiB of footprints for the
/// sphere's texture): `whole_sphere_footprint`.
pub type LitSphereFootprint =
    Pipeline<Adaptive, BilinearFootprint, Repeat, Repeat, ModulateIntensity, DepthLess>;
/// [`LitSphereFootprint`] with the texture's size (256 x 128) fixed at compile time
/// (`BilinearFootprintSized`: the same pixels, the footprint's index from immediates; a
/// chain of another size is refused when the draw is built): `whole_sphere_sized`.
pub type LitSphereSized =
    Pipeline<Adaptive, BilinearFootprintSized<8, 7>, Repeat, Repeat, ModulateIntensity, DepthLess>;
/// `floor` with nearest filtering (unlit).
pub type FloorNearest = Pipeline<SubdividedBy<6>, Nearest, Repeat, Repeat, Replace, DepthLess>;
/// `floor` with bilinear filtering (unlit).
pub type FloorBilinear = Pipeline<SubdividedBy<6>, Bilinear, Repeat, Repeat, Replace, DepthLess>;
/// `floor_bilinear`'s draw: [`FloorBilinear`] reading the texture's bilinear footprints.
pub type FloorBilinearFootprint =
    Pipeline<SubdividedBy<6>, BilinearFootprint, Repeat, Repeat, Replace, DepthLess>;

/// FNV-1a (32 bit) over the RGB565 values as little-endian bytes, rows top to bottom.
#[derive(Clone, Copy, Debug)]
pub struct Fnv1a(pub u32);

impl Default for Fnv1a {
    fn default() -> Self {
        Fnv1a(0x811C_9DC5)
    }
}

impl Fnv1a {
    /// Feeds pixels in order.
    #[inline(never)]
    pub fn pixels(&mut self, px: &[Rgb565]) {
        let mut h = self.0;
        for p in px {
            let v: u16 = p.into_storage();
            for b in v.to_le_bytes() {
                h = (h ^ u32::from(b)).wrapping_mul(0x0100_0193);
            }
        }
        self.0 = h;
    }

    /// The flush of a banded frame: each band's pixels fed in order, between `pause` and
    /// `resume` (the checksum is not the frame's cost).
    pub fn band_flush<'s, E>(
        &'s mut self,
        pause: &'s mut dyn FnMut(),
        resume: &'s mut dyn FnMut(),
    ) -> impl FnMut(&Frame<'_, Rgb565>) -> Result<(), E> + 's {
        move |band| {
            pause();
            self.pixels(band.pixels());
            resume();
            Ok(())
        }
    }
}

/// Buffers a band renderer needs: colour band, depth band, triangle bins, `R` band ranges
/// and a cache of `V` prepared vertices.
pub struct Buffers<
    const R: usize = RANGES,
    const V: usize = CACHE,
    const B: usize = BINS,
    const S: usize = SETUPS,
> {
    /// Colour band.
    pub color: [Rgb565; BAND_PIXELS],
    /// Depth band.
    pub depth: [u16; BAND_PIXELS],
    /// Triangle bins.
    pub bins: [Binned; B],
    /// Band range per triangle (when the bins overflow).
    pub ranges: [BandRange; R],
    /// Prepared-vertex cache.
    pub cache: [CachedVertex; V],
    /// Set-ups kept from one band for the next.
    pub setups: [KeptSetup; S],
}

/// Buffers of the scenes whose triangles fit the bins (cube, floor): no band ranges, a
/// kept set-up per bin (a floor or cube triangle meets up to 30 bands).
pub type SmallBuffers = Buffers<0, 32, BINS, BINS>;
/// Buffers of the sphere firmware: band ranges, a vertex cache and kept set-ups, no bins (its
/// ~650 screen triangles would need 68 KB of them). 10 KiB band + 4.4 KB ranges + 2 KB
/// vertex cache + 3.1 KB set-ups.
pub type SphereBuffers = Buffers<RANGES, CACHE, 0, SETUPS>;
/// Kept set-ups of `sphere_sized` (100 B each): 40 hold every sphere triangle that crosses
/// a band boundary, so no triangle is projected and set up again in a later band (with
/// [`SETUPS`], 76 are: about 3.7 instructions per pixel more on Cortex-M4F). Cortex-M0+,
/// whose stack is deeper, has the RAM for 35 within the 24 KB bar.
pub const SIZED_SETUPS: usize = if cfg!(all(target_arch = "arm", not(target_has_atomic = "32"))) {
    35
} else {
    40
};
/// Buffers of `sphere_sized`: [`SphereBuffers`] with [`SIZED_SETUPS`] kept set-ups.
/// 10 KiB band + 4.4 KB ranges + 2 KB vertex cache + 4 KB set-ups (3.5 KB on Cortex-M0+).
pub type SizedSphereBuffers = Buffers<RANGES, CACHE, 0, SIZED_SETUPS>;

impl Default for Buffers {
    fn default() -> Self {
        Self::new()
    }
}

impl Buffers {
    /// Zeroed buffers with the sphere's storage.
    pub fn new() -> Self {
        Self::with_storage()
    }
}

impl<const R: usize, const V: usize, const B: usize, const S: usize> Buffers<R, V, B, S> {
    /// Zeroed buffers.
    pub fn with_storage() -> Self {
        Buffers {
            color: [Rgb565::new(0, 0, 0); BAND_PIXELS],
            depth: [0; BAND_PIXELS],
            bins: [Binned::default(); B],
            ranges: [BandRange::EMPTY; R],
            cache: [CachedVertex::EMPTY; V],
            setups: [KeptSetup::EMPTY; S],
        }
    }
}

/// Buffers of a whole-frame renderer: a 320 x 240 colour and depth frame (300 KiB) and
/// one prepared vertex per sphere vertex (44 KB). For the boards with the RAM for it.
pub struct Whole {
    /// Colour frame.
    pub color: [Rgb565; (W * H) as usize],
    /// Depth frame.
    pub depth: [u16; (W * H) as usize],
    /// Prepared-vertex cache.
    pub cache: [CachedVertex; demo::SPHERE_VERTICES],
}

impl Whole {
    /// Zeroed buffers.
    pub fn new() -> Self {
        Whole {
            color: [Rgb565::new(0, 0, 0); (W * H) as usize],
            depth: [0; (W * H) as usize],
            cache: [CachedVertex::EMPTY; demo::SPHERE_VERTICES],
        }
    }
}

impl Default for Whole {
    fn default() -> Self {
        Self::new()
    }
}

/// A whole-frame [`Target`] (its band storage parameters are unused).
pub type WholeTarget<'b> = Target<'b, 0, 0, 0, 0>;

/// Where a frame is drawn: in bands through `Buffers`, or whole.
pub enum Target<'b, const R: usize, const V: usize, const B: usize = BINS, const S: usize = SETUPS>
{
    /// Band by band.
    Bands(&'b mut Buffers<R, V, B, S>),
    /// One whole frame.
    Whole(&'b mut Whole),
}

/// What a frame produced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrameResult {
    /// FNV-1a of the whole frame.
    pub checksum: u32,
    /// Renderer statistics (pixels that passed the depth test, bands, rewalk).
    pub stats: BandStats,
}

/// Renders one frame of `mesh` with pipeline `M` in bands through `buf`. `pause` is called
/// before each band's checksum and `resume` after it, so an instruction counter can leave
/// the (harness-only) checksum out of the renderer's count.
#[allow(clippy::too_many_arguments)]
pub fn render<M, const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    texture: MipTexture<'_>,
    mesh: &Mesh<'_>,
    model: &Mat4,
    far: i32,
    lit: bool,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    M: fixel::pipeline::Stages + 'static,
{
    let draw = Draw::new_mip::<M>(Some(texture), viewport()?, Cull::Back)?;
    render_draw(buf, &draw, mesh, model, far, lit, pause, resume)
}

/// The full-frame viewport every scene uses.
pub fn viewport() -> Result<Viewport, Error> {
    Viewport::new(0, 0, W, H)
}

/// Like [`render`] with a ready draw (any mode: see `modes.rs`).
#[allow(clippy::too_many_arguments)]
pub fn render_draw<const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    draw: &Draw<'_, Rgb565>,
    mesh: &Mesh<'_>,
    model: &Mat4,
    far: i32,
    lit: bool,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let transform = MeshTransform::new(model, &demo::camera(far));
    render_walk(buf, draw, mesh, &transform, lit, pause, resume)
}

/// Like [`render_draw`] with a ready transform (which may carry a texture-coordinate
/// generator, `MeshTransform::with_uvs`).
pub fn render_walk<G: VertexUv, const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    draw: &Draw<'_, Rgb565>,
    mesh: &Mesh<'_>,
    transform: &MeshTransform<G>,
    lit: bool,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let light = DirectionalLight::default();
    let light = if lit { Some(&light) } else { None };
    let mut sum = Fnv1a::default();
    let buf = match buf {
        Target::Bands(b) => b,
        Target::Whole(w) => {
            let mut frame = Frame::new(&mut w.color, W, H)?.with_depth(&mut w.depth)?;
            frame.clear(Rgb565::new(0, 0, 0));
            let pixels = draw_mesh_walked(draw, mesh, transform, light, &mut w.cache, &mut frame)?;
            pause();
            sum.pixels(frame.pixels());
            resume();
            return Ok(FrameResult {
                checksum: sum.0,
                stats: BandStats {
                    bands: 1,
                    pixels,
                    ..BandStats::default()
                },
            });
        }
    };
    let mut bands = BandRenderer::new(&mut buf.color, W, ROWS, H)?
        .with_depth(&mut buf.depth)?
        .with_setup_cache(&mut buf.setups);
    let cache = &mut buf.cache;
    let stats = bands.render_spans(
        &[draw],
        &mut buf.bins,
        &mut buf.ranges,
        Rgb565::new(0, 0, 0),
        |sink| {
            mesh_to_sink(draw, 0, mesh, transform, light, cache, 0, sink);
            if sink.fresh() {
                geometry_done();
            }
        },
        sum.band_flush::<Infallible>(pause, resume),
    )?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}

/// Scene `cube`, frame `i`: `texture` must be `T(128, 128)` with its footprints
/// (`MipTexture::with_footprints`, [`data::T128_FP`]; drawn with [`LitFootprint`]).
pub fn cube<const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    texture: MipTexture<'_>,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let m = demo::cube();
    render::<LitFootprint, R, V, B, S>(
        buf,
        texture,
        &m.mesh()?,
        &demo::cube_model(i),
        20,
        true,
        pause,
        resume,
    )
}

/// Scene `sphere`, frame `i`: `texture` must be `T(256, 128)`, `mesh` the demo sphere.
pub fn sphere<const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    texture: Texture<'_>,
    mesh: &Mesh<'_>,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    sphere_mip_as::<LitSphere, R, V, B, S>(buf, MipTexture::single(texture), mesh, i, pause, resume)
}

/// [`sphere`] drawn with the stages `M` (a lit, bilinear mode of the sphere) and texture
/// chain `texture` (`data::T256X128_FP`, with its footprints, for [`LitSphereFootprint`]).
pub fn sphere_mip_as<M, const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    texture: MipTexture<'_>,
    mesh: &Mesh<'_>,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    M: fixel::pipeline::Stages + 'static,
{
    render::<M, R, V, B, S>(
        buf,
        texture,
        mesh,
        &demo::sphere_model(i),
        20,
        true,
        pause,
        resume,
    )
}

/// Model matrix of the teapot scene, frame `i`: the teapot (y up, height centred) seen
/// from slightly above, turning about y by `0.02 i` radians from -30 degrees.
pub fn teapot_model(i: u32) -> Mat4 {
    let turn = Angle::from_radians(Fx::from_bits(-34315 + (1311 * i as i32)));
    Mat4::translation(Vec3::from_num(0, -0.2, -8))
        * Mat4::rotation_x(Angle::from_radians(Fx::from_bits(22877)))
        * Mat4::rotation_y(turn)
}

/// Scene `teapot`, frame `i`: the Utah teapot baked by `cargo xtask bake-obj` (`mesh`, 1560
/// triangles with cylindrical texture coordinates) with `texture` `T(256, 128)`, lit,
/// bilinear, perspective-correct, as the sphere.
pub fn teapot<const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    texture: Texture<'_>,
    mesh: &Mesh<'_>,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    render::<LitSphere, R, V, B, S>(
        buf,
        MipTexture::single(texture),
        mesh,
        &teapot_model(i),
        20,
        true,
        pause,
        resume,
    )
}

/// Scene `floor` (camera fixed, so every frame is frame 0): `texture` must be `T(64, 64)`
/// (with its footprints, [`data::T64_FP`], for [`FloorBilinearFootprint`]).
pub fn floor<M, const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    texture: MipTexture<'_>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    M: fixel::pipeline::Stages + 'static,
{
    let m = demo::floor();
    render::<M, R, V, B, S>(
        buf,
        texture,
        &m.mesh()?,
        &Mat4::IDENTITY,
        200,
        false,
        pause,
        resume,
    )
}

/// Scene `cube`, frame `i`, drawn with `draw` (lit when `lit`; texture `T(128, 128)`).
pub fn cube_with<const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    draw: &Draw<'_, Rgb565>,
    lit: bool,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let m = demo::cube();
    render_draw(
        buf,
        draw,
        &m.mesh()?,
        &demo::cube_model(i),
        20,
        lit,
        pause,
        resume,
    )
}

/// Scene `sphere`, frame `i`, drawn with `draw` (lit when `lit`; texture `T(256, 128)`).
#[allow(clippy::too_many_arguments)]
pub fn sphere_with<const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    draw: &Draw<'_, Rgb565>,
    mesh: &Mesh<'_>,
    lit: bool,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    render_draw(
        buf,
        draw,
        mesh,
        &demo::sphere_model(i),
        20,
        lit,
        pause,
        resume,
    )
}

/// Scene `floor` drawn with `draw` (unlit; texture `T(64, 64)`, with its mip chain for the
/// mipmapped filters).
pub fn floor_with<const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    draw: &Draw<'_, Rgb565>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let m = demo::floor();
    render_draw(
        buf,
        draw,
        &m.mesh()?,
        &Mat4::IDENTITY,
        200,
        false,
        pause,
        resume,
    )
}
