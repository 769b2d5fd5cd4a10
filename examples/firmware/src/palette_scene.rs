//! Palette textures on the benchmark floor and cube: scenes `floor_palette4`,
//! `floor_palette8`, `cube_palette4`, `cube_palette8` (`cargo xtask bake-palette` of
//! `T(64, 64)` and `T(128, 128)`, in `assets/palette/`), and their RGB565 twins
//! `floor_rgb565` and `cube_rgb565`, drawn through the very same open-stage path
//! (`ShadedDraw`, the triangles handed to the band renderer by `triangles_to_sink`), so the
//! rows differ in the texture read alone.
//!
//! * floor: unlit, nearest, repeat, exact every 64 pixels (`SubdividedBy<6>`), depth-tested,
//!   far plane 200; [`Replace`] / [`PaletteReplace`].
//! * cube: lit per vertex, bilinear, repeat, a parabola every 16 pixels (`QuadraticBy<4>`),
//!   depth-tested, frame 0; [`ModulateIntensity`] / [`PaletteModulateIntensity`].
//!
//! 320x240 in bands of 8 rows through [`SmallBuffers`] (the floor's and cube's triangles fit
//! the bins). Shared word for word by the firmware and the host test
//! `host-tests/tests/palette_mcu.rs`.

use core::convert::Infallible;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{ClipVertex, ScreenTriangle, Vertex};
use fixel::pipeline::{DepthLess, ProjectionStage, QuadraticBy, ShadedDraw, SubdividedBy};
use fixel::prelude::*;
use fixel::scene::{mesh_triangles, triangles_to_sink, DirectionalLight, Mesh};
use fixel::shading::{
    ModulateIntensity, PaletteBinding, PaletteModulateIntensity, PaletteReplace, Replace, Shader,
    TexBinding,
};
use fixel::surface::Binnable;
use fixel::texture::{Bilinear, IndexFormat, Lod, MipTexture, Nearest, PaletteTexture, Repeat};
use fixel_scenes as demo;

use crate::scenes::{geometry_done, viewport, Fnv1a, FrameResult, SmallBuffers, H, ROWS, W};

/// The most triangles a scene here hands over (the cube's 12).
pub const MAX_TRIS: usize = 12;

/// The clip-space triangles of `mesh` (`model`, the benchmark camera with far plane `far`,
/// lit when `lit`), their varyings taken from the classic vertex by `vary`.
fn triangles<const N: usize>(
    mesh: &Mesh<'_>,
    model: &Mat4,
    far: i32,
    lit: bool,
    vary: impl Fn(&ClipVertex) -> [i32; N],
) -> ([[Vertex<N>; 3]; MAX_TRIS], usize) {
    let zero = Vertex::new([Fx::ZERO; 4], [0; N]);
    let mut out = [[zero; 3]; MAX_TRIS];
    let mut n = 0;
    let light = DirectionalLight::default();
    mesh_triangles(
        mesh,
        model,
        &demo::camera(far),
        lit.then_some(&light),
        |t| {
            if let Some(slot) = out.get_mut(n) {
                *slot = t.each_ref().map(|v| Vertex::new(v.position, vary(v)));
                n += 1;
            }
        },
    );
    (out, n)
}

/// Draws `tris` with `draw` in bands through `buf`; band checksums between `pause` and
/// `resume`.
fn bands<S, P, const N: usize>(
    buf: &mut SmallBuffers,
    draw: &ShadedDraw<S, P, DepthLess>,
    tris: &[[Vertex<N>; 3]],
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
    ScreenTriangle<N>: Binnable,
{
    let mut sum = Fnv1a::default();
    let mut r = BandRenderer::new(&mut buf.color, W, ROWS, H)?
        .with_depth(&mut buf.depth)?
        .with_setup_cache(&mut buf.setups);
    let stats = r.render_spans(
        &[draw],
        &mut buf.bins,
        &mut buf.ranges,
        Rgb565::new(0, 0, 0),
        |sink| {
            triangles_to_sink(draw, 0, tris.len(), 0, |k, _| tris.get(k).copied(), sink);
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

/// The floor's clip-space triangles (`u, v`).
pub fn floor_tris() -> Result<([[Vertex<2>; 3]; MAX_TRIS], usize), Error> {
    let m = demo::floor();
    Ok(triangles(&m.mesh()?, &Mat4::IDENTITY, 200, false, |v| {
        [v.uv[0].to_bits(), v.uv[1].to_bits()]
    }))
}

/// The cube's clip-space triangles, frame 0 (`u, v`, intensity Q8.16).
pub fn cube_tris() -> Result<([[Vertex<3>; 3]; MAX_TRIS], usize), Error> {
    let m = demo::cube();
    Ok(triangles(&m.mesh()?, &demo::cube_model(0), 20, true, |v| {
        let c = v.to_vertex().varyings;
        [c[0], c[1], c[2]]
    }))
}

/// Scene `floor_rgb565`: the floor with `T(64, 64)` (`t`), nearest, unlit.
pub fn floor_rgb565(
    buf: &mut SmallBuffers,
    t: &MipTexture<'_>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let (tris, n) = floor_tris()?;
    let tex = TexBinding::new(t, Nearest, Repeat, Repeat, Lod::default())?;
    let d =
        ShadedDraw::<_, SubdividedBy<6>, DepthLess>::new(Replace { tex }, viewport()?, Cull::Back)?;
    bands(buf, &d, tris.get(..n).unwrap_or(&[]), pause, resume)
}

/// Scenes `floor_palette8` and `floor_palette4`: the floor with a palette bake of
/// `T(64, 64)` (`t`), nearest (the palette colour of the texel), unlit.
pub fn floor_palette<I: IndexFormat>(
    buf: &mut SmallBuffers,
    t: PaletteTexture<'_, I>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let (tris, n) = floor_tris()?;
    let tex = PaletteBinding::new(t, Nearest, Repeat, Repeat);
    let d = ShadedDraw::<_, SubdividedBy<6>, DepthLess>::new(
        PaletteReplace { tex },
        viewport()?,
        Cull::Back,
    )?;
    bands(buf, &d, tris.get(..n).unwrap_or(&[]), pause, resume)
}

/// Scene `cube_rgb565`: the cube, frame 0, with `T(128, 128)` (`t`), bilinear, lit per
/// vertex.
pub fn cube_rgb565(
    buf: &mut SmallBuffers,
    t: &MipTexture<'_>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let (tris, n) = cube_tris()?;
    let tex = TexBinding::new(t, Bilinear, Repeat, Repeat, Lod::default())?;
    let d = ShadedDraw::<_, QuadraticBy<4>, DepthLess>::new(
        ModulateIntensity { tex },
        viewport()?,
        Cull::Back,
    )?;
    bands(buf, &d, tris.get(..n).unwrap_or(&[]), pause, resume)
}

/// Scenes `cube_palette8` and `cube_palette4`: the cube, frame 0, with a palette bake of
/// `T(128, 128)` (`t`), bilinear (the four palette colours blended), lit per vertex.
pub fn cube_palette<I: IndexFormat>(
    buf: &mut SmallBuffers,
    t: PaletteTexture<'_, I>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let (tris, n) = cube_tris()?;
    let tex = PaletteBinding::new(t, Bilinear, Repeat, Repeat);
    let d = ShadedDraw::<_, QuadraticBy<4>, DepthLess>::new(
        PaletteModulateIntensity { tex },
        viewport()?,
        Cull::Back,
    )?;
    bands(buf, &d, tris.get(..n).unwrap_or(&[]), pause, resume)
}
