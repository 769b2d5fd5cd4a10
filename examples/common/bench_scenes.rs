//! The benchmark scenes of `SCENES.md` as runnable cases, shared by `benches/scenes.rs`
//! (criterion timing) and `examples/count_scene.rs` (instruction counts under callgrind).
//!
//! A case is a scene (cube, sphere, floor) plus a mode (lit or not, filter, projection).
//! Every mode is a typed [`Pipeline`] built with [`Draw::new`], as a firmware would build
//! it: the per-pixel loop is monomorphised for exactly that combination and chosen once per
//! draw. Lit modes use `ModulateIntensity` (per-vertex light times the texel), unlit ones
//! `Replace`; all depth-test (`DepthLess`, 16-bit depth buffer) with repeat wrap and back-face
//! culling.

// Shared by the bench and the example; each uses a different part.
#![allow(dead_code)]

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::demo;
use fixel::pipeline::{Affine, DepthLess, Exact, ModulateIntensity, Pipeline, Replace, Subdivided};
use fixel::prelude::*;
use fixel::scene::{draw_mesh_cached, DirectionalLight, Mesh};
use fixel::texture::{Bilinear, BilinearFast, Nearest, Repeat};

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

    /// Frames per run (`N` of `SCENES.md`).
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

/// Texture filter of a mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filt {
    /// `Nearest`.
    Nearest,
    /// `Bilinear` (Q8 weights, 9 multiplies).
    Bilinear,
    /// `BilinearFast` (packed Q5 weights, 6 multiplies).
    BilinearFast,
}

/// Projection of a mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Proj {
    /// Screen-linear.
    Affine,
    /// Exact every `2^log2_n` pixels.
    Sub(u8),
    /// Exact every pixel.
    Exact,
}

/// How a scene is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mode {
    /// Per-vertex lighting modulated into the texel (`ModulateIntensity`), else `Replace`.
    pub lit: bool,
    /// Texture filter.
    pub filter: Filt,
    /// Projection.
    pub proj: Proj,
}

impl Mode {
    /// `lit-bilinear-exact`, `unlit-nearest-sub16`, ...
    pub fn name(&self) -> String {
        let lit = if self.lit { "lit" } else { "unlit" };
        let f = match self.filter {
            Filt::Nearest => "nearest",
            Filt::Bilinear => "bilinear",
            Filt::BilinearFast => "bilinearfast",
        };
        let p = match self.proj {
            Proj::Affine => "affine".to_string(),
            Proj::Sub(k) => format!("sub{}", 1u32 << k),
            Proj::Exact => "exact".to_string(),
        };
        format!("{lit}-{f}-{p}")
    }

    /// Parses [`Mode::name`].
    pub fn parse(s: &str) -> Option<Self> {
        let mut it = s.split('-');
        let lit = match it.next()? {
            "lit" => true,
            "unlit" => false,
            _ => return None,
        };
        let filter = match it.next()? {
            "nearest" => Filt::Nearest,
            "bilinear" => Filt::Bilinear,
            "bilinearfast" => Filt::BilinearFast,
            _ => return None,
        };
        let proj = match it.next()? {
            "affine" => Proj::Affine,
            "exact" => Proj::Exact,
            p => {
                let n: u32 = p.strip_prefix("sub")?.parse().ok()?;
                if !n.is_power_of_two() || !(2..=64).contains(&n) {
                    return None;
                }
                Proj::Sub(n.trailing_zeros() as u8)
            }
        };
        if it.next().is_some() {
            return None;
        }
        Some(Mode { lit, filter, proj })
    }

