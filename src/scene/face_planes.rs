//! Baked face planes: each triangle's model-space normal, kept beside a mesh so that the
//! model-space back-face test ([`FacingTest`](super::FacingTest), see `face_cull`) reads
//! one 24-byte record per triangle instead of its three corners' positions.
//!
//! The test decides from `s = n . (g + W p0)`, with `n = (p1 - p0) x (p2 - p0)` from the
//! positions cut to 14 signed bits by the mesh's shift, and `(g, W)` the camera's centre
//! (once per frame). Everything but `g` and `W` is the mesh's own, so it can be computed
//! once: a [`FacePlane`] holds `n`, `n . p0` and the edge bound of the test's error margin,
//! and the test becomes `s = n . g + W (n . p0)`, the same integer (both are exact in `i64`:
//! `|n . g| < 2^61`, `|W (n . p0)| < 2^61`), so it culls exactly the same triangles.
//!
//! What it saves: on the Cortex-M4F benchmark sphere (2,208 triangles, 1,447 culled) the
//! test costs about 106 instructions per triangle from the positions; from a plane it needs
//! no index, no position and no cross product. What it costs: 24 bytes per triangle
//! (53 KB for that sphere), in flash when baked at compile time with [`face_planes`], or in
//! RAM with [`write_face_planes`]. A mesh without planes links and runs none of this.
//!
//! ```
//! use fixel_scenes as demo;
//! use fixel::geometry::Cull;
//! use fixel::scene::{face_planes, FacePlane, Mesh, MeshTransform};
//!
//! // At compile time: `static PLANES: [FacePlane; T] = face_planes(&POSITIONS, &INDICES);`
//! // (here at run time, for the demo sphere).
//! let data = demo::sphere();
//! let mut planes = vec![FacePlane::ZERO; data.indices.len()];
//! fixel::scene::write_face_planes(&data.positions, &data.indices, &mut planes)?;
//! let plain = data.mesh()?;
//! let baked = plain.with_face_planes(&planes)?;
//!
//! // The same decisions, triangle by triangle.
//! let transform = MeshTransform::new(&demo::sphere_model(0), &demo::camera(0));
//! let (a, b) = (
//!     transform.facing_test(&plain, Cull::Back).unwrap(),
//!     transform.facing_test(&baked, Cull::Back).unwrap(),
//! );
//! assert!((0..plain.triangles()).all(|t| a.culls(t) == b.culls(t)));
//!
//! // Planes of another mesh are refused where they enter.
//! let cube = demo::cube();
//! assert!(cube.mesh()?.with_face_planes(&planes[..12]).is_err());
//! let cube_planes = face_planes(&cube.positions, &cube.indices);
//! assert!(cube.mesh()?.with_face_planes(&cube_planes).is_ok());
//! # Ok::<(), fixel::Error>(())
//! ```

use crate::math::Vec3;
use crate::Error;

use crate::geometry::mesh_checks::coord_shift;

/// One triangle's baked model-space plane (see the module docs): its normal `n` from the
/// mesh's shifted positions (`|n_i| < 2^29`), `n . p0` (`|n . p0| < 2^45`) and the bound
/// `e` on its edges' components (`< 2^14`) that scales the test's error margin. 24 bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FacePlane {
    pub(super) np0: i64,
    pub(super) n: [i32; 3],
    pub(super) e: u32,
}

impl FacePlane {
    /// All zero (what storage starts as; never a mesh's plane, whose `e` is at least 1).
    pub const ZERO: FacePlane = FacePlane {
        np0: 0,
        n: [0; 3],
        e: 0,
    };

    /// The plane of the triangle with shifted corners `p` (each coordinate in
    /// `-2^13..2^13`, as `face_cull` cuts them): the cross product and edge bound of
    /// `FaceCull::culls`, bit for bit.
    pub(super) const fn of(p: [[i32; 3]; 3]) -> FacePlane {
        let p0 = p[0];
        let (edges, n) = edges_and_normal(p);
        let e = edge_bound(edges);
        let np0 =
            n[0] as i64 * p0[0] as i64 + n[1] as i64 * p0[1] as i64 + n[2] as i64 * p0[2] as i64;
        FacePlane { np0, n, e }
    }

