//! Shadow maps against the f64 reference (`host_tests::reference::shadow`), and the hard
//! cases of the issue: acne at a grazing angle, peter-panning at a contact line, objects
//! partly outside the light's frustum, a spot light's near plane, a 16 x 16 map, a depth
//! range that uses all 16 bits; and the lit pass in bands.
//!
//! Errors are in lit fraction (0..=1) per covered pixel: `mean` is the mean absolute
//! difference, `wrong` the pixels on the other side of a shadow edge (difference > 0.5).

use fixel::geometry::Cull;
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::shading::pcf::{Pcf2x2, Pcf3x3, ShadowFilter, SingleTap};
use fixel::shading::shadow::{Bias, Directional, LightKind, LightSpace, Outside};
use fixel_scenes::shadow::{self as scene, SceneLight};
use host_tests::reference::shadow::{light_map, lit_pass, RefShadowFilter, RefShadowImage};
use host_tests::shadow_scene::{
    demo_meshes, fixel_shadow, fixel_shadow_uv, lit_error, ref_bias, ref_scene, FixelShadow,
    LitError, SceneMesh, Setup,
};

fn ref_filter<F: ShadowFilter>() -> RefShadowFilter {
    match F::NAME {
        "single tap" => RefShadowFilter::Single,
        "PCF 2x2 bilinear" => RefShadowFilter::Pcf2x2,
        _ => RefShadowFilter::Pcf3x3,
    }
}

fn reference<K: LightKind>(
    meshes: &[SceneMesh],
    space: &LightSpace<K>,
    s: &Setup,
    f: RefShadowFilter,
) -> RefShadowImage {
    let sc = ref_scene(meshes, &scene::camera(), space.matrix(), s.w, s.h);
    let map = light_map(&sc, s.size, s.light_cull == Cull::Front);
    let outside = if s.outside == Outside::Lit { 1.0 } else { 0.0 };
    lit_pass(&sc, &map, f, &ref_bias(&s.bias), outside)
}

fn run<K: LightKind, F: ShadowFilter, const M: usize>(
    name: &str,
    meshes: &[SceneMesh],
    space: &LightSpace<K>,
    s: &Setup,
) -> (LitError, FixelShadow, RefShadowImage) {
    let fx = fixel_shadow::<K, F, M>(meshes, &scene::camera(), space, s);
    let r = reference(meshes, space, s, ref_filter::<F>());
    let e = lit_error(&fx.lit, &fx.covered, &r.lit, &r.covered);
    println!(
        "shadow {name}: {} {} map {}: {e} | light pass {} texels, lit pass {} px",
        K::NAME,
        F::NAME,
        s.size,
        fx.texels_written,
        fx.pixels
    );
    (e, fx, r)
}

/// Shadowed pixels (lit fraction < 1/2) of an image.
fn shadowed(lit: &[f64], cov: &[bool]) -> usize {
    lit.iter()
        .zip(cov)
        .filter(|(l, c)| **c && **l < 0.5)
        .count()
}

// Budgets (measured, 320 x 240, demo scene, 47.6 k covered pixels): see each test.

#[test]
fn directional_matches_reference_for_each_filter() {
    let high = scene::directional(SceneLight::High).unwrap();
    let m = demo_meshes();
    let (e1, fx, r) = run::<_, SingleTap, 3>("high", &m, &high, &Setup::new::<SingleTap>(64));
    let (e2, ..) = run::<_, Pcf2x2, 3>("high", &m, &high, &Setup::new::<Pcf2x2>(64));
    let (e3, ..) = run::<_, Pcf3x3, 3>("high", &m, &high, &Setup::new::<Pcf3x3>(64));
    // The scene has a shadow, and fixel and the reference agree it is there.
    let (sf, sr) = (shadowed(&fx.lit, &fx.covered), shadowed(&r.lit, &r.covered));
    assert!(sr > 3000, "the reference casts too little shadow: {sr}");
    assert!(
        sf.abs_diff(sr) < sr / 50,
        "shadowed pixels: fixel {sf}, reference {sr}"
    );
    for e in [e1, e2, e3] {
        assert_eq!(e.coverage_diff, 0, "{e}");
        assert!(e.mean < 0.01, "{e}");
        assert!((e.wrong as f64) < 0.005 * e.both as f64, "{e}");
    }
}

