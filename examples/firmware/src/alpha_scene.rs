//! The `transparency` scene (`cargo xtask mcu`): the benchmark floor drawn opaque, a fence
//! quad cut out by alpha test and a window quad blended over it with an alpha plane, in
//! 320 x 8 bands: three draws of three shader types (the classic floor, `AlphaTest`,
//! `AlphaBlend`) in one frame of fixel's band renderer, projected and binned once, drawn in
//! each band in the order given (the window, blended, last).
//! Included by the firmware binary and by the host's checksum test (outside the firmware
//! library, so the other scenes' code is not touched).

use crate::scenes::{FloorNearest, Fnv1a, FrameResult, H, W};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{ClipVertex, Cull, Vertex, Viewport};
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Draw, Exact, ShadedDraw};
use fixel::scene::mesh_triangles;
use fixel::shading::alpha::{AlphaBlend, AlphaSource, AlphaTest, BlendMode};
use fixel::surface::{BandDraw, BandRenderer, Binned};
use fixel::texture::{Bilinear, Nearest, Texture};
use fixel::Error;
use fixel_scenes as demo;

const ROWS: u32 = 8;
const N: usize = (W * ROWS) as usize;
/// Side of the quads' alpha planes (the 8 x 8 texture's).
pub const A: u32 = 8;

/// Bins: the floor's screen triangles (clipped by the near plane into a few pieces) and
/// the quads' four.
pub const BINS: usize = 16;

/// Band buffers: colour and depth, 10 KB, and the bins (2.7 KB).
pub struct AlphaBuffers {
    color: [Rgb565; N],
    depth: [u16; N],
    bins: [Binned; BINS],
}

impl AlphaBuffers {
    /// Zeroed.
    pub const fn new() -> Self {
        AlphaBuffers {
            color: [Rgb565::new(0, 0, 0); N],
            depth: [0; N],
            bins: [Binned::EMPTY; BINS],
        }
    }
}

/// Fence alpha: boards (opaque) and gaps (clear), 8 x 8.
pub fn fence_alpha() -> [u8; (A * A) as usize] {
    core::array::from_fn(|k| if (k as u32 % A) % 4 == 3 { 0 } else { 255 })
}

/// Window alpha: a lead frame (opaque) around panes at 55 %.
pub fn window_alpha() -> [u8; (A * A) as usize] {
    core::array::from_fn(|k| {
        let (x, y) = (k as u32 % A, k as u32 / A);
        if x == 0 || y == 0 || x == A - 1 || y == A - 1 {
            255
        } else {
            140
        }
    })
}

/// A 2 x 2 quad (uv 0..1, white) at `model` seen by the benchmark camera (far 200), as
/// alpha-shader vertices.
pub fn quad(model: &Mat4) -> [[Vertex<3>; 3]; 2] {
    let cam = demo::camera(200);
    let mvp = cam.projection.mul(&cam.view).mul(model);
    let v = |x: i32, y: i32, u: i32, t: i32| {
        let c = mvp
            .transform_point(Vec3::from_num(x, y, 0))
            .unwrap_or(fixel::math::Vec4::new(
                Fx::ZERO,
                Fx::ZERO,
                Fx::ZERO,
                Fx::ONE,
            ));
        Vertex::new([c.x, c.y, c.z, c.w], [u << 16, t << 16, 256 << 16])
    };
    let (a, b, c, d) = (
        v(-1, -1, 0, 1),
        v(1, -1, 1, 1),
        v(1, 1, 1, 0),
        v(-1, 1, 0, 0),
    );
    [[a, b, c], [a, c, d]]
}

/// Where the frame is drawn.
pub enum AlphaTarget<'b> {
    /// In bands through the band renderer.
    Bands(&'b mut AlphaBuffers),
    /// Into one whole 320 x 240 frame (colour, depth), draw by draw.
    Whole(&'b mut [Rgb565], &'b mut [u16]),
}

/// The frame: floor (`floor_tex`, `T(64, 64)`), fence and window (`quad_tex`, `T(8, 8)`).
pub fn transparency(
    floor_tex: Texture<'_>,
    quad_tex: Texture<'_>,
    buf: &mut AlphaBuffers,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    transparency_in(floor_tex, quad_tex, AlphaTarget::Bands(buf), pause, resume)
}

/// [`transparency`] into `target` (the whole frame has the same checksum).
pub fn transparency_in(
    floor_tex: Texture<'_>,
    quad_tex: Texture<'_>,
    target: AlphaTarget<'_>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let vp = Viewport::new(0, 0, W, H)?;
    let floor_draw = Draw::new::<FloorNearest>(Some(floor_tex), vp, Cull::Back)?;
    let m = demo::floor();
    let mesh = m.mesh()?;
    let mut floor = [[ClipVertex::new([Fx::ZERO; 4], [Fx::ZERO; 2]); 3]; 2];
    let mut k = 0;
    mesh_triangles(&mesh, &Mat4::IDENTITY, &demo::camera(200), None, |t| {
        if let Some(slot) = floor.get_mut(k) {
            *slot = *t;
        }
        k += 1;
    });
    let (fa, wa) = (fence_alpha(), window_alpha());
    let fence = ShadedDraw::<_, Exact, DepthLess>::new(
        AlphaTest::new(quad_tex, AlphaSource::Plane(&fa), 128, Nearest)?,
        vp,
        Cull::None,
    )?;
    let window = ShadedDraw::<_, Exact, DepthLess>::new(
        AlphaBlend::new(
            quad_tex,
            AlphaSource::Plane(&wa),
            255,
            BlendMode::Over,
            Bilinear,
        )?,
        vp,
        Cull::None,
    )?;
    let fence_tris = quad(
        &(Mat4::translation(Vec3::from_num(-1, -0.2, -5))
            * Mat4::rotation_y(Angle::from_degrees(Fx::from_num(30)))),
    );
    let window_tris = quad(&Mat4::translation(Vec3::from_num(1, 0, -6)));
    let mut sum = Fnv1a::default();
    let clear = Rgb565::new(14, 30, 22);
    let buf = match target {
        AlphaTarget::Bands(b) => b,
        AlphaTarget::Whole(color, depth) => {
            let mut frame = fixel::surface::Frame::new(color, W, H)?.with_depth(depth)?;
            frame.clear(clear);
            let pixels = floor_draw.clip_triangles(&floor[..k.min(2)], &mut frame)?
                + fence.clip_triangles(&fence_tris, &mut frame)?
                + window.clip_triangles(&window_tris, &mut frame)?;
            pause();
            sum.pixels(frame.pixels());
            resume();
            return Ok(FrameResult {
                checksum: sum.0,
                stats: fixel::surface::BandStats {
                    bands: 1,
                    pixels,
                    ..fixel::surface::BandStats::default()
                },
            });
        }
    };
    let draws: [&dyn BandDraw<Rgb565>; 3] = [&floor_draw, &fence, &window];
    let mut bands = BandRenderer::new(&mut buf.color, W, ROWS, H)?.with_depth(&mut buf.depth)?;
    let stats = bands.render(
        &draws,
        &mut buf.bins,
        clear,
        |sink| {
            for t in &floor[..k.min(2)] {
                floor_draw.project(t, &mut |s| sink.push(0, s));
            }
            for t in &fence_tris {
                fence.project(t, &mut |s| sink.push(1, s));
            }
            for t in &window_tris {
                window.project(t, &mut |s| sink.push(2, s));
            }
            if sink.fresh() {
                crate::scenes::geometry_done();
            }
        },
        sum.band_flush::<core::convert::Infallible>(pause, resume),
    )?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}
