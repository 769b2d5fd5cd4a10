//! Midpoint subdivision of indexed triangle meshes into caller storage, the first half of
//! displacement mapping ([`displace`](fn@super::displace)): every triangle becomes four, and
//! an edge shared by two triangles shares its midpoint vertex, so the finer mesh has no
//! cracks.
//!
//! # The rule
//! For a triangle `(a, b, c)` with midpoints `ab`, `bc`, `ca` (of positions, texture
//! coordinates and, when the mesh has them, normals: `normalize(n_a + n_b)`), the children
//! are, in this order,
//!
//! ```text
//! (a, ab, ca)   (ab, b, bc)   (ca, bc, c)   (ab, bc, ca)
//! ```
//!
//! so they keep the parent's winding. The vertices of the coarser mesh keep their indices;
//! the midpoints follow, numbered in the order their edges are first met, triangle by
//! triangle, edges `ab`, `bc`, `ca`. An edge with both ends on one vertex (a triangle with a
//! repeated index) has that vertex as its midpoint. Positions and texture coordinates are
//! averaged in I16F16 (`(a + b) >> 1`: within half an LSB of the exact midpoint).
//!
//! # Storage per level
//! A mesh of `V` vertices, `T` triangles and `E` distinct edges becomes, after one level,
//!
//! ```text
//! V' = V + E      T' = 4 T      E' = 2 E + 3 T
//! ```
//!
//! (exact; an upper bound for meshes with repeated indices or duplicate triangles). A closed
//! mesh has `E = 3T/2`, so each level multiplies the vertices by about 4. Per vertex the
//! output needs 12 bytes of positions, 12 of normals and 8 of texture coordinates (32), per
//! triangle 6 bytes of indices. The edge table is scratch, needed only while subdividing:
//! two `u32` words per slot, a power of two of slots at least `1.5 E + 1` for the largest
//! level split. [`subdivide_capacity`] computes all of it; for the demo sphere (1225
//! vertices, 2208 triangles, 3430 edges):
//!
//! | levels | vertices | triangles | storage (bytes) | edge table (bytes) |
//! |---|---|---|---|---|
//! | 1 | 4655 | 8832 | 201,952 | 65,536 |
//! | 2 | 18139 | 35328 | 792,416 | 262,144 |
//!
//! and for a 16 x 16-quad grid (289 vertices, 512 triangles, 800 edges): 1089 vertices,
//! 2048 triangles, 47,136 bytes and a 16,384-byte table at one level.
//!
//! ```
//! use fixel::math::{Fx, Vec3};
//! use fixel::scene::{count_edges, subdivide, subdivide_capacity, Mesh, MeshStorage};
//!
//! // One quad (two triangles, five edges), subdivided twice.
//! let p = [Vec3::from_num(0, 0, 0), Vec3::from_num(1, 0, 0), Vec3::from_num(1, 1, 0), Vec3::from_num(0, 1, 0)];
//! let uv = [[Fx::ZERO; 2]; 4];
//! let ix = [[0u16, 1, 2], [0, 2, 3]];
//! let quad = Mesh::new(&p, None, &uv, &ix)?;
//! let mut table = [0u32; 64];
//! let edges = count_edges(&ix, &mut table)?;
//! assert_eq!(edges, 5);
//! const CAP: fixel::scene::SubdivideCapacity = subdivide_capacity(4, 2, 5, 2);
//! assert_eq!((CAP.vertices, CAP.triangles), (25, 32));
//! let (mut op, mut ouv, mut oix) = ([Vec3::ZERO; CAP.vertices], [[Fx::ZERO; 2]; CAP.vertices], [[0u16; 3]; CAP.triangles]);
//! let mut table = [0u32; CAP.edge_words];
//! let out = MeshStorage { positions: &mut op, normals: None, uvs: &mut ouv, indices: &mut oix };
//! let fine = subdivide(&quad, 2, out, &mut table)?;
//! assert_eq!((fine.vertices(), fine.triangles()), (25, 32)); // a 4 x 4 grid of quads
//! # Ok::<(), fixel::Error>(())
//! ```

use super::{Mesh, MeshStorage};
use crate::geometry::mesh_checks::check_indices;
use crate::math::{Fx, Vec3};
use crate::Error;

/// What [`subdivide`] needs for a mesh, from [`subdivide_capacity`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SubdivideCapacity {
    /// Vertices of the finest mesh (positions, normals and texture coordinates each).
    pub vertices: usize,
    /// Triangles of the finest mesh.
    pub triangles: usize,
    /// Distinct edges of the finest mesh.
    pub edges: usize,
    /// `u32` words of the edge table (two per slot; 0 when `levels` is 0).
    pub edge_words: usize,
}

