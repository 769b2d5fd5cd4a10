//! Transparency (`fixel::shading::alpha`) against an f64 reference that blends in f64: a
//! translucent textured quad with an alpha plane over the textured floor, and the hard
//! cases (alpha 0 and 255 exactly, additive saturation, depth tested but not written,
//! cut-outs writing depth only where they draw).

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::alpha::{AlphaBlend, AlphaSource, AlphaTest, BlendMode};
use fixel::surface::Frame;
use fixel::texture::{Bilinear, Nearest, Texture};
use fixel::Rgb565;
use host_tests::adapter;
use host_tests::reference::{self, RefFilter, RefMode, RefShading, RefTexture, RefTriangle};
use host_tests::scenes::{self, procedural_texture};
use host_tests::synthetic;

const W: u32 = 320;
const H: u32 = 240;

/// An alpha plane for a `n x n` texture: a diagonal ramp 0..255 with a hole.
fn plane(n: u32) -> Vec<u8> {
    (0..n * n)
        .map(|k| {
            let (x, y) = (k % n, k / n);
            if (4..8).contains(&x) && (4..8).contains(&y) {
                0
            } else {
                ((x + y) * 255 / (2 * n - 2)) as u8
            }
        })
        .collect()
}

fn vertices(tris: &[RefTriangle]) -> Vec<[Vertex<3>; 3]> {
    adapter::clip_triangles(tris)
        .iter()
        .map(|t| {
            t.map(|v| {
                Vertex::new(
                    v.position,
                    [
                        v.uv[0].to_bits(),
                        v.uv[1].to_bits(),
                        i32::from(v.color[0]) << 16,
                    ],
                )
            })
        })
        .collect()
}

/// The floor drawn opaque, then `tris` with `shader` (when given), into one frame with
/// depth; colour and depth.
fn draw<S: fixel::shading::Shader<Varyings = [i32; 3]>>(
    shader: Option<S>,
    tris: &[[Vertex<3>; 3]],
) -> (Vec<Rgb565>, Vec<u16>) {
    let floor = scenes::floor();
    let ft = adapter::clip_triangles(&scenes::to_ref_triangles(&floor));
    let mode = adapter::draw_mode(&floor.mode, Some(fixel::pipeline::Projection::Exact), false);
    let texels = adapter::texels(&floor.texture);
    let t = Texture::new(&texels, floor.texture.width, floor.texture.height).unwrap();
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let fd = fixel::pipeline::Draw::dynamic(mode, Some(t), vp).unwrap();
    let (mut color, mut depth) = (
        vec![Rgb565::new(0, 0, 0); (W * H) as usize],
        vec![0u16; (W * H) as usize],
    );
    {
        let mut frame = Frame::new(&mut color, W, H)
            .unwrap()
            .with_depth(&mut depth)
            .unwrap();
        frame.clear(Rgb565::new(0, 0, 0));
        fd.clip_triangles(&ft, &mut frame).unwrap();
        if let Some(sh) = shader {
            ShadedDraw::<_, Exact, DepthLess>::new(sh, vp, Cull::None)
                .unwrap()
                .clip_triangles(tris, &mut frame)
                .unwrap();
        }
    }
    (color, depth)
}

fn raw(px: &[Rgb565]) -> Vec<u16> {
    px.iter().map(|&c| RawU16::from(c).into_inner()).collect()
}

/// The translucent quad over the floor against the f64 blend of the reference's floor and
/// the reference's quad colour and alpha (the alpha plane as a grey texture, nearest).
#[test]
fn translucent_quad_over_the_floor() {
    let n = 16u32;
    let qt = procedural_texture(n, n);
    let qtexels = adapter::texels(&qt);
    let qtex = Texture::new(&qtexels, n, n).unwrap();
    let alpha = plane(n);
    let tris_ref = synthetic::quad([0.0, 0.0], [1.0, 1.0], [[1.0; 3]; 4]);
    let tris = vertices(&tris_ref);
    let shader = AlphaBlend::new(
        qtex,
        AlphaSource::Plane(&alpha),
        255,
        BlendMode::Over,
        Bilinear,
    )
    .unwrap();
    let (px, _) = draw(Some(shader), &tris);
    // Reference: floor, quad colour (bilinear) and quad alpha (nearest), blended in f64.
    let floor = scenes::floor();
    let fimg = reference::render(
        &scenes::to_ref_triangles(&floor),
        Some(&floor.texture),
        &floor.mode,
        W,
        H,
    );
    let qmode = RefMode {
        shading: RefShading::Replace,
        depth_test: false,
        cull: host_tests::reference::RefCull::None,
        ..RefMode::default()
    };
    let qimg = reference::render(&tris_ref, Some(&qt), &qmode, W, H);
    let atex = RefTexture {
        width: n,
        height: n,
        texels: alpha
            .iter()
            .map(|&a| {
                let v = u16::from(a) * 31 / 255;
                (v << 11) | ((u16::from(a) * 63 / 255) << 5) | v
            })
            .collect(),
        border: 0,
    };
    // The alpha itself, exactly: nearest lookups of the plane through the same geometry.
    let amode = RefMode {
        filter: RefFilter::Nearest,
        ..qmode
    };
    let aimg = reference::render(&tris_ref, Some(&atex), &amode, W, H);
    let mut refr = reference::RefImage::new(W, H);
    let (mut worst, mut over1, mut both) = (0u32, 0usize, 0usize);
    #[allow(clippy::needless_range_loop)] // five images indexed together
    for i in 0..(W * H) as usize {
        refr.covered[i] = fimg.covered[i] || qimg.covered[i];
        let a = if qimg.covered[i] {
            // The plane value, from the green channel's 6 bits (a * 63 / 255, rounded down).
            let g = aimg.rgb[i][1];
            let a8 = alpha
                .iter()
                .copied()
                .min_by_key(|&x| {
                    ((f64::from(x) * 63.0 / 255.0).floor() / 63.0 - g)
                        .abs()
                        .mul_add(1e6, 0.0) as i64
                })
                .unwrap_or(0);
            f64::from(a8) / 255.0
        } else {
            0.0
        };
        let w = (a * 255.0 + (a * 255.0 / 128.0).floor()) / 256.0; // fixel's 0..=256 weight
        refr.rgb[i] = core::array::from_fn(|c| qimg.rgb[i][c] * w + fimg.rgb[i][c] * (1.0 - w));
        if qimg.covered[i] {
            both += 1;
            let v = RawU16::from(px[i]).into_inner();
            let ch = [
                f64::from(v >> 11) / 31.0,
                f64::from((v >> 5) & 63) / 63.0,
                f64::from(v & 31) / 31.0,
            ];
            let e = (0..3)
                .map(|c| ((ch[c] - refr.rgb[i][c]) * [31.0, 63.0, 31.0][c]).abs())
                .fold(0.0, f64::max);
            worst = worst.max(e.round() as u32);
            if e > 1.5 {
                over1 += 1;
            }
        }
    }
    println!("translucent quad: {both} pixels, worst {worst} LSB, {over1} over 1.5 LSB");
    assert!(both > 5000);
    // The alpha is looked up nearest: where fixel's and the reference's texel coordinates
    // fall on either side of an alpha-texel edge (the ramp's steps, the hole's rim) the two
    // take neighbouring alphas; elsewhere the blend is within 1.5 LSB.
    assert!(
        over1 * 50 <= both,
        "{over1} of {both} pixels over 1.5 LSB (worst {worst})"
    );
}

