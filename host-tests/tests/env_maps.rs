//! Sphere maps and latitude-longitude maps against the f64 reference
//! (`host_tests::reference::env`): coordinates, lookups, the singularities (sphere-map
//! rim, lat-long poles and seam, the zero direction) and a frame of the benchmark sphere.
//!
//! | what (100k directions; 128 x 128 sphere map, 256 x 128 lat-long) | measured |
//! |---|---|
//! | sphere map `s, t` (away from the rim) | max error 8.0 Q16 units (1.2e-4) |
//! | lat-long `s, t` | max error 8.3 Q16 units |
//! | bilinear lookups | max 1 LSB; mean 0.009 (sphere), 0.006 (lat-long) |
//! | benchmark sphere, per-pixel r, sphere map | max 1, mean 0.014 LSB |
//! | benchmark sphere, per-pixel r, lat-long | max 2, mean 0.014 LSB, > 1 LSB 0.008 % |

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Vec3;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::env::{sky, EnvLookup, EnvVertices, LatLongMap, ReflectPerPixel, SphereMap};
use fixel::shading::Shader;
use fixel::surface::{Frame, DEPTH_CLEAR};
use fixel::texture::{Bilinear, Texture};
use host_tests::env_scene::directions;
use host_tests::metrics::{channel_errors, compare_rgb565};
use host_tests::reference::env::{
    latlong_sample, latlong_st, reflect, render_varyings, sphere_sample, sphere_st,
};
use host_tests::reference::{rgb565_from_f64, RefFilter, RefTexture};
use proptest::prelude::*;

fn f(d: [i32; 3]) -> [f64; 3] {
    d.map(f64::from)
}

fn q16(x: u32) -> f64 {
    f64::from(x) / 65536.0
}

fn latlong_tex(w: u32, h: u32) -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    sky::sky_latlong(w, h, &mut t).unwrap();
    t
}

fn sphere_tex(n: u32) -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); (n * n) as usize];
    sky::sky_spheremap(n, &mut t).unwrap();
    t
}

fn reft(t: &[Rgb565], w: u32, h: u32) -> RefTexture {
    RefTexture {
        width: w,
        height: h,
        texels: t.iter().map(|c| c.into_storage()).collect(),
        border: 0,
    }
}

/// Sphere-map coordinates: within 2^-12 of the reference (measured 8 Q16 units: the atan
/// and hypot tables and the sine table), except within 0.06 rad of the rim singularity,
/// where `s, t` swing around the rim.
#[test]
fn sphere_coords_match_reference() {
    let mut worst = 0.0f64;
    for d in directions(100_000) {
        let (s, t) = SphereMap::<Bilinear>::coords(d);
        let (rs, rt) = sphere_st(f(d));
        let len = f(d).iter().map(|c| c * c).sum::<f64>().sqrt();
        if f64::from(d[2]) / len < -0.998 {
            continue;
        }
        worst = worst.max((q16(s) - rs).abs().max((q16(t) - rt).abs()));
    }
    println!("sphere map: max |error| = {:.2} Q16 units", worst * 65536.0);
    assert!(worst <= 1.0 / 4096.0, "{worst}");
}

/// Lat-long coordinates: within 2^-12 of the reference (s modulo 1; measured 8.3 Q16
/// units, 1/31 texel on a 256-texel-wide map).
#[test]
fn latlong_coords_match_reference() {
    let mut worst = 0.0f64;
    for d in directions(100_000) {
        let (s, t) = LatLongMap::<Bilinear>::coords(d);
        let (rs, rt) = latlong_st(f(d));
        let mut es = (q16(s) - rs).abs();
        es = es.min(1.0 - es);
        worst = worst.max(es.max((q16(t) - rt).abs()));
    }
    println!("lat-long: max |error| = {:.2} Q16 units", worst * 65536.0);
    assert!(worst <= 1.0 / 4096.0, "{worst}");
}

/// Bilinear lookups on 128-texel maps: colours against the reference's bilinear sample.
#[test]
fn lookups_match_reference() {
    let (lt, st) = (latlong_tex(256, 128), sphere_tex(128));
    let ll = LatLongMap::new(Texture::new(&lt, 256, 128).unwrap(), Bilinear);
    let sm = SphereMap::new(Texture::new(&st, 128, 128).unwrap(), Bilinear);
    let (rl, rsm) = (reft(&lt, 256, 128), reft(&st, 128, 128));
    let (mut ml, mut ms, mut sl, mut ss, mut n) = (0, 0, 0u64, 0u64, 0u64);
    for d in directions(100_000) {
        let el = channel_errors(
            ll.lookup(d),
            rgb565_from_f64(latlong_sample(&rl, f(d), RefFilter::Bilinear)),
        );
        ml = ml.max(*el.iter().max().unwrap());
        sl += u64::from(el.iter().sum::<u32>());
        let len = f(d).iter().map(|c| c * c).sum::<f64>().sqrt();
        if f64::from(d[2]) / len > -0.998 {
            let es = channel_errors(
                sm.lookup(d),
                rgb565_from_f64(sphere_sample(&rsm, f(d), RefFilter::Bilinear)),
            );
            ms = ms.max(*es.iter().max().unwrap());
            ss += u64::from(es.iter().sum::<u32>());
        }
        n += 3;
    }
    println!(
        "lat-long bilinear: max {ml} mean {:.4}; sphere map bilinear: max {ms} mean {:.4}",
        sl as f64 / n as f64,
        ss as f64 / n as f64
    );
    assert!(ml <= 1 && ms <= 1, "lat-long {ml}, sphere {ms}");
}

