//! The surface-detail scenes (`fixel_scenes::surface`: the brick sphere under a circling
//! point light) drawn by fixel in each lighting variant and by the f64 reference from the
//! same data, for the tests, goldens and the report.

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565, RgbColor};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{fx, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::scene::{LitMesh, PixelLight, Tangent};
use fixel::shading::bump::{
    derivative_map, normal_map, Bumped, DerivativeMap, HeightDifferences, NormalMap,
};
use fixel::shading::lighting::{Material, Phong, Specular, SpecularTable};
use fixel::shading::{Gouraud, Shader, TexBinding};
use fixel::surface::Frame;
use fixel::texture::{
    chain_len, full_levels, generate_height_mips, Bilinear, HeightMap, Lod, MipTexture, Nearest,
    NearestMipmapNearest, Repeat, Texture,
};
use fixel_scenes::bricks::{brick_colours, brick_heights};
use fixel_scenes::surface;

use crate::reference::lighting::{RefLight, RefLitScene, RefMaterial, RefNormals};
use crate::reference::types::{RefFilter, RefImage, RefTexture};
use crate::shadow_scene::m4;

/// Side of the brick maps in the tests and the report (the firmware's size).
pub const SIZE: u32 = 64;
/// Bump strength σ of the scenes (texel widths per height step).
pub const STRENGTH: f64 = 0.02;

/// The ways of lighting the sphere, cheapest first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variant {
    /// Per-vertex Blinn-Phong on a plain surface (the colour of [`PLAIN`]).
    Gouraud,
    /// Per-pixel Phong (reflection vector) on the plain surface.
    PhongPlain,
    /// Per-pixel Blinn-Phong on the plain surface.
    BlinnPlain,
    /// Per-pixel Blinn-Phong on the brick texture, no bump.
    Textured,
    /// Bump mapping from the precomputed derivative map (nearest mip).
    BumpDerivatives,
    /// Bump mapping from the height map, differences per pixel.
    BumpHeights,
    /// Normal mapping (bilinear).
    NormalMap,
}

impl Variant {
    /// All variants.
    pub const ALL: [Variant; 7] = [
        Variant::Gouraud,
        Variant::PhongPlain,
        Variant::BlinnPlain,
        Variant::Textured,
        Variant::BumpDerivatives,
        Variant::BumpHeights,
        Variant::NormalMap,
    ];

    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            Variant::Gouraud => "gouraud",
            Variant::PhongPlain => "phong",
            Variant::BlinnPlain => "blinn",
            Variant::Textured => "blinn_textured",
            Variant::BumpDerivatives => "bump_derivatives",
            Variant::BumpHeights => "bump_heights",
            Variant::NormalMap => "normal_map",
        }
    }

    /// Whether the surface is the plain colour (else the bricks).
    pub fn plain(self) -> bool {
        matches!(
            self,
            Variant::Gouraud | Variant::PhongPlain | Variant::BlinnPlain
        )
    }
}

/// The plain surface colour.
pub const PLAIN: Rgb565 = Rgb565::new(28, 50, 20);

/// The brick maps: colours, heights (with mips), derivative and normal maps.
pub struct Assets {
    pub strength: f64,
    /// Specular exponent (24 in the demo scenes).
    pub exponent: u8,
    pub colours: Vec<Rgb565>,
    pub heights: Vec<u8>,
    pub levels: u32,
    pub derivs: Vec<Rgb565>,
    pub deriv_scale: Fx,
    pub normals: Vec<Rgb565>,
}

impl Assets {
    /// Builds the `SIZE` brick maps at strength [`STRENGTH`].
    pub fn new() -> Self {
        let mut heights = vec![0u8; (SIZE * SIZE) as usize];
        brick_heights(SIZE, &mut heights).expect("heights");
        Self::with_heights(&heights, STRENGTH)
    }

