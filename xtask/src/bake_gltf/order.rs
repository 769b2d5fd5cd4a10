//! `--order-by-height`: the triangles from the top of the model down, the vertices numbered
//! in the order the triangles first use them.
//!
//! A band renderer draws 8-row bands from the top of the screen down; each band walks the
//! triangles whose band range meets it, in mesh order, through a small direct-mapped cache
//! of prepared vertices (`fixel::scene::mesh_to_sink`). In an upright model seen from the
//! side, a triangle's height in the model says roughly which bands it meets: ordered by
//! height, each band's triangles are neighbours in the mesh and so are their vertices, so
//! the band passes skip fewer triangles and the cache keeps more corners. The pixels are
//! the same (the depth test decides what is seen, whatever the order, except on exact depth
//! ties). A mesh of unshared vertices whose back faces come in long runs (the Fox) gains
//! nothing: the whole-frame walker skips such runs, which the new order breaks up. Measure
//! with `cargo xtask mcu --only NAME`.

use super::Imported;

/// Reorders `m` in place: triangles by their highest corner's `y`, highest first (a stable
/// sort: ties keep the file's order), then vertices by first use (unused ones last, in
/// their order). Positions, normals, texture coordinates and colours move together.
pub fn order_by_height(m: &mut Imported) {
    let mesh = &mut m.mesh;
    let top = |t: &[u32; 3]| {
        t.iter()
            .map(|&i| mesh.positions.get(i as usize).map_or(f64::MIN, |p| p[1]))
            .fold(f64::MIN, f64::max)
    };
    let mut tris: Vec<([u32; 3], f64)> = mesh.indices.iter().map(|t| (*t, top(t))).collect();
    tris.sort_by(|a, b| b.1.total_cmp(&a.1));
    let n = mesh.positions.len();
    // new_of[old] = new index; order[new] = old index.
    let mut new_of = vec![u32::MAX; n];
    let mut order = Vec::with_capacity(n);
    for (t, _) in &tris {
        for &i in t {
            if let Some(slot) = new_of.get_mut(i as usize) {
                if *slot == u32::MAX {
                    *slot = order.len() as u32;
                    order.push(i as usize);
                }
            }
        }
    }
    for (i, slot) in new_of.iter_mut().enumerate() {
        if *slot == u32::MAX {
            *slot = order.len() as u32;
            order.push(i);
        }
    }
    fn permute<T: Copy>(v: &mut Vec<T>, order: &[usize]) {
        if v.len() == order.len() {
            *v = order.iter().map(|&i| v[i]).collect();
        }
    }
    permute(&mut mesh.positions, &order);
    permute(&mut mesh.normals, &order);
    permute(&mut mesh.uvs, &order);
    if let Some(c) = m.colors.as_mut() {
        permute(c, &order);
    }
    mesh.indices = tris
        .iter()
        .map(|(t, _)| t.map(|i| new_of.get(i as usize).copied().unwrap_or(i)))
        .collect();
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bake_obj::F64Mesh;

    /// Three triangles at heights 0, 2 and 1 (the middle one's vertex 4 unused by the
    /// others), one vertex used by none.
    fn model() -> Imported {
        let p = |y: f64| [y, y, -y];
        Imported {
            mesh: F64Mesh {
                positions: vec![p(0.0), p(0.1), p(0.2), p(2.0), p(1.9), p(1.0), p(9.0)],
                normals: (0..7).map(|i| [i as f64, 0.0, 1.0]).collect(),
                uvs: (0..7).map(|i| [i as f64, 0.5]).collect(),
                indices: vec![[0, 1, 2], [3, 4, 1], [5, 2, 0]],
                dropped: 0,
            },
            colors: Some((0..7).map(|i| [i as f64, 0.0, 0.0]).collect()),
            image: None,
            primitives: 1,
        }
    }

    /// A corner's position, normal, texture coordinates and colour.
    type Corner = ([f64; 3], [f64; 3], [f64; 2], [f64; 3]);

    /// Each corner's attributes, triangle by triangle: what the order must not change.
    fn corners(m: &Imported) -> Vec<Vec<Corner>> {
        let c = m.colors.as_ref().unwrap();
        m.mesh
            .indices
            .iter()
            .map(|t| {
                t.iter()
                    .map(|&i| {
                        let i = i as usize;
                        (m.mesh.positions[i], m.mesh.normals[i], m.mesh.uvs[i], c[i])
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn triangles_go_from_the_top_down_with_their_vertices_in_first_use() {
        let before = model();
        let mut m = before.clone();
        order_by_height(&mut m);
        // The same triangles (each with its corners in order), highest first.
        let (a, b) = (corners(&before), corners(&m));
        assert_eq!(b, vec![a[1].clone(), a[2].clone(), a[0].clone()]);
        // Vertices numbered as the triangles first use them; the unused one last.
        assert_eq!(m.mesh.indices, vec![[0, 1, 2], [3, 4, 5], [5, 2, 4]]);
        assert_eq!(m.mesh.positions[6], before.mesh.positions[6]);
    }

    #[test]
    fn ties_keep_the_file_order() {
        let mut m = model();
        m.mesh.positions = vec![[0.0; 3]; 7];
        let before = m.clone();
        order_by_height(&mut m);
        assert_eq!(corners(&m), corners(&before));
    }
}
