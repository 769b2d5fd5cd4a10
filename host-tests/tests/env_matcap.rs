//! Sphere-map (matcap) coordinates per vertex (`fixel::scene::SphereMapUvs`), the real-time
//! environment map: against their own f64 reference (the same per-vertex definition,
//! `host_tests::reference::matcap`), against the f64 per-pixel reflection in the sky cube
//! map (what the accurate modes draw), and bit for bit against a golden.
//!
//! | what (benchmark sphere, frame 0, 128 x 128 sphere map baked from the 64² sky cube) | measured |
//! |---|---|
//! | coordinates per vertex vs f64 (away from the rim) | max 3.9e-4 |
//! | frame vs its own f64 reference | mean 0.012, max 2 LSB, 50.5 dB |
//! | frame vs f64 per-pixel reflection in the cube | 26.3 dB (per-pixel fixel mode: 36.9) |
//! | per-pixel reflection through the same sphere map vs the same | 26.5 dB (the map) |
//! | frame vs f64 per-pixel lookup of the same sphere map | 35.5 dB (the interpolation) |

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::math::{Fx, Vec3};
use fixel::pipeline::{DepthLess, Pipeline, Replace, SubdividedBy};
use fixel::prelude::*;
use fixel::scene::{draw_mesh_walked, CachedVertex, MeshTransform, SphereMapUvs};
use fixel::surface::DEPTH_CLEAR;
use fixel::texture::{Bilinear, ClampToEdge};
use fixel_scenes as demo;
use host_tests::env_scene::{self, H, W};
use host_tests::metrics::{compare_rgb565, Report};
use host_tests::reference::env::{cube_sample, reflect, sphere_st};
use host_tests::reference::matcap::{render_matcap, sphere_map_uv};
use host_tests::reference::{RefFilter, RefTexture};
use proptest::prelude::*;

mod common;

/// The `env_matcap` firmware's draw mode.
type Matcap = Pipeline<SubdividedBy<6>, Bilinear, ClampToEdge, ClampToEdge, Replace, DepthLess>;

fn sky_sphere_map(n: u32) -> Vec<Rgb565> {
    env_scene::sky_sphere_map(n)
}

/// fixel's frame of the benchmark sphere (frame 0) through `map` (`n x n`).
fn matcap_frame(map: &[Rgb565], n: u32) -> (Vec<u16>, Vec<bool>) {
    let tex = Texture::new(map, n, n).unwrap();
    let sphere = demo::sphere();
    let mesh = sphere.mesh().unwrap();
    let draw =
        Draw::new::<Matcap>(Some(tex), Viewport::new(0, 0, W, H).unwrap(), Cull::Back).unwrap();
    let t = MeshTransform::new(&demo::sphere_model(0), &demo::camera(20)).with_uvs(SphereMapUvs);
    let (mut c, mut z) = (
        vec![Rgb565::new(0, 0, 0); (W * H) as usize],
        vec![0u16; (W * H) as usize],
    );
    let mut frame = Frame::new(&mut c, W, H)
        .unwrap()
        .with_depth(&mut z)
        .unwrap();
    let mut cache = vec![CachedVertex::EMPTY; sphere.positions.len()];
    draw_mesh_walked(&draw, &mesh, &t, None, &mut cache, &mut frame).unwrap();
    let cov = frame
        .depth()
        .unwrap()
        .iter()
        .map(|&d| d != DEPTH_CLEAR)
        .collect();
    (
        frame.pixels().iter().map(|p| p.into_storage()).collect(),
        cov,
    )
}

fn reft(t: &[Rgb565], n: u32) -> RefTexture {
    RefTexture {
        width: n,
        height: n,
        texels: t.iter().map(|c| c.into_storage()).collect(),
        border: 0,
    }
}

/// The f64 reference of the same per-vertex definition.
fn own_reference(map: &[Rgb565], n: u32) -> (Vec<u16>, Vec<bool>) {
    let s = demo::sphere();
    let cam = demo::camera(20);
    let mv = cam.view.mul(&demo::sphere_model(0));
    let mvp = cam.projection.mul(&mv);
    render_matcap(
        &s.positions,
        &s.normals,
        &s.indices,
        &mv,
        &mvp,
        &reft(map, n),
        W,
        H,
    )
}

/// The f64 per-pixel reflection in the 64-texel sky cube map, bilinear (the accurate
/// modes' reference).
fn per_pixel_reference() -> (Vec<u16>, Vec<bool>) {
    let faces = env_scene::ref_faces(&env_scene::faces(64), 64);
    env_scene::reference_per_pixel(&env_scene::sphere_pixel(), |r| {
        cube_sample(&faces, r, RefFilter::Bilinear)
    })
}

fn errors(got: &(Vec<u16>, Vec<bool>), want: &(Vec<u16>, Vec<bool>)) -> Report {
    compare_rgb565(&got.0, &got.1, &want.0, &want.1)
}

/// The frame against its own f64 reference: only fixed-point rounding (coordinates, the
/// span interpolation, the bilinear weights) and the edge rule differ.
#[test]
fn matcap_frame_matches_own_reference() {
    let map = sky_sphere_map(128);
    let got = matcap_frame(&map, 128);
    let e = errors(&got, &own_reference(&map, 128));
    println!("matcap 128 vs its own f64 reference: {e}");
    assert!(e.max <= 3 && e.mean <= 0.05 && e.psnr_db >= 45.0, "{e}");
    host_tests::golden::assert_golden("env_matcap_sphere", W, H, &got.0);
}

