//! Shadow maps: property tests of the lookup against the f64 formulas (light-space
//! projection of random points under random lights; the three filters on random maps and
//! points), the refusal of bad input, and golden images of the showcase panels.

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::prelude::*;
use fixel::shading::pcf::{Pcf2x2, Pcf3x3, ShadowFilter, SingleTap};
use fixel::shading::shadow::{
    Bias, Directional, LightKind, LightSpace, Shadowed, Spot, UvLight, DEPTH_STEP, ST_ONE,
    UV_ABSOLUTE as ABSOLUTE,
};
use fixel::shading::{Flat, ModulateIntensity};
use fixel::surface::{DepthMap, ShadowMap};
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat};
use fixel_scenes::shadow::{self as scene, SceneLight};
use host_tests::golden::assert_golden;
use host_tests::reference::shadow::{filter, project, transform, RefMap, RefShadowFilter};
use host_tests::shadow_scene::m4;
use proptest::prelude::*;

fn v3(p: [f64; 3]) -> Vec3 {
    Vec3::new(Fx::from_num(p[0]), Fx::from_num(p[1]), Fx::from_num(p[2]))
}

/// fixel's `(s, t, d)` (as map units 0..1 and depth steps) of model point `p` under `L`, and
/// the f64 formula's on the same (shared) matrix and point.
type Stq = Option<(f64, f64, f64)>;

fn both<K: LightKind>(l: &LightSpace<K>, p: Vec3) -> (Stq, Stq) {
    let fx = K::project(K::vertex(l.matrix(), p)).map(|(s, t, d)| {
        (
            f64::from(s) / f64::from(ST_ONE),
            f64::from(t) / f64::from(ST_ONE),
            f64::from(d) / f64::from(DEPTH_STEP),
        )
    });
    let c = transform(&m4(l.matrix()), [p.x, p.y, p.z].map(|c| c.to_num::<f64>()));
    let r = project(c, 1);
    (fx, r)
}

/// Near the frustum's edges fixel and f64 may disagree on inside / outside.
fn near_edge(r: Stq, c: [f64; 4]) -> bool {
    let [x, y, z, w] = c;
    if w <= 1e-3 {
        return true;
    }
    let e = |v: f64| (v / w).abs() > 1.0 - 1e-4 && (v / w).abs() < 1.0 + 1e-4;
    r.is_none() && (e(x) || e(y) || e(z))
        || r.is_some_and(|(s, t, d)| {
            s < 1e-4
                || t < 1e-4
                || s > 1.0 - 1e-4
                || t > 1.0 - 1e-4
                || !(0.5..=65534.5).contains(&d)
        })
}

