//! The vertex side of per-pixel lighting: a mesh with normals (and tangents for bump
//! mapping) turned into clip-space triangles whose varyings are what
//! [`Phong`](crate::shading::lighting::Phong) and the bump shaders
//! ([`crate::shading::bump`]) interpolate, plus the per-vertex (Gouraud) colours of the
//! same lighting model for comparison.
//!
//! Lighting is in view space: normals, tangents and the light go through the model-view
//! matrix (exact for rotations, translations and uniform scales, as for [`Mesh`](super::Mesh)).
//! The viewer is at infinity along `+z` (`v = (0, 0, 1)`).
//!
//! Formats: normals and unit vectors are written in Q24 (`2^24` = 1.0), a point light's
//! vector `light − p` in Q20 view units (clamped to `±2^30`, i.e. ±1024 units), so that
//! the span interpolators' last bits of error stay far below the per-pixel normalisation's
//! resolution.

use crate::geometry::{Vertex, COLOR_ONE};
use crate::math::{unit_q14, Fx, Mat4, Vec3};
use crate::scene::tangent::{any_orthogonal, orthogonalize, Tangent};
use crate::scene::Camera;
use crate::shading::lighting::{Material, VIEW_Z};
use crate::Error;

/// A light for per-pixel shading, in view space.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelLight {
    /// Parallel light: the unit vector towards it.
    Directional(Vec3),
    /// A point light at a view-space position (no attenuation, as GL's default).
    Point(Vec3),
}

impl PixelLight {
    /// A directional light shining from `towards_light` (normalised).
    ///
    /// # Errors
    /// [`Error::ZeroVector`] for a zero direction.
    pub fn directional(towards_light: Vec3) -> Result<Self, Error> {
        towards_light
            .normalize()
            .map(PixelLight::Directional)
            .ok_or(Error::ZeroVector("light direction"))
    }

    /// A point light at view-space `position`. A surface point exactly at the light gets
    /// no direction and is lit by the ambient term only.
    pub fn point(position: Vec3) -> Result<Self, Error> {
        Ok(PixelLight::Point(position))
    }

    /// The vector towards the light from view-space point `p`: Q24 unit (directional) or
    /// Q20 view units (point).
    fn towards(&self, p: Vec3) -> [i64; 3] {
        match *self {
            PixelLight::Directional(d) => [d.x, d.y, d.z].map(|c| i64::from(c.to_bits()) << 8),
            PixelLight::Point(l) => [(l.x, p.x), (l.y, p.y), (l.z, p.z)]
                .map(|(a, b)| (i64::from(a.to_bits()) - i64::from(b.to_bits())) << 4),
        }
    }
}

/// `c` clamped to `±2^30` as `i32`.
fn fit(c: i64) -> i32 {
    c.clamp(-(1 << 30), 1 << 30) as i32
}

/// Q24 bits of a unit `Fx` vector.
fn q24(v: Vec3) -> [i32; 3] {
    [v.x, v.y, v.z].map(|c| fit(i64::from(c.to_bits()) << 8))
}

/// A mesh for per-pixel lighting: positions, unit normals, uvs, optional tangents (bump
/// and normal mapping need them) and counter-clockwise triangles.
#[derive(Clone, Copy, Debug)]
pub struct LitMesh<'a> {
    positions: &'a [Vec3],
    normals: &'a [Vec3],
    uvs: &'a [[Fx; 2]],
    tangents: Option<&'a [Tangent]>,
    indices: &'a [[u16; 3]],
}

/// One vertex in view space.
struct ViewVertex {
    clip: [Fx; 4],
    uv: [i32; 2],
    n: Vec3,
    light: [i64; 3],
}

impl<'a> LitMesh<'a> {
    /// Checks the lengths and indices.
    ///
    /// # Errors
    /// [`Error::WrongLength`] when normals, uvs or tangents are not one per position,
    /// [`Error::IndexOutOfRange`], [`Error::MeshTooLarge`] past 65536 vertices.
    pub fn new(
        positions: &'a [Vec3],
        normals: &'a [Vec3],
        uvs: &'a [[Fx; 2]],
        tangents: Option<&'a [Tangent]>,
        indices: &'a [[u16; 3]],
    ) -> Result<Self, Error> {
        // Reuses Mesh's checks (positions, normals, uvs, indices).
        super::Mesh::new(positions, Some(normals), uvs, indices)?;
        if let Some(t) = tangents {
            if t.len() != positions.len() {
                return Err(Error::WrongLength {
                    expected: positions.len(),
                    actual: t.len(),
                });
            }
        }
        Ok(LitMesh {
            positions,
            normals,
            uvs,
            tangents,
            indices,
        })
    }

