//! Shared helpers of the hard-case and property tests: a render target with guard rows and
//! columns filled with a sentinel (to catch any write outside the visible buffers), per-pixel
//! write counting, and small constructors.
#![allow(dead_code)]

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{ClipVertex, Cull, ScreenTriangle, Viewport};
use fixel::pipeline::{DepthTest, Draw, DrawMode, Shading};
use fixel::surface::{RenderTarget, Rows};
use fixel::texture::Texture;
use host_tests::adapter;
use host_tests::reference::{RefTexture, RefTriangle, RefVertex};

/// Colour written into the guard area.
pub const SENTINEL: u16 = 0xA55A;
/// Depth written into the guard area.
pub const DEPTH_SENTINEL: u16 = 0x5AA5;
/// Guard rows above and below, and guard columns left and right, of the visible area.
pub const GUARD: usize = 8;

/// A `w` x `h` colour + depth buffer surrounded by `GUARD` rows and columns of sentinel.
///
/// Its rows are handed out `w + 2 GUARD` long (row `y` *plus* the right guard columns and
/// the next row's left ones), and the guard rows above and below are rows too, so a span
/// writer that ignored the target's width or row range would write into the guard, where
/// [`Guarded::check`] finds it.
pub struct Guarded {
    pub w: usize,
    pub h: usize,
    stride: usize,
    color: Vec<Rgb565>,
    depth: Vec<u16>,
    with_depth: bool,
}

impl Guarded {
    /// A guarded `w` x `h` target, cleared to black (depth to 0xFFFF when `with_depth`).
    pub fn new(w: usize, h: usize, with_depth: bool) -> Self {
        let stride = w + 2 * GUARD;
        let n = stride * (h + 2 * GUARD);
        let mut g = Guarded {
            w,
            h,
            stride,
            color: vec![raw(SENTINEL); n],
            depth: vec![DEPTH_SENTINEL; n],
            with_depth,
        };
        g.clear(0);
        g
    }

    fn idx(&self, x: usize, y: usize) -> usize {
        (y + GUARD) * self.stride + x + GUARD
    }

    /// Fills the visible colour with `c` and depth with 0xFFFF; the guard is left alone.
    pub fn clear(&mut self, c: u16) {
        for y in 0..self.h {
            let i = self.idx(0, y);
            self.color[i..i + self.w].fill(raw(c));
            self.depth[i..i + self.w].fill(0xFFFF);
        }
    }

    /// The visible pixels, row-major, as raw RGB565.
    pub fn pixels(&self) -> Vec<u16> {
        let mut out = Vec::with_capacity(self.w * self.h);
        for y in 0..self.h {
            let i = self.idx(0, y);
            out.extend(self.color[i..i + self.w].iter().map(|&c| bits(c)));
        }
        out
    }

    /// The visible depth values, row-major.
    pub fn depths(&self) -> Vec<u16> {
        let mut out = Vec::with_capacity(self.w * self.h);
        for y in 0..self.h {
            let i = self.idx(0, y);
            out.extend_from_slice(&self.depth[i..i + self.w]);
        }
        out
    }

    /// Panics (with `what`) if any guard value changed.
    pub fn check(&self, what: &str) {
        let rows = self.h + 2 * GUARD;
        for yy in 0..rows {
            for xx in 0..self.stride {
                let visible =
                    (GUARD..GUARD + self.h).contains(&yy) && (GUARD..GUARD + self.w).contains(&xx);
                if visible {
                    continue;
                }
                let i = yy * self.stride + xx;
                assert!(
                    bits(self.color[i]) == SENTINEL && self.depth[i] == DEPTH_SENTINEL,
                    "{what}: guard overwritten at buffer ({}, {})",
                    xx as i64 - GUARD as i64,
                    yy as i64 - GUARD as i64
                );
            }
        }
    }
}

impl RenderTarget for Guarded {
    type Color = Rgb565;
    fn width(&self) -> u32 {
        self.w as u32
    }
    fn row_range(&self) -> (i32, i32) {
        (0, self.h as i32)
    }
    fn has_depth(&self) -> bool {
        self.with_depth
    }
    fn rows_mut(&mut self) -> Rows<'_, Rgb565> {
        // Rows `-GUARD..h + GUARD - 1`, each running into the guard columns on its right
        // (and the next row's left ones): a write outside the visible area lands on a
        // sentinel.
        let depth = if self.with_depth {
            Some(&mut self.depth[GUARD..])
        } else {
            None
        };
        Rows {
            color: &mut self.color[GUARD..],
            depth,
            width: self.w + 2 * GUARD,
            stride: self.stride,
            height: self.h + 2 * GUARD - 1,
            y0: -(GUARD as i32),
        }
    }
}

pub fn raw(c: u16) -> Rgb565 {
    Rgb565::from(RawU16::new(c))
}

pub fn bits(c: Rgb565) -> u16 {
    RawU16::from(c).into_inner()
}

