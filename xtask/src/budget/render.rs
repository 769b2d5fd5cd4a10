//! What a model's frame does, counted by drawing it on the host as the model firmwares
//! (`examples/firmware/src/model_scene.rs`) draw the glTF samples: lit, bilinear, repeat,
//! perspective exact every 64 pixels, depth-tested, back faces culled, in bands of 8 rows
//! through band ranges (one per triangle) and a 64-entry vertex cache. It keeps no set-ups
//! for the next band (the same pixels): a triangle kept whole for the next band ends its
//! band range where it is kept, and the pieces are counted from the ranges. The frame's
//! pixels, screen triangles and band pieces, and each band's share of them, feed the cost
//! model of `fit.rs`.

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::pipeline::Pipeline;
use fixel::prelude::*;
use fixel::scene::{mesh_to_sink, CachedVertex, Camera, DirectionalLight, Mesh, MeshTransform};
use fixel::surface::{BandRange, Binned};
use fixel::texture::{Bilinear, MipTexture, Repeat};

use super::fit::{Binning, Counts, Mode};
use crate::bake_obj::Baked;

/// The model scenes' draw (`model_scene::draw`, the firmwares' `LitSphere`).
pub type LitBilinear = Pipeline<
    fixel::pipeline::SubdividedBy<6>,
    Bilinear,
    Repeat,
    Repeat,
    fixel::pipeline::ModulateIntensity,
    fixel::pipeline::DepthLess,
>;

/// Rows per band (the firmwares' bands).
pub const ROWS: u32 = 8;
/// Prepared vertices cached across the band passes (the firmwares' `CACHE`).
pub const CACHE: usize = 64;
/// Set-ups kept from one band for the next (the firmwares' `SETUPS`).
pub const SETUPS: usize = 31;

/// A baked model's data and texture, in fixel's formats.
pub struct Model {
    /// Name in the tables.
    pub name: String,
    /// The mesh as `bake-gltf` converts it.
    pub mesh: Baked,
    /// Texture chain, level 0 first (a 1 x 1 white texel when the model has none).
    pub texels: Vec<Rgb565>,
    /// Level 0 width and height, levels.
    pub texture: (u32, u32, u32),
    /// Whether the model has vertex colours (2 bytes of flash per vertex).
    pub colors: bool,
}

/// Where a band's work goes: its pixels written and band pieces.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BandLoad {
    /// Pixels that differ from the clear colour after the band is drawn.
    pub pixels: u64,
    /// Triangles whose band range covers the band.
    pub pieces: u64,
}

/// The model scenes' view of a model placed by `bake-gltf --center` and scaled to about
/// 3 units: turned 60 degrees about y and 15 about x, 5.2 units down `-z` (`fox_model`).
pub fn view() -> Mat4 {
    Mat4::translation(Vec3::from_num(0, 0, -5.2))
        * Mat4::rotation_x(Angle::from_degrees(Fx::from_num(15)))
        * Mat4::rotation_y(Angle::from_degrees(Fx::from_num(-60)))
}

/// The model scenes' camera (45 degrees vertical field of view, near 0.5, far 20) for a
/// `w x h` frame.
fn camera(w: u32, h: u32) -> Result<Camera, String> {
    Camera::perspective(
        Angle::from_degrees(Fx::from_num(45)),
        Fx::from_num(f64::from(w) / f64::from(h)),
        Fx::from_bits(1 << 15),
        Fx::from_num(20),
    )
    .map_err(|e| format!("camera for {w} x {h}: {e}"))
}

/// Draws `m` with `model` into a `w x h` frame in bands and counts what it does.
pub fn count(
    m: &Model,
    (w, h): (u32, u32),
    model: &Mat4,
) -> Result<(Counts, Vec<BandLoad>), String> {
    let err = |e: fixel::Error| format!("{}: {e}", m.name);
    let mesh = Mesh::new(
        &m.mesh.positions,
        Some(&m.mesh.normals),
        &m.mesh.uvs,
        &m.mesh.indices,
    )
    .map_err(err)?;
    let (tw, th, levels) = m.texture;
    let texture = MipTexture::new(&m.texels, tw, th, levels).map_err(err)?;
    let draw = Draw::new_mip::<LitBilinear>(
        Some(texture),
        Viewport::new(0, 0, w, h).map_err(err)?,
        Cull::Back,
    )
    .map_err(err)?;
    let transform = MeshTransform::new(model, &camera(w, h)?);
    let light = DirectionalLight::default();
    let band_px = (w * ROWS) as usize;
    let mut color = vec![Rgb565::new(0, 0, 0); band_px];
    let mut depth = vec![0u16; band_px];
    let mut cache = vec![CachedVertex::EMPTY; CACHE];
    let mut ranges = vec![BandRange::EMPTY; mesh.triangles()];
    let mut bins: [Binned; 0] = [];
    // A clear colour no texel of the samples has, so a band's drawn pixels can be told.
    let clear = Rgb565::new(31, 0, 31);
    let mut drawn = Vec::new();
    let stats = {
        let mut bands = BandRenderer::new(&mut color, w, ROWS, h)
            .map_err(err)?
            .with_depth(&mut depth)
            .map_err(err)?;
        bands
            .render_spans(
                &[&draw],
                &mut bins,
                &mut ranges,
                clear,
                |sink| {
                    mesh_to_sink(
                        &draw,
                        0,
                        &mesh,
                        &transform,
                        Some(&light),
                        &mut cache,
                        0,
                        sink,
                    );
                },
                |band: &Frame<'_, Rgb565>| {
                    drawn.push(band.pixels().iter().filter(|p| **p != clear).count() as u64);
                    Ok::<(), core::convert::Infallible>(())
                },
            )
            .map_err(|e| format!("{}: {e:?}", m.name))?
    };
    let bands = h.div_ceil(ROWS);
    let loads: Vec<BandLoad> = (0..bands)
        .map(|b| BandLoad {
            pixels: drawn.get(b as usize).copied().unwrap_or(0),
            pieces: ranges.iter().filter(|r| r.covers(b)).count() as u64,
        })
        .collect();
    let counts = Counts {
        scene: m.name.clone(),
        mode: Mode::LitBilinear,
        binning: Binning::Ranges,
        size: (w, h),
        rows: ROWS,
        vertices: mesh.vertices() as u64,
        triangles: mesh.triangles() as u64,
        binned: u64::from(stats.triangles),
        pieces: loads.iter().map(|l| l.pieces).sum(),
        pixels: u64::from(stats.pixels),
    };
    Ok((counts, loads))
}