/// The real-time form (`ShadowedUv`: light coordinates from texture coordinates) against
/// the reference, with the budgets of the light-varying form.
#[test]
fn through_texture_coordinates_matches_reference_for_each_filter() {
    fn check<K: LightKind, F: ShadowFilter, const M: usize>(
        name: &str,
        space: &LightSpace<K>,
    ) -> LitError {
        let m = demo_meshes();
        let s = Setup::new::<F>(64);
        let fx = fixel_shadow_uv::<K, F, M>(&m, &scene::camera(), space, &s);
        let r = reference(&m, space, &s, ref_filter::<F>());
        let e = lit_error(&fx.lit, &fx.covered, &r.lit, &r.covered);
        println!(
            "shadow through uv {name}: {} {} map 64: {e}",
            K::NAME,
            F::NAME
        );
        assert_eq!(e.coverage_diff, 0, "{e}");
        assert!(e.mean < 0.01, "{e}");
        assert!((e.wrong as f64) < 0.005 * e.both as f64, "{e}");
        e
    }
    let high = scene::directional(SceneLight::High).unwrap();
    check::<_, SingleTap, 5>("high", &high);
    check::<_, Pcf2x2, 5>("high", &high);
    check::<_, Pcf3x3, 5>("high", &high);
    check::<_, Pcf2x2, 6>("spot", &scene::spot().unwrap());
}

#[test]
fn spot_matches_reference() {
    let spot = scene::spot().unwrap();
    let m = demo_meshes();
    for outside in [Outside::Lit, Outside::Shadowed] {
        let mut s = Setup::new::<Pcf2x2>(64);
        s.outside = outside;
        let (e, fx, _) = run::<_, Pcf2x2, 4>("spot", &m, &spot, &s);
        assert!(shadowed(&fx.lit, &fx.covered) > 2000);
        assert!(e.mean < 0.01, "{e}");
        assert!((e.wrong as f64) < 0.005 * e.both as f64, "{e}");
    }
    let (e, ..) = run::<_, SingleTap, 4>("spot", &m, &spot, &Setup::new::<SingleTap>(64));
    assert!(e.mean < 0.01, "{e}");
    let (e, ..) = run::<_, Pcf3x3, 4>("spot", &m, &spot, &Setup::new::<Pcf3x3>(64));
    assert!(e.mean < 0.01, "{e}");
}

/// The floor alone under the grazing light (11 degrees): nothing occludes it, so every
/// pixel that is not fully lit is acne.
#[test]
fn acne_at_a_grazing_angle_is_removed_by_the_bias() {
    let grazing = scene::directional(SceneLight::Grazing).unwrap();
    let floor = demo_meshes().remove(1);
    let m = [floor];
    let acne = |fx: &FixelShadow| {
        fx.lit
            .iter()
            .zip(&fx.covered)
            .filter(|(l, c)| **c && **l < 1.0)
            .count()
    };
    let mut none = Setup::new::<SingleTap>(64);
    none.bias = Bias::NONE;
    let (_, raw, _) = run::<_, SingleTap, 3>("acne, no bias", &m, &grazing, &none);
    let mut constant = none;
    constant.bias.constant = 4 * 16;
    let (_, cst, _) = run::<_, SingleTap, 3>("acne, constant 4", &m, &grazing, &constant);
    let (_, single, _) =
        run::<_, SingleTap, 3>("acne, biased", &m, &grazing, &Setup::new::<SingleTap>(64));
    let (_, pcf2, _) = run::<_, Pcf2x2, 3>("acne, biased", &m, &grazing, &Setup::new::<Pcf2x2>(64));
    let (_, pcf3, _) = run::<_, Pcf3x3, 3>("acne, biased", &m, &grazing, &Setup::new::<Pcf3x3>(64));
    let covered = raw.covered.iter().filter(|c| **c).count();
    println!(
        "acne pixels of {covered}: no bias {}, constant 4 steps {}, default bias: single {}, \
         2x2 {}, 3x3 {}",
        acne(&raw),
        acne(&cst),
        acne(&single),
        acne(&pcf2),
        acne(&pcf3)
    );
    assert!(acne(&raw) > covered / 5, "no acne without bias?");
    assert_eq!(acne(&single), 0);
    assert_eq!(acne(&pcf2), 0);
    assert_eq!(acne(&pcf3), 0);
}

