//! A [`UvMapping`] applied to a mesh: texture coordinates per vertex, with the seam and the
//! poles fixed per triangle (the mappings themselves, planar, cylindrical and spherical, are
//! [`shading::uv_mapping`](crate::shading::uv_mapping)'s).
//!
//! # Seams and poles
//!
//! A triangle that straddles the seam has corners near `u = 1` and near `u = 0`: drawn as
//! they are, the whole texture would be squeezed, backwards, into it. [`map_mesh`] handles
//! it per triangle: when a triangle's `u` spans more than one half, the corners below one
//! half get `u + 1` (a repeating wrap samples the same texels). A corner on the axis (a
//! pole: `right = front = 0`, where every `u` is the same point) gets the mean `u` of the
//! triangle's other corners. A corner whose `u` changed in a triangle is a new vertex (a copy
//! of the position and normal), so [`map_mesh`] writes into caller storage with room for
//! them: the source's vertex count plus, for a closed mesh around the axis, about one column
//! of the seam and one copy per triangle at each pole ([`map_mesh_capacity`] gives the exact
//! count).
//!
//! ```
//! use fixel::math::{fx, Fx, Vec3};
//! use fixel::scene::{map_mesh, Axis, MeshStorage, UvMapping};
//!
//! // A square pyramid around +y: its apex is a pole, its back faces straddle the seam.
//! let positions = [
//!     Vec3::from_num(0, 1, 0),
//!     Vec3::from_num(1, 0, 1), Vec3::from_num(1, 0, -1),
//!     Vec3::from_num(-1, 0, -1), Vec3::from_num(-1, 0, 1),
//! ];
//! let indices = [[0u16, 4, 1], [0, 1, 2], [0, 2, 3], [0, 3, 4]];
//! let mapping = UvMapping::Cylindrical { center: Vec3::ZERO, axis: Axis::Y, top: fx(1), bottom: fx(0) };
//! let (mut p, mut uv, mut ix) = ([Vec3::ZERO; 16], [[Fx::ZERO; 2]; 16], [[0u16; 3]; 4]);
//! let storage = MeshStorage { positions: &mut p, normals: None, uvs: &mut uv, indices: &mut ix };
//! let mesh = map_mesh(&mapping, &positions, None, &indices, storage)?;
//! assert!(mesh.vertices() > 5); // seam and apex copies
//! # Ok::<(), fixel::Error>(())
//! ```

use super::Mesh;
use crate::math::{Fx, Vec3};
use crate::shading::uv_mapping::{UvAt, UvGenerator, UvMapping};
use crate::Error;

/// Caller storage for [`map_mesh`]'s output mesh.
#[derive(Debug)]
pub struct MeshStorage<'a> {
    /// Positions (at least the source's count plus the seam and pole copies).
    pub positions: &'a mut [Vec3],
    /// Normals, when the source has them (as long as `positions`).
    pub normals: Option<&'a mut [Vec3]>,
    /// Texture coordinates (as long as `positions`).
    pub uvs: &'a mut [[Fx; 2]],
    /// Triangles (at least the source's count).
    pub indices: &'a mut [[u16; 3]],
}

/// The texture coordinates of one triangle's corners after the seam and pole rules, from
/// the per-vertex `(uv, on the axis)`.
fn fix_triangle(mut c: [([Fx; 2], bool); 3]) -> [[Fx; 2]; 3] {
    let half = 1 << 15;
    let us = c.map(|(uv, pole)| (uv[0].to_bits(), pole));
    let lo = us.iter().filter(|u| !u.1).map(|u| u.0).min();
    let hi = us.iter().filter(|u| !u.1).map(|u| u.0).max();
    if let (Some(lo), Some(hi)) = (lo, hi) {
        if hi - lo > half {
            for (uv, pole) in c.iter_mut() {
                if !*pole && uv[0].to_bits() < half {
                    uv[0] = Fx::from_bits(uv[0].to_bits() + (1 << 16));
                }
            }
        }
    }
    let (sum, n) = c
        .iter()
        .filter(|(_, pole)| !pole)
        .fold((0i64, 0i64), |(s, n), (uv, _)| {
            (s + i64::from(uv[0].to_bits()), n + 1)
        });
    if n > 0 {
        let mean = Fx::from_bits(((2 * sum + n) / (2 * n)) as i32);
        for (uv, pole) in c.iter_mut() {
            if *pole {
                uv[0] = mean;
            }
        }
    }
    c.map(|(uv, _)| uv)
}

/// Enough vertices for [`map_mesh`] with this mesh and mapping: the source's vertices plus
/// one per seam or pole corner (an upper bound: corners that come out equal share a copy).
pub fn map_mesh_capacity(
    mapping: &UvMapping,
    positions: &[Vec3],
    indices: &[[u16; 3]],
) -> Result<usize, Error> {
    map_mesh_capacity_with(mapping, positions, None, indices)
}

