//! The seam between the neutral f64 scene description and fixel: converts reference
//! triangles (clip space, f64) to fixel's [`ClipVertex`] (I16F16), reference modes to
//! [`DrawMode`], and renders them with fixel's low-level entry point. Only data crosses
//! this seam; the reference never calls fixel's raster, sampling or shading code.

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{ClipVertex, Cull, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection, Shading};
use fixel::surface::Frame;
use fixel::texture::{chain_len, full_levels};
use fixel::texture::{
    generate_mips, Filter, Lod, LodGranularity, MipFilter, MipTexture, Texture, Wrap,
};

use crate::reference::{
    RefCull, RefFilter, RefLod, RefMip, RefMode, RefProjection, RefShading, RefTexture,
    RefTriangle, RefWrap,
};

/// A frame rendered by fixel, with which pixels it covered.
#[derive(Clone, Debug)]
pub struct FixelImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGB565 pixels, row-major, black where nothing was drawn.
    pub pixels: Vec<u16>,
    /// Pixels any triangle covered.
    pub covered: Vec<bool>,
    /// Pixels written (passing the depth test, counting overdraw).
    pub written: u32,
}

fn fx(x: f64) -> Fx {
    Fx::saturating_from_num(x)
}

/// Reference clip-space triangles as fixel clip vertices (I16F16, colour Q8).
pub fn clip_triangles(tris: &[RefTriangle]) -> Vec<[ClipVertex; 3]> {
    tris.iter()
        .map(|t| {
            t.0.map(|v| ClipVertex {
                position: v.clip.map(fx),
                uv: v.uv.map(fx),
                color: v.color.map(|c| (c.clamp(0.0, 1.0) * 256.0).round() as u16),
            })
        })
        .collect()
}

/// The texture's texels as RGB565 colours.
pub fn texels(t: &RefTexture) -> Vec<Rgb565> {
    t.texels
        .iter()
        .map(|&p| Rgb565::from(RawU16::new(p)))
        .collect()
}

/// fixel's level-of-detail controls for the reference's (Q8.8, rounded; infinite clamps
/// become fixel's defaults), at granularity `g`.
pub fn lod(l: &RefLod, g: LodGranularity) -> Lod {
    let d = Lod::default();
    let q = |x: f64, inf: i32| {
        if x.is_finite() {
            (x * 256.0).round() as i32
        } else {
            inf
        }
    };
    Lod {
        bias: q(l.bias, 0),
        min: q(l.min, d.min),
        max: q(l.max, d.max),
        granularity: g,
    }
}

/// fixel's mode for a reference mode. `intensity` picks the one-interpolant
/// [`Shading::ModulateIntensity`] for `Modulate` (valid when vertex colours are grey).
/// The LOD is computed per pixel; a separate magnification filter `m.mag` maps to
/// [`DrawMode::mag_filter`].
pub fn draw_mode(m: &RefMode, projection: Option<Projection>, intensity: bool) -> DrawMode {
    let wrap = |w: RefWrap| match w {
        RefWrap::Repeat => Wrap::Repeat,
        RefWrap::MirroredRepeat => Wrap::MirroredRepeat,
        RefWrap::ClampToEdge => Wrap::ClampToEdge,
        RefWrap::ClampToBorder => Wrap::ClampToBorder,
    };
    let filter = |f: RefFilter| match f {
        RefFilter::Nearest => Filter::Nearest,
        RefFilter::Bilinear => Filter::Bilinear,
    };
    DrawMode {
        mag_filter: m.mag.map(filter),
        mip: match m.mip {
            RefMip::None => MipFilter::None,
            RefMip::Nearest => MipFilter::Nearest,
            RefMip::Linear => MipFilter::Linear,
        },
        lod: lod(&m.lod, LodGranularity::Pixel),
        projection: projection.unwrap_or(match m.projection {
            RefProjection::Affine => Projection::Affine,
            RefProjection::Perspective => Projection::Exact,
        }),
        filter: match m.filter {
            RefFilter::Nearest => Filter::Nearest,
            RefFilter::Bilinear => Filter::Bilinear,
        },
        wrap: [wrap(m.wrap_u), wrap(m.wrap_v)],
        shading: match m.shading {
            RefShading::Replace => Shading::Replace,
            RefShading::Modulate if intensity => Shading::ModulateIntensity,
            RefShading::Modulate => Shading::Modulate,
            RefShading::Gouraud => Shading::Gouraud,
            RefShading::Flat(_) => Shading::Flat,
        },
        depth: if m.depth_test {
            DepthTest::Less
        } else {
            DepthTest::Off
        },
        cull: match m.cull {
            RefCull::None => Cull::None,
            RefCull::Back => Cull::Back,
            RefCull::Front => Cull::Front,
        },
    }
}

