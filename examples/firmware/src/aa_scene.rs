//! The `aa_cube` scene (`cargo xtask mcu`): the benchmark cube with the 4-sample rotated
//! grid accumulated through 320 x 4 bands (`BandRenderer::render_accumulated`): colour,
//! depth and channel sums of one band, 12.5 KB. Included by the firmware binary and by the
//! host's checksum test (it lives outside the firmware library so that the library's code,
//! and so the other scenes' optimisation, does not change).

use crate::scenes::{Fnv1a, FrameResult, LitSub4 as Lit, H, W};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Viewport};
use fixel::math::Fx;
use fixel::pipeline::Draw;
use fixel::scene::{mesh_triangles, DirectionalLight, SamplePattern};
use fixel::surface::{BandError, BandRenderer, Binned};
use fixel::texture::Texture;
use fixel::Error;
use fixel_scenes as demo;

/// Rows per band.
pub const ROWS: u32 = 4;
const N: usize = (W * ROWS) as usize;

/// Pixels of the whole frame (one band of 240 rows: the whole-frame firmware).
pub const WHOLE: usize = (W * H) as usize;

/// The band buffers, `P / 320` rows (4 by default; [`WHOLE`] for one band holding the frame).
pub struct AaCubeBuffers<const P: usize = N> {
    color: [Rgb565; P],
    depth: [u16; P],
    sums: [[u16; 3]; P],
}

impl AaCubeBuffers {
    /// Zeroed 4-row bands.
    pub const fn new() -> Self {
        Self::sized()
    }
}

impl<const P: usize> AaCubeBuffers<P> {
    /// Zeroed.
    pub const fn sized() -> Self {
        AaCubeBuffers {
            color: [Rgb565::new(0, 0, 0); P],
            depth: [0; P],
            sums: [[0; 3]; P],
        }
    }
}

/// The cube, frame `i`, rotated grid of 4 accumulated in bands; checksum of the frame.
pub fn aa_cube<const P: usize>(
    texture: Texture<'_>,
    i: u32,
    buf: &mut AaCubeBuffers<P>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let mut offsets = [[Fx::ZERO; 2]; 4];
    let n = SamplePattern::RotatedGrid4.offsets(&mut offsets)?;
    let draw = Draw::new::<Lit>(Some(texture), Viewport::new(0, 0, W, H)?, Cull::Back)?;
    let rows = (P as u32 / W).min(H);
    let mut bands = BandRenderer::new(&mut buf.color, W, rows, H)?.with_depth(&mut buf.depth)?;
    let (m, model, camera, light) = (
        demo::cube(),
        demo::cube_model(i),
        demo::camera(20),
        DirectionalLight::default(),
    );
    let mesh = m.mesh()?;
    let mut sum = Fnv1a::default();
    let mut bins = [Binned::default(); 16];
    let stats = bands
        .render_accumulated(
            &[&draw],
            &mut bins,
            Rgb565::new(0, 0, 0),
            &offsets[..n],
            &mut buf.sums,
            |sink| {
                mesh_triangles(&mesh, &model, &camera, Some(&light), |t| {
                    draw.project(t, &mut |s| sink.push(0, s));
                });
                crate::scenes::geometry_done();
            },
            sum.band_flush::<Error>(pause, resume),
        )
        .map_err(|e| match e {
            BandError::Input(e) | BandError::Flush(e) => e,
        })?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}
