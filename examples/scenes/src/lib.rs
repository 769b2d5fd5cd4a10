//! The benchmark scenes of `docs/scenes.md` (cube, sphere, floor) and their procedural texture,
//! built in fixed point, for examples, benchmarks, tests and firmware.
//!
//! The numbers are fixed so that results compare with other renderers: a 320 x 240 frame,
//! 45 degree vertical field of view, aspect 4:3, near 0.5, far 20 (200 for the floor), the
//! camera at the origin looking down `-z`, lighting `0.3 + 0.7 max(0, n . l)` with
//! `l = normalize(-0.4, 0.6, 1.0)` in view space. Every triangle is counter-clockwise seen
//! from outside. Nothing here allocates: meshes are written into caller-provided arrays.

#![no_std]
#![forbid(unsafe_code)]

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::Rgb565;

use fixel::color::rgb888_to_565;
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::scene::Camera;
use fixel::Error;

pub mod displaced;

/// Frame width of every benchmark scene.
pub const WIDTH: u32 = 320;
/// Frame height of every benchmark scene.
pub const HEIGHT: u32 = 240;

/// Fills `out` (`w * h` long, row 0 first) with the procedural texture `T(w, h)`:
/// `r = x * 256 / w`, `g = y * 256 / h`, `b = 255` on odd 16 x 16 checks, each channel
/// rounded to RGB565 as `(c * max + 127) / 255`.
pub fn checker_texture(w: u32, h: u32, out: &mut [Rgb565]) -> Result<(), Error> {
    let need = w as usize * h as usize;
    if out.len() != need {
        return Err(Error::WrongLength {
            expected: need,
            actual: out.len(),
        });
    }
    for (i, px) in out.iter_mut().enumerate() {
        let (x, y) = ((i as u32) % w.max(1), (i as u32) / w.max(1));
        let r = (x * 256 / w) as u8;
        let g = (y * 256 / h) as u8;
        let b = if (x / 16 + y / 16) % 2 == 1 { 255 } else { 0 };
        *px = Rgb565::from(RawU16::new(rgb888_to_565(r, g, b)));
    }
    Ok(())
}

/// The camera of the benchmark scenes, with the given far plane (20, or 200 for the floor).
pub fn camera(far: i32) -> Camera {
    let fovy = Angle::from_degrees(Fx::from_num(45));
    let aspect = Fx::from_bits(87381); // 4/3
                                       // Valid constants: this cannot fail.
    Camera::perspective(
        fovy,
        aspect,
        Fx::from_bits(1 << 15),
        Fx::from_num(far.clamp(1, 30000)),
    )
    .unwrap_or(Camera {
        view: Mat4::IDENTITY,
        projection: Mat4::IDENTITY,
    })
}

/// Radians (as I16F16 bits) to an [`Angle`].
fn rad(bits: i32) -> Angle {
    Angle::from_radians(Fx::from_bits(bits))
}

/// Radians in thousandths to I16F16 bits, rounded.
const fn milli(m: i32) -> i32 {
    ((m as i64 * 65536 + 500) / 1000) as i32
}

/// A mesh stored in arrays of fixed size.
#[derive(Clone, Debug)]
pub struct MeshData<const V: usize, const T: usize> {
    /// Model-space positions.
    pub positions: [Vec3; V],
    /// Unit normals.
    pub normals: [Vec3; V],
    /// Normalized texture coordinates.
    pub uvs: [[Fx; 2]; V],
    /// Triangles, counter-clockwise from outside.
    pub indices: [[u16; 3]; T],
}

impl<const V: usize, const T: usize> MeshData<V, T> {
    /// The mesh as a [`fixel::scene::Mesh`].
    pub fn mesh(&self) -> Result<fixel::scene::Mesh<'_>, Error> {
        fixel::scene::Mesh::new(
            &self.positions,
            Some(&self.normals),
            &self.uvs,
            &self.indices,
        )
    }
}