    /// The brick colours over the `SIZE x SIZE` `heights` at `strength`.
    pub fn with_heights(base_heights: &[u8], strength: f64) -> Self {
        let levels = full_levels(SIZE, SIZE);
        let n = chain_len(SIZE, SIZE, levels);
        let base = (SIZE * SIZE) as usize;
        let mut colours = vec![Rgb565::BLACK; base];
        brick_colours(SIZE, &mut colours).expect("colours");
        let mut heights = vec![0u8; n];
        heights[..base].copy_from_slice(base_heights);
        generate_height_mips(&mut heights, SIZE, SIZE, levels).expect("mips");
        let map = HeightMap::new(&heights, SIZE, SIZE, levels).expect("map");
        let mut derivs = vec![Rgb565::BLACK; n];
        let deriv_scale = derivative_map(&map, &mut derivs).expect("derivatives");
        let mut normals = vec![Rgb565::BLACK; base];
        let base_map = HeightMap::new(&heights[..base], SIZE, SIZE, 1).expect("map");
        normal_map(&base_map, fx(strength), &mut normals).expect("normals");
        Assets {
            strength,
            exponent: 24,
            colours,
            heights,
            levels,
            derivs,
            deriv_scale,
            normals,
        }
    }

    fn tex(px: &[Rgb565]) -> RefTexture {
        RefTexture {
            width: SIZE,
            height: SIZE,
            texels: px.iter().map(|c| c.into_storage()).collect(),
            border: 0,
        }
    }
}

impl Default for Assets {
    fn default() -> Self {
        Self::new()
    }
}

/// A mesh's arrays (owned) and its model matrix.
#[derive(Clone, Debug)]
pub struct MeshArrays {
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
    pub uvs: Vec<[Fx; 2]>,
    pub tangents: Vec<Tangent>,
    pub indices: Vec<[u16; 3]>,
    /// Model matrix at frame 0 (the sphere turns with the frame).
    pub model: Mat4,
    /// True for the demo sphere (its model matrix follows the frame).
    pub turning: bool,
}

impl MeshArrays {
    fn model(&self, i: u32) -> Mat4 {
        if self.turning {
            surface::sphere_model(i)
        } else {
            self.model
        }
    }
}

/// The demo sphere and its tangents.
pub fn sphere() -> MeshArrays {
    let (m, t) = surface::sphere().expect("sphere");
    MeshArrays {
        positions: m.positions.to_vec(),
        normals: m.normals.to_vec(),
        uvs: m.uvs.to_vec(),
        tangents: t.to_vec(),
        indices: m.indices.to_vec(),
        model: surface::sphere_model(0),
        turning: true,
    }
}

/// A 3 x 3 wall facing the camera at `z = −4`, its corners' uvs given (top-left, top-right,
/// bottom-right, bottom-left), tangents from `fixel::scene::tangents`.
pub fn wall(uv: [[f64; 2]; 4]) -> MeshArrays {
    let positions = vec![
        Vec3::from_num(-1.5, 1.5, 0),
        Vec3::from_num(1.5, 1.5, 0),
        Vec3::from_num(1.5, -1.5, 0),
        Vec3::from_num(-1.5, -1.5, 0),
    ];
    let normals = vec![Vec3::from_num(0, 0, 1); 4];
    let uvs: Vec<[Fx; 2]> = uv.iter().map(|c| c.map(fx)).collect();
    let indices = vec![[0u16, 3, 2], [0, 2, 1]];
    let mut tangents = vec![Tangent::default(); 4];
    fixel::scene::tangents(&positions, &normals, &uvs, &indices, &mut tangents).expect("tangents");
    MeshArrays {
        positions,
        normals,
        uvs,
        tangents,
        indices,
        model: Mat4::translation(Vec3::from_num(0, 0, -4)),
        turning: false,
    }
}

