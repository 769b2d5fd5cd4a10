//! The benchmark scenes of `docs/scenes.md` as runnable cases, shared by `benches/scenes.rs`
//! (criterion timing) and `examples/count_scene.rs` (instruction counts under callgrind).
//!
//! A case is a scene (cube, sphere, floor) plus a [`Mode`] (lit or not, filter, projection).
//! The modes are those of `examples/firmware/src/modes.rs`, included here word for word
//! (as in the report firmwares and `host-tests/src/bin/report/`): one mode table, one
//! [`Mode::draw`] and one [`Mode::write_name`] for the firmwares, the host report and these
//! benchmarks. Every mode is a typed `Pipeline` built with `Draw::new_mip`: the per-pixel
//! loop is monomorphised for exactly that combination and chosen once per draw. Lit modes
//! use `ModulateIntensity` (per-vertex light times the texel), unlit ones `Replace`; all
//! depth-test (`DepthLess`, 16-bit depth buffer) with repeat wrap and back-face culling.
//! Mipmapped filters get the texture's full mip chain.

// Shared by the bench and the example; each uses a different part (and of `modes`, only the
// mode type and its draw and name are used here).
#![allow(dead_code)]

#[path = "../firmware/src/modes.rs"]
mod modes;

pub use modes::{Filt, Mode, Proj};

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::prelude::*;
use fixel::scene::{draw_mesh_cached, DirectionalLight, Mesh};
use fixel::texture::{chain_len, full_levels};
use fixel::texture::{generate_mips, write_footprints, MipTexture};
use fixel_scenes as demo;

/// A benchmark scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scene {
    /// Lit cube, `T(128, 128)`, 100 frames rotating.
    Cube,
    /// Lit UV sphere, `T(256, 128)`, 100 frames rotating.
    Sphere,
    /// Unlit floor quad, `T(64, 64)`, 20 frames, camera fixed.
    Floor,
}

impl Scene {
    /// Name used on the command line and in tables.
    pub fn name(self) -> &'static str {
        match self {
            Scene::Cube => "cube",
            Scene::Sphere => "sphere",
            Scene::Floor => "floor",
        }
    }

    /// Frames per run (`N` of `docs/scenes.md`).
    pub fn frames(self) -> u32 {
        match self {
            Scene::Cube | Scene::Sphere => 100,
            Scene::Floor => 20,
        }
    }

    fn parse(s: &str) -> Option<Self> {
        [Scene::Cube, Scene::Sphere, Scene::Floor]
            .into_iter()
            .find(|k| k.name() == s)
    }
}

/// Every [`Filt`], for parsing names (`filt_listed` fails to compile when one is missing).
const FILTS: [Filt; 6] = [
    Filt::Nearest,
    Filt::Bilinear,
    Filt::BilinearFootprint,
    Filt::NearestMip,
    Filt::Trilinear,
    Filt::TrilinearSpan,
];

/// Every [`Proj`], for parsing names (`proj_listed` fails to compile when one is missing).
const PROJS: [Proj; 10] = modes::PROJS;

/// Exhaustive: a new [`Filt`] variant must be added here and to [`FILTS`].
const fn filt_listed(f: Filt) {
    match f {
        Filt::Nearest
        | Filt::Bilinear
        | Filt::BilinearFootprint
        | Filt::NearestMip
        | Filt::Trilinear
        | Filt::TrilinearSpan => {}
    }
}

/// Exhaustive: a new [`Proj`] variant must be added here and to [`PROJS`].
const fn proj_listed(p: Proj) {
    match p {
        Proj::Affine
        | Proj::Sub4
        | Proj::Sub8
        | Proj::Sub16
        | Proj::Sub32
        | Proj::Sub64
        | Proj::Quad16
        | Proj::Quad32
        | Proj::Exact
        | Proj::Adaptive => {}
    }
}