/// The cube: side 2, 24 vertices (4 per face), 12 triangles, uv (0,0)-(1,1) per face.
pub fn cube() -> MeshData<24, 12> {
    // (normal, t1, t2) with t1 x t2 = normal.
    const FACES: [([i32; 3], [i32; 3], [i32; 3]); 6] = [
        ([0, 0, 1], [1, 0, 0], [0, 1, 0]),
        ([0, 0, -1], [-1, 0, 0], [0, 1, 0]),
        ([1, 0, 0], [0, 0, -1], [0, 1, 0]),
        ([-1, 0, 0], [0, 0, 1], [0, 1, 0]),
        ([0, 1, 0], [1, 0, 0], [0, 0, -1]),
        ([0, -1, 0], [1, 0, 0], [0, 0, 1]),
    ];
    let mut m = MeshData {
        positions: [Vec3::ZERO; 24],
        normals: [Vec3::ZERO; 24],
        uvs: [[Fx::ZERO; 2]; 24],
        indices: [[0; 3]; 12],
    };
    for (f, (n, t1, t2)) in FACES.iter().enumerate() {
        for (k, (a, b)) in [(-1, -1), (1, -1), (1, 1), (-1, 1)].into_iter().enumerate() {
            let i = f * 4 + k;
            let c = |j: usize| n[j] + a * t1[j] + b * t2[j];
            m.positions[i] = Vec3::from_num(c(0), c(1), c(2));
            m.normals[i] = Vec3::from_num(n[0], n[1], n[2]);
            m.uvs[i] = [Fx::from_num((a + 1) / 2), Fx::from_num((b + 1) / 2)];
        }
        let base = (f * 4) as u16;
        m.indices[f * 2] = [base, base + 1, base + 2];
        m.indices[f * 2 + 1] = [base, base + 2, base + 3];
    }
    m
}

/// Model matrix of cube frame `i`: `T(0, 0, -4) * Rx(0.3 + 0.031 i) * Ry(0.7 + 0.05 i)`.
pub fn cube_model(i: u32) -> Mat4 {
    let i = i as i32;
    let ry = rad(milli(700 + 50 * i));
    let rx = rad(milli(300 + 31 * i));
    Mat4::translation(Vec3::from_num(0, 0, -4)) * (Mat4::rotation_x(rx) * Mat4::rotation_y(ry))
}

/// Vertices of the benchmark sphere: 25 stacks by 49 slices.
pub const SPHERE_VERTICES: usize = 25 * 49;
/// Triangles of the benchmark sphere: 48 at each pole row, 96 in each of the 22 others.
pub const SPHERE_TRIANGLES: usize = 2208;

/// The UV sphere: radius 1.5, 24 stacks by 48 slices, vertex `(i, j)` at polar angle
/// `pi i / 24` from `+y` and azimuth `2 pi j / 48`, uv = `(j / 48, i / 24)`.
pub fn sphere() -> MeshData<SPHERE_VERTICES, SPHERE_TRIANGLES> {
    uv_sphere(24, 48)
}

/// Vertices of [`fine_sphere`]: 65 stacks by 81 slices.
pub const FINE_SPHERE_VERTICES: usize = 65 * 81;
/// Triangles of [`fine_sphere`]: 10,080 (the geometry benchmark's ~10k mesh).
pub const FINE_SPHERE_TRIANGLES: usize = 10080;

/// The geometry benchmark's large mesh: the same sphere (radius 1.5) with 64 stacks by 80
/// slices, 5,265 vertices and 10,080 triangles.
pub fn fine_sphere() -> MeshData<FINE_SPHERE_VERTICES, FINE_SPHERE_TRIANGLES> {
    uv_sphere(64, 80)
}