/// The sphere map's rim: `r` pointing away from the viewer reads the rim point `(1, 1/2)`;
/// directions close to it read points close to the rim (radius `sin(θ/2)` near 1).
#[test]
fn sphere_map_rim() {
    for k in [1, 1000, 1 << 20, i32::MAX] {
        assert_eq!(SphereMap::<Bilinear>::coords([0, 0, -k]), (65536, 32768));
    }
    for d in [
        [1, 0, -100_000],
        [0, -3, -1_000_000],
        [5, 5, -i32::MAX],
        [-1, 1, -4096],
    ] {
        let (s, t) = SphereMap::<Bilinear>::coords(d);
        let rho = (q16(s) - 0.5).hypot(q16(t) - 0.5) * 2.0;
        assert!(rho > 0.99 && rho <= 1.0 + 1e-4, "{d:?}: rho {rho}");
        let (rs, rt) = sphere_st(f(d));
        assert!(
            (q16(s) - rs).abs() < 0.01 && (q16(t) - rt).abs() < 0.01,
            "{d:?}"
        );
    }
    // Towards the viewer: the centre.
    assert_eq!(SphereMap::<Bilinear>::coords([0, 0, 7]), (32768, 32768));
    assert_eq!(SphereMap::<Bilinear>::coords([0, 0, 0]), (32768, 32768));
}

/// Near the rim (r within 25° of pointing away from the viewer, where the map squeezes a
/// ring of directions into the last texels), the sky's sphere map filters to the colours
/// around the rim, not to the black outside the disc: averaged over all azimuths, the
/// bilinear lookups are as bright as the sky in those directions. The same map with black
/// outside the disc (what `sky_spheremap` wrote before) is measurably darker there.
#[test]
fn sphere_map_rim_is_not_dark() {
    let n = 64;
    let t = sphere_tex(n);
    let mut black = t.clone();
    for (k, px) in black.iter_mut().enumerate() {
        let (i, j) = ((k as u32) % n, (k as u32) / n);
        let sx = 2.0 * (f64::from(i) + 0.5) / f64::from(n) - 1.0;
        let ty = 2.0 * (f64::from(j) + 0.5) / f64::from(n) - 1.0;
        if sx * sx + ty * ty > 1.0 {
            *px = Rgb565::new(0, 0, 0);
        }
    }
    let lum = |p: u16| f64::from((p >> 11) * 2 + ((p >> 5) & 63) + (p & 31) * 2);
    for deg in [155.0f64, 165.0, 172.0] {
        let th = deg.to_radians();
        let (mut sky_sum, mut got, mut old) = (0.0, 0.0, 0.0);
        for k in 0..512 {
            let phi = f64::from(k) / 512.0 * std::f64::consts::TAU;
            let d = [th.sin() * phi.cos(), th.sin() * phi.sin(), th.cos()];
            let di = d.map(|c| (c * 1e6).round() as i32);
            let c = sky::sky_colour(d.map(|c| c as f32));
            sky_sum += lum(Rgb565::new(
                (c[0] * 31.0).round() as u8,
                (c[1] * 63.0).round() as u8,
                (c[2] * 31.0).round() as u8,
            )
            .into_storage());
            got += lum(SphereMap::new(Texture::new(&t, n, n).unwrap(), Bilinear).lookup(di));
            old += lum(SphereMap::new(Texture::new(&black, n, n).unwrap(), Bilinear).lookup(di));
        }
        let (r, ro) = (got / sky_sum, old / sky_sum);
        println!("sphere map at {deg}°: brightness vs the sky {r:.3} (black outside: {ro:.3})");
        assert!((0.9..=1.1).contains(&r), "{deg}: {r}");
        if deg >= 165.0 {
            assert!(
                ro < 0.85,
                "{deg}: black outside should darken the rim ({ro})"
            );
        }
    }
}

/// The lat-long poles: the first and last rows, at `s = 1/2`; near them, `t` within 2^-12.
#[test]
fn latlong_poles() {
    for k in [1, 77, 1 << 30, i32::MAX] {
        assert_eq!(LatLongMap::<Bilinear>::coords([0, k, 0]), (32768, 0));
        assert_eq!(LatLongMap::<Bilinear>::coords([0, -k, 0]), (32768, 65536));
    }
    for d in [[1, 1_000_000, 0], [-3, -1 << 30, 2], [0, 5000, -1]] {
        let (_, t) = LatLongMap::<Bilinear>::coords(d);
        let (_, rt) = latlong_st(f(d));
        assert!((q16(t) - rt).abs() <= 1.0 / 4096.0, "{d:?}");
    }
    assert_eq!(LatLongMap::<Bilinear>::coords([0, 0, 0]), (32768, 32768));
}