fn draw<S: Shader<Varyings = [i32; N]>, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
    frame: &mut Frame<'_, Rgb565>,
    w: u32,
    h: u32,
) {
    let vp = Viewport::new(0, 0, w, h).expect("viewport");
    ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back)
        .expect("draw")
        .clip_triangles(tris, frame)
        .expect("depth");
}

/// The demo material with `specular` model and exponent `e` (the table is leaked: tests
/// and tools only).
pub fn material(specular: Specular, e: u8) -> Material<'static> {
    let table: &'static SpecularTable =
        Box::leak(Box::new(SpecularTable::new(e).expect("exponent")));
    Material {
        shininess: table,
        ..surface::material(specular)
    }
}

/// fixel's frame of `variant` at scene frame `i` (`w x h`, black background): raw RGB565
/// and coverage.
pub fn render_fixel(
    variant: Variant,
    i: u32,
    light: &PixelLight,
    a: &Assets,
    s: &MeshArrays,
    w: u32,
    h: u32,
) -> (Vec<u16>, Vec<bool>) {
    let mesh = LitMesh::new(
        &s.positions,
        &s.normals,
        &s.uvs,
        Some(&s.tangents),
        &s.indices,
    )
    .expect("mesh");
    let camera = surface::camera().expect("camera");
    let model = s.model(i);
    let mut px = vec![Rgb565::BLACK; (w * h) as usize];
    let mut depth = vec![0xFFFFu16; (w * h) as usize];
    {
        let mut frame = Frame::new(&mut px, w, h)
            .expect("frame")
            .with_depth(&mut depth)
            .expect("depth");
        let lod = Lod::default();
        let plain = [PLAIN];
        let plain_chain = MipTexture::single(Texture::new(&plain, 1, 1).expect("tex"));
        let colour_chain = MipTexture::single(Texture::new(&a.colours, SIZE, SIZE).expect("tex"));
        let tex = TexBinding::new(&colour_chain, Bilinear, Repeat, Repeat, lod).expect("bind");
        let flat = TexBinding::new(&plain_chain, Nearest, Repeat, Repeat, lod).expect("bind");
        let size = (SIZE, SIZE);
        let blinn = material(Specular::Blinn, a.exponent);
        let mut tris = Vec::new();
        let mut bump = Vec::new();
        mesh.phong_triangles(&model, &camera, light, |t| tris.push(*t));
        mesh.bump_triangles(&model, &camera, light, |t| bump.push(*t));
        match variant {
            Variant::Gouraud => {
                let mut g = Vec::new();
                mesh.gouraud_triangles(&model, &camera, light, &blinn, PLAIN.into_storage(), |t| {
                    g.push(*t)
                });
                draw(Gouraud, &g, &mut frame, w, h);
            }
            Variant::PhongPlain => {
                let material = material(Specular::Phong, a.exponent);
                draw(
                    Phong {
                        tex: flat,
                        material,
                    },
                    &tris,
                    &mut frame,
                    w,
                    h,
                );
            }
            Variant::BlinnPlain => draw(
                Phong {
                    tex: flat,
                    material: blinn,
                },
                &tris,
                &mut frame,
                w,
                h,
            ),
            Variant::Textured => draw(
                Phong {
                    tex,
                    material: blinn,
                },
                &tris,
                &mut frame,
                w,
                h,
            ),
            Variant::BumpDerivatives => {
                let chain = MipTexture::new(&a.derivs, SIZE, SIZE, a.levels).expect("chain");
                let b =
                    TexBinding::new(&chain, NearestMipmapNearest::default(), Repeat, Repeat, lod)
                        .expect("bind");
                let n = DerivativeMap::new(b, a.deriv_scale, fx(a.strength)).expect("strength");
                draw(
                    Bumped::new(tex, n, size, blinn).expect("bump"),
                    &bump,
                    &mut frame,
                    w,
                    h,
                );
            }
            Variant::BumpHeights => {
                let map = HeightMap::new(&a.heights, SIZE, SIZE, a.levels).expect("map");
                let n = HeightDifferences::new(map, fx(a.strength)).expect("strength");
                draw(
                    Bumped::new(tex, n, size, blinn).expect("bump"),
                    &bump,
                    &mut frame,
                    w,
                    h,
                );
            }
            Variant::NormalMap => {
                let chain = MipTexture::single(Texture::new(&a.normals, SIZE, SIZE).expect("tex"));
                let b = TexBinding::new(&chain, Bilinear, Repeat, Repeat, lod).expect("bind");
                let n = NormalMap { map: b };
                draw(
                    Bumped::new(tex, n, size, blinn).expect("bump"),
                    &bump,
                    &mut frame,
                    w,
                    h,
                );
            }
        }
    }
    let cov = depth.iter().map(|&d| d != 0xFFFF).collect();
    (px.iter().map(|c| c.into_storage()).collect(), cov)
}

