//! The surface-detail scenes (per-pixel lighting, bump and normal mapping): a brick sphere
//! under a point light that circles it, shared by the example, the host tests, the report
//! and the `bump` firmware scene.
//!
//! The sphere is [`uv_sphere`]`(24, 48)` (radius 1.5, at
//! `z = −5`, turning with the frame) with its uvs scaled by `(4, 2)` so the brick tile
//! ([`bricks`](super::bricks)) repeats 4 times around and twice from pole to pole, and
//! tangents from [`tangents`].

use crate::demo::{uv_sphere, MeshData, SPHERE_TRIANGLES, SPHERE_VERTICES};
use crate::math::{Angle, Fx, Mat4, Vec3};
use crate::scene::{tangents, Camera, PixelLight, Tangent};
use crate::shading::lighting::{Material, Specular, SpecularTable};
use crate::Error;

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
        uv[0] = uv[0].saturating_mul(Fx::from_num(4));
        uv[1] = uv[1].saturating_mul(Fx::from_num(2));
    }
    let mut t = [Tangent::default(); SPHERE_VERTICES];
    tangents(&m.positions, &m.normals, &m.uvs, &m.indices, &mut t)?;
    Ok((m, t))
}

/// Model matrix of frame `i`: `T(0, 0, −5) · Rx(0.3) · Ry(i / 64 turn)`.
pub fn sphere_model(i: u32) -> Mat4 {
    Mat4::translation(Vec3::from_num(0, 0, -5))
        * Mat4::rotation_x(Angle(3130))
        * Mat4::rotation_y(Angle((i.wrapping_mul(1024)) as u16))
}

/// The camera: 45 degrees, square aspect, near 0.5, far 20.
pub fn camera() -> Result<Camera, Error> {
    Camera::perspective(
        Angle(8192),
        Fx::ONE,
        Fx::from_bits(1 << 15),
        Fx::from_num(20),
    )
}

/// The point light of frame `i`: circling the sphere at radius 3.5, 1.5 above its centre,
/// `1/16` turn per frame, starting up and to the left of the camera.
pub fn light(i: u32) -> PixelLight {
    let a = Angle((i.wrapping_mul(4096) as u16).wrapping_add(22938));
    let (s, c) = (a.sin(), a.cos());
    let r = Fx::from_num(3.5);
    PixelLight::Point(Vec3::new(
        r.saturating_mul(c),
        Fx::from_num(1.5),
        Fx::from_num(-5).saturating_add(r.saturating_mul(s)),
    ))
}