    /// Calls `emit` for every triangle whose three vertices transform without overflow.
    fn each<const N: usize>(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: &PixelLight,
        mut vary: impl FnMut(usize, &ViewVertex) -> [i32; N],
        mut emit: impl FnMut(&[Vertex<N>; 3]),
    ) {
        let mv = camera.view.mul(model);
        let mvp = camera.projection.mul(&mv);
        let vertex = |i: u16| -> Option<ViewVertex> {
            let i = usize::from(i);
            let p = *self.positions.get(i)?;
            let c = mvp.transform_point(p)?;
            let pv = mv.transform_point(p)?;
            let n = mv.transform_vector(*self.normals.get(i)?)?;
            let uv = self.uvs.get(i)?;
            Some(ViewVertex {
                clip: [c.x, c.y, c.z, c.w],
                uv: [uv[0].to_bits(), uv[1].to_bits()],
                n: n.normalize().unwrap_or(Vec3::ZERO),
                light: light.towards(Vec3::new(pv.x, pv.y, pv.z)),
            })
        };
        for tri in self.indices {
            if let (Some(a), Some(b), Some(c)) = (vertex(tri[0]), vertex(tri[1]), vertex(tri[2])) {
                let out = [
                    (usize::from(tri[0]), a),
                    (usize::from(tri[1]), b),
                    (usize::from(tri[2]), c),
                ]
                .map(|(i, v)| Vertex::new(v.clip, vary(i, &v)));
                emit(&out);
            }
        }
    }

    /// Triangles for [`Phong`](crate::shading::lighting::Phong): varyings
    /// `u, v, n (Q24), light vector`.
    pub fn phong_triangles(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: &PixelLight,
        emit: impl FnMut(&[Vertex<8>; 3]),
    ) {
        self.each(
            model,
            camera,
            light,
            |_, v| {
                let n = q24(v.n);
                let l = v.light.map(fit);
                [v.uv[0], v.uv[1], n[0], n[1], n[2], l[0], l[1], l[2]]
            },
            emit,
        );
    }

    /// Triangles for the bump shaders ([`crate::shading::bump`]): varyings `u, v`, the light
    /// vector in the vertex's tangent frame `(l·t, l·b, l·n)` and the view vector in it
    /// `(t_z, b_z, n_z)` (Q24), with `t` the model-view tangent made orthogonal to the normal
    /// and `b = handedness · n × t`. A mesh without tangents gets an arbitrary frame per
    /// vertex (fine for normal maps of isotropic detail only).
    pub fn bump_triangles(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: &PixelLight,
        emit: impl FnMut(&[Vertex<8>; 3]),
    ) {
        let mv = camera.view.mul(model);
        self.each(
            model,
            camera,
            light,
            |i, v| {
                let tan = self.tangents.and_then(|t| t.get(i)).copied();
                let t = tan
                    .and_then(|t| mv.transform_vector(t.direction))
                    .and_then(|t| orthogonalize(t, v.n))
                    .unwrap_or_else(|| any_orthogonal(v.n));
                let sign = tan.map_or(1, |t| if t.handedness < 0 { -1 } else { 1 });
                let c = v.n.cross(t);
                let b = if sign < 0 {
                    Vec3::new(-c.x, -c.y, -c.z)
                } else {
                    c
                };
                let dot = |a: Vec3| {
                    let f = [a.x, a.y, a.z].map(|x| i64::from(x.to_bits()));
                    fit((v.light[0] * f[0] + v.light[1] * f[1] + v.light[2] * f[2]) >> 16)
                };
                let z = |a: Vec3| fit(i64::from(a.z.to_bits()) << 8);
                [
                    v.uv[0],
                    v.uv[1],
                    dot(t),
                    dot(b),
                    dot(v.n),
                    z(t),
                    z(b),
                    z(v.n),
                ]
            },
            emit,
        );
    }

    /// Triangles for the built-in [`Gouraud`](crate::shading::Gouraud) shader: the same
    /// lighting model evaluated at the vertices, on a surface of colour `base` (raw RGB565):
    /// varyings `r, g, b` (Q8.16).
    pub fn gouraud_triangles(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: &PixelLight,
        material: &Material<'_>,
        base: u16,
        emit: impl FnMut(&[Vertex<3>; 3]),
    ) {
        let ch = [
            (u32::from(base >> 11) * 256 + 15) / 31,
            (u32::from((base >> 5) & 63) * 256 + 31) / 63,
            (u32::from(base & 31) * 256 + 15) / 31,
        ];
        self.each(
            model,
            camera,
            light,
            |_, v| {
                let n = unit_q14(q24(v.n));
                let l = unit_q14(v.light.map(fit));
                let (i, s) = material.light(n, l, VIEW_Z);
                ch.map(|c| {
                    let x = ((c * u32::from(i) + 128) >> 8) + u32::from(s);
                    (x.min(u32::from(COLOR_ONE)) << 16) as i32
                })
            },
            emit,
        );
    }
}
