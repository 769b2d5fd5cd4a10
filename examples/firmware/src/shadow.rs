//! The shadow-mapping scene (`fixel_scenes::shadow`) for the firmware: the light pass into a
//! 64 x 64 map (8 KiB), then the lit pass in bands of 4 rows (5 KiB of colour and depth),
//! its screen triangles binned once by fixel's band renderer (`BandRenderer::render`). Shared word for word with the host test
//! `host-tests/tests/shadow_mcu.rs` (included there with `#[path]`), so the checksums are
//! computed by the same code. The floor uses `T(64, 64)` here (the host picture uses a
//! stone texture), the cube `T(128, 128)`.

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::ScreenTriangle;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::prelude::*;
use fixel::scene::shadowed_mesh_triangles;
use fixel::shading::pcf::ShadowFilter;
use fixel::shading::shadow::{with_light, Bias, LightKind, LightSpace, Shadowed};
use fixel::shading::Classic;
use fixel::shading::{ModulateIntensity, Shader};
use fixel::surface::DepthMap;
use fixel::surface::{BandRenderer, Binnable, Binned};
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat};
use fixel_scenes::shadow::{self as scene, SceneLight};

use crate::scenes::{Fnv1a, FrameResult, H, W};

/// Shadow map side.
pub const MAP: u32 = 64;
/// Texels of the map.
pub const MAP_TEXELS: usize = (MAP * MAP) as usize;
/// Rows per band (4: colour and depth 5 KiB, so map, band and stack fit 24 KiB of RAM).
pub const ROWS: u32 = 4;
/// Binned screen triangles (the scene has 8 to 10 after culling and clipping).
pub const BINS: usize = 16;

/// Everything the shadowed frame needs in RAM: map 8 KiB, band 5 KiB (the bins, 2.7 KiB,
/// are on the stack).
pub struct ShadowBuffers {
    /// The shadow map.
    pub map: [u16; MAP_TEXELS],
    color: [Rgb565; (W * ROWS) as usize],
    depth: [u16; (W * ROWS) as usize],
}

impl ShadowBuffers {
    /// Zeroed buffers.
    pub const fn new() -> Self {
        ShadowBuffers {
            map: [0; MAP_TEXELS],
            color: [Rgb565::new(0, 0, 0); (W * ROWS) as usize],
            depth: [0; (W * ROWS) as usize],
        }
    }
}

impl Default for ShadowBuffers {
    fn default() -> Self {
        Self::new()
    }
}

/// The light pass of the scene into `map`; returns the texels written.
pub fn light_pass<K: LightKind>(space: &LightSpace<K>, map: &mut [u16]) -> Result<u32, Error> {
    light_pass_culling(space, map, Cull::Back)
}

/// [`light_pass`] culling `cull` faces as seen from the light (`Cull::Front` against acne).
pub fn light_pass_culling<K: LightKind>(
    space: &LightSpace<K>,
    map: &mut [u16],
    cull: Cull,
) -> Result<u32, Error> {
    let mut m = DepthMap::new(map, MAP)?;
    scene::light_pass_culling(space, &mut m, cull)
}

/// The lit pass in bands, with filter `F` under `space` (its map in `buf.map`, drawn
/// before); `M` is 6 for a directional light, 7 for the spot. `pause` and `resume` bracket
/// the checksum of each band (left out of instruction counts).
#[allow(clippy::too_many_arguments)]
pub fn lit_pass<K: LightKind, F: ShadowFilter, const M: usize, const UV: bool>(
    buf: &mut ShadowBuffers,
    space: &LightSpace<K>,
    light: SceneLight,
    cube_tex: Texture<'_>,
    floor_tex: Texture<'_>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    ScreenTriangle<M>: Binnable,
{
    let map = fixel::surface::ShadowMap::new(&buf.map, MAP)?;
    let (ct, ft) = (MipTexture::single(cube_tex), MipTexture::single(floor_tex));
    let shader = |t| -> Result<Shadowed<'_, _, K, F, M, UV>, Error> {
        Shadowed::new(
            ModulateIntensity {
                tex: TexBinding::new(t, Bilinear, Repeat, Repeat, Lod::default())?,
            },
            map,
            Bias::for_filter::<F>(),
        )
    };
    let vp = Viewport::new(0, 0, W, H)?;
    let draws = [
        ShadedDraw::<_, Exact, DepthLess>::new(shader(&ct)?, vp, Cull::Back)?,
        ShadedDraw::<_, Exact, DepthLess>::new(shader(&ft)?, vp, Cull::Back)?,
    ];
    banded(
        &mut buf.color,
        &mut buf.depth,
        &draws,
        space,
        light,
        pause,
        resume,
    )
}