/// Slots of an open-addressing table for `items` keys: a power of two, load at most 2/3,
/// at least 2 (so the hash shift stays below 32).
const fn table_slots(items: usize) -> usize {
    let want = items.saturating_add(items / 2).saturating_add(1);
    let slots = match want.checked_next_power_of_two() {
        Some(s) => s,
        None => usize::MAX,
    };
    if slots < 2 {
        2
    } else {
        slots
    }
}

/// The storage [`subdivide`] needs to split a mesh of `vertices`, `triangles` and `edges`
/// distinct edges ([`count_edges`], or `3 * triangles` as an upper bound without counting)
/// `levels` times (see the module docs for the recurrence). Saturates rather than
/// overflows.
pub const fn subdivide_capacity(
    vertices: usize,
    triangles: usize,
    edges: usize,
    levels: u32,
) -> SubdivideCapacity {
    let (mut v, mut t, mut e, mut most) = (vertices, triangles, edges, 0usize);
    let mut k = 0;
    while k < levels {
        if e > most {
            most = e;
        }
        v = v.saturating_add(e);
        e = e.saturating_mul(2).saturating_add(t.saturating_mul(3));
        t = t.saturating_mul(4);
        k += 1;
        if t == usize::MAX {
            // Saturated: more levels change nothing (and `levels` may be huge).
            k = levels;
        }
    }
    SubdivideCapacity {
        vertices: v,
        triangles: t,
        edges: e,
        edge_words: if levels == 0 {
            0
        } else {
            table_slots(most).saturating_mul(2)
        },
    }
}

/// The key of the undirected edge `(i, j)`, `i != j`: `min << 16 | max`, never 0.
#[inline]
fn edge_key(i: u16, j: u16) -> u32 {
    let (a, b) = if i < j { (i, j) } else { (j, i) };
    (u32::from(a) << 16) | u32::from(b)
}

/// An open-addressing hash table of edges over caller words: slot `s` is words `2s` (the
/// key, 0 = empty) and `2s + 1` (the midpoint's vertex index).
struct EdgeTable<'t> {
    words: &'t mut [u32],
    /// `32 - log2(slots)`.
    shift: u32,
    mask: usize,
}

impl<'t> EdgeTable<'t> {
    /// A cleared table for up to `items` edges, or `None` when `words` is too short.
    fn new(words: &'t mut [u32], items: usize) -> Option<Self> {
        Self::with_slots(words, table_slots(items))
    }

    /// A cleared table of `slots` slots (a power of two, at least 2), or `None` when
    /// `words` is too short.
    fn with_slots(words: &'t mut [u32], slots: usize) -> Option<Self> {
        let words = words.get_mut(..slots.checked_mul(2)?)?;
        words.fill(0);
        Some(EdgeTable {
            words,
            shift: 32 - slots.trailing_zeros(),
            mask: slots - 1,
        })
    }

    /// First slot to probe for `key` (Fibonacci hashing).
    #[inline]
    fn home(&self, key: u32) -> usize {
        (key.wrapping_mul(0x9E37_79B1) >> self.shift) as usize
    }

    /// The value stored under `key`, or stores `value` there; `(value, inserted)`. `None`
    /// only if the table is full (which the load limit prevents).
    fn get_or_insert(&mut self, key: u32, value: u16) -> Option<(u16, bool)> {
        let mut s = self.home(key);
        for _ in 0..=self.mask {
            let k = *self.words.get(2 * s)?;
            if k == key {
                return Some((*self.words.get(2 * s + 1)? as u16, false));
            }
            if k == 0 {
                *self.words.get_mut(2 * s)? = key;
                *self.words.get_mut(2 * s + 1)? = u32::from(value);
                return Some((value, true));
            }
            s = (s + 1) & self.mask;
        }
        None
    }

    /// The value stored under `key`.
    fn get(&self, key: u32) -> Option<u16> {
        let mut s = self.home(key);
        for _ in 0..=self.mask {
            let k = *self.words.get(2 * s)?;
            if k == key {
                return Some(*self.words.get(2 * s + 1)? as u16);
            }
            if k == 0 {
                return None;
            }
            s = (s + 1) & self.mask;
        }
        None
    }
}

