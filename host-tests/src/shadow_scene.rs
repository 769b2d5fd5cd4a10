//! Shadow-mapping scenes drawn by fixel and by the f64 reference from the same data
//! (mesh positions, model, camera and light matrices), and the lit fraction each gives per
//! pixel, for the tests and the report.
//!
//! fixel's lit fraction is read from a white [`Flat`] shader wrapped in [`Shadowed`] with
//! shadows at brightness 0: the green channel (6 bits) is `lit * 63`, so the read-back
//! fraction is within 1/126 of the shader's own Q8 value.

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Mat4, Vec3};
use fixel::pipeline::{DepthLess, DepthOnlyDraw, Exact, ShadedDraw};
use fixel::scene::{light_pass_mesh, shadowed_mesh_triangles, Camera, Mesh};
use fixel::shading::pcf::ShadowFilter;
use fixel::shading::shadow::{
    with_light, Bias, LightKind, LightSpace, Outside, Shadowed, ShadowedUv,
};
use fixel::shading::{Flat, Fragment, Shader};
use fixel::surface::{DepthMap, Frame, ShadowMap};
use fixel_scenes::shadow as scene;

use crate::reference::shadow::{mul, transform, RefBias, ShadowScene, M4};

/// One mesh of a scene: positions, triangles, model matrix.
#[derive(Clone, Debug)]
pub struct SceneMesh {
    /// Model-space positions.
    pub positions: Vec<Vec3>,
    /// Triangles (counter-clockwise from the front).
    pub indices: Vec<[u16; 3]>,
    /// Model matrix.
    pub model: Mat4,
}

/// The demo scene's meshes: the cube (frame 0) and the floor.
pub fn demo_meshes() -> Vec<SceneMesh> {
    let (cube, model, floor) = scene::meshes();
    vec![
        SceneMesh {
            positions: cube.positions.to_vec(),
            indices: cube.indices.to_vec(),
            model,
        },
        SceneMesh {
            positions: floor.positions.to_vec(),
            indices: floor.indices.to_vec(),
            model: Mat4::IDENTITY,
        },
    ]
}

/// A matrix as f64.
pub fn m4(m: &Mat4) -> M4 {
    m.m.map(|r| r.map(|e| e.to_num::<f64>()))
}

/// The reference's view of a scene.
pub fn ref_scene(
    meshes: &[SceneMesh],
    camera: &Camera,
    light: &Mat4,
    w: u32,
    h: u32,
) -> ShadowScene {
    let mut tris = Vec::new();
    for m in meshes {
        let model = m4(&m.model);
        let world: Vec<[f64; 3]> = m
            .positions
            .iter()
            .map(|p| {
                let q = transform(&model, [p.x, p.y, p.z].map(|c| c.to_num::<f64>()));
                [q[0], q[1], q[2]]
            })
            .collect();
        for t in &m.indices {
            tris.push(t.map(|i| world[usize::from(i)]));
        }
    }
    ShadowScene {
        tris,
        camera: mul(&m4(&camera.projection), &m4(&camera.view)),
        light: m4(light),
        width: w,
        height: h,
    }
}

/// fixel's [`Bias`] in the reference's units.
pub fn ref_bias(b: &Bias) -> RefBias {
    RefBias {
        constant: f64::from(b.constant) / 16.0,
        slope: f64::from(b.slope) / 256.0,
        max: f64::from(b.max) / 16.0,
    }
}

/// What fixel drew: lit fraction and coverage per pixel, the map, and the texels and pixels
/// written.
#[derive(Clone, Debug)]
pub struct FixelShadow {
    /// Lit fraction per pixel (0..=1), from the green channel.
    pub lit: Vec<f64>,
    /// Covered pixels.
    pub covered: Vec<bool>,
    /// The shadow map.
    pub map: Vec<u16>,
    /// Texels the light pass wrote.
    pub texels_written: u32,
    /// Pixels the lit pass wrote.
    pub pixels: u32,
}

/// Options of a fixel shadow render.
#[derive(Clone, Copy, Debug)]
pub struct Setup {
    /// Map side.
    pub size: u32,
    /// Bias.
    pub bias: Bias,
    /// Outside the frustum.
    pub outside: Outside,
    /// Light-pass culling.
    pub light_cull: Cull,
    /// Frame size.
    pub w: u32,
    /// Frame height.
    pub h: u32,
}