/// The error of the real-time mode against the f64 per-pixel reflection in the cube map
/// (the per-pixel fixel mode's, for scale), and how much of it the map's size causes.
#[test]
fn matcap_against_per_pixel_reflection() {
    let want = per_pixel_reference();
    let map = sky_sphere_map(128);
    let e = errors(&matcap_frame(&map, 128), &want);
    println!("matcap 128 vs f64 per-pixel reflection (64² cube): {e}");
    // Split: the map's content (the per-pixel reflection through the same sphere map)...
    let sm = fixel::shading::env::SphereMap::new(Texture::new(&map, 128, 128).unwrap(), Bilinear);
    let pp = env_scene::draw(
        fixel::shading::env::ReflectPerPixel(sm),
        &env_scene::sphere_pixel(),
    );
    println!(
        "per-pixel r through the 128 sphere map vs the same: {}",
        errors(&pp, &want)
    );
    // ... and the interpolation (against the f64 per-pixel lookup of the same map).
    let rsm = reft(&map, 128);
    let want_sm = env_scene::reference_per_pixel(&env_scene::sphere_pixel(), |r| {
        host_tests::reference::env::sphere_sample(&rsm, r, RefFilter::Bilinear)
    });
    println!(
        "matcap 128 vs f64 per-pixel r in the same sphere map: {}",
        errors(&matcap_frame(&map, 128), &want_sm)
    );
    let map64 = sky_sphere_map(64);
    let e64 = errors(&matcap_frame(&map64, 64), &want);
    println!("matcap 64 vs f64 per-pixel reflection (64² cube): {e64}");
    let f = env_scene::faces(64);
    let cube = env_scene::cube(&f, 64, Bilinear);
    let px = env_scene::draw(
        fixel::shading::env::ReflectPerPixel(cube),
        &env_scene::sphere_pixel(),
    );
    println!(
        "per-pixel cube (env_pixel) vs the same: {}",
        errors(&px, &want)
    );
}

/// Per-vertex coordinates against the f64 formula over the sphere's vertices in frame 0.
#[test]
fn vertex_coordinates_match_reference() {
    let s = demo::sphere();
    let mv = demo::camera(20).view.mul(&demo::sphere_model(0));
    let mut worst = 0.0f64;
    for (p, n) in s.positions.iter().zip(&s.normals) {
        let pv = mv.transform_point(*p).unwrap();
        let nv = mv.transform_vector(*n).unwrap();
        // Away from the rim singularity (r within 3.6 degrees of pointing away).
        let f = |v: Vec3| [v.x, v.y, v.z].map(|c| c.to_num::<f64>());
        let r = reflect(f(nv), f(Vec3::new(pv.x, pv.y, pv.z)).map(|c| -c));
        let len = (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).sqrt();
        if r[2] / len < -0.998 {
            continue;
        }
        let got = SphereMapUvs::at(nv, Vec3::new(pv.x, pv.y, pv.z));
        let want = sphere_map_uv(&mv, *p, *n);
        for k in 0..2 {
            worst = worst.max((got[k].to_num::<f64>() - want[k]).abs());
        }
    }
    println!("sphere vertices: max |uv error| = {:.2e}", worst);
    assert!(worst <= 1.0 / 2048.0, "{worst}");
}

fn fx3(v: [f64; 3]) -> Vec3 {
    Vec3::new(Fx::from_num(v[0]), Fx::from_num(v[1]), Fx::from_num(v[2]))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(512), ..ProptestConfig::default() })]

    /// Any normal and point (I16F16 bits): coordinates in `[0, 1]`, never a panic.
    #[test]
    fn any_input_gives_coordinates_in_range(
        n in [any::<i32>(), any::<i32>(), any::<i32>()],
        p in [any::<i32>(), any::<i32>(), any::<i32>()],
    ) {
        let v = |a: [i32; 3]| Vec3::new(Fx::from_bits(a[0]), Fx::from_bits(a[1]), Fx::from_bits(a[2]));
        let [s, t] = SphereMapUvs::at(v(n), v(p));
        prop_assert!((Fx::ZERO..=Fx::ONE).contains(&s) && (Fx::ZERO..=Fx::ONE).contains(&t));
    }

    /// Unit-ish normals at points in front of the eye: within 2^-10 of the f64 formula
    /// unless the reflection points within 5 degrees of straight away (the map's rim, where
    /// `s, t` swing around it).
    #[test]
    fn coordinates_match_reference(
        theta in 0.0f64..std::f64::consts::PI,
        phi in 0.0f64..std::f64::consts::TAU,
        p in [-3.0f64..3.0, -3.0f64..3.0, -20.0f64..-0.5],
        len in 0.25f64..2.0,
    ) {
        let n = [theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos()].map(|c| c * len);
        let (nq, pq) = (fx3(n), fx3(p));
        let f = |v: Vec3| [v.x, v.y, v.z].map(|c| c.to_num::<f64>());
        let r = reflect(f(nq), f(pq).map(|c| -c));
        let rl = (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).sqrt();
        // Near the rim (s, t swing around it) nothing is checked but the range.
        if !(rl > 0.0 && r[2] / rl > -(5f64.to_radians().cos())) {
            return Ok(());
        }
        let (ws, wt) = sphere_st(r);
        let [s, t] = SphereMapUvs::at(nq, pq);
        prop_assert!((s.to_num::<f64>() - ws).abs() <= 1.0 / 1024.0, "{} {}", s, ws);
        prop_assert!((t.to_num::<f64>() - wt).abs() <= 1.0 / 1024.0, "{} {}", t, wt);
    }
}