/// A UV sphere of radius 1.5 with `stacks` by `slices` quads: vertex `(i, j)` at polar
/// angle `pi i / stacks` from `+y` and azimuth `2 pi j / slices`, uv =
/// `(j / slices, i / stacks)`; one triangle per slice at each pole row, two elsewhere.
/// `V` must be `(stacks + 1) (slices + 1)` and `T` `2 slices (stacks - 1)`; what does not
/// fit is left out (never a panic).
pub fn uv_sphere<const V: usize, const T: usize>(stacks: u16, slices: u16) -> MeshData<V, T> {
    let mut m = MeshData {
        positions: [Vec3::ZERO; V],
        normals: [Vec3::ZERO; V],
        uvs: [[Fx::ZERO; 2]; V],
        indices: [[0; 3]; T],
    };
    let (stacks, slices) = (stacks.max(2), slices.max(3));
    let radius = Fx::from_num(1.5);
    for i in 0..=stacks {
        // pi i / stacks = i / (2 stacks) turn; 2^-32-turn angles keep vertices on the
        // exact sub-pixel.
        let (st, ct) = sin_cos_fx(u32::from(i), 2 * u32::from(stacks));
        for j in 0..=slices {
            let (sp, cp) = sin_cos_fx(u32::from(j), u32::from(slices));
            let n = Vec3::new(st.saturating_mul(cp), ct, -st.saturating_mul(sp));
            let k = usize::from(i) * (usize::from(slices) + 1) + usize::from(j);
            if k >= V {
                continue;
            }
            m.normals[k] = n;
            m.positions[k] = n.scale(radius);
            m.uvs[k] = [
                Fx::from_bits(((i64::from(j) << 16) / i64::from(slices)) as i32),
                Fx::from_bits(((i64::from(i) << 16) / i64::from(stacks)) as i32),
            ];
        }
    }
    let id = |i: u16, j: u16| i.wrapping_mul(slices + 1).wrapping_add(j);
    let mut t = 0;
    let mut put = |tri: [u16; 3]| {
        if let Some(slot) = m.indices.get_mut(t) {
            *slot = tri;
        }
        t += 1;
    };
    for i in 0..stacks {
        for j in 0..slices {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            if i == 0 {
                put([a, b, c]);
            } else if i == stacks - 1 {
                put([a, b, d]);
            } else {
                put([a, b, c]);
                put([a, c, d]);
            }
        }
    }
    m
}

/// Sine and cosine of `num / den` turn, I16F16, through the 2^-32-turn Q30 table.
fn sin_cos_fx(num: u32, den: u32) -> (Fx, Fx) {
    let t = ((u64::from(num) << 32) + u64::from(den) / 2) / u64::from(den.max(1));
    let (s, c) = fixel::math::sin_cos_q30(t as u32);
    let fx = |q: i32| Fx::from_bits((q + (1 << 13)) >> 14);
    (fx(s), fx(c))
}

/// Model matrix of sphere frame `i`: `T(0, 0, -5) * Ry(0.02 i)`.
pub fn sphere_model(i: u32) -> Mat4 {
    Mat4::translation(Vec3::from_num(0, 0, -5)) * Mat4::rotation_y(rad(milli(20 * i as i32)))
}

/// The floor: a quad on `y = -1`, x in `[-50, 50]`, z in `[-100, -1]`,
/// uv = `((x + 50) / 2, (-z - 1) / 2)`; model = identity, far plane 200.
pub fn floor() -> MeshData<4, 2> {
    let corners = [(-50, -1), (50, -1), (50, -100), (-50, -100)];
    let mut m = MeshData {
        positions: [Vec3::ZERO; 4],
        normals: [Vec3::from_num(0, 1, 0); 4],
        uvs: [[Fx::ZERO; 2]; 4],
        indices: [[0, 1, 2], [0, 2, 3]],
    };
    for (k, (x, z)) in corners.into_iter().enumerate() {
        m.positions[k] = Vec3::from_num(x, -1, z);
        m.uvs[k] = [Fx::from_num(x + 50) / 2, Fx::from_num(-z - 1) / 2];
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn meshes_are_valid() {
        assert!(cube().mesh().is_ok());
        assert!(floor().mesh().is_ok());
        let s = sphere();
        assert_eq!(s.mesh().unwrap().triangles(), SPHERE_TRIANGLES);
    }
}

pub mod bricks;
pub mod noise;
pub mod shadow;
pub mod surface;
