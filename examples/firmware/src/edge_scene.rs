//! The `aa_edge` scene (`cargo xtask mcu`): the `cube` scene's frame (the same draw, bands
//! and buffers) with silhouette anti-aliasing from depth (`fixel::surface::EdgeAa`) run on
//! each finished band before it is sent. Included by the firmware binary, the host's
//! checksum test and the anti-aliasing report (it lives outside the firmware library so
//! that the library's code, and so the other scenes' optimisation, does not change).

use crate::scenes::{
    geometry_done, viewport, Fnv1a, FrameResult, LitFootprint, SmallBuffers, H, ROWS, W,
};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::Cull;
use fixel::pipeline::Draw;
use fixel::scene::{mesh_to_sink, DirectionalLight, MeshTransform};
use fixel::surface::{BandRenderer, EdgeAa};
use fixel::texture::MipTexture;
use fixel::Error;
use fixel_scenes as demo;

/// Depth difference (window depth, `0..=65535`) above which two neighbours are across an
/// edge. The cube's depths are 52,987..=60,449 and change by at most 609 between
/// neighbours; a silhouette against the cleared depth (65535) by 5,086 or more. `2^11 - 1`:
/// the quick test reads the top five bits.
pub const THRESHOLD: u16 = 2047;

/// The pass's own buffers: the two rows held between bands (colour and depth).
pub struct EdgeBuffers {
    held_c: [Rgb565; 2 * W as usize],
    held_d: [u16; 2 * W as usize],
}

impl EdgeBuffers {
    /// Zeroed.
    pub const fn new() -> Self {
        EdgeBuffers {
            held_c: [Rgb565::new(0, 0, 0); 2 * W as usize],
            held_d: [0; 2 * W as usize],
        }
    }
}

impl Default for EdgeBuffers {
    fn default() -> Self {
        Self::new()
    }
}

/// Bytes of RAM the pass adds to the `cube` scene's.
pub const EDGE_RAM: u32 = 2 * W * 4;

/// The cube, frame `i` (`texture`: `T(128, 128)` with its footprints, `data::T128_FP`),
/// in 8-row bands, each smoothed at depth discontinuities before it is hashed (in runs,
/// one row behind the bands); checksum of the smoothed frame, whose rows are also copied
/// into `frame` when given (the host report).
pub fn aa_edge(
    buf: &mut SmallBuffers,
    edge: &mut EdgeBuffers,
    texture: MipTexture<'_>,
    i: u32,
    mut frame: Option<&mut [Rgb565]>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let draw = Draw::new_mip::<LitFootprint>(Some(texture), viewport()?, Cull::Back)?;
    let m = demo::cube();
    let mesh = m.mesh()?;
    let transform = MeshTransform::new(&demo::cube_model(i), &demo::camera(20));
    let light = DirectionalLight::default();
    let mut bands = BandRenderer::new(&mut buf.color, W, ROWS, H)?
        .with_depth(&mut buf.depth)?
        .with_setup_cache(&mut buf.setups);
    let cache = &mut buf.cache;
    let mut aa = EdgeAa::new(W, THRESHOLD, &mut edge.held_c, &mut edge.held_d)?;
    let mut sum = Fnv1a::default();
    let mut at = 0usize;
    let stats = bands.render_spans(
        &[&draw],
        &mut buf.bins,
        &mut buf.ranges,
        Rgb565::new(0, 0, 0),
        |sink| {
            mesh_to_sink(&draw, 0, &mesh, &transform, Some(&light), cache, 0, sink);
            if sink.fresh() {
                geometry_done();
            }
        },
        |band| {
            let last = band.first_row() as u32 + band.height() >= H;
            let depth = band.depth().ok_or(Error::NoDepthBuffer)?;
            aa.band(band.pixels(), depth, last, |r: &[Rgb565]| {
                pause();
                sum.pixels(r);
                if let Some(f) = frame.as_deref_mut() {
                    if let Some(dst) = f.get_mut(at..at + r.len()) {
                        dst.copy_from_slice(r);
                    }
                }
                at += r.len();
                resume();
                Ok::<(), Error>(())
            })?;
            Ok::<(), Error>(())
        },
    );
    let stats = stats.map_err(|e| match e {
        fixel::surface::BandError::Input(e) | fixel::surface::BandError::Flush(e) => e,
    })?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}
