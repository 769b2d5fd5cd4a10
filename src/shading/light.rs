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

    /// Intensity for a unit view-space normal, Q8 (`256` = 1.0), clamped to `0..=256`. A
    /// normal of any other length gives a saturated, never wrapped, intensity.
    pub fn intensity(&self, normal: Vec3) -> u16 {
        let ndotl = normal.dot(self.direction).max(Fx::ZERO);
        let i = self
            .ambient
            .saturating_add(diffuse_term(self.diffuse, ndotl));
        // Q16 -> Q8 rounded half up: floor((x + 128) / 256) as floor((floor(x / 128) + 1) / 2),
        // which cannot overflow when a non-unit normal saturates the sum near `Fx::MAX`.
        (((i.to_bits() >> 7) + 1) >> 1).clamp(0, i32::from(COLOR_ONE)) as u16
    }
}

/// `diffuse * ndotl` as `Fx::saturating_mul` gives it (the exact product rounded toward
/// negative infinity, saturated), from one exact product: on Cortex-M0+ four 16-bit
/// `muls` where `saturating_mul` made four `__aeabi_lmul` calls (about 150 instructions per
/// lit vertex; 2 per pixel of the whole-frame sphere).
#[inline]
fn diffuse_term(diffuse: Fx, ndotl: Fx) -> Fx {
    crate::math::acc::saturate(crate::math::acc::prod(diffuse, ndotl) >> 16)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// `diffuse_term` is `Fx::saturating_mul`, bit for bit, on edge and random operands.
    #[test]
    fn diffuse_term_is_saturating_mul() {
        let edges = [
            i32::MIN,
            i32::MIN + 1,
            -65537,
            -65536,
            -65535,
            -1,
            0,
            1,
            32767,
            32768,
            65535,
            65536,
            65537,
            i32::MAX - 1,
            i32::MAX,
        ];
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 16) as i32 >> (seed % 24)
        };
        let mut pairs: std::vec::Vec<(i32, i32)> = std::vec::Vec::new();
        for &a in &edges {
            for &b in &edges {
                pairs.push((a, b));
            }
        }
        for _ in 0..200_000 {
            pairs.push((next(), next()));
        }
        for (a, b) in pairs {
            let (a, b) = (Fx::from_bits(a), Fx::from_bits(b));
            assert_eq!(diffuse_term(a, b), a.saturating_mul(b), "{a:?} * {b:?}");
        }
    }

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

    /// A long normal saturates `ambient + diffuse * (n . l)` at `Fx::MAX`; rounding it to Q8
    /// gives full intensity instead of overflowing.
    #[test]
    fn long_normal_saturates_to_full_intensity() {
        let light = DirectionalLight {
            direction: Vec3::from_num(0, 0, 1),
            ambient: Fx::from_bits(19661),
            diffuse: Fx::ONE,
        };
        assert_eq!(light.intensity(Vec3::new(Fx::ZERO, Fx::ZERO, Fx::MAX)), 256);
        assert_eq!(light.intensity(Vec3::new(Fx::ZERO, Fx::ZERO, Fx::MIN)), 77);
    }

    /// The overflow-free rounding is `(x + 128) >> 8` wherever that does not overflow.
    #[test]
    fn q8_rounding_is_round_half_up() {
        let mut x = i32::MIN;
        while x < i32::MAX - 128 {
            assert_eq!(((x >> 7) + 1) >> 1, (x + 128) >> 8, "{x}");
            x = x.saturating_add(12_345);
        }
        for x in [
            -257, -256, -129, -128, -127, -1, 0, 1, 127, 128, 129, 255, 256, 383, 384,
        ] {
            assert_eq!(((x >> 7) + 1) >> 1, (x + 128) >> 8, "{x}");
        }
    }

    #[test]
    fn zero_direction_is_refused() {
        let e = DirectionalLight::new(Vec3::ZERO, Fx::ONE, Fx::ONE);
        assert_eq!(e, Err(Error::ZeroVector("light direction")));
    }
}