/// Words of [`count_edges`]'s table that are enough for any mesh of `triangles`
/// triangles (room for `3 * triangles` edges; a closed mesh uses half).
pub const fn count_edges_words(triangles: usize) -> usize {
    subdivide_capacity(0, triangles, triangles.saturating_mul(3), 1).edge_words
}

/// The distinct undirected edges of `indices` (an edge from a vertex to itself is not one),
/// counted in `table`, scratch of at least [`count_edges_words`]`(triangles)` words, or
/// fewer when the mesh has fewer edges.
///
/// # Errors
/// [`Error::CapacityExceeded`] with the words needed for `3 * triangles` edges when `table`
/// fills up.
pub fn count_edges(indices: &[[u16; 3]], table: &mut [u32]) -> Result<usize, Error> {
    let worst = count_edges_words(indices.len());
    let short = Error::CapacityExceeded { capacity: worst };
    // The most edges a table of this size takes at load 2/3.
    // The largest power of two of slots that fits.
    let slots = 1usize << (usize::BITS - 1 - (table.len() / 2).max(1).leading_zeros());
    let limit = slots * 2 / 3;
    let mut t = EdgeTable::with_slots(table, slots.max(2)).ok_or(short)?;
    let mut count = 0usize;
    for tri in indices {
        for (i, j) in [(tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])] {
            if i == j {
                continue;
            }
            if count >= limit {
                // One more distinct edge would pass the load limit.
                if t.get(edge_key(i, j)).is_none() {
                    return Err(short);
                }
                continue;
            }
            let (_, new) = t.get_or_insert(edge_key(i, j), 0).ok_or(short)?;
            count += usize::from(new);
        }
    }
    Ok(count)
}

/// The midpoint of two I16F16 values, `(a + b) >> 1` (within half an LSB).
#[inline]
fn mid(a: Fx, b: Fx) -> Fx {
    Fx::from_bits(((i64::from(a.to_bits()) + i64::from(b.to_bits())) >> 1) as i32)
}

/// Subdivides `mesh` `levels` times (see the module docs) into `out`, with `edges` as the
/// edge table's scratch; returns the finer mesh over `out`. Normals are made (as
/// normalised sums) only when both `mesh` and `out` have them. `levels = 0` copies.
///
/// # Errors
/// * [`Error::CapacityExceeded`] when `out` or `edges` is shorter than
///   [`subdivide_capacity`] says, with the size the first short store needs (vertices,
///   triangles, then edge-table words, in that order); when `edges` cannot even hold the
///   mesh's own edges (to count them), the words for the worst case, `3 * triangles` edges,
///   as [`count_edges`] says;
/// * [`Error::MeshTooLarge`] when the finer mesh has more vertices than a `u16` index
///   reaches.
pub fn subdivide<'a>(
    mesh: &Mesh<'_>,
    levels: u32,
    out: MeshStorage<'a>,
    edges: &mut [u32],
) -> Result<Mesh<'a>, Error> {
    let (v0, t0) = (mesh.vertices(), mesh.triangles());
    check_indices(mesh.indices, v0)?;
    // No level, no edge table: a copy.
    let e0 = if levels == 0 {
        0
    } else {
        count_edges(mesh.indices, edges)?
    };
    let cap = subdivide_capacity(v0, t0, e0, levels);
    if cap.vertices > 1 << 16 {
        return Err(Error::MeshTooLarge {
            what: "vertices (subdivided)",
            count: cap.vertices,
            limit: 1 << 16,
        });
    }
    let MeshStorage {
        positions: op,
        normals: on,
        uvs: ouv,
        indices: oix,
    } = out;
    let with_normals = mesh.normals.is_some() && on.is_some();
    let vlen = op.len().min(ouv.len()).min(match (&on, with_normals) {
        (Some(n), true) => n.len(),
        _ => usize::MAX,
    });
    for (have, need) in [
        (vlen, cap.vertices),
        (oix.len(), cap.triangles),
        (edges.len(), cap.edge_words),
    ] {
        if have < need {
            return Err(Error::CapacityExceeded { capacity: need });
        }
    }
    let (op, ouv, oix) = (
        &mut op[..cap.vertices],
        &mut ouv[..cap.vertices],
        &mut oix[..cap.triangles],
    );
    let mut on = match on {
        Some(n) if with_normals => Some(&mut n[..cap.vertices]),
        _ => None,
    };
    op[..v0].copy_from_slice(mesh.positions);
    ouv[..v0].copy_from_slice(mesh.uvs);
    if let (Some(o), Some(src)) = (on.as_deref_mut(), mesh.normals) {
        o[..v0].copy_from_slice(src);
    }
    oix[..t0].copy_from_slice(mesh.indices);
    let (mut v, mut t, mut e) = (v0, t0, e0);
    for _ in 0..levels {
        let mut table = EdgeTable::new(edges, e).ok_or(Error::CapacityExceeded {
            capacity: cap.edge_words,
        })?;
        // Pass 1, in triangle order: one new vertex per distinct edge.
        let mut next = v;
        for tri in oix[..t].iter() {
            for (i, j) in [(tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])] {
                if i == j || next >= cap.vertices {
                    continue;
                }
                let (m, new) = table
                    .get_or_insert(edge_key(i, j), next as u16)
                    .unwrap_or((i, false));
                if !new {
                    continue;
                }
                let (i, j, m) = (usize::from(i), usize::from(j), usize::from(m));
                op[m] = Vec3::new(
                    mid(op[i].x, op[j].x),
                    mid(op[i].y, op[j].y),
                    mid(op[i].z, op[j].z),
                );
                ouv[m] = [mid(ouv[i][0], ouv[j][0]), mid(ouv[i][1], ouv[j][1])];
                if let Some(n) = on.as_deref_mut() {
                    n[m] = n[i].add(n[j]).normalize().unwrap_or(n[i]);
                }
                next += 1;
            }
        }
        // Pass 2, backwards so that triangle k's children (4k..4k+4) overwrite only
        // triangles already split: the four children.
        for k in (0..t).rev() {
            let [a, b, c] = oix[k];
            let m = |i: u16, j: u16| {
                if i == j {
                    i
                } else {
                    table.get(edge_key(i, j)).unwrap_or(i)
                }
            };
            let (ab, bc, ca) = (m(a, b), m(b, c), m(c, a));
            oix[4 * k..4 * k + 4].copy_from_slice(&[
                [a, ab, ca],
                [ab, b, bc],
                [ca, bc, c],
                [ab, bc, ca],
            ]);
        }
        e = 2 * e + 3 * t;
        t *= 4;
        v = next;
    }
    let (op, ouv, oix): (&'a [Vec3], &'a [[Fx; 2]], &'a [[u16; 3]]) = (op, ouv, oix);
    let on: Option<&'a [Vec3]> = on.map(|n| &n[..v]);
    Mesh::new(&op[..v], on, &ouv[..v], &oix[..t])
}