/// [`lit_pass`]'s frame drawn whole into `color` / `depth` (320 x 240) from the map
/// `map`, through the scene's own lit pass (`fixel_scenes::shadow::lit_pass`): the figure
/// the banded frame is compared with, and the same checksum.
#[allow(clippy::too_many_arguments)]
pub fn lit_pass_whole<K: LightKind, F: ShadowFilter, const M: usize, const UV: bool>(
    color: &mut [Rgb565],
    depth: &mut [u16],
    map: &[u16],
    space: &LightSpace<K>,
    light: SceneLight,
    cube_tex: Texture<'_>,
    floor_tex: Texture<'_>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let map = fixel::surface::ShadowMap::new(map, MAP)?;
    let (ct, ft) = (MipTexture::single(cube_tex), MipTexture::single(floor_tex));
    let shader = |t| -> Result<Shadowed<'_, _, K, F, M, UV>, Error> {
        Shadowed::new(
            ModulateIntensity {
                tex: TexBinding::new(t, Bilinear, Repeat, Repeat, Lod::default())?,
            },
            map,
            Bias::for_filter::<F>(),
        )
    };
    let vp = Viewport::new(0, 0, W, H)?;
    let cube = ShadedDraw::<_, Exact, DepthLess>::new(shader(&ct)?, vp, Cull::Back)?;
    let floor = ShadedDraw::<_, Exact, DepthLess>::new(shader(&ft)?, vp, Cull::Back)?;
    let mut frame = fixel::surface::Frame::new(color, W, H)?.with_depth(depth)?;
    frame.clear(Rgb565::new(4, 10, 14));
    let pixels = scene::lit_pass([&cube, &floor], space, light, &mut frame)?;
    pause();
    let mut sum = Fnv1a::default();
    sum.pixels(frame.pixels());
    resume();
    Ok(FrameResult {
        checksum: sum.0,
        stats: fixel::surface::BandStats {
            bands: 1,
            pixels,
            ..fixel::surface::BandStats::default()
        },
    })
}

/// The same frame without shadows (the inner shader alone, same geometry, light-space
/// varyings computed per vertex and dropped): the baseline of the lit pass's cost.
pub fn unshadowed_pass<K: LightKind>(
    buf: &mut ShadowBuffers,
    space: &LightSpace<K>,
    light: SceneLight,
    cube_tex: Texture<'_>,
    floor_tex: Texture<'_>,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let (ct, ft) = (MipTexture::single(cube_tex), MipTexture::single(floor_tex));
    let shader = |t| -> Result<ModulateIntensity<'_, Bilinear, Repeat, Repeat>, Error> {
        Ok(ModulateIntensity {
            tex: TexBinding::new(t, Bilinear, Repeat, Repeat, Lod::default())?,
        })
    };
    let vp = Viewport::new(0, 0, W, H)?;
    let draws = [
        ShadedDraw::<_, Exact, DepthLess>::new(shader(&ct)?, vp, Cull::Back)?,
        ShadedDraw::<_, Exact, DepthLess>::new(shader(&ft)?, vp, Cull::Back)?,
    ];
    banded(
        &mut buf.color,
        &mut buf.depth,
        &draws,
        space,
        light,
        pause,
        resume,
    )
}