impl Setup {
    /// Map `size`, the filter's default bias, outside lit, back faces culled, 320 x 240.
    pub fn new<F: ShadowFilter>(size: u32) -> Self {
        Setup {
            size,
            bias: Bias::for_filter::<F>(),
            outside: Outside::Lit,
            light_cull: Cull::Back,
            w: 320,
            h: 240,
        }
    }
}

/// Both passes with fixel; `M` is the light's varying count (3 directional, 4 spot).
pub fn fixel_shadow<K: LightKind, F: ShadowFilter, const M: usize>(
    meshes: &[SceneMesh],
    camera: &Camera,
    space: &LightSpace<K>,
    s: &Setup,
) -> FixelShadow {
    let (texels, written) = light_pass(meshes, space, s);
    let lit = |map| Shadowed::new(Flat(0xFFFF), map, s.bias);
    lit_pass::<K, Shadowed<'_, Flat, K, F, M>, M, false>(meshes, camera, space, s, &texels, lit)
        .with_map(texels, written)
}

/// A white shader with texture coordinates (varyings `u, v`, unread): what [`ShadowedUv`]
/// carries the light coordinates through.
#[derive(Clone, Copy, Debug)]
pub struct FlatUv;

impl Shader for FlatUv {
    type Varyings = [i32; 2];
    type Triangle = ();
    const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));
    fn triangle(&self, _: &mut [[i32; 2]; 3]) {}
    fn shade(&self, _: &Fragment<[i32; 2], ()>) -> Option<u16> {
        Some(0xFFFF)
    }
}

/// [`fixel_shadow`] through [`ShadowedUv`]: the light coordinates from texture
/// coordinates `u = x + 0.375 z`, `v = y + 0.625 z` of the model-space position (a linear
/// map whose kernel lies in no coordinate plane, so no face of the scene is degenerate).
/// `M` is 2 plus the light's varying count.
pub fn fixel_shadow_uv<K: LightKind, F: ShadowFilter, const M: usize>(
    meshes: &[SceneMesh],
    camera: &Camera,
    space: &LightSpace<K>,
    s: &Setup,
) -> FixelShadow {
    let (texels, written) = light_pass(meshes, space, s);
    let lit = |map| ShadowedUv::new(FlatUv, map, s.bias);
    lit_pass::<K, ShadowedUv<'_, FlatUv, K, F, M>, M, true>(meshes, camera, space, s, &texels, lit)
        .with_map(texels, written)
}

/// The light pass of `meshes` into a map of `s.size` texels square: its texels and the
/// texels written.
fn light_pass<K: LightKind>(
    meshes: &[SceneMesh],
    space: &LightSpace<K>,
    s: &Setup,
) -> (Vec<u16>, u32) {
    let mut texels = vec![0u16; (s.size * s.size) as usize];
    let mut written = 0;
    {
        let mut map = DepthMap::new(&mut texels, s.size).expect("map size");
        map.clear();
        let light = DepthOnlyDraw::new(&map, s.light_cull).expect("light pass");
        for m in meshes {
            let uvs = uvs_of(m);
            let mesh = Mesh::new(&m.positions, None, &uvs, &m.indices).expect("mesh");
            written +=
                light_pass_mesh(&light, &mesh, &m.model, space, &mut map).expect("light pass");
        }
    }
    (texels, written)
}

