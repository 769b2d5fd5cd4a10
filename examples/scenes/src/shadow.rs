//! The shadow-mapping scene: the benchmark cube (frame 0) standing on a textured floor,
//! seen from above and in front, lit by a directional light (high or grazing) or a spot
//! light, for the showcase, the tests, the firmware scene and the report.
//!
//! World units; the cube of side 2 at `(0, 0, -4)` rotated as `cube_model(0)` has its
//! lowest corner at `y = -1.3717`; the floor is the quad `y = -1.375`, `x` in `[-4, 4]`,
//! `z` in `[-9, 0]`, its texture repeating every 2 units.

use fixel::color::TargetColor;
use fixel::geometry::Vertex;
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthLess, DepthOnlyDraw, ProjectionStage, ShadedDraw};
use fixel::scene::{light_pass_mesh, shadowed_mesh_triangles, Camera, DirectionalLight};
use fixel::shading::pcf::ShadowFilter;
use fixel::shading::shadow::{with_light, Directional, LightKind, LightSpace, Shadowed, Spot};
use fixel::shading::Classic;
use fixel::shading::{ModulateIntensity, Shader};
use fixel::surface::{DepthMap, RenderTarget};
use fixel::texture::{TexSampler, WrapMode};
use fixel::Error;

use super::MeshData;

/// Height of the floor (world `y`).
pub const FLOOR_Y: Fx = Fx::from_bits(-90112); // -1.375

/// The floor quad under the cube: uv repeats every 2 units.
pub fn floor() -> MeshData<4, 2> {
    let corners = [(-4, 0), (4, 0), (4, -9), (-4, -9)];
    let mut m = MeshData {
        positions: [Vec3::ZERO; 4],
        normals: [Vec3::from_num(0, 1, 0); 4],
        uvs: [[Fx::ZERO; 2]; 4],
        indices: [[0, 1, 2], [0, 2, 3]],
    };
    for (k, (x, z)) in corners.into_iter().enumerate() {
        m.positions[k] = Vec3::new(Fx::from_num(x), FLOOR_Y, Fx::from_num(z));
        m.uvs[k] = [Fx::from_num(x + 4) / 2, Fx::from_num(-z) / 2];
    }
    m
}

/// The camera: 45 degrees, 4:3, near 0.5, far 20, at `(2, 3, 1.5)` looking at
/// `(0.3, -1, -4.5)`.
pub fn camera() -> Camera {
    let c = super::camera(20);
    let eye = Vec3::new(Fx::from_num(2), Fx::from_num(3), Fx::from_num(1.5));
    let at = Vec3::new(Fx::from_num(0.3), Fx::from_num(-1), Fx::from_num(-4.5));
    c.looking_at(eye, at, Vec3::from_num(0, 1, 0)).unwrap_or(c)
}

/// The lights of the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneLight {
    /// Directional, from `(-0.5, 1, 0.4)` (about 55 degrees above the floor).
    High,
    /// Directional, from `(-1, 0.2, 0.3)` (about 11 degrees above the floor): long shadows and
    /// a floor at a grazing angle to the light, where acne lives.
    Grazing,
    /// A spot light at `(-3, 3, -3)` aimed at `(0.5, -1.375, -5)`, 70 degree cone.
    Spot,
}

/// Unit-free direction towards the light of each directional variant (world space).
fn towards(l: SceneLight) -> Vec3 {
    match l {
        SceneLight::High => Vec3::new(Fx::from_num(-0.5), Fx::ONE, Fx::from_num(0.4)),
        SceneLight::Grazing => Vec3::new(-Fx::ONE, Fx::from_num(0.2), Fx::from_num(0.3)),
        SceneLight::Spot => Vec3::new(Fx::from_num(-3.5), Fx::from_num(4.375), Fx::from_num(2)),
    }
}

/// The centre the lights aim at.
fn centre() -> Vec3 {
    Vec3::new(Fx::ZERO, Fx::from_num(-1), Fx::from_num(-4.5))
}

/// The directional light space of `l` (`High` or `Grazing`; `Spot` gives `High`'s):
/// an orthographic box of half-side 6.5 around the scene, depth 1..19 from an eye 10 units
/// from the centre.
pub fn directional(l: SceneLight) -> Result<LightSpace<Directional>, Error> {
    let l = if l == SceneLight::Spot {
        SceneLight::High
    } else {
        l
    };
    let dir = towards(l)
        .normalize()
        .ok_or(Error::BadProjection("light"))?;
    let eye = centre() + dir.scale(Fx::from_num(10));
    LightSpace::directional(
        eye,
        centre(),
        Vec3::from_num(0, 1, 0),
        Fx::from_num(6.5),
        Fx::ONE,
        Fx::from_num(19),
    )
}

/// The spot light space.
pub fn spot() -> Result<LightSpace<Spot>, Error> {
    let at = Vec3::new(Fx::from_num(0.5), FLOOR_Y, Fx::from_num(-5));
    LightSpace::spot(
        Vec3::new(Fx::from_num(-3), Fx::from_num(3), Fx::from_num(-3)),
        at,
        Vec3::from_num(0, 1, 0),
        Angle::from_degrees(Fx::from_num(70)),
        Fx::ONE,
        Fx::from_num(12),
    )
}

