//! Instructions per vertex of run-time displacement, for callgrind:
//! `valgrind --tool=callgrind --toggle-collect='fixel::scene::displace::*' \
//!  target/release/examples/displace_cost [frames]` counts `displace_positions` and
//! `recompute_normals` over `frames` frames of the once-subdivided rocky demo sphere
//! (4655 vertices, 8832 triangles) with a moving offset; divide by `frames x 4655`.

use fixel::math::{Fx, Vec3};
use fixel::scene::{
    count_edges, displace, subdivide, subdivide_capacity, weld, weld_table_words, Displacement,
    MeshStorage,
};
use fixel::texture::HeightMap;
use fixel_scenes::{self as demo, displaced};

fn main() -> Result<(), fixel::Error> {
    let frames: u32 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(10);
    let s = demo::sphere();
    let src = s.mesh()?;
    let mut table = vec![0u32; 1 << 16];
    let e = count_edges(src.indices(), &mut table)?;
    let cap = subdivide_capacity(src.vertices(), src.triangles(), e, 1);
    let (mut p, mut n, mut uv, mut ix) = (
        vec![Vec3::ZERO; cap.vertices],
        vec![Vec3::ZERO; cap.vertices],
        vec![[Fx::ZERO; 2]; cap.vertices],
        vec![[0u16; 3]; cap.triangles],
    );
    let mut table = vec![0u32; cap.edge_words.max(weld_table_words(cap.vertices))];
    let out = MeshStorage {
        positions: &mut p,
        normals: Some(&mut n),
        uvs: &mut uv,
        indices: &mut ix,
    };
    let base = subdivide(&src, 1, out, &mut table)?;
    let mut twins = vec![0u16; base.vertices()];
    weld(base.positions(), &mut table, &mut twins)?;
    let mut heights = vec![0u8; (displaced::ROCK_WIDTH * displaced::ROCK_HEIGHT) as usize];
    displaced::rock_heights(&mut heights)?;
    let map = HeightMap::new(&heights, displaced::ROCK_WIDTH, displaced::ROCK_HEIGHT, 1)?;
    let (mut dp, mut dn) = (
        vec![Vec3::ZERO; base.vertices()],
        vec![Vec3::ZERO; base.vertices()],
    );
    let mut sum = 0i64;
    for f in 0..frames {
        let d = Displacement {
            map,
            scale: Fx::from_num(0.45),
            bias: Fx::from_num(0.5),
            offset: [Fx::from_bits(f as i32 * 300), Fx::ZERO],
        };
        let m = displace(&d, &base, Some(&twins), &mut dp, &mut dn)?;
        sum += i64::from(m.normals().unwrap_or(&[])[7].x.to_bits());
    }
    println!(
        "{frames} frames of {} vertices, {} triangles (checksum {sum})",
        base.vertices(),
        base.triangles()
    );
    Ok(())
}