/// [`Mode::write_name`] as a `String`: `lit-bilinear-exact`, `unlit-nearest-sub16`, ...
pub fn mode_name(mode: &Mode) -> String {
    let mut s = String::new();
    mode.write_name(&mut s).expect("write to a String");
    s
}

/// Parses [`mode_name`] (any lighting x filter x projection of `modes.rs`).
pub fn parse_mode(s: &str) -> Option<Mode> {
    [(true, false), (false, false), (true, true)]
        .into_iter()
        .flat_map(|(lit, facet)| {
            FILTS.into_iter().flat_map(move |filter| {
                PROJS.into_iter().map(move |proj| Mode {
                    lit,
                    facet,
                    filter,
                    proj,
                })
            })
        })
        .find(|m| mode_name(m) == s)
}

/// One scene drawn in one mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Case {
    /// The scene.
    pub scene: Scene,
    /// The mode.
    pub mode: Mode,
}

impl Case {
    /// `scene/mode`.
    pub fn id(&self) -> String {
        format!("{}/{}", self.scene.name(), self.mode_name())
    }

    /// The mode's name ([`mode_name`]).
    pub fn mode_name(&self) -> String {
        mode_name(&self.mode)
    }

    /// Parses `scene/mode` (or `scene mode`).
    pub fn parse(s: &str) -> Option<Self> {
        let (scene, mode) = s.split_once(['/', ' '])?;
        Some(Case {
            scene: Scene::parse(scene)?,
            mode: parse_mode(mode)?,
        })
    }
}

const fn case(scene: Scene, lit: bool, filter: Filt, proj: Proj) -> Case {
    Case {
        scene,
        mode: Mode {
            lit,
            facet: false,
            filter,
            proj,
        },
    }
}

/// The cases of `docs/scenes.md` (the floor in its two unmipmapped filters).
pub const SCENES: [Case; 4] = [
    case(Scene::Cube, true, Filt::Bilinear, Proj::Exact),
    case(Scene::Sphere, true, Filt::Bilinear, Proj::Exact),
    case(Scene::Floor, false, Filt::Nearest, Proj::Exact),
    case(Scene::Floor, false, Filt::Bilinear, Proj::Exact),
];

/// Cheaper and dearer modes on the cube and the floor (the per-pixel loop is chosen per
/// draw; the cheapest, unlit nearest affine, is the fill-rate floor). Any other mode of
/// `modes.rs` can be named on the command line of `count_scene`.
pub const MODES: [Case; 13] = [
    case(Scene::Cube, false, Filt::Nearest, Proj::Affine),
    case(Scene::Cube, false, Filt::Nearest, Proj::Exact),
    case(Scene::Cube, true, Filt::Nearest, Proj::Exact),
    case(Scene::Cube, true, Filt::Bilinear, Proj::Sub16),
    case(Scene::Cube, true, Filt::Bilinear, Proj::Sub8),
    case(Scene::Cube, true, Filt::Bilinear, Proj::Sub4),
    case(Scene::Cube, true, Filt::Bilinear, Proj::Quad32),
    case(Scene::Cube, true, Filt::Bilinear, Proj::Affine),
    case(Scene::Floor, false, Filt::Nearest, Proj::Affine),
    case(Scene::Floor, false, Filt::Nearest, Proj::Sub16),
    case(Scene::Floor, false, Filt::Nearest, Proj::Sub8),
    case(Scene::Floor, false, Filt::Bilinear, Proj::Sub16),
    case(Scene::Floor, false, Filt::Bilinear, Proj::Sub8),
];

/// Everything a case needs, built once (texture, mesh, buffers).
pub struct Bench {
    /// The case.
    pub case: Case,
    /// Level 0, then (mipmapped filters only) the rest of the full mip chain.
    texels: Vec<Rgb565>,
    /// Level 0's footprints (`Filt::BilinearFootprint` only; else empty).
    footprints: Vec<u64>,
    tex_size: (u32, u32),
    levels: u32,
    cube: demo::MeshData<24, 12>,
    sphere: Option<Box<demo::MeshData<{ demo::SPHERE_VERTICES }, { demo::SPHERE_TRIANGLES }>>>,
    floor: demo::MeshData<4, 2>,
    color: Vec<Rgb565>,
    depth: Vec<u16>,
    camera: fixel::scene::Camera,
    light: DirectionalLight,
}

