//! Displacement mapping (issue 14 §3): fixel's subdivision, displacement and recomputed
//! normals against the f64 reference (`host_tests::reference::displace`), a property test
//! over scale, bias and offset, and the hard cases: a fold, zero-area triangles, storage
//! too small, indices out of range.
//!
//! Error budgets (I16F16 LSB = 2^-16 model units), see `position_budget`: positions within
//! `1 + |scale| + levels / 2` LSB, plus, once subdivided, `|scale| Δh (w + h) / 256` LSB for the
//! midpoints' texture coordinates rounded to I16F16 (`Δh` the largest step between
//! neighbouring texels of the `w x h` map). On the rocky sphere (scale 0.45, Δh = 102, 128 x
//! 64) that measures 1.1, 9.2 and 15.8 LSB at 0, 1 and 2 levels. Normals within
//! `NORMAL_BUDGET` (2^-7) per component where the reference's direction is well conditioned
//! (the vertex's normal sum at least 1/64 of the largest face's; elsewhere, near a fold,
//! only unit length is checked): the positions' error over edges of 0.05 units, measured
//! 3.4e-4, 9.0e-4 and 3.1e-3.

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use fixel::demo::displaced::{
    grid, rock_heights, wave_heights, ROCK_HEIGHT, ROCK_WIDTH, WAVE_SIDE,
};
use fixel::demo::{self, MeshData};
use fixel::geometry::{Cull, Viewport};
use fixel::math::{fx, Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection, Shading};
use fixel::scene::{
    count_edges, count_edges_words, displace, draw_mesh, recompute_normals, subdivide,
    subdivide_capacity, weld, weld_table_words, Camera, DirectionalLight, Displacement, Mesh,
    MeshStorage,
};
use fixel::surface::Frame;
use fixel::texture::HeightMap;
use fixel::{Error, Rgb565};
use host_tests::reference::displace::{self as reference, RefDisplacement, RefHeights, RefMesh};
use proptest::prelude::*;

const NORMAL_BUDGET: f64 = 1.0 / 128.0;
const LSB: f64 = 65536.0;

fn f3(v: Vec3) -> [f64; 3] {
    [v.x.to_num(), v.y.to_num(), v.z.to_num()]
}

fn to_ref(m: &Mesh<'_>) -> RefMesh {
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
struct Fine {
    base: Vec<Vec3>,
    normals: Vec<Vec3>,
    uvs: Vec<[Fx; 2]>,
    indices: Vec<[u16; 3]>,
    twins: Vec<u16>,
}

impl Fine {
    fn new(src: &Mesh<'_>, levels: u32) -> Result<Fine, Error> {
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

    fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.base, Some(&self.normals), &self.uvs, &self.indices).unwrap()
    }

    fn displaced(&self, d: &Displacement<'_>) -> (Vec<Vec3>, Vec<Vec3>) {
        let n = self.base.len();
        let (mut p, mut nm) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        displace(d, &self.mesh(), Some(&self.twins), &mut p, &mut nm).unwrap();
        (p, nm)
    }
}

