//! fixel's texture-coordinate generators (`fixel::scene::uv_gen`) against the f64
//! reference (`host_tests::reference::uv_gen`): the per-vertex error budget, the seam and
//! pole rules per triangle, and a sphere whose texture coordinates are generated, rendered
//! by both.

use fixel::math::{Fx, Vec3};
use fixel::pipeline::{DrawMode, Projection};
use fixel::scene::{map_mesh, map_mesh_capacity, Axis, MeshStorage, UvMapping};
use host_tests::adapter;
use host_tests::metrics::compare;
use host_tests::reference::uv_gen::{RefAxis, RefUvMapping};
use host_tests::reference::{self, RefTriangle};
use host_tests::scenes;
use proptest::prelude::*;

/// Largest error of a generated coordinate, in units of 2^-16 texture: the table `atan2`
/// (1.5 units, tested in `env::angles`) plus rounding.
const UV_BUDGET: f64 = 2.5;

fn axes() -> [(Axis, RefAxis); 3] {
    [
        (Axis::X, RefAxis::X),
        (Axis::Y, RefAxis::Y),
        (Axis::Z, RefAxis::Z),
    ]
}

fn to_f64(p: Vec3) -> [f64; 3] {
    [p.x.to_num(), p.y.to_num(), p.z.to_num()]
}

/// Distance of two `u` on the circle (1.0 = a turn), and of two `v`, in 2^-16 units.
fn errors(a: [Fx; 2], b: [f64; 2], wrap: bool) -> (f64, f64) {
    let du = a[0].to_num::<f64>() - b[0];
    let du = if wrap { du - du.round() } else { du };
    (
        du.abs() * 65536.0,
        (a[1].to_num::<f64>() - b[1]).abs() * 65536.0,
    )
}

