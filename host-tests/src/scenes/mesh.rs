//! The benchmark meshes (docs/scenes.md) in f64, in object space, and the shared
//! procedural texture `T(w, h)`. Every triangle is counter-clockwise seen
//! from outside (its geometric normal points outwards): front faces in GL.

use super::math::cross;
use crate::reference::RefTexture;

/// An indexed triangle mesh with per-vertex normal and uv.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshDesc {
    /// Object-space positions.
    pub positions: Vec<[f64; 3]>,
    /// Unit normals, one per position.
    pub normals: Vec<[f64; 3]>,
    /// Normalised texture coordinates, one per position.
    pub uvs: Vec<[f64; 2]>,
    /// Triangles, counter-clockwise seen from outside.
    pub indices: Vec<[u16; 3]>,
}

/// Procedural texture `T(w, h)`, RGB565, row y = 0 (t = 0) first.
///
/// Texel (x, y): `r8 = x * 256 / w`, `g8 = y * 256 / h`, `b8 = 255` if
/// `x / 16 + y / 16` is odd else 0 (integer division). THE SHARED DEFINITION
/// of the RGB565 conversion is rounding to nearest:
/// `r5 = (r8 * 31 + 127) / 255`, `g6 = (g8 * 63 + 127) / 255`,
/// `b5 = (b8 * 31 + 127) / 255`, packed `r5 << 11 | g6 << 5 | b5`.
/// Border colour: 0 (black).
pub fn procedural_texture(w: u32, h: u32) -> RefTexture {
    let mut texels = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let r8 = (x * 256 / w) as u8;
            let g8 = (y * 256 / h) as u8;
            let b8: u8 = if (x / 16 + y / 16) % 2 == 1 { 255 } else { 0 };
            texels.push(rgb888_to_rgb565(r8, g8, b8));
        }
    }
    RefTexture {
        width: w,
        height: h,
        texels,
        border: 0,
    }
}

/// The shared 8-bit to RGB565 conversion (round to nearest), see
/// [`procedural_texture`].
pub fn rgb888_to_rgb565(r8: u8, g8: u8, b8: u8) -> u16 {
    let c = |v: u8, max: u32| (u32::from(v) * max + 127) / 255;
    ((c(r8, 31) << 11) | (c(g8, 63) << 5) | c(b8, 31)) as u16
}

/// Cube of side 2 centred at the origin: 6 faces x 4 vertices (per-face
/// outward normals), 12 triangles, each face mapped with uv (0,0)-(1,1).
///
/// A face with outward normal `n` uses tangents `t1`, `t2` with
/// `t1 x t2 = n`; corner uv (0,0) is at `n - t1 - t2`, u grows along `t1`,
/// v along `t2`.
pub fn cube_mesh() -> MeshDesc {
    // (normal, t1, t2) with t1 x t2 = normal.
    let faces: [([f64; 3], [f64; 3], [f64; 3]); 6] = [
        ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
        ([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]),
        ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
    ];
    let mut m = MeshDesc {
        positions: Vec::new(),
        normals: Vec::new(),
        uvs: Vec::new(),
        indices: Vec::new(),
    };
    for (n, t1, t2) in faces {
        debug_assert_eq!(cross(t1, t2), n);
        let base = m.positions.len() as u16;
        for (a, b) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            m.positions
                .push(core::array::from_fn(|k| n[k] + a * t1[k] + b * t2[k]));
            m.normals.push(n);
            m.uvs.push([(a + 1.0) / 2.0, (b + 1.0) / 2.0]);
        }
        m.indices.push([base, base + 1, base + 2]);
        m.indices.push([base, base + 2, base + 3]);
    }
    m
}

/// UV sphere of `radius` centred at the origin, `stacks x slices`.
///
/// Vertex (i, j), i in 0..=stacks, j in 0..=slices, at polar angle
/// `θ = π i / stacks` from +y and azimuth `φ = 2π j / slices`, position
/// `r (sin θ cos φ, cos θ, -sin θ sin φ)` (φ grows like a right-handed turn
/// about +y: from +x towards -z), uv `(j / slices, i / stacks)`, normal =
/// position / r. Pole rows give one triangle per slice, other rows two.
pub fn sphere_mesh(radius: f64, stacks: u16, slices: u16) -> MeshDesc {
    let mut m = MeshDesc {
        positions: Vec::new(),
        normals: Vec::new(),
        uvs: Vec::new(),
        indices: Vec::new(),
    };
    for i in 0..=stacks {
        let theta = core::f64::consts::PI * f64::from(i) / f64::from(stacks);
        for j in 0..=slices {
            let phi = 2.0 * core::f64::consts::PI * f64::from(j) / f64::from(slices);
            let n = [
                theta.sin() * phi.cos(),
                theta.cos(),
                -theta.sin() * phi.sin(),
            ];
            m.positions.push(n.map(|c| c * radius));
            m.normals.push(n);
            m.uvs.push([
                f64::from(j) / f64::from(slices),
                f64::from(i) / f64::from(stacks),
            ]);
        }
    }
    let id = |i: u16, j: u16| i * (slices + 1) + j;
    for i in 0..stacks {
        for j in 0..slices {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            if i == 0 {
                m.indices.push([a, b, c]);
            } else if i == stacks - 1 {
                m.indices.push([a, b, d]);
            } else {
                m.indices.push([a, b, c]);
                m.indices.push([a, c, d]);
            }
        }
    }
    m
}

/// The floor quad: plane y = -1, x in [-50, 50], z in [-1, -100], uv =
/// `((x + 50) / 2, (-z - 1) / 2)`, normal +y, 2 triangles.
pub fn floor_mesh() -> MeshDesc {
    let corners = [[-50.0, -1.0], [50.0, -1.0], [50.0, -100.0], [-50.0, -100.0]];
    MeshDesc {
        positions: corners.iter().map(|&[x, z]| [x, -1.0, z]).collect(),
        normals: vec![[0.0, 1.0, 0.0]; 4],
        uvs: corners
            .iter()
            .map(|&[x, z]| [(x + 50.0) / 2.0, (-z - 1.0) / 2.0])
            .collect(),
        indices: vec![[0, 1, 2], [0, 2, 3]],
    }
}
