//! A directional light evaluated per vertex (Gouraud): `ambient + diffuse * max(0, n . l)`.

use crate::geometry::COLOR_ONE;
use crate::math::{Fx, Vec3};
use crate::Error;

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
        // normalize(-0.4, 0.6, 1.0), checked by a test.
        DirectionalLight {
            direction: Vec3::from_bits(-21262, 31894, 53157),
            ambient: Fx::from_bits(19661), // 0.3
            diffuse: Fx::from_bits(45875), // 0.7
        }
    }
}

impl DirectionalLight {
    /// A light from `towards_light` (any length but zero; it is normalised), with the given
    /// ambient and diffuse terms (each clamped to `0..=1`).
    ///
    /// ```
    /// use fixel::math::{fx, Vec3};
    /// use fixel::scene::DirectionalLight;
    /// let light = DirectionalLight::new(Vec3::from_num(0, 1, 1), fx(0.2), fx(0.8))?;
    /// assert!(DirectionalLight::new(Vec3::ZERO, fx(0.2), fx(0.8)).is_err()); // no direction
    /// # Ok::<(), fixel::Error>(())
    /// ```
    pub fn new(towards_light: Vec3, ambient: Fx, diffuse: Fx) -> Result<Self, Error> {
        let direction = towards_light
            .normalize()
            .ok_or(Error::ZeroVector("light direction"))?;
        Ok(DirectionalLight {
            direction,
            ambient: ambient.clamp(Fx::ZERO, Fx::ONE),
            diffuse: diffuse.clamp(Fx::ZERO, Fx::ONE),
        })
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_is_the_normalised_benchmark_light() {
        let v = Vec3::new(Fx::from_bits(-26214), Fx::from_bits(39322), Fx::ONE);
        let l = DirectionalLight::new(v, Fx::from_bits(19661), Fx::from_bits(45875)).unwrap();
        let d = l.direction;
        assert_eq!(
            l,
            DirectionalLight::default(),
            "{} {} {}",
            d.x.to_bits(),
            d.y.to_bits(),
            d.z.to_bits()
        );
    }

    #[test]
    fn zero_direction_is_refused() {
        let e = DirectionalLight::new(Vec3::ZERO, Fx::ONE, Fx::ONE);
        assert_eq!(e, Err(Error::ZeroVector("light direction")));
    }
}
