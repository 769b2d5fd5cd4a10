//! The lighting model shared by the per-pixel shaders: ambient + diffuse + specular
//! (Phong or Blinn-Phong) from unit vectors in Q14, with the specular power through a table.
//!
//! For unit normal `n`, unit vector towards the light `l` and unit vector towards the viewer
//! `v` (all Q14, `16384` = 1.0):
//!
//! ```text
//! diffuse   d = max(0, n·l)
//! specular  x = r·v with r = 2 (n·l) n − l          (Phong)
//!           x = n·h with h = (l + v) / |l + v|      (Blinn-Phong)
//!           s = max(0, x)^e, and 0 where n·l <= 0   (no highlight from behind)
//! colour    texel × min(1, ka + kd d) + ks s × white, per RGB565 channel, saturated
//! ```
//!
//! `ka`, `kd`, `ks` are Q8 (`256` = 1.0). The exponent `e` (1..=128) is a
//! [`SpecularTable`]: `x^e` for `x` near 1 is `(1 − u/e)^e` with `u = e (1 − x)`, so the
//! table is indexed by `u` over `[0, min(e, 10)]` in 128 steps (beyond, `x^e < e^-10`, is 0)
//! and keeps the same resolution across the highlight for every exponent. Interpolated
//! linearly, it is within `1/768` of `x^e`, a third of the Q8 result's step (a test sweeps
//! all exponents).

use crate::math::{dot_q14, unit_q14, UNIT_Q14};
use crate::Error;

/// Entries of a [`SpecularTable`] minus one.
const STEPS: u32 = 128;

/// `x^e` for `x` in `[0, 1]` (see the module docs): 129 entries, Q15, built at compile time
/// for a `static` or at run time (both through [`SpecularTable::new`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpecularTable {
    table: [u16; STEPS as usize + 1],
    /// `(1 − x)` in Q14 at and beyond which the power is 0.
    d_max: u32,
    /// `(1 − x)` (Q14) times this, `>> 16`, is the table position in Q8.
    scale: u32,
    exponent: u8,
}

/// `a * b` in Q30.
const fn mul_q30(a: u64, b: u64) -> u64 {
    (a * b + (1 << 29)) >> 30
}

impl SpecularTable {
    /// The table for exponent `e`.
    ///
    /// ```
    /// use fixel::shading::lighting::SpecularTable;
    /// static SHINY: SpecularTable = match SpecularTable::new(32) {
    ///     Ok(t) => t,
    ///     Err(_) => panic!("exponent out of range"),
    /// };
    /// assert_eq!(SHINY.power(16384), 32768); // 1^32 = 1 (Q15)
    /// assert!(SpecularTable::new(0).is_err());
    /// ```
    ///
    /// # Errors
    /// [`Error::BadMode`] unless `1 <= e <= 128`.
    pub const fn new(e: u8) -> Result<Self, Error> {
        if e == 0 || e > 128 {
            return Err(Error::BadMode("specular exponent must be 1..=128"));
        }
        let ee = e as u64;
        // Domain of u = e (1 - x): [0, U], U = min(e, 10).
        let u_max = if ee < 10 { ee } else { 10 };
        let mut table = [0u16; STEPS as usize + 1];
        let mut k = 0;
        while k <= STEPS as usize {
            // base = 1 - u/e with u = k U / STEPS, in Q30 (exact rational, rounded).
            let num = (k as u64) * u_max; // u * STEPS
            let den = (STEPS as u64) * ee;
            let base = (1u64 << 30) - ((num << 30) + den / 2) / den;
            // base^e by squaring, Q30.
            let mut result = 1u64 << 30;
            let mut b = base;
            let mut p = ee;
            while p > 0 {
                if p & 1 == 1 {
                    result = mul_q30(result, b);
                }
                b = mul_q30(b, b);
                p >>= 1;
            }
            table[k] = ((result + (1 << 14)) >> 15) as u16;
            k += 1;
        }
        // d (Q14) -> u = e d / 2^14 -> position = u STEPS / U (entries) -> Q8: d * scale >> 16
        // with scale = e STEPS 2^10 / U.
        let scale = (ee * STEPS as u64 * 1024 / u_max) as u32;
        // d_max = U 2^14 / e: beyond it the table has run out.
        let d_max = (u_max * (1 << 14) / ee) as u32;
        Ok(SpecularTable {
            table,
            d_max,
            scale,
            exponent: e,
        })
    }

    /// The exponent.
    pub const fn exponent(&self) -> u8 {
        self.exponent
    }

    /// `max(0, x)^e` for `x` in Q14 (`16384` = 1.0; larger is 1.0), Q15 (`32768` = 1.0).
    #[inline(always)]
    pub fn power(&self, x: i32) -> u32 {
        if x <= 0 {
            return 0;
        }
        let d = (UNIT_Q14 - x).max(0) as u32;
        if d >= self.d_max {
            return 0;
        }
        // d < d_max = U 2^14 / e, so d * scale < 2^14 STEPS 2^10 = 2^31.
        let pos = (d * self.scale) >> 16; // Q8 entries
        let i = ((pos >> 8) as usize).min(STEPS as usize - 1);
        let f = pos & 0xFF;
        let a = u32::from(self.table.get(i).copied().unwrap_or(0));
        let b = u32::from(self.table.get(i + 1).copied().unwrap_or(0));
        // b <= a.
        a - (((a - b) * f + 128) >> 8)
    }
}