/// An unrotated cube standing on the floor (bottom face at the floor's height): the shadow
/// should reach the contact line. Light leaking through the gap (pixels the 1024 x 1024 f64
/// map with a tiny bias shadows and fixel lights) grows with the bias.
#[test]
fn peter_panning_gap_against_the_bias() {
    let high = scene::directional(SceneLight::High).unwrap();
    let mut m = demo_meshes();
    m[0].model = Mat4::translation(Vec3::new(
        Fx::ZERO,
        scene::FLOOR_Y + Fx::ONE,
        Fx::from_num(-4),
    ));
    let truth_setup = Setup {
        bias: Bias {
            constant: 16,
            slope: 128,
            max: 1 << 20,
        },
        ..Setup::new::<SingleTap>(1024)
    };
    let truth = reference(&m, &high, &truth_setup, RefShadowFilter::Single);
    let mut leaks = Vec::new();
    for slope in [64, 192, 384, 768, 1536] {
        let mut s = Setup::new::<SingleTap>(64);
        s.bias.slope = slope;
        let fx = fixel_shadow::<Directional, SingleTap, 3>(&m, &scene::camera(), &high, &s);
        let leak = (0..fx.lit.len())
            .filter(|&i| {
                fx.covered[i] && truth.covered[i] && truth.lit[i] < 0.5 && fx.lit[i] >= 0.5
            })
            .count();
        println!(
            "peter-panning: slope factor {:.2}: {leak} leaking pixels",
            f64::from(slope) / 256.0
        );
        leaks.push(leak);
    }
    assert!(leaks.windows(2).all(|w| w[0] <= w[1] + 5), "{leaks:?}");
    assert!(leaks[4] > leaks[0], "{leaks:?}");
    assert!(
        leaks[1] < 600,
        "default-size bias leaks too much: {leaks:?}"
    );
}

/// A light box of half-side 2 around the cube: most of the floor is outside it.
#[test]
fn objects_partly_outside_the_light_frustum() {
    let dir = Vec3::new(Fx::from_num(-0.5), Fx::ONE, Fx::from_num(0.4))
        .normalize()
        .unwrap();
    let c = Vec3::new(Fx::ZERO, Fx::from_num(-1), Fx::from_num(-4));
    let small = LightSpace::directional(
        c + dir.scale(Fx::from_num(6)),
        c,
        Vec3::from_num(0, 1, 0),
        Fx::from_num(2),
        Fx::ONE,
        Fx::from_num(12),
    )
    .unwrap();
    let m = demo_meshes();
    let mut counts = Vec::new();
    for outside in [Outside::Lit, Outside::Shadowed] {
        let s = Setup {
            outside,
            ..Setup::new::<Pcf2x2>(32)
        };
        let (e, fx, _) = run::<_, Pcf2x2, 3>("small box", &m, &small, &s);
        assert!(
            e.mean < 0.01 && (e.wrong as f64) < 0.005 * e.both as f64,
            "{e}"
        );
        counts.push(shadowed(&fx.lit, &fx.covered));
    }
    assert!(
        counts[1] > counts[0] + 10_000,
        "outside policy has no effect: {counts:?}"
    );
}

/// A spot light whose near plane (at 1.5) cuts through the cube: the cut-off part casts
/// nothing, points in front of the near plane are outside (lit), and nothing panics.
#[test]
fn spot_light_near_plane() {
    let close = LightSpace::spot(
        Vec3::new(Fx::from_num(-1.8), Fx::from_num(1.2), Fx::from_num(-3.2)),
        Vec3::new(Fx::from_num(0.5), scene::FLOOR_Y, Fx::from_num(-5)),
        Vec3::from_num(0, 1, 0),
        Angle::from_degrees(Fx::from_num(90)),
        Fx::from_num(1.5),
        Fx::from_num(10),
    )
    .unwrap();
    let m = demo_meshes();
    let (e, fx, r) = run::<_, Pcf2x2, 4>("near plane", &m, &close, &Setup::new::<Pcf2x2>(64));
    assert!(fx.texels_written > 0);
    assert!(shadowed(&r.lit, &r.covered) > 500);
    assert!(
        e.mean < 0.015 && (e.wrong as f64) < 0.01 * e.both as f64,
        "{e}"
    );
}