/// Alpha 0 is no draw and alpha 255 an opaque draw, bit for bit; a translucent draw tests
/// depth but leaves it as it was; a cut-out writes depth exactly where it draws.
#[test]
fn exact_ends_and_depth() {
    let n = 16u32;
    let qt = procedural_texture(n, n);
    let qtexels = adapter::texels(&qt);
    let qtex = Texture::new(&qtexels, n, n).unwrap();
    let tris = vertices(&synthetic::quad([0.0, 0.0], [1.0, 1.0], [[1.0; 3]; 4]));
    let none: Option<AlphaBlend<'_, Nearest>> = None;
    let (floor_px, floor_depth) = draw(none, &tris);
    let zero = AlphaBlend::new(qtex, AlphaSource::Opaque, 0, BlendMode::Over, Nearest).unwrap();
    let (px0, d0) = draw(Some(zero), &tris);
    assert_eq!(raw(&px0), raw(&floor_px), "alpha 0 must equal no draw");
    assert_eq!(d0, floor_depth, "a translucent draw must not write depth");
    let full = AlphaBlend::new(qtex, AlphaSource::Opaque, 255, BlendMode::Over, Nearest).unwrap();
    let (px1, d1) = draw(Some(full), &tris);
    assert_eq!(d1, floor_depth, "blending never writes depth");
    // The opaque draw of the same texture (cut-out that keeps everything: same colours).
    let keep_all = AlphaTest::new(qtex, AlphaSource::Opaque, 1, Nearest).unwrap();
    let (px2, d2) = draw(Some(keep_all), &tris);
    assert_eq!(raw(&px1), raw(&px2), "alpha 255 must equal an opaque draw");
    // The cut-out with a colour key (texel (0, 0), the only black one) over a black frame:
    // depth is written exactly where a texel was drawn.
    let key = RawU16::from(qtexels[0]).into_inner();
    assert_eq!(key, 0);
    let cut = AlphaTest::new(qtex, AlphaSource::Key(key), 128, Nearest).unwrap();
    let (mut c, mut d) = (
        vec![Rgb565::new(0, 0, 0); (W * H) as usize],
        vec![0u16; (W * H) as usize],
    );
    {
        let mut f = Frame::new(&mut c, W, H)
            .unwrap()
            .with_depth(&mut d)
            .unwrap();
        f.clear(Rgb565::new(0, 0, 0));
        ShadedDraw::<_, Exact, DepthLess>::new(cut, Viewport::new(0, 0, W, H).unwrap(), Cull::None)
            .unwrap()
            .clip_triangles(&tris, &mut f)
            .unwrap();
    }
    let mut drawn = 0;
    for i in 0..(W * H) as usize {
        let wrote_depth = d[i] != fixel::surface::DEPTH_CLEAR;
        let coloured = c[i] != Rgb565::new(0, 0, 0);
        assert_eq!(
            wrote_depth, coloured,
            "pixel {i}: depth written {wrote_depth}, drawn {coloured}"
        );
        drawn += usize::from(coloured);
    }
    assert!(drawn > 1000);
    assert!(
        d2.iter().zip(&floor_depth).any(|(a, b)| a != b),
        "the opaque cut-out writes depth"
    );
    // Too short an alpha plane is refused.
    assert!(AlphaBlend::new(
        qtex,
        AlphaSource::Plane(&[0u8; 10]),
        255,
        BlendMode::Over,
        Nearest
    )
    .is_err());
    let _ = Fx::ZERO;
}