/// Which specular term.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Specular {
    /// No highlight (diffuse only).
    None,
    /// Phong: the reflected light vector against the view vector.
    Phong,
    /// Blinn-Phong: the normal against the half vector (the default: cheaper with a
    /// directional light, and GL's fixed-function model).
    #[default]
    Blinn,
}

/// Surface response to light: the coefficients of the module docs and the exponent table.
#[derive(Clone, Copy, Debug)]
pub struct Material<'a> {
    /// Ambient `ka`, Q8 (`0..=256`).
    pub ambient: u16,
    /// Diffuse `kd`, Q8 (`0..=256`).
    pub diffuse: u16,
    /// Specular `ks`, Q8 (`0..=256`).
    pub specular: u16,
    /// The specular model.
    pub model: Specular,
    /// `x^e`.
    pub shininess: &'a SpecularTable,
}

impl<'a> Material<'a> {
    /// A material with coefficients in Q8 (`256` = 1.0).
    ///
    /// # Errors
    /// [`Error::BadMode`] when a coefficient exceeds 256.
    pub fn new(
        ambient: u16,
        diffuse: u16,
        specular: u16,
        model: Specular,
        shininess: &'a SpecularTable,
    ) -> Result<Self, Error> {
        if ambient > 256 || diffuse > 256 || specular > 256 {
            return Err(Error::BadMode(
                "material coefficients are Q8 and at most 256 (1.0)",
            ));
        }
        Ok(Material {
            ambient,
            diffuse,
            specular,
            model,
            shininess,
        })
    }

    /// `(intensity, highlight)` for unit Q14 vectors `n`, `l`, `v`: the diffuse intensity
    /// `min(256, ka + kd d)` (Q8) and the specular `ks s` (Q8, `0..=256`).
    #[inline(always)]
    pub fn light(&self, n: [i32; 3], l: [i32; 3], v: [i32; 3]) -> (u16, u16) {
        let ndl = dot_q14(n, l);
        let d = ndl.max(0) as u32;
        let i = (u32::from(self.ambient) + ((u32::from(self.diffuse) * d + (1 << 13)) >> 14))
            .min(256) as u16;
        if ndl <= 0 || self.specular == 0 {
            return (i, 0);
        }
        let x = match self.model {
            Specular::None => return (i, 0),
            Specular::Phong => {
                // r·v = 2 (n·l)(n·v) − l·v.
                2 * ((ndl * dot_q14(n, v)) >> 14) - dot_q14(l, v)
            }
            Specular::Blinn => {
                let h = unit_q14([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
                dot_q14(n, h)
            }
        };
        let s = (u32::from(self.specular) * self.shininess.power(x) + (1 << 14)) >> 15;
        (i, s.min(256) as u16)
    }
}

/// `modulate(texel, i) + s × white` per RGB565 channel, saturated (`i`, `s` Q8).
#[inline(always)]
pub fn lit_texel(texel: u16, i: u16, s: u16) -> u16 {
    let c = crate::color::modulate_scalar(texel, i);
    if s == 0 {
        return c;
    }
    let s = u32::from(s);
    let r = (u32::from(c >> 11) + ((31 * s + 128) >> 8)).min(31);
    let g = (u32::from((c >> 5) & 0x3F) + ((63 * s + 128) >> 8)).min(63);
    let b = (u32::from(c & 0x1F) + ((31 * s + 128) >> 8)).min(31);
    ((r << 11) | (g << 5) | b) as u16
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_follows_x_to_the_e() {
        for e in 1..=128u8 {
            let t = SpecularTable::new(e).unwrap();
            let mut worst = 0f64;
            for x in (0..=16384).step_by(7) {
                let want = (x as f64 / 16384.0).powi(i32::from(e));
                let got = f64::from(t.power(x)) / 32768.0;
                worst = worst.max((got - want).abs());
            }
            assert!(worst < 1.0 / 768.0, "e = {e}: worst {worst}");
        }
        assert!(SpecularTable::new(129).is_err());
    }

    #[test]
    fn light_along_the_normal_is_full() {
        let t = SpecularTable::new(16).unwrap();
        let m = Material::new(64, 192, 256, Specular::Blinn, &t).unwrap();
        let z = [0, 0, UNIT_Q14];
        assert_eq!(m.light(z, z, z), (256, 256));
        let m = Material {
            model: Specular::Phong,
            ..m
        };
        assert_eq!(m.light(z, z, z), (256, 256));
        // From behind: ambient only, no highlight.
        assert_eq!(m.light(z, [0, 0, -UNIT_Q14], z), (64, 0));
    }
}