#[test]
fn map_of_16x16() {
    let high = scene::directional(SceneLight::High).unwrap();
    let m = demo_meshes();
    let (e, ..) = run::<_, Pcf2x2, 3>("tiny", &m, &high, &Setup::new::<Pcf2x2>(16));
    assert!(
        e.mean < 0.015 && (e.wrong as f64) < 0.01 * e.both as f64,
        "{e}"
    );
    let (e, ..) = run::<_, SingleTap, 3>("tiny", &m, &high, &Setup::new::<SingleTap>(16));
    assert!(
        e.mean < 0.015 && (e.wrong as f64) < 0.01 * e.both as f64,
        "{e}"
    );
}

/// A light box whose near and far planes touch the scene: stored depths span the whole
/// 16-bit range, and the compare near 65535 neither wraps nor shadows the far floor.
#[test]
fn depth_range_uses_all_16_bits() {
    let down = Vec3::new(Fx::ZERO, Fx::ONE, Fx::ZERO);
    let c = Vec3::new(Fx::ZERO, Fx::ZERO, Fx::from_num(-4.5));
    // Eye 3 above the centre, looking down (up = -z): the cube's top corner (y 1.37) is at
    // distance 1.63, the floor (y -1.375) at 4.375.
    let tight = LightSpace::directional(
        c + down.scale(Fx::from_num(3)),
        c,
        Vec3::from_num(0, 0, -1),
        Fx::from_num(5),
        Fx::from_num(1.6),
        Fx::from_num(4.38),
    )
    .unwrap();
    let m = demo_meshes();
    let (e, fx, _) =
        run::<_, SingleTap, 3>("16-bit range", &m, &tight, &Setup::new::<SingleTap>(64));
    let drawn: Vec<u16> = fx.map.iter().copied().filter(|&d| d != u16::MAX).collect();
    let (lo, hi) = (*drawn.iter().min().unwrap(), *drawn.iter().max().unwrap());
    println!("16-bit range: stored depths {lo}..={hi}");
    // The sharp top corner of the cube is at 660 but no texel centre falls on it.
    assert!(lo < 2000 && hi > 65_000, "{lo}..{hi}");
    assert!(
        e.mean < 0.01 && (e.wrong as f64) < 0.005 * e.both as f64,
        "{e}"
    );
}

/// Front-face culling in the light pass: the map holds the cube's back faces, so the lit
/// faces do not shadow themselves even without a bias; the cube's shadow on the floor stays
/// (the floor, one-sided, drops out of the map and is never self-shadowed).
#[test]
fn front_face_culling_against_acne() {
    let high = scene::directional(SceneLight::High).unwrap();
    let m = demo_meshes();
    let mut back = Setup::new::<SingleTap>(64);
    back.bias = Bias::NONE;
    let front = Setup {
        light_cull: Cull::Front,
        ..back
    };
    let (_, fb, rb) = run::<_, SingleTap, 3>("no bias, back faces culled", &m, &high, &back);
    let (e, ff, rf) = run::<_, SingleTap, 3>("no bias, front faces culled", &m, &high, &front);
    // Shadowed pixels fixel and the reference both see as lit with a proper bias.
    let biased = reference(
        &m,
        &high,
        &Setup::new::<SingleTap>(64),
        RefShadowFilter::Single,
    );
    let acne = |lit: &[f64], cov: &[bool]| {
        (0..lit.len())
            .filter(|&i| cov[i] && lit[i] < 0.5 && biased.covered[i] && biased.lit[i] >= 0.5)
            .count()
    };
    let (ab, af) = (acne(&fb.lit, &fb.covered), acne(&ff.lit, &ff.covered));
    println!(
        "front-face culling: acne {ab} px (back faces culled) -> {af} px (front faces culled); \
         reference {} -> {}",
        acne(&rb.lit, &rb.covered),
        acne(&rf.lit, &rf.covered)
    );
    assert!(af * 10 < ab, "{af} vs {ab}");
    assert!(shadowed(&ff.lit, &ff.covered) > 3000);
    assert!(
        e.mean < 0.01 && (e.wrong as f64) < 0.005 * e.both as f64,
        "{e}"
    );
}

