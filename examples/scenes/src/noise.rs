//! Where the solid-texture showcase puts its objects: the model matrices of the marble
//! sphere and the wooden cube, and the lattice scales of the objects and of the granite floor,
//! shared by the noise example, its firmware scenes, the host tests and the baker.

/// Model matrix of the showcase's marble sphere ([`crate::sphere`], radius 1.5):
/// `T(-1.6, 0.5, -6) · Ry(0.4)`.
pub fn marble_sphere_model() -> fixel::math::Mat4 {
    use fixel::math::{Angle, Fx, Mat4, Vec3};
    Mat4::translation(Vec3::new(
        Fx::from_bits(-104_858),
        Fx::from_bits(32_768),
        Fx::from_num(-6),
    )) * Mat4::rotation_y(Angle::from_turns(4172))
}

/// Model matrix of the showcase's wooden cube ([`crate::cube`], side 2):
/// `T(1.8, 0, -6.5) · Rx(0.06 turn) · Ry(0.1 turn)`.
pub fn wood_cube_model() -> fixel::math::Mat4 {
    use fixel::math::{Angle, Fx, Mat4, Vec3};
    Mat4::translation(Vec3::new(
        Fx::from_bits(117_965),
        Fx::ZERO,
        Fx::from_bits(-425_984),
    )) * (Mat4::rotation_x(Angle::from_turns(3932)) * Mat4::rotation_y(Angle::from_turns(6554)))
}

/// Lattice cells per model unit of the showcase objects (about 1.8; odd bits, so no face
/// of the cube lies on a lattice plane at any octave, where the noise's zeros would show
/// as a grid).
pub const SHOWCASE_SCALE: fixel::math::Fx = fixel::math::Fx::from_bits(117_965);

/// The benchmark sphere ([`crate::sphere`], radius 1.5) as a baking surface at
/// [`SHOWCASE_SCALE`] (radius 1.5 x 1.8 = 2.7 lattice cells): the solid textures baked for
/// the sphere's own texture coordinates (`fixel::shading::noise::bake`).
pub fn baked_sphere_surface() -> fixel::shading::noise::SphereSurface {
    fixel::shading::noise::SphereSurface {
        radius: fixel::math::Fx::from_bits(((SHOWCASE_SCALE.to_bits() as i64 * 3) >> 1) as i32),
    }
}

/// Lattice cells per model unit of the showcase's granite floor (about 0.81, odd bits).
pub const FLOOR_SCALE: fixel::math::Fx = fixel::math::Fx::from_bits(53_001);
