//! The f64 reference for displacement mapping, written from the formulas;
//! it shares only data (the mesh, the height bytes) and the documented conventions (the
//! order of the children and of the new vertices, which copies are welded) with fixel.
//!
//! ```text
//! subdivision   (a, b, c) -> (a, ab, ca) (ab, b, bc) (ca, bc, c) (ab, bc, ca)
//!               p_ab = (p_a + p_b) / 2,  uv_ab = (uv_a + uv_b) / 2,
//!               n_ab = (n_a + n_b) / |n_a + n_b|
//! displacement  p' = p + n · s · (h(uv + o) − bias)
//!               h = bilinear height / 256 (texel centres at (i + 0.5) / size, repeat)
//! normals       n' = Σ (p1 − p0) × (p2 − p0) / |Σ …|   (over a vertex's triangles;
//!               the undisplaced normal when the sum is zero)
//! ```
//!
//! Vertices at the same undisplaced position (seam and pole copies) are welded: each takes
//! the first copy's displaced position and the normal summed over all copies' triangles.

use std::collections::HashMap;

/// An indexed triangle mesh in f64.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RefMesh {
    pub positions: Vec<[f64; 3]>,
    pub normals: Vec<[f64; 3]>,
    pub uvs: Vec<[f64; 2]>,
    pub indices: Vec<[usize; 3]>,
}

/// A height map: `width x height` bytes, row 0 at `t = 0`.
#[derive(Clone, Debug)]
pub struct RefHeights<'a> {
    pub bytes: &'a [u8],
    pub width: usize,
    pub height: usize,
}

impl RefHeights<'_> {
    /// The bilinear height at `(s, t)` (1.0 = the whole map, repeating), as a fraction of
    /// 256 steps.
    pub fn at(&self, s: f64, t: f64) -> f64 {
        let (x, y) = (s * self.width as f64 - 0.5, t * self.height as f64 - 0.5);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let texel = |i: f64, j: f64| {
            let i = (i as i64).rem_euclid(self.width as i64) as usize;
            let j = (j as i64).rem_euclid(self.height as i64) as usize;
            f64::from(self.bytes[j * self.width + i])
        };
        let top = texel(x0, y0) * (1.0 - fx) + texel(x0 + 1.0, y0) * fx;
        let bottom = texel(x0, y0 + 1.0) * (1.0 - fx) + texel(x0 + 1.0, y0 + 1.0) * fx;
        (top * (1.0 - fy) + bottom * fy) / 256.0
    }
}

pub fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub fn length(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// `v / |v|`, or `None` for the zero vector.
pub fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
    let l = length(v);
    (l > 0.0).then(|| v.map(|c| c / l))
}