/// The lat-long seam (+z, where the longitude wraps): directions either side land at the
/// two ends of `s`, and bilinear sampling there blends the first and last columns, as the
/// reference's repeat does.
#[test]
fn latlong_seam() {
    let lt = latlong_tex(256, 128);
    let ll = LatLongMap::new(Texture::new(&lt, 256, 128).unwrap(), Bilinear);
    let rl = reft(&lt, 256, 128);
    let (a, _) = LatLongMap::<Bilinear>::coords([1000, 300, 1_000_000]);
    let (b, _) = LatLongMap::<Bilinear>::coords([-1000, 300, 1_000_000]);
    // +x of +z is just before the seam (s near 1), -x just after it (s near 0).
    assert!(a > 65336 && b < 200, "{a} {b}");
    assert_eq!(LatLongMap::<Bilinear>::coords([0, 0, 5]).0, 0);
    for d in [
        [1000, 300, 1_000_000],
        [-1000, 300, 1_000_000],
        [0, -9, 1 << 20],
    ] {
        let e = channel_errors(
            ll.lookup(d),
            rgb565_from_f64(latlong_sample(&rl, f(d), RefFilter::Bilinear)),
        );
        assert!(e.iter().all(|&c| c <= 1), "{d:?}: {e:?}");
    }
}

fn frame<S: Shader<Varyings = [i32; 6]>>(
    shader: S,
    tris: &[[Vertex<6>; 3]],
) -> (Vec<u16>, Vec<bool>) {
    let (w, h) = (320, 240);
    let vp = Viewport::new(0, 0, w, h).unwrap();
    let d = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).unwrap();
    let (mut c, mut z) = (vec![Rgb565::new(0, 0, 0); 320 * 240], vec![0u16; 320 * 240]);
    let mut fr = Frame::new(&mut c, w, h)
        .unwrap()
        .with_depth(&mut z)
        .unwrap();
    d.clip_triangles(tris, &mut fr).unwrap();
    let cov = fr
        .depth()
        .unwrap()
        .iter()
        .map(|&v| v != DEPTH_CLEAR)
        .collect();
    (fr.pixels().iter().map(|c| c.into_storage()).collect(), cov)
}

/// The benchmark sphere mirroring the sky through the sphere map and the lat-long map, `r`
/// per pixel: fixel against the f64 reference.
#[test]
fn sphere_frames_match_reference() {
    let m = fixel_scenes::sphere();
    let cam = fixel_scenes::camera(20);
    let s = EnvVertices::new(
        &fixel_scenes::sphere_model(0),
        &cam.projection.mul(&cam.view),
        Vec3::ZERO,
    );
    let tris: Vec<[Vertex<6>; 3]> = m
        .indices
        .iter()
        .map(|t| {
            t.map(|i| {
                s.per_pixel(m.positions[usize::from(i)], m.normals[usize::from(i)])
                    .unwrap()
            })
        })
        .collect();
    let (lt, st) = (latlong_tex(256, 128), sphere_tex(128));
    let ll = LatLongMap::new(Texture::new(&lt, 256, 128).unwrap(), Bilinear);
    let sm = SphereMap::new(Texture::new(&st, 128, 128).unwrap(), Bilinear);
    let (rl, rsm) = (reft(&lt, 256, 128), reft(&st, 128, 128));
    let r = |a: [f64; 6]| reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]]);
    let got = frame(ReflectPerPixel(ll), &tris);
    let want = render_varyings(&tris, 320, 240, |_, _, a| {
        latlong_sample(&rl, r(a), RefFilter::Bilinear)
    });
    let e = compare_rgb565(&got.0, &got.1, &want.0, &want.1);
    println!("per-pixel sphere, lat-long bilinear: {e}");
    assert!(e.max <= 3 && e.mean <= 0.03, "{e}");
    // Bit for bit too (bless with FIXEL_BLESS=1 after an intended change).
    host_tests::golden::assert_golden("env_sphere_latlong", 320, 240, &got.0);
    let got = frame(ReflectPerPixel(sm), &tris);
    let want = render_varyings(&tris, 320, 240, |_, _, a| {
        sphere_sample(&rsm, r(a), RefFilter::Bilinear)
    });
    let e = compare_rgb565(&got.0, &got.1, &want.0, &want.1);
    println!("per-pixel sphere, sphere map bilinear: {e}");
    assert!(e.max <= 3 && e.mean <= 0.03, "{e}");
    host_tests::golden::assert_golden("env_sphere_spheremap", 320, 240, &got.0);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    /// Any direction: coordinates in range, never a panic.
    #[test]
    fn any_direction(d in [any::<i32>(), any::<i32>(), any::<i32>()]) {
        let (s, t) = SphereMap::<Bilinear>::coords(d);
        prop_assert!(s <= 65536 && t <= 65536);
        let (s, t) = LatLongMap::<Bilinear>::coords(d);
        prop_assert!(s < 65536 && t <= 65536);
    }
}
