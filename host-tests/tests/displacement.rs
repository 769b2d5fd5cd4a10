//! Displacement mapping: fixel's subdivision, displacement and recomputed
//! normals against the f64 reference (`host_tests::reference::displace`), property tests
//! over scale, bias, offset and levels, the baked assets' freshness and a rendered
//! checksum. The hard cases are in `displacement_hard_cases.rs`.
//!
//! Error budgets (I16F16 LSB = 2^-16 model units), see `position_budget`: positions within
//! `1 + |scale| + levels / 2` LSB, plus, once subdivided, `|scale| Δh (w + h) / 256` LSB for the
//! midpoints' texture coordinates rounded to I16F16 (`Δh` the largest step between
//! neighbouring texels of the `w x h` map). On the rocky sphere (scale 0.45, Δh = 102, 128 x
//! 64) that measures 1.1, 9.2 and 15.8 LSB at 0, 1 and 2 levels. Normals within
//! `NORMAL_BUDGET` (2^-7) per component where the reference's direction is well conditioned
//! (the vertex's normal sum at least 1/16 of the largest face's; between 1/64 and 1/16 the
//! error is weighed by `16 cond`, since a short normal sum's direction moves by the
//! positions' error over its length; below 1/64, near a fold, only unit length is checked): the positions' error over edges of 0.05 units, measured
//! 3.4e-4, 9.0e-4 and 3.1e-3.

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use fixel::geometry::{Cull, Viewport};
use fixel::math::{fx, Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection, Shading};
use fixel::scene::{draw_mesh, Camera, DirectionalLight, Displacement, Mesh};
use fixel::surface::Frame;
use fixel::texture::HeightMap;
use fixel::Rgb565;
use fixel_scenes::displaced::{grid, ROCK_HEIGHT, ROCK_WIDTH, WAVE_SIDE};
use fixel_scenes::{self as demo, MeshData};
use host_tests::displaced::{f3, max_step, rock, to_ref, waves, Fine, LSB};
use host_tests::reference::displace::{self as reference, RefDisplacement, RefHeights};
use proptest::prelude::*;

const NORMAL_BUDGET: f64 = 1.0 / 128.0;

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
            // The direction of a normal sum of relative size `cond` moves by the positions'
            // error over `cond`: below 1/16 the error is weighed by `16 cond` (a vertex at
            // 1/64, next to a fold, may be off by 4x the budget).
            let weight = (16.0 * cond[i]).min(1.0);
            for k in 0..3 {
                en = en.max((a[k] - b[k]).abs() * weight);
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
