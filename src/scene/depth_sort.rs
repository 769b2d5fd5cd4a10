//! Back-to-front order for transparent triangles, with no heap: blending is order-dependent
//! and blending shaders do not write depth, so the far triangles must be drawn first.
//!
//! ```
//! use fixel::geometry::Vertex;
//! use fixel::math::Fx;
//! use fixel::scene::sort_back_to_front;
//!
//! let at = |w: i32| Vertex::<1>::new([Fx::ZERO, Fx::ZERO, Fx::ZERO, Fx::from_num(w)], [0]);
//! let mut tris = [[at(2); 3], [at(9); 3], [at(5); 3]];
//! sort_back_to_front(&mut tris);
//! assert_eq!(tris.map(|t| t[0].position[3].to_num::<i32>()), [9, 5, 2]);
//! ```

use crate::geometry::Vertex;

/// Sorts clip-space triangles so the farthest (largest summed clip `w`, i.e. view-space
/// depth of the centroid for a perspective projection) comes first. In place, no heap
/// (`sort_unstable_by_key`); ties keep no particular order. Centroid order is exact for
/// triangles that do not overlap in depth; interpenetrating transparent triangles need
/// splitting, which this does not do.
pub fn sort_back_to_front<const N: usize>(tris: &mut [[Vertex<N>; 3]]) {
    tris.sort_unstable_by_key(|t| {
        let w: i64 = t.iter().map(|v| i64::from(v.position[3].to_bits())).sum();
        core::cmp::Reverse(w)
    });
}
