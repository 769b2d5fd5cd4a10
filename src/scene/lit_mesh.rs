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

use crate::color::TargetColor;
use crate::geometry::{Vertex, COLOR_ONE};
use crate::math::{unit_q14, Fx, Mat4, Vec3};
use crate::pipeline::{DepthStage, ProjectionStage, ShadedDraw};
use crate::scene::tangent::{any_orthogonal, orthogonalize, Tangent};
use crate::scene::Camera;
use crate::shading::lighting::{Material, VIEW_Z};
use crate::shading::Shader;
use crate::surface::RenderTarget;
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

    /// The vertex builder shared by the triangle and vertex-array entry points: `vary`
    /// turns a view-space vertex into the varyings.
    fn builder<'s, const N: usize>(
        &'s self,
        model: &Mat4,
        camera: &Camera,
        light: &'s PixelLight,
        vary: impl Fn(usize, &ViewVertex) -> [i32; N] + 's,
    ) -> impl Fn(usize) -> Option<Vertex<N>> + 's {
        let mv = camera.view.mul(model);
        let mvp = camera.projection.mul(&mv);
        move |i: usize| {
            let p = *self.positions.get(i)?;
            let c = mvp.transform_point(p)?;
            let pv = mv.transform_point(p)?;
            let n = mv.transform_vector(*self.normals.get(i)?)?;
            let uv = self.uvs.get(i)?;
            let v = ViewVertex {
                clip: [c.x, c.y, c.z, c.w],
                uv: [uv[0].to_bits(), uv[1].to_bits()],
                n: n.normalize().unwrap_or(Vec3::ZERO),
                light: light.towards(Vec3::new(pv.x, pv.y, pv.z)),
            };
            Some(Vertex::new(v.clip, vary(i, &v)))
        }
    }

    /// Calls `emit` for every triangle whose three vertices transform without overflow,
    /// building each corner from scratch (no storage).
    fn each<const N: usize>(
        &self,
        vertex: impl Fn(usize) -> Option<Vertex<N>>,
        mut emit: impl FnMut(&[Vertex<N>; 3]),
    ) {
        for tri in self.indices {
            let v = |k: usize| vertex(usize::from(tri[k]));
            if let (Some(a), Some(b), Some(c)) = (v(0), v(1), v(2)) {
                emit(&[a, b, c]);
            }
        }
    }

    /// Fills `out` (one per position) with every vertex, each built once; a vertex that
    /// overflows gets `w = 0` and [`LitMesh::indexed`] skips its triangles. Returns how many
    /// overflowed.
    fn fill<const N: usize>(
        &self,
        vertex: impl Fn(usize) -> Option<Vertex<N>>,
        out: &mut [Vertex<N>],
    ) -> Result<usize, Error> {
        if out.len() != self.positions.len() {
            return Err(Error::WrongLength {
                expected: self.positions.len(),
                actual: out.len(),
            });
        }
        let mut failed = 0;
        for (i, o) in out.iter_mut().enumerate() {
            *o = vertex(i).unwrap_or_else(|| {
                failed += 1;
                Vertex::new([Fx::ZERO; 4], [0; N])
            });
        }
        Ok(failed)
    }

    /// Calls `emit` with each triangle of the mesh over `vertices` (from one of the
    /// `*_vertices` functions), skipping triangles with an overflowed vertex (`w = 0`) or an
    /// index past `vertices`.
    pub fn indexed<const N: usize>(
        &self,
        vertices: &[Vertex<N>],
        mut emit: impl FnMut(&[Vertex<N>; 3]),
    ) {
        for tri in self.indices {
            let v = |k: usize| {
                vertices
                    .get(usize::from(tri[k]))
                    .filter(|v| v.position[3] != Fx::ZERO)
                    .copied()
            };
            if let (Some(a), Some(b), Some(c)) = (v(0), v(1), v(2)) {
                emit(&[a, b, c]);
            }
        }
    }

    /// Draws the mesh over `vertices` (from one of the `*_vertices` functions) with `draw`
    /// into `target`, as [`LitMesh::indexed`] hands the triangles over; returns the pixels
    /// written.
    ///
    /// # Errors
    /// [`Error::NoDepthBuffer`] when the draw tests depth and `target` has none (nothing is
    /// drawn).
    pub fn draw_indexed<S, P, D, C, T, const N: usize>(
        &self,
        draw: &ShadedDraw<S, P, D>,
        vertices: &[Vertex<N>],
        target: &mut T,
    ) -> Result<u32, Error>
    where
        S: Shader<Varyings = [i32; N]>,
        P: ProjectionStage,
        D: DepthStage,
        C: TargetColor,
        T: RenderTarget<Color = C>,
    {
        draw.check_target(target)?;
        let mut pixels = 0u32;
        self.indexed(vertices, |t| {
            // The target was checked: drawing cannot fail.
            if let Ok(n) = draw.clip_triangles(core::slice::from_ref(t), target) {
                pixels = pixels.wrapping_add(n);
            }
        });
        Ok(pixels)
    }

    fn phong_vary(_: usize, v: &ViewVertex) -> [i32; 8] {
        let n = q24(v.n);
        let l = v.light.map(fit);
        [v.uv[0], v.uv[1], n[0], n[1], n[2], l[0], l[1], l[2]]
    }

    fn bump_vary(&self, mv: &Mat4, i: usize, v: &ViewVertex) -> [i32; 8] {
        let tan = self.tangents.and_then(|t| t.get(i)).copied();
        let t = tan
            .and_then(|t| mv.transform_vector(t.direction))
            .and_then(|t| orthogonalize(t, v.n))
            .unwrap_or_else(|| any_orthogonal(v.n));
        let c = v.n.cross(t);
        let b = match tan {
            Some(t) if t.handedness < 0 => Vec3::new(-c.x, -c.y, -c.z),
            _ => c,
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
    }

    fn gouraud_vary(material: &Material<'_>, base: u16, v: &ViewVertex) -> [i32; 3] {
        let ch = [
            (u32::from(base >> 11) * 256 + 15) / 31,
            (u32::from((base >> 5) & 63) * 256 + 31) / 63,
            (u32::from(base & 31) * 256 + 15) / 31,
        ];
        let n = unit_q14(q24(v.n));
        let l = unit_q14(v.light.map(fit));
        let (i, s) = material.light(n, l, VIEW_Z);
        ch.map(|c| {
            let x = ((c * u32::from(i) + 128) >> 8) + u32::from(s);
            (x.min(u32::from(COLOR_ONE)) << 16) as i32
        })
    }

    /// Triangles for [`Phong`](crate::shading::lighting::Phong): varyings
    /// `u, v, n (Q24), light vector`. Each corner is built from scratch: use
    /// [`LitMesh::phong_vertices`] and [`LitMesh::indexed`] when RAM allows one
    /// [`Vertex`] (48 bytes) per mesh vertex.
    pub fn phong_triangles(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: &PixelLight,
        emit: impl FnMut(&[Vertex<8>; 3]),
    ) {
        self.each(self.builder(model, camera, light, Self::phong_vary), emit);
    }

    /// [`LitMesh::phong_triangles`]' vertices, each built once, into `out` (one per
    /// position); returns how many overflowed (see [`LitMesh::indexed`]).
    ///
    /// # Errors
    /// [`Error::WrongLength`] when `out` is not one per position.
    pub fn phong_vertices(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: &PixelLight,
        out: &mut [Vertex<8>],
    ) -> Result<usize, Error> {
        self.fill(self.builder(model, camera, light, Self::phong_vary), out)
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
            self.builder(model, camera, light, move |i, v| self.bump_vary(&mv, i, v)),
            emit,
        );
    }

    /// [`LitMesh::bump_triangles`]' vertices, each built once, into `out` (one per
    /// position); returns how many overflowed (see [`LitMesh::indexed`]).
    ///
    /// # Errors
    /// [`Error::WrongLength`] when `out` is not one per position.
    pub fn bump_vertices(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: &PixelLight,
        out: &mut [Vertex<8>],
    ) -> Result<usize, Error> {
        let mv = camera.view.mul(model);
        self.fill(
            self.builder(model, camera, light, move |i, v| self.bump_vary(&mv, i, v)),
            out,
        )
    }

    /// The vertex of [`LitMesh::bump_triangles`] at an index, built on demand (`None` past
    /// the mesh or where a transform overflows): for a band renderer's geometry closure,
    /// which builds only the triangles a band meets and stores no vertex per mesh vertex.
    pub fn bump_vertex<'s>(
        &'s self,
        model: &Mat4,
        camera: &Camera,
        light: &'s PixelLight,
    ) -> impl Fn(usize) -> Option<Vertex<8>> + use<'s, 'a> {
        let mv = camera.view.mul(model);
        self.builder(model, camera, light, move |i, v| self.bump_vary(&mv, i, v))
    }

    /// The vertex of [`LitMesh::phong_triangles`] at an index, built on demand (see
    /// [`LitMesh::bump_vertex`]).
    pub fn phong_vertex<'s>(
        &'s self,
        model: &Mat4,
        camera: &Camera,
        light: &'s PixelLight,
    ) -> impl Fn(usize) -> Option<Vertex<8>> + use<'s, 'a> {
        self.builder(model, camera, light, Self::phong_vary)
    }

    /// The triangles' vertex indices.
    pub fn indices(&self) -> &'a [[u16; 3]] {
        self.indices
    }

    /// The vertex positions (model space).
    pub fn positions(&self) -> &'a [Vec3] {
        self.positions
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
        let m = *material;
        self.each(
            self.builder(model, camera, light, move |_, v| {
                Self::gouraud_vary(&m, base, v)
            }),
            emit,
        );
    }

    /// [`LitMesh::gouraud_triangles`]' vertices, each built once, into `out` (one per
    /// position); returns how many overflowed (see [`LitMesh::indexed`]).
    ///
    /// # Errors
    /// [`Error::WrongLength`] when `out` is not one per position.
    pub fn gouraud_vertices(
        &self,
        model: &Mat4,
        camera: &Camera,
        light: &PixelLight,
        material: &Material<'_>,
        base: u16,
        out: &mut [Vertex<3>],
    ) -> Result<usize, Error> {
        let m = *material;
        self.fill(
            self.builder(model, camera, light, move |_, v| {
                Self::gouraud_vary(&m, base, v)
            }),
            out,
        )
    }
}