    /// The typed draw for this mode.
    pub fn draw<'a>(&self, tex: Texture<'a>, vp: Viewport) -> Result<Draw<'a, Rgb565>, Error> {
        macro_rules! typed {
            ($p:ty, $f:ty) => {
                if self.lit {
                    Draw::new::<Pipeline<$p, $f, Repeat, Repeat, ModulateIntensity, DepthLess>>(
                        Some(tex),
                        vp,
                        Cull::Back,
                    )
                } else {
                    Draw::new::<Pipeline<$p, $f, Repeat, Repeat, Replace, DepthLess>>(
                        Some(tex),
                        vp,
                        Cull::Back,
                    )
                }
            };
        }
        macro_rules! by_filter {
            ($p:ty) => {
                match self.filter {
                    Filt::Nearest => typed!($p, Nearest),
                    Filt::Bilinear => typed!($p, Bilinear),
                    Filt::BilinearFast => typed!($p, BilinearFast),
                }
            };
        }
        match self.proj {
            Proj::Affine => by_filter!(Affine),
            Proj::Exact => by_filter!(Exact),
            Proj::Sub(k) => by_filter!(Subdivided)?.with_subdivision(k),
        }
    }
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
        format!("{}/{}", self.scene.name(), self.mode.name())
    }

    /// Parses `scene/mode` (or `scene mode`).
    pub fn parse(s: &str) -> Option<Self> {
        let (scene, mode) = s.split_once(['/', ' '])?;
        Some(Case {
            scene: Scene::parse(scene)?,
            mode: Mode::parse(mode)?,
        })
    }
}

const fn mode(lit: bool, filter: Filt, proj: Proj) -> Mode {
    Mode { lit, filter, proj }
}

/// The cases of `SCENES.md` (trilinear is not implemented yet, so the floor has two).
pub const SCENES: [Case; 4] = [
    Case {
        scene: Scene::Cube,
        mode: mode(true, Filt::Bilinear, Proj::Exact),
    },
    Case {
        scene: Scene::Sphere,
        mode: mode(true, Filt::Bilinear, Proj::Exact),
    },
    Case {
        scene: Scene::Floor,
        mode: mode(false, Filt::Nearest, Proj::Exact),
    },
    Case {
        scene: Scene::Floor,
        mode: mode(false, Filt::Bilinear, Proj::Exact),
    },
];

/// Cheaper and dearer modes on the cube and the floor (the per-pixel loop is chosen per
/// draw; the cheapest, unlit nearest affine, is the fill-rate floor).
pub const MODES: [Case; 12] = [
    Case {
        scene: Scene::Cube,
        mode: mode(false, Filt::Nearest, Proj::Affine),
    },
    Case {
        scene: Scene::Cube,
        mode: mode(false, Filt::Nearest, Proj::Exact),
    },
    Case {
        scene: Scene::Cube,
        mode: mode(true, Filt::Nearest, Proj::Exact),
    },
    Case {
        scene: Scene::Cube,
        mode: mode(true, Filt::BilinearFast, Proj::Exact),
    },
    Case {
        scene: Scene::Cube,
        mode: mode(true, Filt::Bilinear, Proj::Sub(4)),
    },
    Case {
        scene: Scene::Cube,
        mode: mode(true, Filt::Bilinear, Proj::Sub(3)),
    },
    Case {
        scene: Scene::Cube,
        mode: mode(true, Filt::Bilinear, Proj::Affine),
    },
    Case {
        scene: Scene::Floor,
        mode: mode(false, Filt::Nearest, Proj::Affine),
    },
    Case {
        scene: Scene::Floor,
        mode: mode(false, Filt::Nearest, Proj::Sub(4)),
    },
    Case {
        scene: Scene::Floor,
        mode: mode(false, Filt::Nearest, Proj::Sub(3)),
    },
    Case {
        scene: Scene::Floor,
        mode: mode(false, Filt::Bilinear, Proj::Sub(4)),
    },
    Case {
        scene: Scene::Floor,
        mode: mode(false, Filt::Bilinear, Proj::Sub(3)),
    },
];

/// Everything a case needs, built once (texture, mesh, buffers).
pub struct Bench {
    /// The case.
    pub case: Case,
    texels: Vec<Rgb565>,
    tex_size: (u32, u32),
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
        let mut texels = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
        demo::checker_texture(w, h, &mut texels).expect("texture");
        let n = (demo::WIDTH * demo::HEIGHT) as usize;
        Bench {
            case,
            texels,
            tex_size: (w, h),
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
        let tex = Texture::new(&self.texels, self.tex_size.0, self.tex_size.1).expect("texture");
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
            );
            total += u64::from(n);
        }
        total
    }

    /// The last frame rendered.
    pub fn pixels(&self) -> &[Rgb565] {
        &self.color
    }
}