/// The reference's view of the scene at frame `i` with `light`.
pub fn ref_scene(
    i: u32,
    light: &PixelLight,
    s: &MeshArrays,
    specular: Specular,
    exponent: u8,
) -> RefLitScene {
    let camera = surface::camera().expect("camera");
    let mv: Mat4 = camera.view.mul(&s.model(i));
    let v3 = |v: fixel::math::Vec3| [v.x, v.y, v.z].map(|c| c.to_num::<f64>());
    let m = material(specular, exponent);
    RefLitScene {
        positions: s.positions.iter().map(|&p| v3(p)).collect(),
        normals: s.normals.iter().map(|&p| v3(p)).collect(),
        uvs: s
            .uvs
            .iter()
            .map(|uv| uv.map(|c| c.to_num::<f64>()))
            .collect(),
        tangents: s
            .tangents
            .iter()
            .map(|t| (v3(t.direction), f64::from(t.handedness)))
            .collect(),
        indices: s.indices.clone(),
        model_view: m4(&mv),
        projection: m4(&camera.projection),
        light: match *light {
            PixelLight::Directional(d) => RefLight::Directional(v3(d)),
            PixelLight::Point(p) => RefLight::Point(v3(p)),
        },
        material: RefMaterial {
            ka: f64::from(m.ambient) / 256.0,
            kd: f64::from(m.diffuse) / 256.0,
            ks: f64::from(m.specular) / 256.0,
            exponent: f64::from(m.shininess.exponent()),
            blinn: specular == Specular::Blinn,
        },
    }
}

/// The reference frame of `variant` (per pixel for every variant: Gouraud is measured
/// against the per-pixel ideal).
pub fn render_reference(
    variant: Variant,
    i: u32,
    light: &PixelLight,
    a: &Assets,
    s: &MeshArrays,
    w: u32,
    h: u32,
) -> RefImage {
    let spec = if variant == Variant::PhongPlain {
        Specular::Phong
    } else {
        Specular::Blinn
    };
    let scene = ref_scene(i, light, s, spec, a.exponent);
    let plain = RefTexture {
        width: 1,
        height: 1,
        texels: vec![PLAIN.into_storage()],
        border: 0,
    };
    let colours = Assets::tex(&a.colours);
    let normals = Assets::tex(&a.normals);
    let base = (SIZE * SIZE) as usize;
    let (tex, filter) = if variant.plain() {
        (&plain, RefFilter::Nearest)
    } else {
        (&colours, RefFilter::Bilinear)
    };
    let source = match variant {
        Variant::BumpDerivatives | Variant::BumpHeights => RefNormals::Height {
            heights: &a.heights[..base],
            size: SIZE,
            strength: a.strength,
        },
        Variant::NormalMap => RefNormals::NormalMap(&normals),
        _ => RefNormals::Flat,
    };
    crate::reference::lighting::render(&scene, tex, filter, source, w, h)
}

/// A raw RGB565 value as a colour.
pub fn rgb(c: u16) -> Rgb565 {
    Rgb565::from(RawU16::new(c))
}
