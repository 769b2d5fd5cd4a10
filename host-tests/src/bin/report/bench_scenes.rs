//! The three benchmark scenes (cube, sphere, floor): their parameters and modes, and the
//! textures and meshes they are drawn with.

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::math::Mat4;
use fixel::scene::Mesh;
use fixel::texture::{chain_len, full_levels};
use fixel::texture::{generate_mips, write_footprints, MipTexture, Texture};
use fixel_scenes as demo;
use host_tests::scenes as refscenes;

use crate::modes::{self, Filt, Mode};

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Scene {
    Cube,
    Sphere,
    Floor,
}

impl Scene {
    pub const ALL: [Scene; 3] = [Scene::Cube, Scene::Sphere, Scene::Floor];
    pub fn name(self) -> &'static str {
        match self {
            Scene::Cube => "cube",
            Scene::Sphere => "sphere",
            Scene::Floor => "floor",
        }
    }
    pub fn modes(self) -> &'static [Mode] {
        match self {
            Scene::Floor => &modes::FLOOR_MODES,
            Scene::Cube => &modes::CUBE_MODES,
            Scene::Sphere => &modes::SPHERE_MODES,
        }
    }
    pub fn frames(self) -> u32 {
        match self {
            Scene::Floor => 20,
            _ => 100,
        }
    }
    /// Frames whose errors are pooled.
    pub fn error_frames(self) -> &'static [u32] {
        match self {
            Scene::Cube => &[0, 25, 50, 75],
            Scene::Sphere => &[0, 50],
            Scene::Floor => &[0],
        }
    }
    pub fn tex_size(self) -> (u32, u32) {
        match self {
            Scene::Cube => (128, 128),
            Scene::Sphere => (256, 128),
            Scene::Floor => (64, 64),
        }
    }
    pub fn far(self) -> i32 {
        match self {
            Scene::Floor => 200,
            _ => 20,
        }
    }
    pub fn model(self, i: u32) -> Mat4 {
        match self {
            Scene::Cube => demo::cube_model(i),
            Scene::Sphere => demo::sphere_model(i),
            Scene::Floor => Mat4::IDENTITY,
        }
    }
    pub fn desc(self, i: u32) -> refscenes::SceneDesc {
        match self {
            Scene::Cube => refscenes::cube(i),
            Scene::Sphere => refscenes::sphere(i),
            Scene::Floor => refscenes::floor(),
        }
    }
    pub fn lit(self) -> bool {
        self != Scene::Floor
    }
    pub fn ideal(self) -> &'static str {
        match self {
            Scene::Floor => "8x8 supersampled reference",
            _ => "bilinear f64 reference",
        }
    }
}

pub fn mode_name(m: &Mode) -> String {
    let mut s = String::new();
    m.write_name(&mut s).expect("name");
    s
}

/// `T(w, h)` with a full mip chain (level 0 alone for the unmipmapped scenes), and level 0's
/// bilinear footprints (for `Filt::BilinearFootprint`).
pub struct Tex {
    chain: Vec<Rgb565>,
    footprints: Vec<u64>,
    w: u32,
    h: u32,
    levels: u32,
}

impl Tex {
    pub fn new(scene: Scene) -> Self {
        let (w, h) = scene.tex_size();
        let levels = if scene == Scene::Floor {
            full_levels(w, h)
        } else {
            1
        };
        let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(w, h, levels)];
        demo::checker_texture(w, h, &mut chain[..(w * h) as usize]).expect("texture");
        if levels > 1 {
            generate_mips(&mut chain, w, h, levels).expect("mips");
        }
        let mut footprints = vec![0u64; (w * h) as usize];
        let base = Texture::new(&chain[..(w * h) as usize], w, h).expect("texture");
        write_footprints(&base, &mut footprints).expect("footprints");
        Tex {
            chain,
            footprints,
            w,
            h,
            levels,
        }
    }
    /// The texture `m` samples: level 0 with its footprints for `Filt::BilinearFootprint`,
    /// else [`Tex::mip`].
    pub fn for_mode(&self, m: &Mode) -> MipTexture<'_> {
        if m.filter != Filt::BilinearFootprint {
            return self.mip();
        }
        let n = (self.w * self.h) as usize;
        let base = Texture::new(&self.chain[..n], self.w, self.h).expect("texture");
        MipTexture::single(base)
            .with_footprints(&self.footprints)
            .expect("footprints")
    }
    fn mip(&self) -> MipTexture<'_> {
        if self.levels > 1 {
            MipTexture::new(&self.chain, self.w, self.h, self.levels).expect("chain")
        } else {
            MipTexture::single(Texture::new(&self.chain, self.w, self.h).expect("texture"))
        }
    }
}

pub struct Meshes {
    pub cube: demo::MeshData<24, 12>,
    pub sphere: Box<demo::MeshData<{ demo::SPHERE_VERTICES }, { demo::SPHERE_TRIANGLES }>>,
    pub floor: demo::MeshData<4, 2>,
}

impl Meshes {
    pub fn mesh(&self, s: Scene) -> Mesh<'_> {
        match s {
            Scene::Cube => self.cube.mesh(),
            Scene::Sphere => self.sphere.mesh(),
            Scene::Floor => self.floor.mesh(),
        }
        .expect("mesh")
    }
}
