//! Displacement mapping's hard cases: a fold, zero-area triangles, storage too
//! small, indices out of range, seam and pole copies that must not crack, and the
//! silhouette against bump mapping's.

use fixel::geometry::{Cull, Viewport};
use fixel::math::{fx, Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthTest, Draw, DrawMode, Shading};
use fixel::scene::{
    count_edges, count_edges_words, displace, draw_mesh, recompute_normals, subdivide,
    subdivide_capacity, Camera, Displacement, Mesh, MeshStorage,
};
use fixel::surface::Frame;
use fixel::texture::HeightMap;
use fixel::{Error, Rgb565};
use fixel_scenes as demo;
use fixel_scenes::displaced::{ROCK_HEIGHT, ROCK_WIDTH};
use host_tests::displaced::{f3, rock, Fine};
use host_tests::reference::displace as reference;

/// A scale far past what the sphere's curvature takes: triangles turn over. Nothing
/// panics, every normal is unit, and some face inwards (the surface did fold).
#[test]
fn a_fold_keeps_unit_normals() {
    let s = demo::sphere();
    let bytes = rock();
    let fine = Fine::new(&s.mesh().unwrap(), 1).unwrap();
    for scale in [12.0, -12.0, 200.0, -30000.0] {
        let d = Displacement {
            map: HeightMap::new(&bytes, ROCK_WIDTH, ROCK_HEIGHT, 1).unwrap(),
            scale: fx(scale),
            bias: fx(0.5),
            offset: [Fx::ZERO; 2],
        };
        let (p, n) = fine.displaced(&d);
        let mut flipped = 0;
        for t in &fine.indices {
            let c = t.map(|i| f3(p[usize::from(i)]));
            let f = reference::cross(reference::sub(c[1], c[0]), reference::sub(c[2], c[0]));
            let centre = fine.base[usize::from(t[0])];
            let out = f3(centre);
            if f[0] * out[0] + f[1] * out[1] + f[2] * out[2] < 0.0 {
                flipped += 1;
            }
        }
        for v in &n {
            let l = reference::length(f3(*v));
            assert!((l - 1.0).abs() < 1.0 / 4096.0, "scale {scale}: |n| = {l}");
        }
        println!(
            "scale {scale}: {flipped} of {} triangles flipped",
            fine.indices.len()
        );
        assert!(flipped > 0, "scale {scale} should fold the surface");
    }
}

/// Zero-area triangles (collinear corners, a repeated index) subdivide and displace; a
/// vertex that only zero-area triangles use keeps its undisplaced normal.
#[test]
fn zero_area_triangles_fall_back_to_the_base_normal() {
    let p = [
        Vec3::from_num(0, 0, 0),
        Vec3::from_num(1, 0, 0),
        Vec3::from_num(2, 0, 0), // collinear with 0 and 1
        Vec3::from_num(0, 1, 0),
        Vec3::from_num(5, 5, 0), // only on the repeated-index triangle
    ];
    let nm = [Vec3::from_num(0, 0, 1); 5];
    let uv = [[Fx::ZERO; 2]; 5];
    let ix = [[0u16, 1, 3], [0, 1, 2], [4, 4, 2]];
    let m = Mesh::new(&p, Some(&nm), &uv, &ix).unwrap();
    let fine = Fine::new(&m, 2).unwrap();
    let flat = [100u8; 4];
    let d = Displacement {
        map: HeightMap::new(&flat, 2, 2, 1).unwrap(),
        scale: fx(1),
        bias: Fx::ZERO,
        offset: [Fx::ZERO; 2],
    };
    let (dp, dn) = fine.displaced(&d);
    // Everything moved up by 100/256 along +z.
    for (a, b) in dp.iter().zip(&fine.base) {
        assert_eq!(a.z - b.z, fx(100.0 / 256.0));
    }
    for v in &dn {
        assert_eq!(
            *v,
            Vec3::from_num(0, 0, 1),
            "every normal is +z or falls back to it"
        );
    }
    // With a different fallback, the lone vertex shows it is used.
    let tilted = vec![Vec3::from_num(1, 0, 0); dp.len()];
    let mut out = vec![Vec3::ZERO; dp.len()];
    recompute_normals(&dp, &fine.indices, &tilted, None, &mut out).unwrap();
    assert_eq!(out[4], Vec3::from_num(1, 0, 0));
    assert_eq!(out[3], Vec3::from_num(0, 0, 1));
}

