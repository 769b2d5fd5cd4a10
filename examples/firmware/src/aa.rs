//! Regular-grid supersampling in bands (`report_aa`, shared with the host report): the
//! benchmark cube rendered at `k` times the resolution in bands of `8 k` rows, each band
//! resolved by `fixel::surface::resolve_box` into an 8-row band of the 320 x 240 frame
//! before it is hashed (flushed). RAM: `k²` times one band.

use crate::scenes::{Fnv1a, FrameResult, LitSub4 as Lit, H, ROWS, W};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Viewport};
use fixel::pipeline::Draw;
use fixel::scene::{mesh_triangles, DirectionalLight};
use fixel::surface::{resolve_box, BandError, BandRenderer, Binned};
use fixel::texture::Texture;
use fixel::Error;
use fixel_scenes as demo;

/// Largest supersampling factor the buffers hold.
pub const K_MAX: u32 = 4;
const HI: usize = (W * ROWS * K_MAX * K_MAX) as usize;

/// Band buffers for up to `K_MAX x K_MAX` supersampling: a `k`-times colour and depth band
/// and one display band (the cube's 16 bins live on the stack).
pub struct AaBuffers {
    color: [Rgb565; HI],
    depth: [u16; HI],
    lo: [Rgb565; (W * ROWS) as usize],
}

impl AaBuffers {
    /// Zeroed.
    pub const fn new() -> Self {
        AaBuffers {
            color: [Rgb565::new(0, 0, 0); HI],
            depth: [0; HI],
            lo: [Rgb565::new(0, 0, 0); (W * ROWS) as usize],
        }
    }
}

impl Default for AaBuffers {
    fn default() -> Self {
        Self::new()
    }
}

/// Bytes of band RAM the cube needs at factor `k`: the `k`-times colour and depth bands
/// and the display band.
pub fn band_ram(k: u32) -> u32 {
    W * ROWS * k * k * 4 + W * ROWS * 2
}

/// The benchmark cube's geometry for frame `i`: mesh, model, camera and light.
struct CubeScene {
    data: fixel_scenes::MeshData<24, 12>,
    model: fixel::math::Mat4,
    camera: fixel::scene::Camera,
    light: DirectionalLight,
}

impl CubeScene {
    fn new(i: u32) -> Self {
        CubeScene {
            data: demo::cube(),
            model: demo::cube_model(i),
            camera: demo::camera(20),
            light: DirectionalLight::default(),
        }
    }

    /// Pushes the cube's screen triangles through `draw` into `sink`.
    fn push(
        &self,
        draw: &Draw<'_, Rgb565>,
        sink: &mut fixel::surface::TriangleSink<'_, '_, '_, Rgb565>,
    ) {
        if let Ok(mesh) = self.data.mesh() {
            mesh_triangles(&mesh, &self.model, &self.camera, Some(&self.light), |t| {
                draw.project(t, &mut |s| sink.push(0, s));
            });
        }
    }
}

/// Copies a finished band (frame rows from `first_row`) into `frame` when there is one.
fn keep(frame: &mut Option<&mut [Rgb565]>, first_row: u32, pixels: &[Rgb565]) {
    if let Some(f) = frame.as_deref_mut() {
        let at = (first_row * W) as usize;
        if let Some(dst) = f.get_mut(at..at + pixels.len()) {
            dst.copy_from_slice(pixels);
        }
    }
}

/// The cube, frame `i`, supersampled `k x k` (`1..=K_MAX`; 1 is the plain band render
/// through the same path), lit bilinear (the `cube` firmware's draw); checksum of the
/// resolved 320 x 240 frame, whose bands are also copied into `frame` when given (the
/// host report).
#[allow(clippy::too_many_arguments)]
pub fn cube(
    k: u32,
    texture: Texture<'_>,
    i: u32,
    buf: &mut AaBuffers,
    mut frame: Option<&mut [Rgb565]>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    if k == 0 || k > K_MAX {
        return Err(Error::BadSize(k));
    }
    let (w, h, rows) = (W * k, H * k, ROWS * k);
    let n = (w * rows) as usize;
    let draw = Draw::new::<Lit>(Some(texture), Viewport::new(0, 0, w, h)?, Cull::Back)?;
    let mut bands =
        BandRenderer::new(&mut buf.color[..n], w, rows, h)?.with_depth(&mut buf.depth[..n])?;
    let scene = CubeScene::new(i);
    let lo = &mut buf.lo;
    let mut sum = Fnv1a::default();
    let mut bins = [Binned::default(); 16];
    let stats = bands
        .render(
            &[&draw],
            &mut bins,
            Rgb565::new(0, 0, 0),
            |sink| scene.push(&draw, sink),
            |band| {
                resolve_box(band, k, lo)?;
                pause();
                sum.pixels(&lo[..]);
                keep(&mut frame, band.first_row() as u32 / k, &lo[..]);
                resume();
                Ok::<(), Error>(())
            },
        )
        .map_err(|e| match e {
            BandError::Input(e) | BandError::Flush(e) => e,
        })?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}

/// Band sums for [`cube_accumulated`]: 6 bytes per band pixel.
pub struct AccumBuffers {
    color: [Rgb565; (W * ROWS) as usize],
    depth: [u16; (W * ROWS) as usize],
    sums: [[u16; 3]; (W * ROWS) as usize],
}