impl Bench {
    /// Builds the texture and mesh of `case`.
    pub fn new(case: Case) -> Self {
        let (w, h) = match case.scene {
            Scene::Cube => (128, 128),
            Scene::Sphere => (256, 128),
            Scene::Floor => (64, 64),
        };
        let levels = if case.mode.filter.mipmapped() {
            full_levels(w, h)
        } else {
            1
        };
        let mut texels = vec![Rgb565::new(0, 0, 0); chain_len(w, h, levels)];
        demo::checker_texture(w, h, &mut texels[..(w * h) as usize]).expect("texture");
        if levels > 1 {
            generate_mips(&mut texels, w, h, levels).expect("mips");
        }
        let mut footprints = Vec::new();
        if case.mode.filter == Filt::BilinearFootprint {
            let base = Texture::new(&texels, w, h).expect("texture");
            footprints = vec![0u64; texels.len()];
            write_footprints(&base, &mut footprints).expect("footprints");
        }
        let n = (demo::WIDTH * demo::HEIGHT) as usize;
        Bench {
            case,
            texels,
            footprints,
            tex_size: (w, h),
            levels,
            cube: demo::cube(),
            sphere: (case.scene == Scene::Sphere).then(|| Box::new(demo::sphere())),
            floor: demo::floor(),
            color: vec![Rgb565::new(0, 0, 0); n],
            depth: vec![0u16; n],
            camera: demo::camera(if case.scene == Scene::Floor { 200 } else { 20 }),
            light: DirectionalLight::default(),
        }
    }

    /// Renders frames `0..frames` (clear to black, then draw frame `i`); returns the pixels
    /// that passed the depth test, summed over the frames.
    pub fn run(&mut self, frames: u32) -> u64 {
        let (w, h) = self.tex_size;
        let tex = if self.footprints.is_empty() {
            MipTexture::new(&self.texels, w, h, self.levels).expect("texture")
        } else {
            let base = Texture::new(&self.texels, w, h).expect("texture");
            MipTexture::single(base)
                .with_footprints(&self.footprints)
                .expect("footprints")
        };
        let vp = Viewport::new(0, 0, demo::WIDTH, demo::HEIGHT).expect("viewport");
        let draw = self.case.mode.draw(tex, vp).expect("draw");
        let mesh: Mesh<'_> = match self.case.scene {
            Scene::Cube => self.cube.mesh(),
            Scene::Sphere => self.sphere.as_ref().expect("sphere mesh").mesh(),
            Scene::Floor => self.floor.mesh(),
        }
        .expect("mesh");
        let light = self.case.mode.lit.then_some(&self.light);
        let mut total = 0u64;
        // One transform per vertex, not per triangle corner.
        let mut cache = vec![None; demo::SPHERE_VERTICES];
        for i in 0..frames {
            let model = match self.case.scene {
                Scene::Cube => demo::cube_model(i),
                Scene::Sphere => demo::sphere_model(i),
                Scene::Floor => Mat4::IDENTITY,
            };
            let mut frame = Frame::new(&mut self.color, demo::WIDTH, demo::HEIGHT)
                .expect("frame")
                .with_depth(&mut self.depth)
                .expect("depth");
            frame.clear(Rgb565::new(0, 0, 0));
            let n = draw_mesh_cached(
                &draw,
                &mesh,
                &model,
                &self.camera,
                light,
                &mut cache,
                &mut frame,
            )
            .unwrap();
            total += u64::from(n);
        }
        total
    }

    /// The last frame rendered.
    pub fn pixels(&self) -> &[Rgb565] {
        &self.color
    }
}