    /// The plane of triangle `idx` of `positions` cut by `shift`, or `None` for an index out
    /// of range.
    pub(super) const fn of_triangle(
        positions: &[Vec3],
        idx: &[u16; 3],
        shift: u32,
    ) -> Option<FacePlane> {
        let mut p = [[0i32; 3]; 3];
        let mut k = 0;
        while k < 3 {
            let i = idx[k] as usize;
            if i >= positions.len() {
                return None;
            }
            let v = &positions[i];
            p[k] = [
                v.x.to_bits() >> shift,
                v.y.to_bits() >> shift,
                v.z.to_bits() >> shift,
            ];
            k += 1;
        }
        Some(FacePlane::of(p))
    }
}

/// The face planes of the mesh `positions`, `indices`, at compile time:
/// `static PLANES: [FacePlane; T] = face_planes(&POSITIONS, &INDICES);` puts them in flash
/// (24 bytes per triangle). Hand them to [`Mesh::with_face_planes`](super::Mesh::with_face_planes).
///
/// # Panics
/// If an index is out of range (a compile error in a `static`); [`write_face_planes`]
/// returns an error instead.
pub const fn face_planes<const T: usize>(
    positions: &[Vec3],
    indices: &[[u16; 3]; T],
) -> [FacePlane; T] {
    let shift = coord_shift(positions) as u32;
    let mut out = [FacePlane::ZERO; T];
    let mut t = 0;
    while t < T {
        match FacePlane::of_triangle(positions, &indices[t], shift) {
            Some(p) => out[t] = p,
            None => panic!("a triangle index is out of range of the positions"),
        }
        t += 1;
    }
    out
}

/// Writes the face planes of the mesh `positions`, `indices` into `out` (one per triangle),
/// at run time. [`Error::WrongLength`] when `out` is not one per triangle,
/// [`Error::IndexOutOfRange`] for an index out of range.
pub fn write_face_planes(
    positions: &[Vec3],
    indices: &[[u16; 3]],
    out: &mut [FacePlane],
) -> Result<(), Error> {
    if out.len() != indices.len() {
        return Err(Error::WrongLength {
            expected: indices.len(),
            actual: out.len(),
        });
    }
    crate::geometry::mesh_checks::check_indices(indices, positions.len())?;
    let shift = u32::from(coord_shift(positions));
    for (o, idx) in out.iter_mut().zip(indices) {
        *o = FacePlane::of_triangle(positions, idx, shift).unwrap_or_default();
    }
    Ok(())
}

/// Checks that `planes` are the face planes of the mesh `positions`, `indices` cut by
/// `shift` (the mesh's): the first that is not is [`Error::FacePlaneMismatch`]. Returns the
/// largest edge bound `e` of the planes (the scale of the test's largest margin).
pub(super) fn check_face_planes(
    positions: &[Vec3],
    indices: &[[u16; 3]],
    shift: u8,
    planes: &[FacePlane],
) -> Result<u32, Error> {
    if planes.len() != indices.len() {
        return Err(Error::FacePlaneMismatch {
            triangle: planes.len().min(indices.len()),
        });
    }
    let shift = u32::from(shift);
    let mut e_max = 0;
    for (triangle, (idx, p)) in indices.iter().zip(planes).enumerate() {
        if FacePlane::of_triangle(positions, idx, shift) != Some(*p) {
            return Err(Error::FacePlaneMismatch { triangle });
        }
        e_max = e_max.max(p.e);
    }
    Ok(e_max)
}

/// The edges `(p1 - p0, p2 - p0)` of a triangle's cut model-space corners `p` and their
/// cross product `n`, the face test's normal: shared by the baked plane ([`FacePlane`])
/// and the test from positions ([`FaceCull::culls`](super::FaceCull::culls)). Corners
/// within `2^13` in magnitude (the cut [`FaceCull`](super::FaceCull) applies): the edges
/// and `n` fit `i32`.
#[inline(always)]
pub(super) const fn edges_and_normal(p: [[i32; 3]; 3]) -> ([[i32; 3]; 2], [i32; 3]) {
    let [p0, p1, p2] = p;
    let e1 = [p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]];
    let e2 = [p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]];
    let n = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    ([e1, e2], n)
}

/// An upper bound `e` on every edge component's magnitude: the or of their one's
/// complement magnitudes, plus one (the error margin's input, see
/// [`FaceCull::culls`](super::FaceCull::culls)).
#[inline(always)]
pub(super) const fn edge_bound(e: [[i32; 3]; 2]) -> u32 {
    let mut or = 0u32;
    let mut k = 0;
    while k < 3 {
        or |= (e[0][k] ^ (e[0][k] >> 31)) as u32 | (e[1][k] ^ (e[1][k] >> 31)) as u32;
        k += 1;
    }
    or + 1
}
