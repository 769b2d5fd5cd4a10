//! [`SolidShader`]: a [`Pattern`] drawn through the open fragment stage, lit by an
//! interpolated intensity.
//!
//! Varyings (raw `i32` bits):
//!
//! | index | name | format |
//! |---|---|---|
//! | 0, 1, 2 | `x, y, z` | object-space point, I16F16 lattice units (`65536` = one noise cell) |
//! | 3 | `i` | light intensity, Q8.16 (`256 << 16` = 1.0), as [`ModulateIntensity`](crate::shading::ModulateIntensity) |
//!
//! # The pixel footprint
//!
//! A band-limited pattern needs the pixel's footprint in lattice cells. The span loop
//! measures the level of detail of one varying pair ([`Shader::TEXCOORDS`]), so the
//! triangle hook rotates the three coordinates so that the pair `(0, 1)` holds the two axes
//! of the coordinate plane the triangle is most parallel to (the dropped axis is the one
//! its normal is closest to); the shader rotates them back per pixel. The footprint on
//! that plane is the true one within a factor `1/√3..1` (at most 0.79 octave smaller):
//! this is fixel's definition of the footprint, and the f64 reference uses the same.
//! Use the exact or subdivided projection (the adaptive one would bound its error in
//! lattice cells).

use super::patterns::Pattern;
use super::turbulence::Octaves;
use crate::color::modulate_scalar;
use crate::shading::builtin::q8;
use crate::shading::{Fragment, Shader};
use crate::texture::LodGranularity;

/// The per-triangle rotation of the coordinates (see the module docs): slot `j` holds
/// axis `(j + rot) % 3`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SolidTriangle {
    /// 0, 1 or 2.
    pub rot: u8,
}

impl SolidTriangle {
    /// The rotation that moves the axis closest to the normal of the triangle with
    /// object-space corners `v` (I16F16) to slot 2.
    pub fn of(v: [[i32; 3]; 3]) -> SolidTriangle {
        let d = |i: usize, a: usize| (i64::from(v[i][a]) - i64::from(v[0][a])) >> 8;
        let (e1, e2) = ([d(1, 0), d(1, 1), d(1, 2)], [d(2, 0), d(2, 1), d(2, 2)]);
        let n = [
            (e1[1] * e2[2] - e1[2] * e2[1]).unsigned_abs(),
            (e1[2] * e2[0] - e1[0] * e2[2]).unsigned_abs(),
            (e1[0] * e2[1] - e1[1] * e2[0]).unsigned_abs(),
        ];
        let rot = if n[2] >= n[0] && n[2] >= n[1] {
            0
        } else if n[0] >= n[1] {
            1
        } else {
            2
        };
        SolidTriangle { rot }
    }

    /// Slots back to `(x, y, z)`.
    #[inline(always)]
    pub fn unrotate(self, s: [i32; 3]) -> [i32; 3] {
        match self.rot {
            1 => [s[2], s[0], s[1]],
            2 => [s[1], s[2], s[0]],
            _ => s,
        }
    }

    /// `(x, y, z)` to slots.
    #[inline(always)]
    pub fn rotate(self, p: [i32; 3]) -> [i32; 3] {
        match self.rot {
            1 => [p[1], p[2], p[0]],
            2 => [p[2], p[0], p[1]],
            _ => p,
        }
    }
}

/// A solid texture `P` with octaves `O` ([`Fixed`](super::Fixed) or [`BandLimit`](super::BandLimit)), times the
/// interpolated light intensity. Varyings `x, y, z, i` (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct SolidShader<P, O> {
    /// The pattern.
    pub pattern: P,
    /// The octave policy.
    pub octaves: O,
    /// Where a band-limited pattern measures the footprint: per pixel or per span.
    pub granularity: LodGranularity,
}

impl<P: Pattern, O: Octaves> SolidShader<P, O> {
    /// `pattern` with `octaves`, footprint measured once per span.
    pub fn new(pattern: P, octaves: O) -> Self {
        SolidShader {
            pattern,
            octaves,
            granularity: LodGranularity::Span,
        }
    }
}

impl<P: Pattern, O: Octaves> Shader for SolidShader<P, O> {
    type Varyings = [i32; 4];
    type Triangle = SolidTriangle;
    const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));
    const LOD: bool = O::LOD;

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.granularity
    }

    fn triangle(&self, v: &mut [[i32; 4]; 3]) -> SolidTriangle {
        let t = SolidTriangle::of([0, 1, 2].map(|i| [v[i][0], v[i][1], v[i][2]]));
        for c in v.iter_mut() {
            let [a, b, d] = t.rotate([c[0], c[1], c[2]]);
            (c[0], c[1], c[2]) = (a, b, d);
        }
        t
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 4], SolidTriangle>) -> Option<u16> {
        let [a, b, c, i] = f.varyings;
        let p = f.triangle.unrotate([a, b, c]);
        let color = self.pattern.color(p, &self.octaves, f.lambda);
        Some(modulate_scalar(color, q8(i)))
    }
}
