//! The solid-texture test scenes, drawn by fixel and by the f64 reference
//! ([`crate::reference::noise`]): a marble sphere, a wooden cube and a granite floor running
//! to the horizon, each alone in a 160 x 120 frame so the reference needs no depth test.

use crate::reference::noise::{render_solid, RefOctaves, RefPattern, RefSolidImage};
use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Fx, Mat4};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::scene::DirectionalLight;
use fixel::shading::noise::{BandLimit, Fixed, Octaves, Pattern, Ramps, SolidMesh, SolidShader};
use fixel::shading::Shader;
use fixel::surface::{Frame, DEPTH_CLEAR};
use fixel::texture::LodGranularity;
use fixel_scenes as demo;
use fixel_scenes::noise::{marble_sphere_model, wood_cube_model, FLOOR_SCALE, SHOWCASE_SCALE};

/// Frame width of the test scenes.
pub const W: u32 = 160;
/// Frame height of the test scenes.
pub const H: u32 = 120;

/// Which object.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SolidScene {
    /// The marble sphere.
    Marble,
    /// The wooden cube.
    Wood,
    /// The granite floor (x in ±50, z from -1 to -100: footprints up to many cells).
    Granite,
}

impl SolidScene {
    /// All three.
    pub const ALL: [SolidScene; 3] = [SolidScene::Marble, SolidScene::Wood, SolidScene::Granite];

    /// Short name.
    pub fn name(self) -> &'static str {
        match self {
            SolidScene::Marble => "marble",
            SolidScene::Wood => "wood",
            SolidScene::Granite => "granite",
        }
    }

    /// The clip-space triangles (fixel's vertices, shared with the reference).
    pub fn triangles(self) -> Vec<[Vertex<4>; 3]> {
        fn tris<const V: usize, const T: usize>(
            m: &demo::MeshData<V, T>,
            model: &Mat4,
            scale: Fx,
        ) -> Vec<[Vertex<4>; 3]> {
            let mesh = SolidMesh::new(&m.positions, Some(&m.normals), &m.indices, scale)
                .expect("the demo meshes are valid");
            let mut out = Vec::new();
            let light = DirectionalLight::default();
            mesh.triangles(model, &demo::camera(200), Some(&light), |t| out.push(*t));
            out
        }
        match self {
            SolidScene::Marble => tris(&demo::sphere(), &marble_sphere_centred(), SHOWCASE_SCALE),
            SolidScene::Wood => tris(&demo::cube(), &wood_cube_centred(), SHOWCASE_SCALE),
            SolidScene::Granite => tris(&demo::floor(), &Mat4::IDENTITY, FLOOR_SCALE),
        }
    }

    /// The reference pattern.
    pub fn ref_pattern(self) -> RefPattern {
        let [m, w, g] = RefPattern::presets();
        match self {
            SolidScene::Marble => m,
            SolidScene::Wood => w,
            SolidScene::Granite => g,
        }
    }

    /// Draws the scene with fixel: raw RGB565 pixels and coverage.
    pub fn draw(self, ramps: &Ramps, octaves: OctaveMode) -> (Vec<u16>, Vec<bool>) {
        let tris = self.triangles();
        match (self, octaves) {
            (SolidScene::Marble, OctaveMode::Fixed(k)) => {
                draw(ramps.marble(), Fixed(k), None, &tris)
            }
            (SolidScene::Wood, OctaveMode::Fixed(k)) => draw(ramps.wood(), Fixed(k), None, &tris),
            (SolidScene::Granite, OctaveMode::Fixed(k)) => {
                draw(ramps.granite(), Fixed(k), None, &tris)
            }
            (SolidScene::Marble, OctaveMode::Band(k, g)) => {
                draw(ramps.marble(), BandLimit::new(k), Some(g), &tris)
            }
            (SolidScene::Wood, OctaveMode::Band(k, g)) => {
                draw(ramps.wood(), BandLimit::new(k), Some(g), &tris)
            }
            (SolidScene::Granite, OctaveMode::Band(k, g)) => {
                draw(ramps.granite(), BandLimit::new(k), Some(g), &tris)
            }
        }
    }

    /// The f64 reference of the scene (`ss × ss` samples per pixel).
    pub fn reference(self, octaves: RefOctaves, ss: u32) -> RefSolidImage {
        render_solid(&self.triangles(), self.ref_pattern(), octaves, ss, W, H)
    }
}

/// The marble sphere moved to the middle of the frame (same rotation as the showcase).
pub fn marble_sphere_centred() -> Mat4 {
    Mat4::translation(fixel::math::Vec3::new(
        Fx::from_num(1.6),
        Fx::from_num(-0.5),
        Fx::from_num(1.5),
    )) * marble_sphere_model()
}

/// The wooden cube moved to the middle of the frame.
pub fn wood_cube_centred() -> Mat4 {
    Mat4::translation(fixel::math::Vec3::new(
        Fx::from_num(-1.8),
        Fx::ZERO,
        Fx::from_num(2),
    )) * wood_cube_model()
}

/// Octaves as fixel draws them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OctaveMode {
    /// A fixed count.
    Fixed(u8),
    /// Band-limited to at most this many octaves, footprint at this granularity.
    Band(u8, LodGranularity),
}

impl OctaveMode {
    /// The reference's octaves for this mode.
    pub fn reference(self) -> RefOctaves {
        match self {
            OctaveMode::Fixed(k) => RefOctaves::Fixed(u32::from(k)),
            OctaveMode::Band(k, _) => RefOctaves::Band {
                max: u32::from(k),
                bias: 0.0,
            },
        }
    }
}

fn draw<P: Pattern, O: Octaves>(
    pattern: P,
    octaves: O,
    granularity: Option<LodGranularity>,
    tris: &[[Vertex<4>; 3]],
) -> (Vec<u16>, Vec<bool>)
where
    SolidShader<P, O>: Shader<Varyings = [i32; 4]>,
{
    let mut shader = SolidShader::new(pattern, octaves);
    if let Some(g) = granularity {
        shader.granularity = g;
    }
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).expect("draw");
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::BLACK; n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, W, H)
        .expect("frame")
        .with_depth(&mut depth)
        .expect("depth");
    frame.clear(Rgb565::BLACK);
    draw.clip_triangles(tris, &mut frame)
        .expect("frame has depth");
    let px = frame
        .pixels()
        .iter()
        .map(|c| RawU16::from(*c).into_inner())
        .collect();
    let cov = frame
        .depth()
        .expect("depth")
        .iter()
        .map(|&d| d != DEPTH_CLEAR)
        .collect();
    (px, cov)
}