impl AccumBuffers {
    /// Zeroed.
    pub const fn new() -> Self {
        AccumBuffers {
            color: [Rgb565::new(0, 0, 0); (W * ROWS) as usize],
            depth: [0; (W * ROWS) as usize],
            sums: [[0; 3]; (W * ROWS) as usize],
        }
    }
}

impl Default for AccumBuffers {
    fn default() -> Self {
        Self::new()
    }
}

/// Band RAM of [`cube_accumulated`]: colour, depth and sums of one 8-row band.
pub const ACCUM_RAM: u32 = W * ROWS * 10;

/// The cube, frame `i`, with the samples of `pattern` accumulated through 8-row bands
/// (`BandRenderer::render_accumulated`: geometry binned once, each band drawn once per
/// sample); checksum of the averaged frame, copied into `frame` when given.
#[allow(clippy::too_many_arguments)]
pub fn cube_accumulated(
    pattern: fixel::scene::SamplePattern,
    texture: Texture<'_>,
    i: u32,
    buf: &mut AccumBuffers,
    mut frame: Option<&mut [Rgb565]>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let mut offsets = [[fixel::math::Fx::ZERO; 2]; 16];
    let n = pattern.offsets(&mut offsets)?;
    let draw = Draw::new::<Lit>(Some(texture), Viewport::new(0, 0, W, H)?, Cull::Back)?;
    let mut bands = BandRenderer::new(&mut buf.color, W, ROWS, H)?.with_depth(&mut buf.depth)?;
    let scene = CubeScene::new(i);
    let mut sum = Fnv1a::default();
    let mut bins = [Binned::default(); 16];
    let stats = bands
        .render_accumulated(
            &[&draw],
            &mut bins,
            Rgb565::new(0, 0, 0),
            &offsets[..n],
            &mut buf.sums,
            |sink| scene.push(&draw, sink),
            |band| {
                pause();
                sum.pixels(band.pixels());
                keep(&mut frame, band.first_row() as u32, band.pixels());
                resume();
                Ok::<(), Error>(())
            },
        )
        .map_err(|e| match e {
            BandError::Input(e) | BandError::Flush(e) => e,
        })?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}

/// Buffers of [`cube_smoothed`]: the band, its depth, a copy to smooth in place, the row
/// above it and two scratch rows.
pub struct SmoothBuffers {
    color: [Rgb565; (W * ROWS) as usize],
    depth: [u16; (W * ROWS) as usize],
    out: [Rgb565; (W * ROWS) as usize],
    above: [Rgb565; W as usize],
    scratch: [Rgb565; 2 * W as usize],
}

impl SmoothBuffers {
    /// Zeroed.
    pub const fn new() -> Self {
        SmoothBuffers {
            color: [Rgb565::new(0, 0, 0); (W * ROWS) as usize],
            depth: [0; (W * ROWS) as usize],
            out: [Rgb565::new(0, 0, 0); (W * ROWS) as usize],
            above: [Rgb565::new(0, 0, 0); W as usize],
            scratch: [Rgb565::new(0, 0, 0); 2 * W as usize],
        }
    }
}

impl Default for SmoothBuffers {
    fn default() -> Self {
        Self::new()
    }
}

/// Band RAM of [`cube_smoothed`].
pub const SMOOTH_RAM: u32 = W * ROWS * 6 + W * 6;

/// Luma contrast below which [`cube_smoothed`] leaves a pixel alone.
pub const SMOOTH_THRESHOLD: u8 = 24;

/// The cube, frame `i`, at 1x in 8-row bands, each band edge-smoothed
/// (`fixel::surface::smooth_edges`, the previous band's last row above it) before it is
/// hashed; checksum of the frame, copied into `frame` when given.
pub fn cube_smoothed(
    texture: Texture<'_>,
    i: u32,
    buf: &mut SmoothBuffers,
    mut frame: Option<&mut [Rgb565]>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let draw = Draw::new::<Lit>(Some(texture), Viewport::new(0, 0, W, H)?, Cull::Back)?;
    let mut bands = BandRenderer::new(&mut buf.color, W, ROWS, H)?.with_depth(&mut buf.depth)?;
    let scene = CubeScene::new(i);
    let (out, above, scratch) = (&mut buf.out, &mut buf.above, &mut buf.scratch);
    let mut sum = Fnv1a::default();
    let mut bins = [Binned::default(); 16];
    let stats = bands
        .render(
            &[&draw],
            &mut bins,
            Rgb565::new(0, 0, 0),
            |sink| scene.push(&draw, sink),
            |band| {
                let n = band.pixels().len();
                let rows = n as u32 / W;
                out[..n].copy_from_slice(band.pixels());
                let first = band.first_row() == 0;
                let mut f = fixel::surface::Frame::new(&mut out[..n], W, rows)?;
                fixel::surface::smooth_edges(
                    &mut f,
                    (!first).then_some(&above[..]),
                    scratch,
                    SMOOTH_THRESHOLD,
                )?;
                above.copy_from_slice(&band.pixels()[n - W as usize..]);
                pause();
                sum.pixels(&out[..n]);
                keep(&mut frame, band.first_row() as u32, &out[..n]);
                resume();
                Ok::<(), Error>(())
            },
        )
        .map_err(|e| match e {
            BandError::Input(e) | BandError::Flush(e) => e,
        })?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}