/// A fixel texture over `texels` for a reference texture (border included).
pub fn texture<'a>(t: &RefTexture, texels: &'a [Rgb565]) -> Texture<'a> {
    Texture::new(texels, t.width, t.height)
        .expect("valid texture")
        .with_border(raw(t.border))
}

/// Draws `tris` with `mode` into a fresh guarded target (cleared to black), checks the
/// guard, and returns the target and the pixels written.
pub fn draw_guarded(
    tris: &[[ClipVertex; 3]],
    tex: Option<&RefTexture>,
    mode: DrawMode,
    w: usize,
    h: usize,
) -> (Guarded, u32) {
    let texels = tex.map(adapter::texels);
    let t = tex.zip(texels.as_deref()).map(|(r, t)| texture(r, t));
    let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
    let draw = Draw::dynamic(mode, t, vp).expect("valid mode");
    let mut g = Guarded::new(w, h, mode.depth == DepthTest::Less);
    let n = draw.clip_triangles(tris, &mut g).unwrap();
    g.check("draw");
    (g, n)
}

/// How often each pixel is written when every screen triangle of `tris` (after clipping
/// and culling with `cull`) is drawn on its own, flat and without depth test. Also checks
/// that each draw's pixel count matches what changed and that the guard stays intact.
pub fn write_counts(tris: &[[ClipVertex; 3]], cull: Cull, w: usize, h: usize) -> Vec<u32> {
    let vp = Viewport::new(0, 0, w as u32, h as u32).unwrap();
    let mode = DrawMode {
        shading: Shading::Flat,
        depth: DepthTest::Off,
        cull,
        ..DrawMode::default()
    };
    let draw = Draw::dynamic(mode, None, vp)
        .unwrap()
        .with_flat_color(raw(0xFFFF));
    let mut screen: Vec<ScreenTriangle> = Vec::new();
    for t in tris {
        draw.project(t, &mut |s| screen.push(*s));
    }
    let mut g = Guarded::new(w, h, false);
    let mut counts = vec![0u32; w * h];
    for s in &screen {
        g.clear(0);
        let n = draw.screen_triangle(s, &mut g).unwrap();
        g.check("write_counts");
        let px = g.pixels();
        let mut changed = 0;
        for (c, &p) in counts.iter_mut().zip(&px) {
            if p == 0xFFFF {
                *c += 1;
                changed += 1;
            }
        }
        assert_eq!(n, changed, "pixels reported vs written for {s:?}");
    }
    counts
}

/// Rounds to the nearest I16F16 value, so the reference sees exactly what fixel sees.
pub fn q16(x: f64) -> f64 {
    (x * 65536.0).round() / 65536.0
}

/// A white reference vertex (inputs rounded to I16F16).
pub fn rv(clip: [f64; 4], uv: [f64; 2]) -> RefVertex {
    RefVertex {
        clip: clip.map(q16),
        uv: uv.map(q16),
        color: [1.0; 3],
    }
}

/// A vertex at window pixel position `(x, y)` (y down) of a `w` x `h` viewport, with
/// clip-space `z` and `wc` (clip x, y = NDC times `wc`).
pub fn at_px(x: f64, y: f64, z: f64, wc: f64, w: usize, h: usize) -> RefVertex {
    let xn = 2.0 * x / w as f64 - 1.0;
    let yn = 1.0 - 2.0 * y / h as f64;
    rv([xn * wc, yn * wc, z * wc, wc], [0.0, 0.0])
}

pub fn tri(a: RefVertex, b: RefVertex, c: RefVertex) -> RefTriangle {
    RefTriangle([a, b, c])
}

/// A deterministic pseudo-random RGB565 texture (high contrast: the hardest case for
/// filtering errors).
pub fn noise_texture(w: u32, h: u32, seed: u32) -> RefTexture {
    let texels = (0..w * h)
        .map(|i| {
            let mut x = i.wrapping_mul(0x9E37_79B9) ^ seed.wrapping_mul(0x85EB_CA6B);
            x ^= x >> 15;
            x = x.wrapping_mul(0x2C1B_3C6D);
            x ^= x >> 12;
            x as u16
        })
        .collect();
    RefTexture {
        width: w,
        height: h,
        texels,
        border: 0x07E0,
    }
}

/// A tiny deterministic generator (xorshift) for hand-written sweeps.
pub struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    /// Uniform in `[a, b)`.
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * ((self.next() >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// Any `i32`, weighted towards small magnitudes and the extremes: direction and vertex
/// components for the environment maps' never-panics properties.
pub fn any_bits_env() -> impl proptest::strategy::Strategy<Value = i32> {
    use proptest::prelude::*;
    prop_oneof![
        3 => any::<i32>(),
        2 => -(1i32 << 16)..(1 << 16),
        1 => prop::sample::select(vec![0, 1, -1, i32::MAX, i32::MIN, 1 << 30, -(1 << 30)]),
    ]
}

/// A property's case count: `ci` in the test run, or `PROPTEST_CASES` when set (for the long
/// runs that precede a change to a property: `PROPTEST_CASES=100000 cargo test ...`).
#[allow(dead_code)]
pub fn cases(ci: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(ci)
}