/// Subdivides `m` into storage of `v` vertices, `t` triangles and `words` table words.
fn try_subdivide(
    m: &Mesh<'_>,
    levels: u32,
    v: usize,
    t: usize,
    words: usize,
) -> Result<usize, Error> {
    let (mut p, mut n, mut uv, mut ix) = (
        vec![Vec3::ZERO; v],
        vec![Vec3::ZERO; v],
        vec![[Fx::ZERO; 2]; v],
        vec![[0u16; 3]; t],
    );
    let mut table = vec![0u32; words];
    let out = MeshStorage {
        positions: &mut p,
        normals: Some(&mut n),
        uvs: &mut uv,
        indices: &mut ix,
    };
    subdivide(m, levels, out, &mut table).map(|f| f.vertices())
}

#[test]
fn short_storage_is_refused_with_the_size_it_needs() {
    let s = demo::sphere();
    let m = s.mesh().unwrap();
    let mut table = vec![0u32; 1 << 16];
    let e = count_edges(m.indices(), &mut table).unwrap();
    let cap = subdivide_capacity(m.vertices(), m.triangles(), e, 1);
    assert_eq!(cap.triangles, 4 * m.triangles());
    let try_with = |v: usize, t: usize, words: usize| try_subdivide(&m, 1, v, t, words);
    let (v, t, w) = (cap.vertices, cap.triangles, cap.edge_words);
    assert_eq!(try_with(v, t, w), Ok(v));
    assert_eq!(
        try_with(v - 1, t, w),
        Err(Error::CapacityExceeded { capacity: v })
    );
    assert_eq!(
        try_with(v, t - 1, w),
        Err(Error::CapacityExceeded { capacity: t })
    );
    // Two levels: a table that holds the sphere's edges but not the finer mesh's.
    let cap2 = subdivide_capacity(m.vertices(), m.triangles(), e, 2);
    let try2 = |words: usize| try_subdivide(&m, 2, cap2.vertices, cap2.triangles, words);
    assert_eq!(try2(cap2.edge_words), Ok(cap2.vertices));
    assert_eq!(
        try2(w),
        Err(Error::CapacityExceeded {
            capacity: cap2.edge_words
        })
    );
    // A table too small even to count the edges asks for the worst case (3 per triangle).
    let worst = count_edges_words(m.triangles());
    assert_eq!(
        try_with(v, t, 64),
        Err(Error::CapacityExceeded { capacity: worst })
    );
    // Past what u16 indices reach.
    let big = subdivide_capacity(m.vertices(), m.triangles(), e, 3);
    assert!(big.vertices > 1 << 16);
    let r = try_subdivide(&m, 3, big.vertices, big.triangles, big.edge_words);
    assert!(matches!(r, Err(Error::MeshTooLarge { .. })), "{r:?}");
    // The displaced buffers must be one per vertex.
    let fine = Fine::new(&m, 0).unwrap();
    let bytes = rock();
    let d = Displacement {
        map: HeightMap::new(&bytes, ROCK_WIDTH, ROCK_HEIGHT, 1).unwrap(),
        scale: fx(0.3),
        bias: fx(0.5),
        offset: [Fx::ZERO; 2],
    };
    let (mut p, mut n) = (vec![Vec3::ZERO; 10], vec![Vec3::ZERO; m.vertices()]);
    assert_eq!(
        displace(&d, &fine.mesh(), None, &mut p, &mut n).err(),
        Some(Error::WrongLength {
            expected: m.vertices(),
            actual: 10
        })
    );
    // A mesh without normals cannot be displaced (it has 0 of them).
    let bare = Mesh::new(m.positions(), None, m.uvs(), m.indices()).unwrap();
    let mut p = vec![Vec3::ZERO; m.vertices()];
    assert_eq!(
        displace(&d, &bare, None, &mut p, &mut n).err(),
        Some(Error::WrongLength {
            expected: m.vertices(),
            actual: 0
        })
    );
}

#[test]
fn indices_out_of_range_are_refused() {
    let p = [Vec3::ZERO; 3];
    let uv = [[Fx::ZERO; 2]; 3];
    let bad = [[0u16, 1, 3]];
    assert_eq!(
        Mesh::new(&p, None, &uv, &bad).err(),
        Some(Error::IndexOutOfRange {
            at: 2,
            index: 3,
            vertices: 3
        })
    );
    let mut out = [Vec3::ZERO; 3];
    assert_eq!(
        recompute_normals(&p, &bad, &p, None, &mut out).err(),
        Some(Error::IndexOutOfRange {
            at: 2,
            index: 3,
            vertices: 3
        })
    );
    // A twin after its vertex is refused too.
    let good = [[0u16, 1, 2]];
    assert_eq!(
        recompute_normals(&p, &good, &p, Some(&[0, 2, 2]), &mut out).err(),
        Some(Error::IndexOutOfRange {
            at: 1,
            index: 2,
            vertices: 3
        })
    );
}

