//! Scenes `fox` and `cesium_man`: the Khronos glTF sample models Fox (576 triangles) and
//! CesiumMan (4,672), baked by `cargo xtask bake-gltf` (`assets/gltf/`), in their static
//! pose, drawn at 240 x 320 (portrait, the size another MCU renderer publishes board
//! figures for), lit, bilinear, perspective-correct, depth-tested, in 240 x 8 bands through
//! `BandRenderer` or into one whole frame. Shared word for word by the firmware and the host
//! (`host-tests/tests/model_mcu.rs`, the `models` example), as `scenes.rs` is.
//!
//! Only `fixel`, `core` and `scenes` are used here: no allocation, no platform code.

use core::convert::Infallible;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::pipeline::KeptSetup;
use fixel::prelude::*;
use fixel::scene::{draw_mesh_walked, mesh_to_sink, CachedVertex, DirectionalLight, Mesh};
use fixel::scene::{Camera, MeshTransform};
use fixel::surface::{BandRange, BandStats, Binned};
use fixel::texture::MipTexture;

use crate::scenes::{geometry_done, Fnv1a, FrameResult, LitSphere, Whole, CACHE, ROWS, SETUPS};

/// Frame width of the model scenes (portrait).
pub const W: u32 = 240;
/// Frame height of the model scenes.
pub const H: u32 = 320;
/// Pixels in a band buffer: 240 x 8, colour + depth 7.5 KiB.
pub const BAND_PIXELS: usize = (W * ROWS) as usize;
/// Band ranges of `fox`: one per triangle (2 B each).
pub const FOX_RANGES: usize = 576;
/// Band ranges of `cesium_man`: one per triangle (2 B each, 9.1 KiB).
pub const CESIUM_MAN_RANGES: usize = 4672;
/// Kept set-ups of `cesium_man` (100 B each): 7, not the sphere's 31, so that its band
/// ranges, band, vertex cache and stack stay within the 24 KB RAM bar (with the sphere's
/// the stack ran below RAM on Cortex-M).
pub const CESIUM_MAN_SETUPS: usize = 7;
/// Kept set-ups of `fox` (100 B each): its triangles are larger than the sphere's, and
/// more of them cross each band boundary. With 64 every band resumes what the band above
/// kept (more save nothing, measured with `cargo xtask mcu --only fox`), within 22 KB.
pub const FOX_SETUPS: usize = 64;

/// Band storage of a model scene: colour and depth band, `R` band ranges (one per
/// triangle), the prepared-vertex cache and `S` kept set-ups.
pub struct ModelBuffers<const R: usize, const S: usize = SETUPS> {
    /// Colour band.
    pub color: [Rgb565; BAND_PIXELS],
    /// Depth band.
    pub depth: [u16; BAND_PIXELS],
    /// Band range per triangle.
    pub ranges: [BandRange; R],
    /// Prepared-vertex cache.
    pub cache: [CachedVertex; CACHE],
    /// Set-ups kept from one band for the next.
    pub setups: [KeptSetup; S],
}

impl<const R: usize, const S: usize> ModelBuffers<R, S> {
    /// Zeroed buffers.
    pub fn new() -> Self {
        ModelBuffers {
            color: [Rgb565::new(0, 0, 0); BAND_PIXELS],
            depth: [0; BAND_PIXELS],
            ranges: [BandRange::EMPTY; R],
            cache: [CachedVertex::EMPTY; CACHE],
            setups: [KeptSetup::EMPTY; S],
        }
    }
}

impl<const R: usize, const S: usize> Default for ModelBuffers<R, S> {
    fn default() -> Self {
        Self::new()
    }
}

/// Where a model frame is drawn: in bands, or whole (the 320 x 240 whole-frame storage
/// holds 240 x 320 as well).
pub enum ModelTarget<'b, const R: usize, const S: usize = SETUPS> {
    /// Band by band.
    Bands(&'b mut ModelBuffers<R, S>),
    /// One whole frame.
    Whole(&'b mut Whole),
}

/// The camera of the model scenes: 45 degree vertical field of view, aspect 3:4, near 0.5,
/// far 20, at the origin looking down `-z`.
pub fn camera() -> Camera {
    Camera::perspective(
        Angle::from_degrees(Fx::from_num(45)),
        Fx::from_bits(49152), // 3/4
        Fx::from_bits(1 << 15),
        Fx::from_num(20),
    )
    .unwrap_or(Camera {
        view: Mat4::IDENTITY,
        projection: Mat4::IDENTITY,
    })
}

/// Model matrix of `fox` (the bake centred and scaled by 0.02: 3.1 units nose to tail,
/// along z): turned 60 degrees about y so its left side and face show, seen from slightly
/// above, 5.2 units away.
pub fn fox_model() -> Mat4 {
    Mat4::translation(Vec3::from_num(0, 0, -5.2))
        * Mat4::rotation_x(Angle::from_degrees(Fx::from_num(15)))
        * Mat4::rotation_y(Angle::from_degrees(Fx::from_num(-60)))
}

/// Model matrix of `cesium_man` (the bake centred and scaled by 2: 3 units tall, facing
/// `+x`): turned 70 degrees about y so he faces the camera a little from his left, 4.4
/// units away.
pub fn cesium_man_model() -> Mat4 {
    Mat4::translation(Vec3::from_num(0, 0, -4.4))
        * Mat4::rotation_x(Angle::from_degrees(Fx::from_num(5)))
        * Mat4::rotation_y(Angle::from_degrees(Fx::from_num(-70)))
}

/// The draw of both scenes: [`LitSphere`] (exact every 64 pixels, bilinear, repeat, lit per
/// vertex, depth-tested) on level 0 of `texture`, back faces culled.
pub fn draw(texture: MipTexture<'_>) -> Result<Draw<'_, Rgb565>, Error> {
    Draw::new_mip::<LitSphere>(Some(texture), Viewport::new(0, 0, W, H)?, Cull::Back)
}

/// Renders `mesh` with `model` into `buf` (240 x 320); `pause` and `resume` bracket the
/// checksum of each band, which is left out of the count.
pub fn render<const R: usize, const S: usize>(
    buf: ModelTarget<'_, R, S>,
    texture: MipTexture<'_>,
    mesh: &Mesh<'_>,
    model: &Mat4,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let draw = draw(texture)?;
    let transform = MeshTransform::new(model, &camera());
    let light = DirectionalLight::default();
    let mut sum = Fnv1a::default();
    let buf = match buf {
        ModelTarget::Bands(b) => b,
        ModelTarget::Whole(w) => {
            let n = (W * H) as usize;
            let mut frame = Frame::new(&mut w.color[..n], W, H)?.with_depth(&mut w.depth[..n])?;
            frame.clear(Rgb565::new(0, 0, 0));
            let pixels = draw_mesh_walked(
                &draw,
                mesh,
                &transform,
                Some(&light),
                &mut w.cache,
                &mut frame,
            )?;
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
    let mut bins: [Binned; 0] = [];
    let stats = bands.render_spans(
        &[&draw],
        &mut bins,
        &mut buf.ranges,
        Rgb565::new(0, 0, 0),
        |sink| {
            mesh_to_sink(&draw, 0, mesh, &transform, Some(&light), cache, 0, sink);
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