fn mappings(c: Vec3, k: usize) -> (UvMapping, RefUvMapping) {
    let (axis, raxis) = axes()[k % 3];
    let rc = to_f64(c);
    match k / 3 {
        0 => (
            UvMapping::Spherical { center: c, axis },
            RefUvMapping::Spherical {
                center: rc,
                axis: raxis,
            },
        ),
        1 => (
            UvMapping::Cylindrical {
                center: c,
                axis,
                top: Fx::from_num(2),
                bottom: Fx::from_num(-3),
            },
            RefUvMapping::Cylindrical {
                center: rc,
                axis: raxis,
                top: 2.0,
                bottom: -3.0,
            },
        ),
        _ => {
            let (s, t) = (Vec3::from_num(0.25, 0.5, 0), Vec3::from_num(0, -0.125, 1));
            (
                UvMapping::Planar { origin: c, s, t },
                RefUvMapping::Planar {
                    origin: rc,
                    s: to_f64(s),
                    t: to_f64(t),
                },
            )
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]
    /// Every generator within the budget of the f64 formula, on any axis, away from the
    /// axis itself (where the longitude is undefined).
    #[test]
    fn generated_uv_within_budget(
        x in -60.0f64..60.0, y in -60.0f64..60.0, z in -60.0f64..60.0,
        cx in -2.0f64..2.0, k in 0usize..9,
    ) {
        let c = Vec3::from_num(cx, -cx, 0.5 * cx);
        let p = Vec3::from_num(x, y, z);
        let (m, r) = mappings(c, k);
        let (_, up, _) = r_frame(&r, to_f64(p), to_f64(c));
        let radial = (to_f64(p).iter().zip(to_f64(c)).map(|(a, b)| (a - b).powi(2)).sum::<f64>() - up * up).max(0.0).sqrt();
        prop_assume!(radial > 1e-3);
        let (got, want) = (m.uv(p).unwrap(), r.uv(to_f64(p)).0);
        let (eu, ev) = errors(got, want, r.wraps());
        // Planar products of 60-unit positions: rounding of two Q16 products.
        prop_assert!(eu <= UV_BUDGET && ev <= UV_BUDGET, "{p:?} {m:?}: u {eu:.2} v {ev:.2}");
    }
}

/// The `up` component of `p − c` in `r`'s frame (0 for planar).
fn r_frame(r: &RefUvMapping, p: [f64; 3], c: [f64; 3]) -> (f64, f64, f64) {
    let d = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
    match *r {
        RefUvMapping::Spherical { axis, .. } | RefUvMapping::Cylindrical { axis, .. } => {
            axis.frame(d)
        }
        RefUvMapping::Planar { .. } => (0.0, 0.0, 0.0),
    }
}

/// The demo sphere mapped spherically and cylindrically: every triangle's corners (after
/// the seam and pole rules) match the reference's per-triangle rule within the budget,
/// and no triangle spans more than half the texture.
#[test]
fn seam_and_poles_match_the_reference() {
    let s = fixel_scenes::sphere();
    for k in [1, 4] {
        let (m, r) = mappings(Vec3::ZERO, k);
        let need = map_mesh_capacity(&m, &s.positions, &s.indices).unwrap();
        let (mut p, mut uv, mut ix) = (
            vec![Vec3::ZERO; need],
            vec![[Fx::ZERO; 2]; need],
            vec![[0u16; 3]; s.indices.len()],
        );
        let storage = MeshStorage {
            positions: &mut p,
            normals: None,
            uvs: &mut uv,
            indices: &mut ix,
        };
        let used = map_mesh(&m, &s.positions, None, &s.indices, storage)
            .unwrap()
            .vertices();
        assert!(used <= need);
        let mut worst: f64 = 0.0;
        let mut seams = 0;
        for (t, src) in s.indices.iter().enumerate() {
            let want = r.triangle(src.map(|i| to_f64(s.positions[usize::from(i)])));
            if want.iter().any(|c| c[0] >= 1.0) {
                seams += 1;
            }
            for c in 0..3 {
                let got = uv[usize::from(ix[t][c])];
                let (eu, ev) = errors(got, want[c], false);
                worst = worst.max(eu).max(ev);
            }
            let us = ix[t].map(|i| uv[usize::from(i)][0].to_num::<f64>());
            let span = us.iter().copied().fold(f64::MIN, f64::max)
                - us.iter().copied().fold(f64::MAX, f64::min);
            assert!(span <= 0.5, "triangle {t} spans {span} of the texture");
        }
        assert!(
            seams >= 24,
            "the seam column should be fixed ({seams} triangles)"
        );
        assert!(worst <= UV_BUDGET, "{m:?}: {worst:.2} units");
        println!(
            "{m:?}: {} vertices -> {} (bound {need}; {seams} seam triangles), worst {worst:.2} / 65536",
            s.positions.len(),
            used
        );
    }
}

/// The benchmark sphere with spherically generated coordinates, rendered by fixel and by
/// the reference (both from the same clip positions): the seam column and the poles
/// within the sphere scene's usual budget (a squeezed seam would miss it by far).
#[test]
fn generated_sphere_renders_like_the_reference() {
    let scene = scenes::sphere(0);
    let fs = fixel_scenes::sphere();
    let (m, r) = mappings(Vec3::ZERO, 1);
    let need = map_mesh_capacity(&m, &fs.positions, &fs.indices).unwrap();
    let (mut p, mut uv, mut ix) = (
        vec![Vec3::ZERO; need],
        vec![[Fx::ZERO; 2]; need],
        vec![[0u16; 3]; fs.indices.len()],
    );
    let storage = MeshStorage {
        positions: &mut p,
        normals: None,
        uvs: &mut uv,
        indices: &mut ix,
    };
    map_mesh(&m, &fs.positions, None, &fs.indices, storage).unwrap();
    let mut tris: Vec<RefTriangle> = scenes::to_ref_triangles(&scene);
    assert_eq!(tris.len(), fs.indices.len());
    let mesh = &scene.mesh;
    for (t, tri) in tris.iter_mut().enumerate() {
        let want = r.triangle(mesh.indices[t].map(|i| mesh.positions[usize::from(i)]));
        for (v, uv) in tri.0.iter_mut().zip(want) {
            v.uv = uv;
        }
    }
    let reference = reference::render(&tris, Some(&scene.texture), &scene.mode, 320, 240);
    let mut clip = adapter::clip_triangles(&tris);
    for (t, tri) in clip.iter_mut().enumerate() {
        for c in 0..3 {
            tri[c].uv = uv[usize::from(ix[t][c])];
        }
    }
    let mode: DrawMode = adapter::draw_mode(&scene.mode, Some(Projection::Exact), true);
    let img = adapter::render(&clip, Some(&scene.texture), mode, 320, 240);
    let rep = compare(&img.pixels, &img.covered, &reference);
    println!("generated sphere: {rep}");
    assert!(rep.psnr_db > 40.0 && rep.p99 <= 2, "{rep}");
}
