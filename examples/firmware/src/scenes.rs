//! The benchmark frames, band by band: shared word for word by the firmware and the host
//! test `host-tests/tests/mcu_checksums.rs` (included there with `#[path]`), so the checksum
//! printed by a microcontroller and the one computed on the host come from the same code.
//!
//! Only `fixel` and `core` are used here: no allocation, no platform code.

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::demo;
use fixel::pipeline::{DepthLess, ModulateIntensity, Pipeline, Replace, SubdividedBy};
use fixel::prelude::*;
use fixel::scene::{mesh_triangles, DirectionalLight, Mesh};
use fixel::surface::band::{BandStats, Binned};
use fixel::texture::{Bilinear, Nearest, Repeat};

/// Frame size of every scene.
pub const W: u32 = demo::WIDTH;
/// Frame height.
pub const H: u32 = demo::HEIGHT;
/// Rows per band: colour + depth band = 320 * 8 * 4 B = 10 KiB.
pub const ROWS: u32 = 8;
/// Binned screen triangles (~104 B each). The cube and floor fit; the sphere overflows and
/// the renderer runs its geometry once per band instead (reported as `rewalked`).
pub const BINS: usize = 16;
/// Pixels in a band buffer.
pub const BAND_PIXELS: usize = (W * ROWS) as usize;

/// `cube` and `sphere`: lit, bilinear, perspective-correct, repeat, depth-tested.
pub type Lit = Pipeline<SubdividedBy<2>, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
/// `floor` with nearest filtering (unlit).
pub type FloorNearest = Pipeline<SubdividedBy<5>, Nearest, Repeat, Repeat, Replace, DepthLess>;
/// `floor` with bilinear filtering (unlit).
pub type FloorBilinear = Pipeline<SubdividedBy<5>, Bilinear, Repeat, Repeat, Replace, DepthLess>;

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
}

/// Buffers a band renderer needs: colour band, depth band, triangle bins.
pub struct Buffers {
    /// Colour band.
    pub color: [Rgb565; BAND_PIXELS],
    /// Depth band.
    pub depth: [u16; BAND_PIXELS],
    /// Triangle bins.
    pub bins: [Binned; BINS],
}

impl Default for Buffers {
    fn default() -> Self {
        Self::new()
    }
}

impl Buffers {
    /// Zeroed buffers.
    pub fn new() -> Self {
        Buffers {
            color: [Rgb565::new(0, 0, 0); BAND_PIXELS],
            depth: [0; BAND_PIXELS],
            bins: [Binned::default(); BINS],
        }
    }
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
pub fn render<M>(
    buf: &mut Buffers,
    texture: Texture<'_>,
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
    let draw = Draw::new::<M>(Some(texture), viewport()?, Cull::Back)?;
    render_draw(buf, &draw, mesh, model, far, lit, pause, resume)
}

/// The full-frame viewport every scene uses.
pub fn viewport() -> Result<Viewport, Error> {
    Viewport::new(0, 0, W, H)
}

/// Like [`render`] with a ready draw (any mode: see `modes.rs`).
#[allow(clippy::too_many_arguments)]
pub fn render_draw(
    buf: &mut Buffers,
    draw: &Draw<'_, Rgb565>,
    mesh: &Mesh<'_>,
    model: &Mat4,
    far: i32,
    lit: bool,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let camera = demo::camera(far);
    let light = DirectionalLight::default();
    let light = if lit { Some(&light) } else { None };
    let mut sum = Fnv1a::default();
    let mut bands = BandRenderer::new(&mut buf.color, W, ROWS, H)?.with_depth(&mut buf.depth)?;
    let stats = bands
        .render(
            &[draw],
            &mut buf.bins,
            Rgb565::new(0, 0, 0),
            |sink| {
                mesh_triangles(mesh, model, &camera, light, |t| {
                    draw.project(t, &mut |s| sink.push(0, s))
                })
            },
            |band| {
                pause();
                sum.pixels(band.pixels());
                resume();
                Ok::<(), ()>(())
            },
        )
        .map_err(|()| Error::BadMode("flush failed"))?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}

/// Scene `cube`, frame `i`: `texture` must be `T(128, 128)`.
pub fn cube(
    buf: &mut Buffers,
    texture: Texture<'_>,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let m = demo::cube();
    render::<Lit>(
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
pub fn sphere(
    buf: &mut Buffers,
    texture: Texture<'_>,
    mesh: &Mesh<'_>,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    render::<Lit>(
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

/// Scene `floor` (camera fixed, so every frame is frame 0): `texture` must be `T(64, 64)`.
pub fn floor<M>(
    buf: &mut Buffers,
    texture: Texture<'_>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    M: fixel::pipeline::Stages + 'static,
{
    let m = demo::floor();
    render::<M>(
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
pub fn cube_with(
    buf: &mut Buffers,
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
pub fn sphere_with(
    buf: &mut Buffers,
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
pub fn floor_with(
    buf: &mut Buffers,
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
