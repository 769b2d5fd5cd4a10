//! The checks every mesh builder runs on its slices (vertex count, normals' length, indices
//! in range) and the coordinate shift that keeps a mesh's positions in the 14-bit range of
//! the exact facing tests.

use crate::math::Vec3;
use crate::Error;

/// At most 65536 positions (what a `u16` index reaches) and, if there are normals, one per
/// position.
pub(crate) fn check_vertices(positions: usize, normals: Option<&[Vec3]>) -> Result<(), Error> {
    if positions > 1 << 16 {
        return Err(Error::MeshTooLarge {
            what: "vertices",
            count: positions,
            limit: 1 << 16,
        });
    }
    match normals {
        Some(nm) if nm.len() != positions => Err(Error::WrongLength {
            expected: positions,
            actual: nm.len(),
        }),
        _ => Ok(()),
    }
}

/// Every index of `indices` below `n`, or the first that is not.
pub(crate) fn check_indices(indices: &[[u16; 3]], n: usize) -> Result<(), Error> {
    for (t, tri) in indices.iter().enumerate() {
        for (k, &i) in tri.iter().enumerate() {
            if usize::from(i) >= n {
                return Err(Error::IndexOutOfRange {
                    at: t * 3 + k,
                    index: i,
                    vertices: n,
                });
            }
        }
    }
    Ok(())
}

/// Magnitude bound of a model-space coordinate after the mesh's shift: `p >> shift` lies
/// in `-2^13..2^13`, so edges are below 2^14 and the cross product's components below 2^29.
pub(crate) const COORD_BITS: u32 = 13;

/// The right shift that brings every coordinate of `positions` (I16F16 bits) into
/// `-2^13..2^13`. One pass over the positions, in [`Mesh::new`](crate::scene::Mesh::new) (and, at compile time, in
/// [`face_planes`](crate::scene::face_planes)).
pub(crate) const fn coord_shift(positions: &[Vec3]) -> u8 {
    // `b ^ (b >> 31)` is |b| for b >= 0 and |b| - 1 below: b lies in -2^k..2^k when the
    // or of these is below 2^k.
    let mut or = 0u32;
    let mut i = 0;
    while i < positions.len() {
        let p = &positions[i];
        let c = [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()];
        let mut k = 0;
        while k < 3 {
            or |= (c[k] ^ (c[k] >> 31)) as u32;
            k += 1;
        }
        i += 1;
    }
    let bits = u32::BITS - or.leading_zeros();
    bits.saturating_sub(COORD_BITS) as u8
}
