//! A directional light evaluated per vertex (Gouraud): `ambient + diffuse * max(0, n . l)`.

use crate::geometry::COLOR_ONE;
use crate::math::{Fx, Vec3};

/// A directional light in view space.
///
/// The default is the benchmark scenes' light: `l = normalize(-0.4, 0.6, 1.0)`,
/// ambient 0.3, diffuse 0.7.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DirectionalLight {
    /// Unit vector towards the light, view space.
    pub direction: Vec3,
    /// Ambient term (0..=1).
    pub ambient: Fx,
    /// Diffuse term (0..=1).
    pub diffuse: Fx,
}

impl Default for DirectionalLight {
    fn default() -> Self {
        DirectionalLight::new(
            Vec3::new(Fx::from_bits(-26214), Fx::from_bits(39322), Fx::ONE), // (-0.4, 0.6, 1.0)
            Fx::from_bits(19661),                                            // 0.3
            Fx::from_bits(45875),                                            // 0.7
        )
    }
}

impl DirectionalLight {
    /// A light from `towards_light` (need not be unit length; a zero vector gives ambient
    /// only), with the given ambient and diffuse terms.
    pub fn new(towards_light: Vec3, ambient: Fx, diffuse: Fx) -> Self {
        DirectionalLight {
            direction: towards_light.normalize().unwrap_or(Vec3::ZERO),
            ambient,
            diffuse,
        }
    }

    /// Intensity for a unit view-space normal, Q8 (`256` = 1.0), clamped to `0..=256`.
    pub fn intensity(&self, normal: Vec3) -> u16 {
        let ndotl = normal.dot(self.direction).max(Fx::ZERO);
        let i = self
            .ambient
            .saturating_add(self.diffuse.saturating_mul(ndotl));
        // Q16 -> Q8 rounded.
        ((i.to_bits() + 128) >> 8).clamp(0, i32::from(COLOR_ONE)) as u16
    }
}