/// [`map_mesh_capacity`] for any [`UvGenerator`] (`normals` as for [`map_mesh_with`]).
pub fn map_mesh_capacity_with<G: UvGenerator>(
    generator: &G,
    positions: &[Vec3],
    normals: Option<&[Vec3]>,
    indices: &[[u16; 3]],
) -> Result<usize, Error> {
    let m = generator.ready()?;
    let mut extra = 0usize;
    if m.wraps() {
        for tri in indices {
            let c = tri.map(|i| {
                let i = usize::from(i);
                match positions.get(i) {
                    Some(&p) => m.at(p, normal_at(normals, i)),
                    None => ([Fx::ZERO; 2], false),
                }
            });
            let fixed = fix_triangle(c);
            extra += (0..3).filter(|&k| fixed[k] != c[k].0).count();
        }
    }
    Ok(positions.len() + extra)
}

fn normal_at(normals: Option<&[Vec3]>, i: usize) -> Vec3 {
    normals
        .and_then(|n| n.get(i))
        .copied()
        .unwrap_or(Vec3::ZERO)
}

/// [`map_mesh_with`] for a [`UvMapping`].
pub fn map_mesh<'a>(
    mapping: &UvMapping,
    positions: &[Vec3],
    normals: Option<&[Vec3]>,
    indices: &[[u16; 3]],
    out: MeshStorage<'a>,
) -> Result<Mesh<'a>, Error> {
    map_mesh_with(mapping, positions, normals, indices, out)
}