/// No cracks: every edge of the subdivided sphere's triangles meets its neighbour's at the
/// same two displaced points, seams and poles included, because copies of a vertex (found by
/// `weld`) move together; without the twins the pole copies, whose `u` differs, part.
#[test]
fn welded_copies_move_together() {
    let s = demo::sphere();
    let bytes = rock();
    let fine = Fine::new(&s.mesh().unwrap(), 1).unwrap();
    let d = Displacement {
        map: HeightMap::new(&bytes, ROCK_WIDTH, ROCK_HEIGHT, 1).unwrap(),
        scale: fx(0.45),
        bias: fx(0.5),
        offset: [Fx::ZERO; 2],
    };
    let (p, n) = fine.displaced(&d);
    let copies = (0..p.len())
        .filter(|&i| usize::from(fine.twins[i]) != i)
        .count();
    assert!(
        copies > 100,
        "the sphere has seam and pole copies ({copies})"
    );
    for i in 0..p.len() {
        let t = usize::from(fine.twins[i]);
        assert_eq!(fine.base[i], fine.base[t]);
        assert_eq!((p[i], n[i]), (p[t], n[t]), "vertex {i} and its twin {t}");
    }
    let (mut apart, mut nm) = (vec![Vec3::ZERO; p.len()], vec![Vec3::ZERO; p.len()]);
    displace(&d, &fine.mesh(), None, &mut apart, &mut nm).unwrap();
    let cracked = (0..p.len())
        .filter(|&i| apart[i] != apart[usize::from(fine.twins[i])])
        .count();
    assert!(cracked > 0, "without twins some copies part");
}

/// The silhouette, the difference from bump mapping: drawn the same way, the
/// undisplaced sphere (what a bump-mapped sphere's outline is: bump mapping only tilts
/// normals) has a round outline, the displaced one a rough outline. Measured as the spread
/// of the outline's radius, row by row, about the frame centre (where the sphere's centre
/// projects), in pixels.
#[test]
fn displacement_roughens_the_silhouette() {
    let s = demo::sphere();
    let bytes = rock();
    let fine = Fine::new(&s.mesh().unwrap(), 1).unwrap();
    let d = Displacement {
        map: HeightMap::new(&bytes, ROCK_WIDTH, ROCK_HEIGHT, 1).unwrap(),
        scale: fx(0.45),
        bias: fx(0.5),
        offset: [Fx::ZERO; 2],
    };
    let (p, n) = fine.displaced(&d);
    let rough = Mesh::new(&p, Some(&n), &fine.uvs, &fine.indices).unwrap();
    let spread = |mesh: &Mesh<'_>| {
        let (w, h) = (240u32, 240u32);
        let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
        let mut depth = vec![0u16; (w * h) as usize];
        let mut frame = Frame::new(&mut color, w, h)
            .unwrap()
            .with_depth(&mut depth)
            .unwrap();
        let camera =
            Camera::perspective(Angle::from_degrees(fx(40)), fx(1), fx(0.5), fx(20)).unwrap();
        let mode = DrawMode {
            shading: Shading::Flat,
            depth: DepthTest::Less,
            cull: Cull::Back,
            ..DrawMode::default()
        };
        let draw = Draw::dynamic(mode, None, Viewport::new(0, 0, w, h).unwrap())
            .unwrap()
            .with_flat_color(Rgb565::new(31, 63, 31));
        let model = Mat4::translation(Vec3::from_num(0, 0, -6));
        draw_mesh(&draw, mesh, &model, &camera, None, &mut frame).unwrap();
        // Outline radius per row: the farthest covered pixel centre from the centre.
        let c = f64::from(w) / 2.0;
        let radii: Vec<f64> = (0..h)
            .filter_map(|y| {
                let row = &color[(y * w) as usize..((y + 1) * w) as usize];
                let lit: Vec<u32> = (0..w)
                    .filter(|&x| row[x as usize] != Rgb565::new(0, 0, 0))
                    .collect();
                let dy = f64::from(y) + 0.5 - c;
                let (&a, &b) = (lit.first()?, lit.last()?);
                let dx = (c - f64::from(a) - 0.5).max(f64::from(b) + 0.5 - c);
                // Rows near the poles say little about the radius.
                (dy.abs() < 0.8 * dx.hypot(dy)).then(|| dx.hypot(dy))
            })
            .collect();
        let mean = radii.iter().sum::<f64>() / radii.len() as f64;
        let var = radii.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / radii.len() as f64;
        (mean, var.sqrt())
    };
    let smooth = spread(&s.mesh().unwrap());
    let displaced = spread(&rough);
    println!(
        "outline radius: smooth {:.1} ± {:.2} px, displaced {:.1} ± {:.2} px",
        smooth.0, smooth.1, displaced.0, displaced.1
    );
    assert!(smooth.1 < 1.0, "the undisplaced outline is round");
    assert!(
        displaced.1 > 3.0 * smooth.1.max(0.5),
        "the displaced outline is rough"
    );
}