/// The light coordinates [`UvLight`] gives at barycentric point `(b1, b2)` of a triangle,
/// the exact affine value there (f64) and the triangle's conditioning, for texture
/// coordinates `uv` and light coordinates `light` at the vertices; `None` for a sliver.
fn uv_light_at(
    uv: [[i32; 2]; 3],
    light: [[i32; 4]; 3],
    b1: f64,
    b2: f64,
) -> Option<([i32; 4], [f64; 4], f64)> {
    let m = UvLight::solve(uv, 0, light, 4);
    let lerp = |a: i32, b: i32, c: i32| {
        f64::from(a) + b1 * (f64::from(b) - f64::from(a)) + b2 * (f64::from(c) - f64::from(a))
    };
    let u = lerp(uv[0][0], uv[1][0], uv[2][0]);
    let v = lerp(uv[0][1], uv[1][1], uv[2][1]);
    let area = (f64::from(uv[1][0]) - f64::from(uv[0][0]))
        * (f64::from(uv[2][1]) - f64::from(uv[0][1]))
        - (f64::from(uv[2][0]) - f64::from(uv[0][0])) * (f64::from(uv[1][1]) - f64::from(uv[0][1]));
    let extent = |k: usize| {
        let c = uv.map(|p| f64::from(p[k]));
        c[0].max(c[1]).max(c[2]) - c[0].min(c[1]).min(c[2])
    };
    // The conditioning: 2 for a right triangle along the axes, large for a sliver.
    let cond = extent(0) * extent(1) / area.abs();
    if cond.is_nan() || cond > 64.0 {
        return None;
    }
    let got = m.at(u.round() as i32, v.round() as i32, 4);
    // The first `ABSOLUTE` coordinates come out as they are, the others as differences.
    let want = core::array::from_fn(|c| {
        let base = if c < ABSOLUTE {
            0.0
        } else {
            f64::from(light[0][c])
        };
        lerp(light[0][c], light[1][c], light[2][c]) - base
    });
    Some((got, want, cond))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    /// `UvLight` inside random triangles (texture coordinates up to 2^12 texels apart in
    /// I16F16, light coordinates up to 2^21 apart, conditioning `c = e_u e_v / A` up to 64):
    /// within `2^-11 c` of the largest light difference plus 2 units of the exact affine
    /// value (plus `2^-14` of the largest value for the coordinates it gives absolute),
    /// `u, v` rounded to the fragment's integers.
    #[test]
    fn light_from_texture_coordinates_is_the_affine_map(
        uv in proptest::array::uniform3(proptest::array::uniform2(-(1i32 << 27)..(1 << 27))),
        light in proptest::array::uniform3(proptest::array::uniform4(-(1i32 << 20)..(1 << 20))),
        b1 in 0.0f64..1.0,
        b2 in 0.0f64..1.0,
    ) {
        let (b1, b2) = if b1 + b2 > 1.0 { (1.0 - b1, 1.0 - b2) } else { (b1, b2) };
        if let Some((got, want, cond)) = uv_light_at(uv, light, b1, b2) {
            for c in 0..4 {
                let range = (1..3)
                    .map(|i| (f64::from(light[i][c]) - f64::from(light[0][c])).abs())
                    .fold(1.0, f64::max);
                let err = (f64::from(got[c]) - want[c]).abs();
                // An absolute coordinate's precision is capped by its magnitude.
                let magnitude = light.iter().map(|l| f64::from(l[c]).abs()).fold(0.0, f64::max);
                let capped = if c < ABSOLUTE { magnitude / 16384.0 } else { 0.0 };
                let allowed = range * cond / 2048.0 + 2.0 + capped;
                prop_assert!(err <= allowed,
                    "c={c} got={} want={} range={range} cond={cond}", got[c], want[c]);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    /// Directional light: s, t within 2^-18 of the map, d within 0.1 step of the f64 formula
    /// (the matrix is shared; fixel computes in i64 without intermediate rounding).
    #[test]
    fn directional_projection_matches_f64(
        dir in (-1.0f64..1.0, 0.2f64..1.0, -1.0f64..1.0), half in 2.0f64..10.0,
        p in prop::array::uniform3(-8.0f64..8.0),
    ) {
        // The light above the scene (y > 0.2), drawn rather than assumed: a rejection per
        // case (60 % of them) put the test within reach of proptest's 1,024 global rejects.
        let dir = [dir.0, dir.1, dir.2];
        let c = v3([0.0, -1.0, -4.0]);
        let l = LightSpace::directional(c + v3(dir).scale(Fx::from_num(8)), c, Vec3::from_num(0, 1, 0),
            Fx::from_num(half), Fx::ONE, Fx::from_num(18));
        prop_assume!(l.is_ok());
        let l = l.unwrap();
        let (f, r) = both(&l, v3(p));
        let cl = transform(&m4(l.matrix()), [p[0], p[1], p[2]].map(|v| Fx::from_num(v).to_num::<f64>()));
        if near_edge(r, cl) { return Ok(()); }
        prop_assert_eq!(f.is_some(), r.is_some(), "{:?} vs {:?}", f, r);
        if let (Some(f), Some(r)) = (f, r) {
            prop_assert!((f.0 - r.0).abs() < 4e-6 && (f.1 - r.1).abs() < 4e-6, "{:?} vs {:?}", f, r);
            prop_assert!((f.2 - r.2).abs() < 0.1, "{:?} vs {:?}", f, r);
        }
    }

    /// Spot light: s, t within 2^-15 of the map (1/128 texel on a 256 map), d within 1.5
    /// steps: half a step of rounding plus the per-pixel table reciprocal's relative error
    /// below 2^-16, which is up to one step at depths near 65535 (a random case found 1.07
    /// steps at depth 33,417, over the one step this bound used to claim).
    #[test]
    fn spot_projection_matches_f64(
        eye in prop::array::uniform3(-4.0f64..4.0), fov in 30.0f64..120.0,
        p in prop::array::uniform3(-8.0f64..8.0),
    ) {
        let eye = [eye[0], eye[1].abs() + 1.0, eye[2] - 4.0];
        let l = LightSpace::spot(v3(eye), v3([0.0, -1.375, -4.5]), Vec3::from_num(0, 1, 0),
            Angle::from_degrees(Fx::from_num(fov)), Fx::from_num(0.5), Fx::from_num(16));
        prop_assume!(l.is_ok());
        let l = l.unwrap();
        let (f, r) = both(&l, v3(p));
        let cl = transform(&m4(l.matrix()), [p[0], p[1], p[2]].map(|v| Fx::from_num(v).to_num::<f64>()));
        if near_edge(r, cl) { return Ok(()); }
        prop_assert_eq!(f.is_some(), r.is_some(), "{:?} vs {:?}", f, r);
        if let (Some(f), Some(r)) = (f, r) {
            prop_assert!((f.0 - r.0).abs() < 3.1e-5 && (f.1 - r.1).abs() < 3.1e-5, "{:?} vs {:?}", f, r);
            prop_assert!((f.2 - r.2).abs() < 1.5, "{:?} vs {:?}", f, r);
        }
    }

    /// The three filters against the reference's on random 16x16 maps at random points:
    /// single tap exactly, 3x3 within its Q8 ninths, 2x2 within its truncated 8-bit weights
    /// (each weight and the final product truncated: below 3/256).
    #[test]
    fn filters_match_f64(
        texels in prop::collection::vec(0u16..4, 256),
        s in 0i32..ST_ONE, t in 0i32..ST_ONE, d in 0i32..4,
    ) {
        // Depths 0, 1000, 2000, 3000 and a reference depth between them.
        let texels: Vec<u16> = texels.iter().map(|k| k * 1000).collect();
        let map = ShadowMap::new(&texels, 16).unwrap();
        let rmap = RefMap { size: 16, depth: texels.iter().map(|&v| f64::from(v)).collect() };
        let dq = (d * 1000 + 500) * DEPTH_STEP;
        let (x, y) = (f64::from(s) / f64::from(ST_ONE) * 16.0, f64::from(t) / f64::from(ST_ONE) * 16.0);
        let dr = f64::from(dq) / 16.0;
        let a = f64::from(SingleTap::lit(&map, s, t, dq)) / 256.0;
        prop_assert_eq!(a, filter(&rmap, x, y, dr, RefShadowFilter::Single));
        let c = f64::from(Pcf3x3::lit(&map, s, t, dq)) / 256.0;
        prop_assert!((c - filter(&rmap, x, y, dr, RefShadowFilter::Pcf3x3)).abs() < 0.002);
        let b = f64::from(Pcf2x2::lit(&map, s, t, dq)) / 256.0;
        prop_assert!((b - filter(&rmap, x, y, dr, RefShadowFilter::Pcf2x2)).abs() < 3.0 / 256.0);
    }
}

#[test]
fn bad_input_is_refused_with_errors_that_say_what() {
    let mut t = vec![0u16; 48 * 48];
    assert_eq!(
        DepthMap::new(&mut t, 48).unwrap_err(),
        Error::NotPowerOfTwo(48)
    );
    let mut t = vec![0u16; 8 * 8];
    assert_eq!(DepthMap::new(&mut t, 8).unwrap_err(), Error::BadSize(8));
    let mut t = vec![0u16; 512 * 512];
    assert_eq!(DepthMap::new(&mut t, 512).unwrap_err(), Error::BadSize(512));
    let mut t = vec![0u16; 100];
    assert_eq!(
        DepthMap::new(&mut t, 16).unwrap_err(),
        Error::WrongLength {
            expected: 256,
            actual: 100
        }
    );
    assert!(ShadowMap::new(&t, 16).is_err());
    // A light pass built for a 64 x 64 map refuses a 32 x 32 one, and draws nothing into it.
    let mut big = vec![0u16; 64 * 64];
    let pass =
        fixel::pipeline::DepthOnlyDraw::new(&DepthMap::new(&mut big, 64).unwrap(), Cull::Back)
            .unwrap();
    let mut small = vec![0xFFFFu16; 32 * 32];
    let mut small_map = DepthMap::new(&mut small, 32).unwrap();
    let space = scene::directional(SceneLight::High).unwrap();
    let cube = fixel_scenes::cube();
    assert_eq!(
        fixel::scene::light_pass_mesh(
            &pass,
            &cube.mesh().unwrap(),
            &Mat4::IDENTITY,
            &space,
            &mut small_map
        ),
        Err(Error::ShadowMapSizeMismatch(64))
    );
    assert!(small.iter().all(|&t| t == 0xFFFF));
    let (o, up) = (Vec3::ZERO, Vec3::from_num(0, 1, 0));
    let eye = Vec3::from_num(1, 5, 1);
    let dir = |half: f64, near: f64, far: f64| {
        LightSpace::directional(
            eye,
            o,
            up,
            Fx::from_num(half),
            Fx::from_num(near),
            Fx::from_num(far),
        )
    };
    assert!(matches!(dir(0.0, 1.0, 5.0), Err(Error::BadProjection(_))));
    assert!(matches!(dir(2.0, 5.0, 5.0), Err(Error::BadProjection(_))));
    assert!(matches!(
        LightSpace::directional(eye, eye, up, Fx::ONE, Fx::ONE, Fx::from_num(5)),
        Err(Error::BadProjection(_))
    ));
    assert!(LightSpace::<Directional>::from_matrix(*scene::spot().unwrap().matrix()).is_err());
    assert!(matches!(
        LightSpace::spot(
            eye,
            o,
            up,
            Angle::from_degrees(Fx::ZERO),
            Fx::ONE,
            Fx::from_num(5)
        ),
        Err(Error::BadProjection(_))
    ));
    // Light-space varyings of extreme points under extreme matrices saturate (no overflow,
    // also in debug builds).
    let big = Mat4::from_rows([[Fx::MAX; 4], [Fx::MIN; 4], [Fx::MAX; 4], [Fx::MIN; 4]]);
    for p in [
        Vec3::new(Fx::MAX, Fx::MAX, Fx::MAX),
        Vec3::new(Fx::MIN, Fx::MIN, Fx::MIN),
    ] {
        for v in [Directional::vertex(&big, p), Spot::vertex(&big, p)] {
            assert!(v.iter().all(|x| x.unsigned_abs() <= 1 << 30), "{v:?}");
            let _ = Directional::project(v);
            let _ = Spot::project(v);
        }
    }
    let texels = [u16::MAX; 256];
    let map = ShadowMap::new(&texels, 16).unwrap();
    let s = Shadowed::<_, Spot, SingleTap, 4>::new(Flat(0xFFFF), map, Bias::NONE).unwrap();
    assert!(matches!(s.with_darkness(257), Err(Error::BadMode(_))));
    // Drawing with a degenerate light-space triangle or wild varyings never panics.
    let s =
        Shadowed::<_, Directional, Pcf3x3, 3>::new(Flat(0xFFFF), map, Bias::for_filter::<Pcf3x3>())
            .unwrap();
    let vp = Viewport::new(0, 0, 32, 32).unwrap();
    let draw = ShadedDraw::<_, Exact, DepthLess>::new(s, vp, Cull::None).unwrap();
    let p = |x: f32, y: f32| [Fx::from_num(x), Fx::from_num(y), Fx::ZERO, Fx::ONE];
    for l in [
        [0; 3],
        [i32::MAX; 3],
        [i32::MIN; 3],
        [1 << 30, -(1 << 30), 7],
    ] {
        let tri = [
            Vertex::new(p(-1.0, -1.0), l),
            Vertex::new(p(1.0, -1.0), [0, 0, 0]),
            Vertex::new(p(0.0, 1.0), l),
        ];
        let (mut c, mut z) = ([Rgb565::new(0, 0, 0); 32 * 32], [0u16; 32 * 32]);
        let mut f = Frame::new(&mut c, 32, 32)
            .unwrap()
            .with_depth(&mut z)
            .unwrap();
        f.clear(Rgb565::new(0, 0, 0));
        assert!(draw.clip_triangles(&[tri], &mut f).unwrap() > 0);
    }
}

/// The showcase panels (64x64 map, textured): goldens catch unintended changes.
#[test]
fn golden_showcase_panels() {
    fn panel<K: LightKind, F: ShadowFilter, const M: usize, const UV: bool>(
        space: &LightSpace<K>,
        light: SceneLight,
        name: &str,
    ) {
        let mut t128 = vec![Rgb565::new(0, 0, 0); 128 * 128];
        fixel_scenes::checker_texture(128, 128, &mut t128).unwrap();
        let mut t64 = vec![Rgb565::new(0, 0, 0); 64 * 64];
        scene::floor_texture(&mut t64).unwrap();
        let (ct, ft) = (
            MipTexture::single(Texture::new(&t128, 128, 128).unwrap()),
            MipTexture::single(Texture::new(&t64, 64, 64).unwrap()),
        );
        let mut texels = vec![0u16; 64 * 64];
        let mut map = DepthMap::new(&mut texels, 64).unwrap();
        scene::light_pass(space, &mut map).unwrap();
        let view = map.view();
        let vp = Viewport::new(0, 0, 320, 240).unwrap();
        let draw = |t| {
            let tex = TexBinding::new(t, Bilinear, Repeat, Repeat, Lod::default()).unwrap();
            let s = Shadowed::<_, K, F, M, UV>::new(
                ModulateIntensity { tex },
                view,
                Bias::for_filter::<F>(),
            )
            .unwrap();
            ShadedDraw::<_, Exact, DepthLess>::new(s, vp, Cull::Back).unwrap()
        };
        let (dc, df) = (draw(&ct), draw(&ft));
        let (mut c, mut z) = (vec![Rgb565::new(0, 0, 0); 320 * 240], vec![0u16; 320 * 240]);
        let mut f = Frame::new(&mut c, 320, 240)
            .unwrap()
            .with_depth(&mut z)
            .unwrap();
        f.clear(Rgb565::new(4, 10, 14));
        scene::lit_pass([&dc, &df], space, light, &mut f).unwrap();
        let px: Vec<u16> = f.pixels().iter().map(|p| p.into_storage()).collect();
        assert_golden(name, 320, 240, &px);
    }
    let high = scene::directional(SceneLight::High).unwrap();
    let grazing = scene::directional(SceneLight::Grazing).unwrap();
    panel::<_, Pcf2x2, 6, false>(&high, SceneLight::High, "shadow-high-pcf2x2");
    panel::<_, Pcf3x3, 6, false>(&grazing, SceneLight::Grazing, "shadow-grazing-pcf3x3");
    panel::<_, SingleTap, 6, false>(&high, SceneLight::High, "shadow-high-single");
    panel::<_, SingleTap, 6, true>(&high, SceneLight::High, "shadow-high-single-uv");
    panel::<_, Pcf2x2, 7, false>(
        &scene::spot().unwrap(),
        SceneLight::Spot,
        "shadow-spot-pcf2x2",
    );
    let _ = Mat4::IDENTITY;
}