/// Generates texture coordinates for a mesh with `generator`, handling the seam and the
/// poles per triangle (see the module docs), into `out`; returns the mesh over `out`. The
/// generator sees each vertex's normal (zero when `normals` is `None`).
///
/// Errors: the source is invalid (as [`Mesh::new`]), the mapping is degenerate, or `out`
/// is too small ([`Error::CapacityExceeded`] with the size it needs; see
/// [`map_mesh_capacity`]), or the copies push the vertex count past what a `u16` index
/// reaches ([`Error::MeshTooLarge`]).
pub fn map_mesh_with<'a, G: UvGenerator>(
    generator: &G,
    positions: &[Vec3],
    normals: Option<&[Vec3]>,
    indices: &[[u16; 3]],
    out: MeshStorage<'a>,
) -> Result<Mesh<'a>, Error> {
    let n = positions.len();
    if let Some(nm) = normals {
        if nm.len() != n {
            return Err(Error::WrongLength {
                expected: n,
                actual: nm.len(),
            });
        }
    }
    crate::geometry::mesh_checks::check_indices(indices, n)?;
    let m = generator.ready()?;
    let capacity = || map_mesh_capacity_with(generator, positions, normals, indices);
    let MeshStorage {
        positions: out_p,
        normals: out_n,
        uvs: out_uv,
        indices: out_i,
    } = out;
    let cap = out_p.len().min(out_uv.len()).min(match (&out_n, normals) {
        (Some(o), Some(_)) => o.len(),
        // Normals are copied only when both the source and the storage have them.
        _ => usize::MAX,
    });
    if cap < n || out_i.len() < indices.len() {
        return Err(Error::CapacityExceeded {
            capacity: capacity()?,
        });
    }
    let mut out_n = out_n;
    for i in 0..n {
        out_p[i] = positions[i];
        out_uv[i] = m.at(positions[i], normal_at(normals, i)).0;
        if let (Some(o), Some(src)) = (out_n.as_deref_mut(), normals) {
            o[i] = src[i];
        }
    }
    let mut count = n;
    for (t, tri) in indices.iter().enumerate() {
        let mut new_tri = *tri;
        if m.wraps() {
            let c = tri.map(|i| {
                let i = usize::from(i);
                m.at(positions[i], normal_at(normals, i))
            });
            let fixed = fix_triangle(c);
            for k in 0..3 {
                if fixed[k] == c[k].0 {
                    continue;
                }
                let src = usize::from(tri[k]);
                let normal = normals.map(|nm| nm[src]);
                // Reuse an earlier copy of this vertex with the same coordinates.
                let found = (n..count).find(|&j| {
                    out_p[j] == positions[src]
                        && out_uv[j] == fixed[k]
                        && match (out_n.as_deref(), normal) {
                            (Some(o), Some(nv)) => o[j] == nv,
                            _ => true,
                        }
                });
                let j = match found {
                    Some(j) => j,
                    None => {
                        if count >= cap {
                            return Err(Error::CapacityExceeded {
                                capacity: capacity()?,
                            });
                        }
                        if count >= 1 << 16 {
                            return Err(Error::MeshTooLarge {
                                what: "vertices (with seam and pole copies)",
                                count: capacity()?,
                                limit: 1 << 16,
                            });
                        }
                        out_p[count] = positions[src];
                        out_uv[count] = fixed[k];
                        if let (Some(o), Some(nv)) = (out_n.as_deref_mut(), normal) {
                            o[count] = nv;
                        }
                        count += 1;
                        count - 1
                    }
                };
                new_tri[k] = j as u16;
            }
        }
        out_i[t] = new_tri;
    }
    // The storage, now written, is lent out for the mesh's lifetime.
    let (out_p, out_uv, out_i): (&'a [Vec3], &'a [[Fx; 2]], &'a [[u16; 3]]) =
        (out_p, out_uv, out_i);
    let nm: Option<&'a [Vec3]> = match out_n {
        Some(o) if normals.is_some() => Some(&o[..count]),
        _ => None,
    };
    Mesh::new(
        &out_p[..count],
        nm,
        &out_uv[..count],
        &out_i[..indices.len()],
    )
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::math::fx;
    use crate::shading::uv_mapping::Axis;
    use crate::test_scenes as demo;
    use std::vec;

    const CYL: UvMapping = UvMapping::Cylindrical {
        center: Vec3::ZERO,
        axis: Axis::Y,
        top: Fx::from_bits(1 << 16),
        bottom: Fx::from_bits(-(1 << 16)),
    };

    fn u_of(m: &UvMapping, x: f64, y: f64, z: f64) -> f64 {
        m.uv(Vec3::from_num(x, y, z)).unwrap()[0].to_num::<f64>()
    }

    #[test]
    fn front_is_the_middle_column_and_u_grows_to_the_right() {
        assert!((u_of(&CYL, 0.0, 0.0, 1.0) - 0.5).abs() < 1e-4);
        assert!((u_of(&CYL, 1.0, 0.0, 0.0) - 0.75).abs() < 1e-4);
        assert!((u_of(&CYL, -1.0, 0.0, 0.0) - 0.25).abs() < 1e-4);
        let v = |y: f64| CYL.uv(Vec3::from_num(1.0, y, 0.0)).unwrap()[1].to_num::<f64>();
        assert!(v(1.0).abs() < 1e-4 && (v(-1.0) - 1.0).abs() < 1e-4 && (v(0.0) - 0.5).abs() < 1e-4);
        let sph = UvMapping::Spherical {
            center: Vec3::ZERO,
            axis: Axis::Y,
        };
        let v = |p: Vec3| sph.uv(p).unwrap()[1].to_num::<f64>();
        assert!(v(Vec3::from_num(0, 2, 0)).abs() < 1e-4);
        assert!((v(Vec3::from_num(0, -2, 0)) - 1.0).abs() < 1e-4);
        assert!((v(Vec3::from_num(1, 1, 0)) - 0.25).abs() < 1e-3);
    }

    #[test]
    fn degenerate_cylinder_is_refused() {
        let m = UvMapping::Cylindrical {
            center: Vec3::ZERO,
            axis: Axis::Y,
            top: fx(1),
            bottom: fx(1),
        };
        assert!(matches!(m.uv(Vec3::ZERO), Err(Error::OutOfRange { .. })));
    }

    /// The demo sphere mapped spherically: no triangle spans more than half the texture,
    /// the poles take their neighbours' mean, and the capacity is what was used.
    #[test]
    fn seam_and_poles_are_fixed_per_triangle() {
        let s = demo::sphere();
        let m = UvMapping::Spherical {
            center: Vec3::ZERO,
            axis: Axis::Y,
        };
        let need = map_mesh_capacity(&m, &s.positions, &s.indices).unwrap();
        assert!(need > s.positions.len());
        let mut p = vec![Vec3::ZERO; need];
        let mut nm = vec![Vec3::ZERO; need];
        let mut uv = vec![[Fx::ZERO; 2]; need];
        let mut ix = vec![[0u16; 3]; s.indices.len()];
        let out = MeshStorage {
            positions: &mut p,
            normals: Some(&mut nm),
            uvs: &mut uv,
            indices: &mut ix,
        };
        let mesh = map_mesh(&m, &s.positions, Some(&s.normals), &s.indices, out).unwrap();
        assert!(mesh.vertices() <= need);
        for &tri in mesh.indices {
            let us = tri.map(|i| mesh.uvs[usize::from(i)][0].to_bits());
            let span = us.iter().max().unwrap() - us.iter().min().unwrap();
            assert!(span <= 1 << 15, "{tri:?}: u {us:?}");
        }
        // Too little storage says how much is needed.
        let mut small = vec![Vec3::ZERO; s.positions.len()];
        let mut suv = vec![[Fx::ZERO; 2]; s.positions.len()];
        let mut six = vec![[0u16; 3]; s.indices.len()];
        let out = MeshStorage {
            positions: &mut small,
            normals: None,
            uvs: &mut suv,
            indices: &mut six,
        };
        assert_eq!(
            map_mesh(&m, &s.positions, None, &s.indices, out).unwrap_err(),
            Error::CapacityExceeded { capacity: need }
        );
    }

    #[test]
    fn planar_is_a_pair_of_dot_products() {
        let m = UvMapping::Planar {
            origin: Vec3::from_num(-1, 0, 0),
            s: Vec3::from_num(0.5, 0, 0),
            t: Vec3::from_num(0, 0, 0.25),
        };
        let uv = m.uv(Vec3::from_num(1, 7, 2)).unwrap();
        assert_eq!(uv, [fx(1), fx(0.5)]);
    }
}