/// The per-vertex (Gouraud) light of the lit pass, in the camera's view space, from the
/// same direction as the shadow's light: ambient 0.35, diffuse 0.65.
pub fn gouraud_light(l: SceneLight) -> DirectionalLight {
    let cam = camera();
    let d = cam.view.transform_vector(towards(l)).unwrap_or(Vec3::ZERO);
    // A zero direction cannot happen for the demo's lights; fall back to the default.
    DirectionalLight::new(d, Fx::from_num(0.35), Fx::from_num(0.65)).unwrap_or_default()
}

/// The floor's texture (`64 x 64`, `out` of that length): a quiet stone checker of 16-texel
/// cells, two warm greys with a faint diagonal grain, so shadows read at a glance.
pub fn floor_texture(out: &mut [embedded_graphics_core::pixelcolor::Rgb565]) -> Result<(), Error> {
    use embedded_graphics_core::pixelcolor::raw::RawU16;
    if out.len() != 64 * 64 {
        return Err(Error::WrongLength {
            expected: 64 * 64,
            actual: out.len(),
        });
    }
    for (i, px) in out.iter_mut().enumerate() {
        let (x, y) = (i % 64, i / 64);
        let light = (x / 16 + y / 16) % 2 == 0;
        let grain = ((x + 2 * y) % 7) as u8;
        let (r, g, b) = if light {
            (222, 212, 190)
        } else {
            (160, 150, 134)
        };
        *px = embedded_graphics_core::pixelcolor::Rgb565::from(RawU16::new(
            fixel::color::rgb888_to_565(r - grain, g - grain, b - grain),
        ));
    }
    Ok(())
}

/// The meshes with their model matrices: the cube (frame 0), then the floor.
pub fn meshes() -> (MeshData<24, 12>, Mat4, MeshData<4, 2>) {
    (super::cube(), super::cube_model(0), floor())
}

/// The light pass of the whole scene (cube and floor) into `map` (cleared first), culling
/// back faces; returns the texels written.
pub fn light_pass<K: LightKind>(
    space: &LightSpace<K>,
    map: &mut DepthMap<'_>,
) -> Result<u32, Error> {
    light_pass_culling(space, map, fixel::geometry::Cull::Back)
}

/// [`light_pass`] culling `cull` faces as seen from the light: `Cull::Front` keeps only the
/// faces turned away from the light in the map (the floor, open to the light, is then not
/// in it and cannot shadow itself: the usual cure for acne at grazing angles).
pub fn light_pass_culling<K: LightKind>(
    space: &LightSpace<K>,
    map: &mut DepthMap<'_>,
    cull: fixel::geometry::Cull,
) -> Result<u32, Error> {
    map.clear();
    let draw = DepthOnlyDraw::new(map, cull)?;
    let (cube, model, floor) = meshes();
    let mut n = light_pass_mesh(&draw, &cube.mesh()?, &model, space, map)?;
    n += light_pass_mesh(&draw, &floor.mesh()?, &Mat4::IDENTITY, space, map)?;
    Ok(n)
}

/// The lit pass of the whole scene into `target` (colour and depth, cleared by the caller):
/// the cube with `draws[0]`, the floor with `draws[1]` (a [`Shadowed`] textured, lit shader
/// each, usually differing in texture only); `M` is 6 (directional) or 7 (spot).
/// Returns the pixels written.
#[allow(clippy::type_complexity)]
pub fn lit_pass<'a, P, K, F, FS, WU, WV, C, T, const M: usize, const UV: bool>(
    draws: [&ShadedDraw<Shadowed<'a, ModulateIntensity<'a, FS, WU, WV>, K, F, M, UV>, P, DepthLess>;
        2],
    space: &LightSpace<K>,
    light: SceneLight,
    target: &mut T,
) -> Result<u32, Error>
where
    P: ProjectionStage,
    K: LightKind,
    F: ShadowFilter,
    FS: TexSampler,
    WU: WrapMode,
    WV: WrapMode,
    C: TargetColor,
    T: RenderTarget<Color = C>,
    Shadowed<'a, ModulateIntensity<'a, FS, WU, WV>, K, F, M, UV>: Shader<Varyings = [i32; M]>,
{
    let (cube, model, floor) = meshes();
    let cam = camera();
    let gl = gouraud_light(light);
    for draw in draws.iter() {
        draw.check_target(target)?;
    }
    let mut n = 0u32;
    for ((mesh, m), draw) in [(cube.mesh()?, model), (floor.mesh()?, Mat4::IDENTITY)]
        .into_iter()
        .zip(draws)
    {
        shadowed_mesh_triangles(&mesh, &m, &cam, Some(&gl), space, |cv, lv| {
            let tri = [0, 1, 2].map(|k| {
                let inner = Vertex::new(
                    cv[k].position,
                    ModulateIntensity::<FS, WU, WV>::from_classic(&cv[k].to_vertex().varyings),
                );
                with_light::<3, M>(&inner, lv[k])
            });
            // The target was checked above: this draw cannot fail.
            n = n.wrapping_add(draw.clip_triangles(&[tri], target).unwrap_or(0));
        });
    }
    Ok(n)
}
