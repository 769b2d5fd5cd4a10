//! The surface-detail scenes (per-pixel lighting, bump and normal mapping): a brick sphere
//! under a point light that circles it, shared by the example, the host tests, the report
//! and the `bump` firmware scene.
//!
//! The sphere is [`uv_sphere`]`(24, 48)` (radius 1.5, at
//! `z = −5`, turning with the frame) with its uvs scaled by `(4, 2)` so the brick tile
//! ([`bricks`](super::bricks)) repeats 4 times around and twice from pole to pole, and
//! tangents from [`tangents`].

use super::{uv_sphere, MeshData, SPHERE_TRIANGLES, SPHERE_VERTICES};
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::scene::{tangents, Camera, PixelLight, Tangent};
use fixel::shading::lighting::{Material, Specular, SpecularTable};
use fixel::Error;

/// The specular exponent table of the scenes (`e = 24`).
pub static SHININESS: SpecularTable = match SpecularTable::new(24) {
    Ok(t) => t,
    Err(_) => panic!("24 is a valid exponent"),
};

/// The material: ambient 0.2, diffuse 0.85, specular 0.5, Blinn-Phong.
pub fn material(model: Specular) -> Material<'static> {
    Material {
        ambient: 51,
        diffuse: 218,
        specular: 128,
        model,
        shininess: &SHININESS,
    }
}

/// The brick sphere and its tangents.
pub fn sphere() -> Result<
    (
        MeshData<SPHERE_VERTICES, SPHERE_TRIANGLES>,
        [Tangent; SPHERE_VERTICES],
    ),
    Error,
> {
    let mut m = uv_sphere::<SPHERE_VERTICES, SPHERE_TRIANGLES>(24, 48);
    for uv in m.uvs.iter_mut() {
        uv[0] = uv[0].saturating_mul(Fx::from_bits(4 << 16));
        uv[1] = uv[1].saturating_mul(Fx::from_bits(2 << 16));
    }
    let mut t = [Tangent::default(); SPHERE_VERTICES];
    tangents(&m.positions, &m.normals, &m.uvs, &m.indices, &mut t)?;
    Ok((m, t))
}

/// Model matrix of frame `i`: `T(0, 0, −5) · Rx(0.3) · Ry(i / 64 turn)`.
pub fn sphere_model(i: u32) -> Mat4 {
    Mat4::translation(Vec3::from_bits(0, 0, -5 << 16))
        * Mat4::rotation_x(Angle(3130))
        * Mat4::rotation_y(Angle((i.wrapping_mul(1024)) as u16))
}

/// The camera: 45 degrees, square aspect, near 0.5, far 20.
pub fn camera() -> Result<Camera, Error> {
    Camera::perspective(
        Angle(8192),
        Fx::ONE,
        Fx::from_bits(1 << 15),
        Fx::from_bits(20 << 16),
    )
}

/// The point light of frame `i`: circling the sphere at radius 3.5, 1.5 above its centre,
/// `1/16` turn per frame, starting up and to the left of the camera.
pub fn light(i: u32) -> PixelLight {
    let a = Angle((i.wrapping_mul(4096) as u16).wrapping_add(22938));
    // Integer products of raw bits (3.5 = 7 << 15): the RV32IMC build computed this light
    // wrongly through `Fx::saturating_mul` once inlined into the `bump` firmware; plain i64
    // products give every target the host's value.
    let (s, c) = (i64::from(a.sin().to_bits()), i64::from(a.cos().to_bits()));
    let r = 7i64 << 15;
    let bits = |v: i64| Fx::from_bits(v as i32);
    PixelLight::Point(Vec3::new(
        bits((r * c) >> 16),
        bits(3 << 15), // 1.5
        bits((-5i64 << 16) + ((r * s) >> 16)),
    ))
}

/// The direction towards the light (object space, unit length within 2^-16) for which the
/// brick sphere's lighting is resolved into its texture
/// ([`resolve_sphere`](fixel::shading::bump::resolve_sphere), the `bump_fast` scene): up,
/// left and towards the viewer of the benchmark sphere's frame 0, about `(−0.48, 0.64,
/// 0.6)`.
pub fn resolve_light() -> Vec3 {
    Vec3::from_bits(-31_457, 41_943, 39_322)
}

/// The bump strength σ of the resolved brick sphere (I16F16 bits: 0.02 texel widths per
/// height step, the `bump` scene's).
pub const RESOLVE_STRENGTH: i32 = 1311;

/// Builds the `n x n` brick maps of the scenes into caller storage: `colours` (`n * n`),
/// `heights` (the full mip chain, [`chain_len`](fixel::texture::chain_len)`(n, n,
/// levels)`) and its derivative map `derivs` (the same chain length); returns the
/// derivative map's scale (see [`derivative_map`](fixel::shading::bump::derivative_map)).
///
/// # Errors
/// The size and length errors of [`bricks`](super::bricks) and
/// [`HeightMap::new`](fixel::texture::HeightMap::new).
pub fn brick_maps(
    n: u32,
    levels: u32,
    colours: &mut [embedded_graphics_core::pixelcolor::Rgb565],
    heights: &mut [u8],
    derivs: &mut [embedded_graphics_core::pixelcolor::Rgb565],
) -> Result<Fx, Error> {
    use fixel::texture::{generate_height_mips, HeightMap};
    super::bricks::brick_colours(n, colours)?;
    let base = (n as usize).saturating_mul(n as usize);
    let len = heights.len();
    let level0 = heights.get_mut(..base).ok_or(Error::WrongLength {
        expected: base,
        actual: len,
    })?;
    super::bricks::brick_heights(n, level0)?;
    generate_height_mips(heights, n, n, levels)?;
    let map = HeightMap::new(heights, n, n, levels)?;
    fixel::shading::bump::derivative_map(&map, derivs)
}