/// The scene's geometry once (screen triangles binned with their draw: `draws[0]` the
/// cube, `draws[1]` the floor; vertices `u, v, intensity` then the first `M - 3` light
/// varyings), then each band of `ROWS` rows drawn from the bins and hashed.
#[allow(clippy::too_many_arguments)]
fn banded<K: LightKind, S: Shader<Varyings = [i32; M]>, const M: usize>(
    color: &mut [Rgb565],
    depth: &mut [u16],
    draws: &[ShadedDraw<S, Exact, DepthLess>; 2],
    space: &LightSpace<K>,
    light: SceneLight,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error>
where
    ScreenTriangle<M>: Binnable,
{
    let mut bins = [Binned::EMPTY; BINS];
    let (cube, model, floor) = scene::meshes();
    let (cam, gl) = (scene::camera(), scene::gouraud_light(light));
    let meshes = [(cube.mesh()?, model), (floor.mesh()?, Mat4::IDENTITY)];
    let mut sum = Fnv1a::default();
    let mut bands = BandRenderer::new(color, W, ROWS, H)?.with_depth(depth)?;
    let stats = bands.render(
        &[&draws[0], &draws[1]],
        &mut bins,
        Rgb565::new(4, 10, 14),
        |sink| {
            for (d, (mesh, m)) in meshes.iter().enumerate() {
                let draw = &draws[d];
                shadowed_mesh_triangles(mesh, m, &cam, Some(&gl), space, |cv, lv| {
                    let tri = [0, 1, 2].map(|k| {
                        let v = cv[k].to_vertex();
                        let inner = ModulateIntensity::<Bilinear, Repeat, Repeat>::from_classic(
                            &v.varyings,
                        );
                        with_light::<3, M>(&fixel::geometry::Vertex::new(v.position, inner), lv[k])
                    });
                    draw.project(&tri, &mut |s| sink.push(d as u8, s));
                });
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

/// A whole `shadow_*` firmware under directional light `light`: see [`run`].
/// (Firmware only: the host tests include this file for the scene code above.)
#[cfg(target_os = "none")]
pub fn run_directional<F: ShadowFilter, const UV: bool>(
    name: &str,
    light: SceneLight,
    cull: Cull,
    buf: &mut ShadowBuffers,
) -> bool {
    match scene::directional(light) {
        Ok(space) => run::<_, F, 6, UV>(name, &space, light, cull, buf),
        Err(_) => false,
    }
}

/// A whole `shadow_*` firmware: the light pass of `space` culling `cull` faces (not
/// counted), then the lit pass with filter `F` (`M`: 6 directional, 7 spot), counted and
/// reported as scene `name`.
#[cfg(target_os = "none")]
pub fn run<K: LightKind, F: ShadowFilter, const M: usize, const UV: bool>(
    name: &str,
    space: &LightSpace<K>,
    light: SceneLight,
    cull: Cull,
    buf: &mut ShadowBuffers,
) -> bool
where
    ScreenTriangle<M>: Binnable,
{
    if light_pass_culling(space, &mut buf.map, cull).is_err() {
        return false;
    }
    crate::report(name, |pause, resume| {
        lit_pass::<_, F, M, UV>(
            buf,
            space,
            light,
            core::hint::black_box(crate::data::T128),
            core::hint::black_box(crate::data::T64),
            pause,
            resume,
        )
    })
}

/// The whole-frame twin of a directional `shadow_*` firmware: the light pass into `map`
/// (not counted), then [`lit_pass_whole`] with filter `F`, counted and reported as `name`.
#[cfg(target_os = "none")]
pub fn run_whole_directional<F: ShadowFilter, const UV: bool>(
    name: &str,
    light: SceneLight,
    map: &mut [u16],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> bool {
    let Ok(space) = scene::directional(light) else {
        return false;
    };
    if light_pass_culling(&space, map, Cull::Back).is_err() {
        return false;
    }
    crate::report(name, |pause, resume| {
        lit_pass_whole::<_, F, 6, UV>(
            color,
            depth,
            map,
            &space,
            light,
            core::hint::black_box(crate::data::T128),
            core::hint::black_box(crate::data::T64),
            pause,
            resume,
        )
    })
}
