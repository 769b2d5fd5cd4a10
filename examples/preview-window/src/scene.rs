//! The scenes the window shows (the benchmark cube, sphere and teapot with their textures),
//! the techniques it switches between, the orbiting camera, and the frame drawn in 8-row
//! bands through `BandRenderer::render_spans`, as the band firmwares draw it
//! (`examples/firmware/src/scenes.rs`): each band is flushed to the display through
//! `DrawTargetFlush` and copied into the whole frame kept for the PNG.

use std::convert::Infallible;

use embedded_graphics_core::draw_target::DrawTarget;
use fixel::math::Fx;
use fixel::pipeline::KeptSetup;
use fixel::prelude::*;
use fixel::scene::{mesh_to_sink, CachedVertex, DirectionalLight, Mesh, MeshTransform};
use fixel::surface::{BandRange, BandRenderer, BandStats, Binned, DrawTargetFlush};
use fixel::texture::{write_footprints, MipTexture};
use fixel_scenes::{self as demo, MeshData};

use crate::modes::{Filt, Mode, Proj};

/// The Utah teapot as the teapot firmware has it (`cargo xtask bake-obj`, cylindrical uv).
#[allow(dead_code)] // TEAPOT_TANGENTS: no technique here maps normals.
mod teapot {
    include!("../../../assets/teapot/teapot_mesh.rs");
}

/// Frame width (the benchmark display's).
pub const W: u32 = demo::WIDTH;
/// Frame height.
pub const H: u32 = demo::HEIGHT;
/// Rows per band, as in the band firmwares: 320 x 8 colour + 16-bit depth, 10 KiB.
pub const ROWS: u32 = 8;
/// Binned screen triangles (the cube's fit; the sphere and teapot keep band ranges).
const BINS: usize = 16;
/// Prepared-vertex cache, as the sphere firmware's.
const CACHE: usize = 64;
/// Raster set-ups kept from one band for the next, as the sphere firmware's.
const SETUPS: usize = 36;

/// A scene of the window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneKind {
    /// The lit cube, `T(128, 128)`.
    Cube,
    /// The lit UV sphere (2,208 triangles), `T(256, 128)`.
    Sphere,
    /// The Utah teapot (1,560 triangles), `T(256, 128)`.
    Teapot,
}

impl SceneKind {
    /// Every scene, in the order the `s` key steps through them.
    pub const ALL: [SceneKind; 3] = [SceneKind::Cube, SceneKind::Sphere, SceneKind::Teapot];

    /// Name on the command line (`--scene`).
    pub fn name(self) -> &'static str {
        match self {
            SceneKind::Cube => "cube",
            SceneKind::Sphere => "sphere",
            SceneKind::Teapot => "teapot",
        }
    }

    /// Parses [`SceneKind::name`].
    pub fn parse(s: &str) -> Option<SceneKind> {
        SceneKind::ALL.into_iter().find(|k| k.name() == s)
    }

    /// The scene after this one.
    pub fn next(self) -> SceneKind {
        let i = SceneKind::ALL.iter().position(|&k| k == self).unwrap_or(0);
        SceneKind::ALL[(i + 1) % SceneKind::ALL.len()]
    }

    /// The technique the scene's firmware draws it with.
    pub fn firmware_technique(self) -> usize {
        match self {
            SceneKind::Cube => 1,
            SceneKind::Sphere | SceneKind::Teapot => 0,
        }
    }

    /// The camera of the benchmark's frame 0 of this scene.
    pub fn start(self) -> Orbit {
        let rad = |bits: i32| Angle::from_radians(Fx::from_bits(bits));
        match self {
            // demo::cube_model(0): T(0, 0, -4) * Rx(0.3) * Ry(0.7).
            SceneKind::Cube => Orbit {
                yaw: rad(45875),
                pitch: rad(19661),
                distance: Fx::from_num(4),
                lift: Fx::ZERO,
            },
            // demo::sphere_model(0): T(0, 0, -5).
            SceneKind::Sphere => Orbit {
                yaw: Angle::ZERO,
                pitch: Angle::ZERO,
                distance: Fx::from_num(5),
                lift: Fx::ZERO,
            },
            // The teapot firmware's frame 0: T(0, -0.2, -8) * Rx(0.349) * Ry(-0.524).
            SceneKind::Teapot => Orbit {
                yaw: rad(-34315),
                pitch: rad(22877),
                distance: Fx::from_num(8),
                lift: Fx::from_num(-0.2),
            },
        }
    }
}

/// The techniques the `t` key steps through: typed pipelines of `modes.rs` (one
/// monomorphised span loop each, as in a firmware), all lit, `Repeat` wrap, depth-tested.
pub const TECHNIQUES: [Mode; 6] = [
    // The sphere and teapot firmwares' mode.
    mode(true, false, Filt::Bilinear, Proj::Sub64),
    // The cube firmware's mode: light once per face, bilinear from footprints, parabolas.
    mode(true, true, Filt::BilinearFootprint, Proj::Quad16),
    // The report's balanced mode for the sphere.
    mode(true, false, Filt::BilinearFootprint, Proj::Adaptive),
    mode(true, false, Filt::Bilinear, Proj::Exact),
    mode(true, false, Filt::Bilinear, Proj::Adaptive),
    // The cheapest lit mode.
    mode(true, false, Filt::Nearest, Proj::Affine),
];

const fn mode(lit: bool, facet: bool, filter: Filt, proj: Proj) -> Mode {
    Mode {
        lit,
        facet,
        filter,
        proj,
    }
}

/// A technique's name: `lit-bilinear-sub64`, ...
pub fn technique_name(mode: &Mode) -> String {
    let mut s = String::new();
    // Writing to a String cannot fail.
    let _ = mode.write_name(&mut s);
    s
}