/// Largest step between neighbouring texels (wrapping), in height steps.
fn max_step(bytes: &[u8], w: usize, h: usize) -> f64 {
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

/// `(max position error in LSB, max normal error per component where well conditioned,
/// largest |length - 1| of any normal)`.
fn compare(
    src: &Mesh<'_>,
    levels: u32,
    bytes: &[u8],
    (w, h): (u32, u32),
    scale: f64,
    bias: f64,
    offset: [f64; 2],
) -> (f64, f64, f64) {
    let fine = Fine::new(src, levels).unwrap();
    let d = Displacement {
        map: HeightMap::new(bytes, w, h, 1).unwrap(),
        scale: fx(scale),
        bias: fx(bias),
        offset: offset.map(fx),
    };
    let (p, n) = fine.displaced(&d);
    let map = RefHeights {
        bytes,
        width: w as usize,
        height: h as usize,
    };
    // The reference sees the values fixel was given (scale, bias, offset in I16F16).
    let rd = RefDisplacement {
        scale: d.scale.to_num(),
        bias: d.bias.to_num(),
        offset: d.offset.map(|c| c.to_num()),
    };
    let (r, cond) = reference::displaced(&to_ref(src), levels, &map, &rd);
    assert_eq!(r.positions.len(), p.len(), "vertex count");
    assert_eq!(
        r.indices,
        fine.indices
            .iter()
            .map(|t| t.map(usize::from))
            .collect::<Vec<_>>(),
        "triangles"
    );
    let (mut ep, mut en, mut unit) = (0f64, 0f64, 0f64);
    for i in 0..p.len() {
        let (a, b) = (f3(p[i]), r.positions[i]);
        for k in 0..3 {
            ep = ep.max((a[k] - b[k]).abs() * LSB);
        }
        let (a, b) = (f3(n[i]), r.normals[i]);
        unit = unit.max((reference::length(a) - 1.0).abs());
        if cond[i] >= 1.0 / 64.0 {
            for k in 0..3 {
                en = en.max((a[k] - b[k]).abs());
            }
        }
    }
    (ep, en, unit)
}

/// The position budget in LSB for a `w x h` map whose largest texel step is `step`: the
/// height rounded twice, to Q8 steps and to a Q16 fraction (`|scale|`), the rounding of `scale (h − bias)` and of its product with the normal, half an LSB per
/// level of midpoints, and, once subdivided, the midpoints' texture coordinates rounded to
/// I16F16 (up to 1 LSB of `u` and `v`: `step · (w + h) / 65536` height steps).
fn position_budget(levels: u32, scale: f64, step: f64, (w, h): (u32, u32)) -> f64 {
    let uv = if levels > 0 {
        scale.abs() * step * f64::from(w + h) / 256.0
    } else {
        0.0
    };
    1.0 + scale.abs() + f64::from(levels) / 2.0 + uv
}

fn rock() -> Vec<u8> {
    let mut h = vec![0u8; (ROCK_WIDTH * ROCK_HEIGHT) as usize];
    rock_heights(&mut h).unwrap();
    h
}

#[test]
fn rocky_sphere_within_budget() {
    let s = demo::sphere();
    let bytes = rock();
    let step = max_step(&bytes, ROCK_WIDTH as usize, ROCK_HEIGHT as usize);
    for levels in [0, 1, 2] {
        let (ep, en, unit) = compare(
            &s.mesh().unwrap(),
            levels,
            &bytes,
            (ROCK_WIDTH, ROCK_HEIGHT),
            0.45,
            0.5,
            [0.0; 2],
        );
        let budget = position_budget(levels, 0.45, step, (ROCK_WIDTH, ROCK_HEIGHT));
        println!(
            "rock sphere, {levels} levels: positions {ep:.2} LSB (budget {budget:.2}, step {step}), \
             normals {en:.2e} per component, |n| - 1 <= {unit:.1e}"
        );
        assert!(ep <= budget, "positions {ep} LSB > {budget}");
        assert!(en <= NORMAL_BUDGET, "normals {en}");
        assert!(unit <= 1.0 / 4096.0, "unit length {unit}");
    }
}

fn small_grid() -> MeshData<25, 32> {
    grid(4, fx(1))
}

fn waves() -> Vec<u8> {
    let mut h = vec![0u8; (WAVE_SIDE * WAVE_SIDE) as usize];
    wave_heights(&mut h).unwrap();
    h
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Any scale (including folds), bias and offset: positions within budget, normals unit,
    /// and within budget wherever the surface is not folded onto itself.
    #[test]
    fn random_displacements_stay_within_budget(
        scale in -3.0f64..3.0,
        bias in 0.0f64..1.0,
        ou in -4.0f64..4.0,
        ov in -4.0f64..4.0,
        levels in 0u32..3,
    ) {
        let g = small_grid();
        let bytes = waves();
        let step = max_step(&bytes, WAVE_SIDE as usize, WAVE_SIDE as usize);
        let (ep, en, unit) = compare(
            &g.mesh().unwrap(), levels, &bytes, (WAVE_SIDE, WAVE_SIDE), scale, bias, [ou, ov],
        );
        prop_assert!(ep <= position_budget(levels, scale, step, (WAVE_SIDE, WAVE_SIDE)), "positions {} LSB", ep);
        prop_assert!(en <= NORMAL_BUDGET, "normals {}", en);
        prop_assert!(unit <= 1.0 / 4096.0, "unit length {}", unit);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    /// The same on a small sphere, where large scales fold the surface (normals converge):
    /// positions within budget, normals unit, and within budget where well conditioned.
    #[test]
    fn random_displacements_of_a_sphere_stay_within_budget(
        scale in -4.0f64..4.0,
        bias in 0.0f64..1.0,
        ou in -2.0f64..2.0,
        levels in 0u32..2,
    ) {
        let s: MeshData<{ 7 * 13 }, { 2 * 12 * 5 }> = demo::uv_sphere(6, 12);
        let bytes = rock();
        let step = max_step(&bytes, ROCK_WIDTH as usize, ROCK_HEIGHT as usize);
        let (ep, en, unit) = compare(
            &s.mesh().unwrap(), levels, &bytes, (ROCK_WIDTH, ROCK_HEIGHT), scale, bias, [ou, 0.0],
        );
        prop_assert!(
            ep <= position_budget(levels, scale, step, (ROCK_WIDTH, ROCK_HEIGHT)),
            "positions {} LSB", ep
        );
        prop_assert!(en <= NORMAL_BUDGET, "normals {}", en);
        prop_assert!(unit <= 1.0 / 4096.0, "unit length {}", unit);
    }
}

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

/// A checksum of the displaced sphere drawn lit (Gouraud), so any change to subdivision,
/// displacement or normals shows; FNV-1a of the RGB565 frame.
#[test]
fn rendered_rocky_sphere_checksum() {
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
    let mesh = Mesh::new(&p, Some(&n), &fine.uvs, &fine.indices).unwrap();
    let (w, h) = (160u32, 120u32);
    let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    let mut depth = vec![0u16; (w * h) as usize];
    let mut frame = Frame::new(&mut color, w, h)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    let camera =
        Camera::perspective(Angle::from_degrees(fx(40)), fx(4) / 3, fx(0.5), fx(20)).unwrap();
    let mode = DrawMode {
        projection: Projection::Exact,
        shading: Shading::Gouraud,
        depth: DepthTest::Less,
        cull: Cull::Back,
        ..DrawMode::default()
    };
    let draw = Draw::dynamic(mode, None, Viewport::new(0, 0, w, h).unwrap()).unwrap();
    let model = Mat4::translation(Vec3::from_num(0, 0, -6))
        * Mat4::rotation_y(Angle::from_degrees(fx(-40)));
    let light = DirectionalLight::default();
    let px = draw_mesh(&draw, &mesh, &model, &camera, Some(&light), &mut frame).unwrap();
    let mut hash = 0xcbf2_9ce4_8422_2325u64;
    for c in &color {
        for b in RawU16::from(*c).into_inner().to_le_bytes() {
            hash = (hash ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
        }
    }
    println!("rocky sphere: {px} pixels, checksum {hash:#018x}");
    assert!(px > 4000);
    assert_eq!(
        hash, 0x9294_7d21_3da2_39d7,
        "checksum changed: look at examples/displacement and update"
    );
}

mod baked {
    include!("../../assets/displaced/rock_sphere.rs");
}

/// `assets/displaced/rock_sphere.rs` (`cargo xtask bake-displaced`) is what the run-time
/// functions make from the coarse demo sphere: re-bake after changing them.
#[test]
fn baked_rock_sphere_is_fresh() {
    let s: MeshData<{ 13 * 25 }, { 2 * 24 * 11 }> = demo::uv_sphere(12, 24);
    let fine = Fine::new(&s.mesh().unwrap(), 1).unwrap();
    let bytes = rock();
    let d = Displacement {
        map: HeightMap::new(&bytes, ROCK_WIDTH, ROCK_HEIGHT, 1).unwrap(),
        scale: fx(0.45),
        bias: fx(0.5),
        offset: [Fx::ZERO; 2],
    };
    let (p, n) = fine.displaced(&d);
    assert_eq!(p.as_slice(), baked::ROCK_POSITIONS.as_slice());
    assert_eq!(n.as_slice(), baked::ROCK_NORMALS.as_slice());
    assert_eq!(fine.uvs.as_slice(), baked::ROCK_UVS.as_slice());
    assert_eq!(fine.indices.as_slice(), baked::ROCK_INDICES.as_slice());
}

mod water_base {
    include!("../../assets/displaced/water_base.rs");
}

/// `assets/displaced/water_base.rs` (`cargo xtask bake-displaced --mesh water`, the
/// firmware's `water` scene) is the 6 x 6 grid subdivided once, flat, and the swell.
#[test]
fn baked_water_base_is_fresh() {
    let g: MeshData<49, 72> = grid(6, fx(2.4));
    let fine = Fine::new(&g.mesh().unwrap(), 1).unwrap();
    let bytes = waves();
    let d = Displacement {
        map: HeightMap::new(&bytes, WAVE_SIDE, WAVE_SIDE, 1).unwrap(),
        scale: Fx::ZERO,
        bias: fx(0.5),
        offset: [Fx::ZERO; 2],
    };
    let (p, n) = fine.displaced(&d);
    assert_eq!(p.as_slice(), water_base::WATER_POSITIONS.as_slice());
    assert_eq!(n.as_slice(), water_base::WATER_NORMALS.as_slice());
    assert_eq!(fine.uvs.as_slice(), water_base::WATER_UVS.as_slice());
    assert_eq!(
        fine.indices.as_slice(),
        water_base::WATER_INDICES.as_slice()
    );
    assert_eq!(bytes.as_slice(), water_base::WATER_HEIGHTS.as_slice());
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

/// The silhouette, the difference from bump mapping (issue 14 §3): drawn the same way, the
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
