//! Tests of the mesh's facing tests against each other: the baked face planes against the
//! position test, the public facing test against the walker's.

extern crate std;
use crate::geometry::Cull;
use crate::math::{Angle, Fx, Mat4, Vec3};
use crate::scene::face_cull::{camera_centre, test_camera, FaceCull};
use crate::scene::face_planes::*;
use crate::scene::walk::MeshTransform;
use crate::scene::Mesh;
use crate::test_rng::Rng;
use crate::Error;
use std::vec::Vec;

fn fx_of(rng: &mut Rng, range: f64) -> Fx {
    Fx::saturating_from_num((rng.unit01() * 2.0 - 1.0) * range)
}

/// The plane's test decides as the positions' test, triangle by triangle: meshes from
/// 0.001 to 30,000 units across (every shift, coordinates up to the I16F16 limit),
/// slivers and repeated corners, random cameras, both culled orientations.
#[test]
fn the_plane_test_is_the_position_test() {
    let mut rng = Rng(0xface_91a7);
    let camera = test_camera();
    let (mut culled, mut total) = (0usize, 0usize);
    for round in 0..400u32 {
        let scale = [0.001f64, 0.3, 2.0, 40.0, 900.0, 30_000.0][round as usize % 6];
        let n = 3 + (rng.next() % 40) as usize;
        let positions: Vec<Vec3> = (0..n)
            .map(|_| {
                Vec3::new(
                    fx_of(&mut rng, scale),
                    fx_of(&mut rng, scale),
                    fx_of(&mut rng, scale),
                )
            })
            .collect();
        let uvs = std::vec![[Fx::ZERO; 2]; n];
        let indices: Vec<[u16; 3]> = (0..60)
            .map(|_| core::array::from_fn(|_| (rng.next() % n as u64) as u16))
            .collect();
        let mut planes = std::vec![FacePlane::ZERO; indices.len()];
        write_face_planes(&positions, &indices, &mut planes).unwrap();
        let mesh = Mesh::new(&positions, None, &uvs, &indices).unwrap();
        let baked = mesh.with_face_planes(&planes).unwrap();
        let s = Fx::saturating_from_num(1.0 / scale.max(1.0));
        let turn = Angle((rng.next() >> 48) as u16);
        let model = Mat4::translation(Vec3::new(
            fx_of(&mut rng, 1.0),
            fx_of(&mut rng, 1.0),
            Fx::from_num(-6),
        ))
        .mul(&Mat4::rotation_y(turn))
        .mul(&Mat4::rotation_x(Angle(turn.0.wrapping_mul(5))))
        .mul(&Mat4::scaling(Vec3::new(s, s, s)));
        let mvp = camera.projection.mul(&camera.view.mul(&model));
        let eye = camera_centre(&mvp);
        for cull in [Cull::Back, Cull::Front] {
            let test = FaceCull::new(&eye, &mesh, cull).unwrap();
            // The baked mesh's largest margin bounds every plane's.
            let m = test.margin_max(&baked);
            for (t, (idx, p)) in indices.iter().zip(&planes).enumerate() {
                let by_positions = test.culls(&positions, idx);
                assert_eq!(
                    test.culls_plane(p, m),
                    by_positions,
                    "round {round} triangle {t}"
                );
                assert_eq!(test.culls_in(&baked, t, idx), by_positions);
                culled += usize::from(by_positions);
                total += 1;
            }
        }
    }
    // Both answers occur often.
    assert!(
        culled > total / 5 && culled < total * 4 / 5,
        "{culled} of {total}"
    );
}

/// Baked at compile time, the planes are the run-time ones; storage of the wrong length,
/// a plane of another triangle and an index out of range are errors, not panics.
#[test]
fn baking_and_checking() {
    const P: [Vec3; 4] = [
        Vec3::new(Fx::from_bits(0), Fx::from_bits(0), Fx::from_bits(0)),
        Vec3::new(Fx::from_bits(1 << 16), Fx::from_bits(0), Fx::from_bits(0)),
        Vec3::new(Fx::from_bits(0), Fx::from_bits(1 << 16), Fx::from_bits(0)),
        Vec3::new(Fx::from_bits(0), Fx::from_bits(0), Fx::from_bits(-3 << 16)),
    ];
    const I: [[u16; 3]; 3] = [[0, 1, 2], [0, 3, 1], [2, 3, 0]];
    static BAKED: [FacePlane; 3] = face_planes(&P, &I);
    let mut run = [FacePlane::ZERO; 3];
    write_face_planes(&P, &I, &mut run).unwrap();
    assert_eq!(BAKED, run);
    let uvs = [[Fx::ZERO; 2]; 4];
    let mesh = Mesh::new(&P, None, &uvs, &I).unwrap();
    assert_eq!(mesh.with_face_planes(&BAKED).unwrap().face_planes(), &BAKED);
    assert_eq!(
        mesh.with_face_planes(&BAKED[..2]).unwrap_err(),
        Error::FacePlaneMismatch { triangle: 2 }
    );
    let swapped = [BAKED[0], BAKED[2], BAKED[1]];
    assert_eq!(
        mesh.with_face_planes(&swapped).unwrap_err(),
        Error::FacePlaneMismatch { triangle: 1 }
    );
    assert_eq!(
        write_face_planes(&P, &I, &mut run[..2]).unwrap_err(),
        Error::WrongLength {
            expected: 3,
            actual: 2
        }
    );
    let bad = [[0u16, 1, 4]];
    assert!(matches!(
        write_face_planes(&P, &bad, &mut run[..1]),
        Err(Error::IndexOutOfRange { index: 4, .. })
    ));
}

/// The public test is the walker's, triangle by triangle; a triangle is never culled
/// both as a back and as a front face, and an index out of range is never culled.
#[test]
fn the_facing_test_is_the_walkers() {
    let data = crate::test_scenes::sphere();
    let mesh = data.mesh().unwrap();
    let camera = crate::test_scenes::camera(0);
    for frame in 0..4 {
        let transform = MeshTransform::new(&crate::test_scenes::sphere_model(frame), &camera);
        let mvp = camera
            .projection
            .mul(&camera.view.mul(&crate::test_scenes::sphere_model(frame)));
        let eye = camera_centre(&mvp);
        let back = transform.facing_test(&mesh, Cull::Back).unwrap();
        let front = transform.facing_test(&mesh, Cull::Front).unwrap();
        let walker = FaceCull::new(&eye, &mesh, Cull::Back).unwrap();
        let mut culled = 0;
        for (t, idx) in mesh.indices().iter().enumerate() {
            assert_eq!(back.culls(t), walker.culls(mesh.positions(), idx));
            assert!(!(back.culls(t) && front.culls(t)));
            culled += usize::from(back.culls(t));
        }
        assert!(culled * 2 > mesh.triangles());
        assert!(!back.culls(mesh.triangles()) && !back.culls(usize::MAX));
        assert!(transform.facing_test(&mesh, Cull::None).is_none());
    }
}