/// The cube alone, turned about its vertical axis so that the face towards the camera is
/// at `theta` degrees to a horizontal directional light (90: edge-on), drawn from straight
/// in front: the lit fraction of fixel and of the reference over the middle of that face
/// (a 60 x 60 pixel box that no other face reaches).
fn face_at_angle<F: ShadowFilter>(theta: f64) -> (Vec<f64>, Vec<f64>) {
    use fixel::math::fx;
    use fixel::scene::Camera;
    let cube = fixel_scenes::cube();
    let turn = Angle::from_degrees(fx(-(90.0 - theta)));
    let centre = Vec3::new(Fx::ZERO, Fx::ZERO, fx(-4.0));
    let mesh = SceneMesh {
        positions: cube.positions.to_vec(),
        indices: cube.indices.to_vec(),
        model: Mat4::translation(centre).mul(&Mat4::rotation_y(turn)),
    };
    // Towards the light: -x, so the front face's normal (sin a, 0, cos a) is at theta to it.
    let space = LightSpace::directional(
        centre + Vec3::new(fx(-10.0), Fx::ZERO, Fx::ZERO),
        centre,
        Vec3::new(Fx::ZERO, Fx::ONE, Fx::ZERO),
        fx(3.0),
        Fx::ONE,
        fx(19.0),
    )
    .unwrap();
    let camera = Camera::perspective(
        Angle::from_degrees(fx(45.0)),
        fx(4.0 / 3.0),
        fx(0.5),
        fx(20.0),
    )
    .unwrap();
    let s = Setup::new::<F>(64);
    let m = [mesh];
    let fx_img = fixel_shadow::<Directional, F, 3>(&m, &camera, &space, &s);
    let sc = ref_scene(&m, &camera, space.matrix(), s.w, s.h);
    let map = light_map(&sc, s.size, false);
    let r = lit_pass(&sc, &map, ref_filter::<F>(), &ref_bias(&s.bias), 1.0);
    let boxed = |lit: &[f64], cov: &[bool]| {
        let mut v = Vec::new();
        for y in 90..150 {
            for x in 130..190 {
                let i = y * 320 + x;
                assert!(cov[i], "pixel ({x}, {y}) of the face not covered");
                v.push(lit[i]);
            }
        }
        v
    };
    (
        boxed(&fx_img.lit, &fx_img.covered),
        boxed(&r.lit, &r.covered),
    )
}

/// A face of a convex solid never shadows itself: at 80, 85 and 89 degrees to the light
/// every pixel of it is lit, by every filter, in fixel and in the reference; edge-on (90)
/// and turned away (95) it is in its own shade.
#[test]
fn a_face_at_a_grazing_angle_does_not_shadow_itself() {
    fn check<F: ShadowFilter>() {
        for theta in [80.0, 85.0, 89.0, 90.0, 95.0] {
            let (fx, rf) = face_at_angle::<F>(theta);
            let lit = |v: &[f64]| v.iter().filter(|&&l| l >= 1.0).count();
            let dark = |v: &[f64]| v.iter().filter(|&&l| l <= 0.0).count();
            println!(
                "face at {theta} degrees, {}: lit {} / {} (reference {}), in shade {} ({})",
                F::NAME,
                lit(&fx),
                fx.len(),
                lit(&rf),
                dark(&fx),
                dark(&rf)
            );
            if theta < 90.0 {
                assert_eq!(lit(&fx), fx.len(), "{} at {theta}", F::NAME);
                assert_eq!(lit(&rf), rf.len(), "reference, {} at {theta}", F::NAME);
            } else {
                assert_eq!(dark(&fx), fx.len(), "{} at {theta}", F::NAME);
                assert_eq!(dark(&rf), rf.len(), "reference, {} at {theta}", F::NAME);
            }
        }
    }
    check::<SingleTap>();
    check::<Pcf2x2>();
    check::<Pcf3x3>();
}