/// The camera turned around the model: the model matrix is
/// `T(0, lift, -distance) * (Rx(pitch) * Ry(yaw))` under the benchmark camera (at the
/// origin, looking down `-z`, 45 degrees, near 0.5, far 20).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Orbit {
    /// Turn about the model's `y` axis.
    pub yaw: Angle,
    /// Tilt about the view's `x` axis.
    pub pitch: Angle,
    /// Distance from the camera, in model units (I16F16).
    pub distance: Fx,
    /// Vertical offset in view space, in model units (I16F16).
    pub lift: Fx,
}

impl Orbit {
    /// The model matrix.
    pub fn model(&self) -> Mat4 {
        Mat4::translation(Vec3::new(Fx::ZERO, self.lift, -self.distance))
            * (Mat4::rotation_x(self.pitch) * Mat4::rotation_y(self.yaw))
    }

    /// Yaw and pitch in whole degrees, for the status line.
    pub fn degrees(&self) -> (i32, i32) {
        // An Angle is n / 65536 of a turn; as i16, n runs from -half a turn.
        let deg = |a: Angle| (f64::from(a.0 as i16) * 360.0 / 65536.0).round() as i32;
        (deg(self.yaw), deg(self.pitch))
    }
}

/// The meshes, textures and band storage of the window, built once.
pub struct Scenes {
    cube: MeshData<24, 12>,
    sphere: Box<MeshData<{ demo::SPHERE_VERTICES }, { demo::SPHERE_TRIANGLES }>>,
    /// `T(128, 128)` and its bilinear footprints (the cube's).
    t128: (Vec<Rgb565>, Vec<u64>),
    /// `T(256, 128)` and its bilinear footprints (the sphere's and the teapot's).
    t256: (Vec<Rgb565>, Vec<u64>),
    color: Vec<Rgb565>,
    depth: Vec<u16>,
    bins: Vec<Binned>,
    ranges: Vec<BandRange>,
    cache: Vec<CachedVertex>,
    setups: Vec<KeptSetup>,
}

/// The benchmark texture `T(w, h)` and its footprints.
fn texture(w: u32, h: u32) -> Result<(Vec<Rgb565>, Vec<u64>), Error> {
    let mut texels = vec![Rgb565::BLACK; (w * h) as usize];
    demo::checker_texture(w, h, &mut texels)?;
    let mut footprints = vec![0u64; texels.len()];
    write_footprints(&Texture::new(&texels, w, h)?, &mut footprints)?;
    Ok((texels, footprints))
}

impl Scenes {
    /// Builds the meshes, textures and buffers.
    pub fn new() -> Result<Scenes, Error> {
        let band = (W * ROWS) as usize;
        Ok(Scenes {
            cube: demo::cube(),
            sphere: Box::new(demo::sphere()),
            t128: texture(128, 128)?,
            t256: texture(256, 128)?,
            color: vec![Rgb565::BLACK; band],
            depth: vec![0; band],
            bins: vec![Binned::default(); BINS],
            ranges: vec![BandRange::EMPTY; demo::SPHERE_TRIANGLES],
            cache: vec![CachedVertex::EMPTY; CACHE],
            setups: vec![KeptSetup::EMPTY; SETUPS],
        })
    }

    /// Draws `scene` in `technique` seen from `orbit`, band by band: each band goes to
    /// `display` through [`DrawTargetFlush`] and into `frame` (`W * H` pixels, row 0 first).
    pub fn render<D>(
        &mut self,
        scene: SceneKind,
        technique: &Mode,
        orbit: &Orbit,
        display: &mut D,
        frame: &mut [Rgb565],
    ) -> Result<BandStats, Error>
    where
        D: DrawTarget<Color = Rgb565, Error = Infallible>,
    {
        let (texels, footprints, tw, th) = match scene {
            SceneKind::Cube => (&self.t128.0, &self.t128.1, 128, 128),
            SceneKind::Sphere | SceneKind::Teapot => (&self.t256.0, &self.t256.1, 256, 128),
        };
        let texture =
            MipTexture::single(Texture::new(texels, tw, th)?).with_footprints(footprints)?;
        let draw = technique.draw(texture, Viewport::new(0, 0, W, H)?)?;
        let mesh = match scene {
            SceneKind::Cube => self.cube.mesh()?,
            SceneKind::Sphere => self.sphere.mesh()?,
            SceneKind::Teapot => Mesh::new(
                &teapot::TEAPOT_POSITIONS,
                Some(&teapot::TEAPOT_NORMALS),
                &teapot::TEAPOT_UVS,
                &teapot::TEAPOT_INDICES,
            )?,
        };
        let transform = MeshTransform::new(&orbit.model(), &demo::camera(20));
        let light = DirectionalLight::default();
        let light = technique.lit.then_some(&light);

        let mut bands = BandRenderer::new(&mut self.color, W, ROWS, H)?
            .with_depth(&mut self.depth)?
            .with_setup_cache(&mut self.setups);
        let cache = &mut self.cache;
        let mut out = DrawTargetFlush(display);
        let stats = bands.render_spans(
            &[&draw],
            &mut self.bins,
            &mut self.ranges,
            Rgb565::BLACK,
            |sink| {
                mesh_to_sink(&draw, 0, &mesh, &transform, light, cache, 0, sink);
            },
            |band| {
                let start = band.first_row().max(0) as usize * W as usize;
                let px = band.pixels();
                if let Some(dst) = frame.get_mut(start..start + px.len()) {
                    dst.copy_from_slice(px);
                }
                out.flush(band)
            },
        )?;
        Ok(stats)
    }
}