/// One level of midpoint subdivision (new vertices in the order their edges are first met:
/// triangle by triangle, edges ab, bc, ca; an edge from a vertex to itself is that vertex).
pub fn subdivide_once(m: &RefMesh) -> RefMesh {
    let mut out = m.clone();
    out.indices.clear();
    let mut mids: HashMap<(usize, usize), usize> = HashMap::new();
    let has_normals = !m.normals.is_empty();
    let mut mid = |out: &mut RefMesh, a: usize, b: usize| -> usize {
        if a == b {
            return a;
        }
        *mids.entry((a.min(b), a.max(b))).or_insert_with(|| {
            let p = add(m.positions[a], m.positions[b]).map(|c| c / 2.0);
            out.positions.push(p);
            let (ua, ub) = (m.uvs[a], m.uvs[b]);
            out.uvs.push([(ua[0] + ub[0]) / 2.0, (ua[1] + ub[1]) / 2.0]);
            if has_normals {
                let n = unit(add(m.normals[a], m.normals[b])).unwrap_or(m.normals[a]);
                out.normals.push(n);
            }
            out.positions.len() - 1
        })
    };
    let mut children = Vec::with_capacity(4 * m.indices.len());
    for &[a, b, c] in &m.indices {
        let ab = mid(&mut out, a, b);
        let bc = mid(&mut out, b, c);
        let ca = mid(&mut out, c, a);
        children.push([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
    }
    out.indices = children.into_iter().flatten().collect();
    out
}

/// `levels` levels of [`subdivide_once`].
pub fn subdivide(m: &RefMesh, levels: u32) -> RefMesh {
    let mut m = m.clone();
    for _ in 0..levels {
        m = subdivide_once(&m);
    }
    m
}

/// For each vertex, the first vertex at exactly the same position.
pub fn twins(positions: &[[f64; 3]]) -> Vec<usize> {
    let mut first: HashMap<[u64; 3], usize> = HashMap::new();
    positions
        .iter()
        .enumerate()
        .map(|(i, p)| *first.entry(p.map(f64::to_bits)).or_insert(i))
        .collect()
}

/// How a height map moves vertices: `p' = p + n · scale · (h(uv + offset) − bias)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefDisplacement {
    pub scale: f64,
    pub bias: f64,
    pub offset: [f64; 2],
}

/// The displaced positions of `m` (welded copies take the first copy's).
pub fn displace_positions(m: &RefMesh, map: &RefHeights<'_>, d: &RefDisplacement) -> Vec<[f64; 3]> {
    let tw = twins(&m.positions);
    let mut out: Vec<[f64; 3]> = Vec::with_capacity(m.positions.len());
    for i in 0..m.positions.len() {
        if tw[i] < i {
            let p = out[tw[i]];
            out.push(p);
            continue;
        }
        let uv = m.uvs[i];
        let h = map.at(uv[0] + d.offset[0], uv[1] + d.offset[1]);
        let dist = d.scale * (h - d.bias);
        out.push(add(m.positions[i], m.normals[i].map(|c| c * dist)));
    }
    out
}

/// Area-weighted vertex normals of `positions` / `indices`, summed over welded copies
/// (`twins` from the undisplaced mesh); `fallback` where the sum is zero. Also returns
/// each vertex's sum length relative to the largest face's cross product (how well
/// conditioned the direction is).
pub fn normals(
    positions: &[[f64; 3]],
    indices: &[[usize; 3]],
    fallback: &[[f64; 3]],
    twins: &[usize],
) -> (Vec<[f64; 3]>, Vec<f64>) {
    let mut sum = vec![[0.0; 3]; positions.len()];
    let mut largest = 0.0f64;
    for &[a, b, c] in indices {
        let f = cross(
            sub(positions[b], positions[a]),
            sub(positions[c], positions[a]),
        );
        largest = largest.max(length(f));
        for i in [a, b, c] {
            sum[twins[i]] = add(sum[twins[i]], f);
        }
    }
    let n = (0..positions.len())
        .map(|i| unit(sum[twins[i]]).unwrap_or(fallback[twins[i]]))
        .collect();
    let cond = (0..positions.len())
        .map(|i| length(sum[twins[i]]) / largest.max(f64::MIN_POSITIVE))
        .collect();
    (n, cond)
}

/// The displaced mesh: subdivided, moved, normals recomputed.
pub fn displaced(
    m: &RefMesh,
    levels: u32,
    map: &RefHeights<'_>,
    d: &RefDisplacement,
) -> (RefMesh, Vec<f64>) {
    let fine = subdivide(m, levels);
    let tw = twins(&fine.positions);
    let positions = displace_positions(&fine, map, d);
    let (normals, cond) = normals(&positions, &fine.indices, &fine.normals, &tw);
    (
        RefMesh {
            positions,
            normals,
            uvs: fine.uvs,
            indices: fine.indices,
        },
        cond,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_level_of_a_triangle() {
        let m = RefMesh {
            positions: vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]],
            normals: vec![[0.0, 0.0, 1.0]; 3],
            uvs: vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
            indices: vec![[0, 1, 2]],
        };
        let f = subdivide_once(&m);
        assert_eq!(f.positions[3], [1.0, 0.0, 0.0]);
        assert_eq!(f.positions[5], [0.0, 1.0, 0.0]);
        assert_eq!(f.indices[3], [3, 4, 5]);
        let bytes = [0u8, 128, 0, 128];
        let map = RefHeights {
            bytes: &bytes,
            width: 2,
            height: 2,
        };
        assert_eq!(map.at(0.75, 0.25), 0.5);
        assert_eq!(map.at(0.5, 0.5), 0.25);
    }
}