/// Slots of [`weld`]'s table for `vertices` vertices (one `u32` word per slot).
pub const fn weld_table_words(vertices: usize) -> usize {
    table_slots(vertices)
}

/// Finds the vertices that share a position (the copies a mesh has along a texture seam
/// or at a pole): `twins[i]` is the first vertex with the position of vertex `i` (`i`
/// itself when it is the first). [`displace`](fn@super::displace) moves twins together and
/// gives them one normal, so a seam neither cracks nor shows. Returns the number of
/// distinct positions. `table` is scratch of at least [`weld_table_words`]`(n)` words.
///
/// # Errors
/// [`Error::WrongLength`] when `twins` is not as long as `positions`,
/// [`Error::CapacityExceeded`] when `table` is short, [`Error::MeshTooLarge`] past 65536
/// vertices.
pub fn weld(positions: &[Vec3], table: &mut [u32], twins: &mut [u16]) -> Result<usize, Error> {
    let n = positions.len();
    if twins.len() != n {
        return Err(Error::WrongLength {
            expected: n,
            actual: twins.len(),
        });
    }
    if n > 1 << 16 {
        return Err(Error::MeshTooLarge {
            what: "vertices",
            count: n,
            limit: 1 << 16,
        });
    }
    let slots = table_slots(n);
    let table = table.get_mut(..slots).ok_or(Error::CapacityExceeded {
        capacity: weld_table_words(n),
    })?;
    table.fill(0);
    let (shift, mask) = (32 - slots.trailing_zeros(), slots - 1);
    let mut distinct = 0;
    for (i, p) in positions.iter().enumerate() {
        let h = (p.x.to_bits() as u32)
            .wrapping_mul(0x9E37_79B1)
            .wrapping_add((p.y.to_bits() as u32).wrapping_mul(0x85EB_CA77))
            .wrapping_add((p.z.to_bits() as u32).wrapping_mul(0xC2B2_AE3D));
        let mut s = (h.wrapping_mul(0x9E37_79B1) >> shift) as usize;
        twins[i] = i as u16;
        for _ in 0..slots {
            let w = table[s];
            if w == 0 {
                table[s] = i as u32 + 1;
                distinct += 1;
                break;
            }
            let j = (w - 1) as usize;
            if positions.get(j) == Some(p) {
                twins[i] = j as u16;
                break;
            }
            s = (s + 1) & mask;
        }
    }
    Ok(distinct)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tetrahedron_splits_into_a_crack_free_mesh() {
        let p = [
            Vec3::from_num(0, 0, 0),
            Vec3::from_num(1, 0, 0),
            Vec3::from_num(0, 1, 0),
            Vec3::from_num(0, 0, 1),
        ];
        let uv = [[Fx::ZERO; 2]; 4];
        let ix = [[0u16, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        let m = Mesh::new(&p, None, &uv, &ix).unwrap();
        let mut table = [0u32; 64];
        assert_eq!(count_edges(&ix, &mut table), Ok(6));
        let cap = subdivide_capacity(4, 4, 6, 2);
        assert_eq!((cap.vertices, cap.triangles, cap.edges), (34, 64, 96));
        let (mut op, mut ouv, mut oix) = ([Vec3::ZERO; 34], [[Fx::ZERO; 2]; 34], [[0u16; 3]; 64]);
        let mut words = [0u32; 128];
        let out = MeshStorage {
            positions: &mut op,
            normals: None,
            uvs: &mut ouv,
            indices: &mut oix,
        };
        let fine = subdivide(&m, 2, out, &mut words).unwrap();
        // Closed: every edge is used by exactly two triangles, once each way.
        let mut tbl = [0u32; 512];
        assert_eq!(count_edges(fine.indices, &mut tbl), Ok(96));
        assert_eq!(fine.vertices(), 34);
        // Storage one short of the need is refused with the need.
        let (mut op, mut ouv, mut oix) = ([Vec3::ZERO; 33], [[Fx::ZERO; 2]; 33], [[0u16; 3]; 64]);
        let out = MeshStorage {
            positions: &mut op,
            normals: None,
            uvs: &mut ouv,
            indices: &mut oix,
        };
        assert_eq!(
            subdivide(&m, 2, out, &mut words).err(),
            Some(Error::CapacityExceeded { capacity: 34 })
        );
    }

    #[test]
    fn absurd_sizes_saturate_instead_of_looping_or_panicking() {
        let c = subdivide_capacity(10, 10, 20, u32::MAX);
        assert_eq!(c.triangles, usize::MAX);
        let mut tiny = [0u32; 3];
        assert!(matches!(
            count_edges(&[[0, 1, 2]], &mut tiny),
            Err(Error::CapacityExceeded { .. })
        ));
        assert_eq!(count_edges(&[[0, 1, 2]], &mut [0u32; 16]), Ok(3));
    }

    /// The storage table of the module docs.
    #[test]
    fn documented_storage_per_level() {
        let s = crate::test_scenes::sphere();
        let mut table = [0u32; 1 << 15];
        let e = count_edges(&s.indices, &mut table).unwrap();
        assert_eq!(e, 3430);
        let bytes = |c: SubdivideCapacity| (c.vertices * 32 + c.triangles * 6, c.edge_words * 4);
        let one = subdivide_capacity(1225, 2208, e, 1);
        assert_eq!((one.vertices, one.triangles), (4655, 8832));
        assert_eq!(bytes(one), (201_952, 65_536));
        let two = subdivide_capacity(1225, 2208, e, 2);
        assert_eq!((two.vertices, two.triangles), (18139, 35328));
        assert_eq!(bytes(two), (792_416, 262_144));
        let g: crate::test_scenes::MeshData<289, 512> =
            crate::test_scenes::displaced::grid(16, Fx::ONE);
        assert_eq!(count_edges(&g.indices, &mut table), Ok(800));
        assert_eq!(
            bytes(subdivide_capacity(289, 512, 800, 1)),
            (47_136, 16_384)
        );
    }

    #[test]
    fn weld_finds_copies() {
        let p = [
            Vec3::from_num(0, 0, 0),
            Vec3::from_num(1, 0, 0),
            Vec3::from_num(0, 0, 0),
            Vec3::from_num(1, 0, 0),
            Vec3::from_num(2, 0, 0),
        ];
        let mut table = [0u32; 16];
        let mut twins = [0u16; 5];
        assert_eq!(weld(&p, &mut table, &mut twins), Ok(3));
        assert_eq!(twins, [0, 1, 0, 1, 4]);
        assert!(weld(&p, &mut table[..4], &mut twins).is_err());
    }
}