/// Renders clip-space triangles with fixel into a `width` x `height` RGB565 frame (with a
/// depth buffer), plus a second untextured pass for the coverage mask.
pub fn render(
    tris: &[[ClipVertex; 3]],
    texture: Option<&RefTexture>,
    mode: DrawMode,
    width: u32,
    height: u32,
) -> FixelImage {
    let texels_vec = texture.map(texels);
    let tex = match (&texels_vec, texture) {
        (Some(t), Some(rt)) => Some(
            Texture::new(t, rt.width, rt.height)
                .expect("valid texture")
                .with_border(Rgb565::from(RawU16::new(rt.border))),
        ),
        _ => None,
    };
    render_tex(tris, tex.map(MipTexture::single), mode, width, height)
}

/// fixel's run-time mip chain of `levels` levels (`None`: full) for a reference texture:
/// level 0 copied, the rest filled by [`generate_mips`]. Returns the contiguous chain.
pub fn mip_chain(t: &RefTexture, levels: Option<u32>) -> Vec<Rgb565> {
    let levels = levels.unwrap_or_else(|| full_levels(t.width, t.height));
    let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(t.width, t.height, levels)];
    chain[..t.texels.len()].copy_from_slice(&texels(t));
    generate_mips(&mut chain, t.width, t.height, levels).expect("valid chain");
    chain
}

/// Like [`render`], with a mip chain of `levels` levels (`None`: full) built by fixel's
/// [`generate_mips`]; `mode.mip` and `mode.lod` select the filtering.
pub fn render_mip(
    tris: &[[ClipVertex; 3]],
    texture: Option<&RefTexture>,
    levels: Option<u32>,
    mode: DrawMode,
    width: u32,
    height: u32,
) -> FixelImage {
    let chain = texture.map(|t| (mip_chain(t, levels), t));
    let tex = chain.as_ref().map(|(c, t)| {
        let l = levels.unwrap_or_else(|| full_levels(t.width, t.height));
        MipTexture::new(c, t.width, t.height, l)
            .expect("valid chain")
            .with_border(Rgb565::from(RawU16::new(t.border)))
    });
    render_tex(tris, tex, mode, width, height)
}

/// Like [`render`] with fixel's texture (plain or mipmapped) given directly.
pub fn render_tex(
    tris: &[[ClipVertex; 3]],
    tex: Option<MipTexture<'_>>,
    mode: DrawMode,
    width: u32,
    height: u32,
) -> FixelImage {
    render_tex_viewport(tris, tex, mode, (width, height), width, height)
}

/// Like [`render`], through a viewport of `viewport` pixels at the origin, which may be
/// larger than the `width` x `height` frame (cropped).
pub fn render_viewport(
    tris: &[[ClipVertex; 3]],
    texture: Option<&RefTexture>,
    mode: DrawMode,
    viewport: (u32, u32),
    width: u32,
    height: u32,
) -> FixelImage {
    let texels_vec = texture.map(texels);
    let tex = match (&texels_vec, texture) {
        (Some(t), Some(rt)) => Some(MipTexture::single(
            Texture::new(t, rt.width, rt.height).expect("valid texture"),
        )),
        _ => None,
    };
    render_tex_viewport(tris, tex, mode, viewport, width, height)
}

fn render_tex_viewport(
    tris: &[[ClipVertex; 3]],
    tex: Option<MipTexture<'_>>,
    mode: DrawMode,
    viewport: (u32, u32),
    width: u32,
    height: u32,
) -> FixelImage {
    let n = (width * height) as usize;
    let vp = Viewport::new(0, 0, viewport.0, viewport.1).expect("viewport");
    let mut color = vec![Rgb565::new(0, 0, 0); n];
    let mut depth = vec![0u16; n];
    let mut frame = Frame::new(&mut color, width, height)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    let draw = Draw::dynamic_mip(mode, tex, vp).expect("draw mode");
    let written = draw.clip_triangles(tris, &mut frame).unwrap();
    let pixels: Vec<u16> = color
        .iter()
        .map(|&c| RawU16::from(c).into_inner())
        .collect();

    let cov_mode = DrawMode {
        shading: Shading::Flat,
        depth: DepthTest::Off,
        ..mode
    };
    let mut cov = vec![Rgb565::new(0, 0, 0); n];
    let mut cov_frame = Frame::new(&mut cov, width, height).unwrap();
    let cov_draw = Draw::dynamic(cov_mode, None, vp)
        .unwrap()
        .with_flat_color(Rgb565::new(31, 63, 31));
    cov_draw.clip_triangles(tris, &mut cov_frame).unwrap();
    let covered = cov.iter().map(|&c| c != Rgb565::new(0, 0, 0)).collect();
    FixelImage {
        width,
        height,
        pixels,
        covered,
        written,
    }
}
