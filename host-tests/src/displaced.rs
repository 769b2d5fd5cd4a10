//! Shared by the displacement tests (`tests/displacement.rs`,
//! `tests/displacement_hard_cases.rs`): fixel's subdivided, welded and displaced meshes as
//! vectors, their f64 twins for the reference, and the demo height maps.

use fixel::math::{Fx, Vec3};
use fixel::scene::{
    count_edges, count_edges_words, displace, subdivide, subdivide_capacity, weld,
    weld_table_words, Displacement, Mesh, MeshStorage,
};
use fixel::Error;
use fixel_scenes::displaced::{rock_heights, wave_heights, ROCK_HEIGHT, ROCK_WIDTH, WAVE_SIDE};

use crate::reference::displace::RefMesh;

/// One I16F16 LSB, in model units.
pub const LSB: f64 = 65536.0;

/// `v` in f64.
pub fn f3(v: Vec3) -> [f64; 3] {
    [v.x.to_num(), v.y.to_num(), v.z.to_num()]
}

/// `m` in f64 (indices as `usize`).
pub fn to_ref(m: &Mesh<'_>) -> RefMesh {
    RefMesh {
        positions: m.positions().iter().map(|&p| f3(p)).collect(),
        normals: m.normals().unwrap_or(&[]).iter().map(|&n| f3(n)).collect(),
        uvs: m
            .uvs()
            .iter()
            .map(|c| [c[0].to_num(), c[1].to_num()])
            .collect(),
        indices: m.indices().iter().map(|t| t.map(usize::from)).collect(),
    }
}

/// fixel's subdivided, welded, displaced mesh, as vectors.
pub struct Fine {
    /// Undisplaced positions.
    pub base: Vec<Vec3>,
    /// Undisplaced normals.
    pub normals: Vec<Vec3>,
    /// Texture coordinates.
    pub uvs: Vec<[Fx; 2]>,
    /// Triangles.
    pub indices: Vec<[u16; 3]>,
    /// [`weld`]'s twins.
    pub twins: Vec<u16>,
}

impl Fine {
    /// `src` subdivided `levels` times and welded.
    pub fn new(src: &Mesh<'_>, levels: u32) -> Result<Fine, Error> {
        let mut table = vec![0u32; count_edges_words(src.triangles())];
        let e = count_edges(src.indices(), &mut table)?;
        let cap = subdivide_capacity(src.vertices(), src.triangles(), e, levels);
        let mut f = Fine {
            base: vec![Vec3::ZERO; cap.vertices],
            normals: vec![Vec3::ZERO; cap.vertices],
            uvs: vec![[Fx::ZERO; 2]; cap.vertices],
            indices: vec![[0; 3]; cap.triangles],
            twins: vec![0; cap.vertices],
        };
        let mut table = vec![0u32; cap.edge_words.max(weld_table_words(cap.vertices))];
        let out = MeshStorage {
            positions: &mut f.base,
            normals: Some(&mut f.normals),
            uvs: &mut f.uvs,
            indices: &mut f.indices,
        };
        let n = subdivide(src, levels, out, &mut table)?.vertices();
        for v in [&mut f.base, &mut f.normals] {
            v.truncate(n);
        }
        f.uvs.truncate(n);
        f.twins.truncate(n);
        weld(&f.base, &mut table, &mut f.twins)?;
        Ok(f)
    }

    /// The undisplaced mesh.
    pub fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.base, Some(&self.normals), &self.uvs, &self.indices).unwrap()
    }

    /// Displaced positions and normals.
    pub fn displaced(&self, d: &Displacement<'_>) -> (Vec<Vec3>, Vec<Vec3>) {
        let n = self.base.len();
        let (mut p, mut nm) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        displace(d, &self.mesh(), Some(&self.twins), &mut p, &mut nm).unwrap();
        (p, nm)
    }
}

/// Largest step between neighbouring texels (wrapping), in height steps.
pub fn max_step(bytes: &[u8], w: usize, h: usize) -> f64 {
    let mut m = 0i32;
    for j in 0..h {
        for i in 0..w {
            let a = i32::from(bytes[j * w + i]);
            m = m.max((a - i32::from(bytes[j * w + (i + 1) % w])).abs());
            m = m.max((a - i32::from(bytes[((j + 1) % h) * w + i])).abs());
        }
    }
    f64::from(m)
}

/// The rock heights (128 x 64).
pub fn rock() -> Vec<u8> {
    let mut h = vec![0u8; (ROCK_WIDTH * ROCK_HEIGHT) as usize];
    rock_heights(&mut h).unwrap();
    h
}

/// The swell (64 x 64).
pub fn waves() -> Vec<u8> {
    let mut h = vec![0u8; (WAVE_SIDE * WAVE_SIDE) as usize];
    wave_heights(&mut h).unwrap();
    h
}