/// The lit pass with the shader `make` builds on the map `texels`. `UV`: the lit-pass
/// vertices carry the texture coordinates (the inner shader's two varyings) before the
/// light's; otherwise the light's alone.
fn lit_pass<'m, K: LightKind, S, const M: usize, const UV: bool>(
    meshes: &[SceneMesh],
    camera: &Camera,
    space: &LightSpace<K>,
    s: &Setup,
    texels: &'m [u16],
    make: impl FnOnce(ShadowMap<'m>) -> Result<S, fixel::Error>,
) -> FixelShadow
where
    S: Shader<Varyings = [i32; M]> + ShadowedLike,
{
    let view = ShadowMap::new(texels, s.size).expect("map");
    let shader = make(view).expect("shader").dark_outside(s.outside);
    let vp = Viewport::new(0, 0, s.w, s.h).expect("viewport");
    let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).expect("draw");
    let n = (s.w * s.h) as usize;
    let (mut color, mut depth) = (vec![Rgb565::BLACK; n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, s.w, s.h)
        .expect("frame")
        .with_depth(&mut depth)
        .expect("depth");
    frame.clear(Rgb565::BLACK);
    let mut pixels = 0;
    for m in meshes {
        let uvs = uvs_of(m);
        let mesh = Mesh::new(&m.positions, None, &uvs, &m.indices).expect("mesh");
        shadowed_mesh_triangles(&mesh, &m.model, camera, None, space, |cv, lv| {
            let tri = [0, 1, 2].map(|k| {
                if UV {
                    let v = cv[k].to_vertex();
                    let uv = Vertex::new(v.position, [v.varyings[0], v.varyings[1]]);
                    with_light::<2, M>(&uv, lv[k])
                } else {
                    with_light::<0, M>(&Vertex::new(cv[k].position, []), lv[k])
                }
            });
            pixels += draw
                .clip_triangles(&[tri], &mut frame)
                .expect("frame has depth");
        });
    }
    let covered = frame
        .depth()
        .expect("depth")
        .iter()
        .map(|&d| d != u16::MAX)
        .collect();
    let lit = color.iter().map(|c| f64::from(c.g()) / 63.0).collect();
    FixelShadow {
        lit,
        covered,
        map: Vec::new(),
        texels_written: 0,
        pixels,
    }
}

impl FixelShadow {
    /// The lit pass's result with the light pass's map and texels written.
    fn with_map(self, map: Vec<u16>, texels_written: u32) -> Self {
        FixelShadow {
            map,
            texels_written,
            ..self
        }
    }
}

/// The texture coordinates of [`fixel_shadow_uv`] for a mesh.
fn uvs_of(m: &SceneMesh) -> Vec<[fixel::math::Fx; 2]> {
    m.positions
        .iter()
        .map(|p| {
            let z = p.z.to_num::<f64>();
            [
                fixel::math::Fx::from_num(p.x.to_num::<f64>() + 0.375 * z),
                fixel::math::Fx::from_num(p.y.to_num::<f64>() + 0.625 * z),
            ]
        })
        .collect()
}

/// Shadows at brightness 0 with the setup's choice outside the frustum, for either
/// shadowed form.
pub trait ShadowedLike: Sized {
    /// Darkness 0 and `outside`.
    fn dark_outside(self, outside: Outside) -> Self;
}

impl<S: Shader, K: LightKind, F: ShadowFilter, const M: usize, const UV: bool> ShadowedLike
    for Shadowed<'_, S, K, F, M, UV>
{
    fn dark_outside(self, outside: Outside) -> Self {
        self.with_darkness(0)
            .expect("darkness")
            .with_outside(outside)
    }
}

/// Lit-fraction error over pixels both cover: mean absolute difference, and the share of
/// pixels whose difference exceeds 0.5 (on the other side of a shadow edge), and how many.
#[derive(Clone, Copy, Debug, Default)]
pub struct LitError {
    /// Pixels both cover.
    pub both: usize,
    /// Mean |lit - lit_ref|.
    pub mean: f64,
    /// Pixels with |lit - lit_ref| > 0.5.
    pub wrong: usize,
    /// Covered by one only.
    pub coverage_diff: usize,
}

impl core::fmt::Display for LitError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "mean |Δlit| {:.4}, wrong side {} px ({:.2} %) of {}, coverage diff {}",
            self.mean,
            self.wrong,
            100.0 * self.wrong as f64 / self.both.max(1) as f64,
            self.both,
            self.coverage_diff
        )
    }
}

/// Compares two lit-fraction images.
pub fn lit_error(a: &[f64], a_cov: &[bool], b: &[f64], b_cov: &[bool]) -> LitError {
    let mut e = LitError::default();
    let mut sum = 0.0;
    for i in 0..a.len() {
        match (a_cov[i], b_cov[i]) {
            (true, true) => {
                let d = (a[i] - b[i]).abs();
                e.both += 1;
                sum += d;
                if d > 0.5 {
                    e.wrong += 1;
                }
            }
            (false, false) => {}
            _ => e.coverage_diff += 1,
        }
    }
    e.mean = sum / e.both.max(1) as f64;
    e
}
