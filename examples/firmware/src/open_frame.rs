//! One frame of an open-stage draw (`ShadedDraw` with any shader), in bands or whole, from
//! a triangle closure: the frame loop the technique scenes share. Shared word for word with
//! the host tests that include the scenes with `#[path]` (so both checksums come from the
//! same code).
//!
//! In bands, fixel's band renderer (`BandRenderer::render_spans`) runs the closure once for
//! the binning pass (rows only: `attributes == false`, clip positions without varyings) and
//! keeps each triangle's band range (2 B each); each band then builds, with their varyings,
//! only the triangles that meet it. Whole, every triangle is built once and drawn into one
//! frame; the checksum runs over the same pixels in the same order, so both are equal.

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::Vertex;
use fixel::pipeline::{DepthLess, ProjectionStage, ShadedDraw};
use fixel::scene::triangles_to_sink;
use fixel::shading::Shader;
use fixel::surface::{BandRange, BandRenderer, BandStats, Binnable, Binned, Frame};
use fixel::Error;

use crate::scenes::{Fnv1a, FrameResult, H, ROWS, W};

/// Draws triangles `0..count` of `triangle(k, attributes)` with `draw` in bands of
/// [`ROWS`] rows through `color` / `depth` (one band each) and `ranges` (one per triangle),
/// cleared to `clear`; `pause` / `resume` bracket each band's checksum.
#[allow(clippy::too_many_arguments)]
pub fn open_bands<S, P, const N: usize>(
    color: &mut [Rgb565],
    depth: &mut [u16],
    ranges: &mut [BandRange],
    draw: &ShadedDraw<S, P, DepthLess>,
    count: usize,
    triangle: impl Fn(usize, bool) -> Option<[Vertex<N>; 3]>,
    clear: Rgb565,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
    fixel::geometry::ScreenTriangle<N>: Binnable,
{
    let mut hash = Fnv1a::default();
    let mut bands = BandRenderer::new(color, W, ROWS, H)?.with_depth(depth)?;
    let stats = bands.render_spans(
        &[draw],
        &mut [] as &mut [Binned],
        ranges,
        clear,
        |sink| {
            triangles_to_sink(draw, 0, count, 0, &triangle, sink);
            if sink.fresh() {
                crate::scenes::geometry_done();
            }
        },
        hash.band_flush::<core::convert::Infallible>(pause, resume),
    )?;
    Ok(FrameResult {
        checksum: hash.0,
        stats,
    })
}

/// [`open_bands`]' frame drawn whole into `color` / `depth` (320 x 240), triangle by
/// triangle (each built once, with its varyings): the figure the banded frame is compared
/// with, and the same checksum.
#[allow(clippy::too_many_arguments)]
pub fn open_whole<S, P, const N: usize>(
    color: &mut [Rgb565],
    depth: &mut [u16],
    draw: &ShadedDraw<S, P, DepthLess>,
    count: usize,
    triangle: impl Fn(usize, bool) -> Option<[Vertex<N>; 3]>,
    clear: Rgb565,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
{
    let mut frame = Frame::new(color, W, H)?.with_depth(depth)?;
    frame.clear(clear);
    let mut pixels = 0u32;
    for k in 0..count {
        if let Some(t) = triangle(k, true) {
            pixels = pixels.wrapping_add(draw.clip_triangles(&[t], &mut frame)?);
        }
    }
    pause();
    let mut hash = Fnv1a::default();
    hash.pixels(frame.pixels());
    resume();
    Ok(FrameResult {
        checksum: hash.0,
        stats: BandStats {
            bands: 1,
            pixels,
            ..BandStats::default()
        },
    })
}
