//! Randomized robustness checks (`cargo xtask fuzz`): random clip-space triangles over
//! every [`DrawMode`] combination [`Draw::dynamic_mip`] takes (mipmapping and extreme
//! level-of-detail clamps included), the same positions through a technique shader's typed
//! span loop ([`ShadedDraw`]: Gouraud, flat, solid noise, flame, environment reflection,
//! alpha blending and testing, triplanar; exact or affine, depth-tested or not), and random
//! convex quads, drawn into frames with canary pixels around their buffers, counting what
//! must never
//! happen: a panic, a write outside the buffers or the viewport, a pixel written against
//! the depth rule (`GL_LESS` against the depth stored before), a band frame that differs
//! from the whole frame, and an `Ok` whose picture is implausible (more pixels changed than
//! reported, a covered quad pixel left undrawn).
//!
//! Every case is a pure function of its seed ([`case`]), so a count names reproducers.

use std::panic::{catch_unwind, AssertUnwindSafe};

use fixel::geometry::Vertex;
use fixel::geometry::{ClipVertex, Cull, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{Affine, DepthLess, DepthStage, Exact, NoDepth, ProjectionStage, ShadedDraw};
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection, Shading};
use fixel::scene::draw_quad;
use fixel::shading::alpha::{AlphaBlend, AlphaSource, AlphaTest, BlendMode};
use fixel::shading::env::{CubeMap, ReflectPerPixel};
use fixel::shading::noise::{BandLimit, FlameShader, Ramp, Ramps, SolidShader, FLAME_KEYS};
use fixel::shading::{Flat, Gouraud, Shader};
use fixel::surface::{BandRenderer, Binned, Frame};
use fixel::texture::{
    Bilinear, Filter, Lod, LodGranularity, MipFilter, MipTexture, Nearest, Texture, Wrap,
};
use fixel::Rgb565;

/// Canary pixels before and after every buffer.
const PAD: usize = 64;
const CANARY_COLOR: u16 = 0xDEAD;
const CANARY_DEPTH: u16 = 0xBEEF;

/// What a run found; every field but `triangles`, `quads` and `refused` must stay 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Random triangles drawn (each also drawn in bands).
    pub triangles: u64,
    /// Of those, triangles that wrote at least one pixel.
    pub drawn: u64,
    /// Pixels the triangles reported written.
    pub pixels: u64,
    /// Triangles drawn again with a technique shader (typed span loops).
    pub shaded: u64,
    /// Random quads drawn.
    pub quads: u64,
    /// Draws or quads refused with an `Error` (not a failure).
    pub refused: u64,
    /// Panics caught.
    pub panics: u64,
    /// Pixels written against the depth rule.
    pub depth_violations: u64,
    /// Canaries overwritten or pixels outside the viewport changed.
    pub out_of_bounds: u64,
    /// Band frames unequal to whole frames, and implausible pictures.
    pub mismatches: u64,
    /// The first failing case's seed, for a reproducer.
    pub first_failure: Option<u64>,
}

impl Counts {
    /// Whether nothing went wrong.
    pub fn clean(&self) -> bool {
        self.panics + self.depth_violations + self.out_of_bounds + self.mismatches == 0
    }

    fn add(&mut self, o: &Counts, seed: u64) {
        self.triangles += o.triangles;
        self.drawn += o.drawn;
        self.pixels += o.pixels;
        self.shaded += o.shaded;
        self.quads += o.quads;
        self.refused += o.refused;
        self.panics += o.panics;
        self.depth_violations += o.depth_violations;
        self.out_of_bounds += o.out_of_bounds;
        self.mismatches += o.mismatches;
        if !o.clean() && self.first_failure.is_none() {
            self.first_failure = Some(seed);
        }
    }
}

/// xorshift64* (deterministic, no dependency).
struct Rng(u64);

impl Rng {
    fn new(seed: u64) -> Rng {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n.max(1)
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[self.below(xs.len() as u64) as usize]
    }
    /// An I16F16 coordinate at a random scale, or any bits.
    fn coord(&mut self) -> i32 {
        let v = self.next() as i32;
        match self.below(4) {
            0 => v,
            1 => v >> (1 + self.below(30)),
            2 => (v >> 14) + (1 << 16),
            _ => v >> 12,
        }
    }
}

fn mode(rng: &mut Rng) -> DrawMode {
    let projection = match rng.below(5) {
        0 => Projection::Affine,
        1 => Projection::Exact,
        2 => Projection::Subdivided {
            log2_n: 1 + rng.below(6) as u8,
        },
        3 => Projection::Quadratic {
            log2_n: 1 + rng.below(6) as u8,
        },
        _ => Projection::Adaptive {
            budget: rng.below(1024) as u16,
        },
    };
    DrawMode {
        projection,
        filter: rng.pick(&[Filter::Nearest, Filter::Bilinear]),
        wrap: [0, 1].map(|_| {
            rng.pick(&[
                Wrap::Repeat,
                Wrap::MirroredRepeat,
                Wrap::ClampToEdge,
                Wrap::ClampToBorder,
            ])
        }),
        shading: rng.pick(&[
            Shading::Replace,
            Shading::Modulate,
            Shading::ModulateIntensity,
            Shading::Gouraud,
            Shading::Flat,
        ]),
        depth: rng.pick(&[DepthTest::Off, DepthTest::Less]),
        cull: rng.pick(&[Cull::None, Cull::Back, Cull::Front]),
        ..DrawMode::default()
    }
}

/// A buffer with canaries before and after its `n` pixels.
fn padded<T: Copy>(n: usize, canary: T, mut fill: impl FnMut(usize) -> T) -> Vec<T> {
    let mut v = vec![canary; n + 2 * PAD];
    for (i, x) in v[PAD..PAD + n].iter_mut().enumerate() {
        *x = fill(i);
    }
    v
}

fn canaries_intact<T: Copy + PartialEq>(v: &[T], n: usize, canary: T) -> bool {
    v[..PAD].iter().chain(&v[PAD + n..]).all(|&x| x == canary)
}

/// One case: a random draw of one random triangle into a frame (depth cleared or kept),
/// the same triangle in bands against a whole cleared frame, and a random quad.
pub fn case(seed: u64) -> Counts {
    let mut c = Counts::default();
    let r = catch_unwind(AssertUnwindSafe(|| case_inner(seed, &mut c)));
    if r.is_err() {
        c.panics += 1;
    }
    c
}

fn case_inner(seed: u64, c: &mut Counts) {
    let mut rng = Rng::new(seed);
    let (w, h) = (1 + rng.below(64) as u32, 1 + rng.below(48) as u32);
    let vp = (
        rng.below(u64::from(w)) as u32,
        rng.below(u64::from(h)) as u32,
        1 + rng.below(80) as u32,
        1 + rng.below(60) as u32,
    );
    let Ok(viewport) = Viewport::new(vp.0, vp.1, vp.2, vp.3) else {
        return;
    };
    let texels: Vec<Rgb565> = (0..16)
        .map(|_| {
            Rgb565::from(embedded_graphics_core::pixelcolor::raw::RawU16::new(
                rng.next() as u16,
            ))
        })
        .collect();
    let mut chain = texels.clone();
    chain.resize(fixel::texture::chain_len(4, 4, 3), Rgb565::new(0, 0, 0));
    fixel::texture::generate_mips(&mut chain, 4, 4, 3).unwrap();
    let mip = MipTexture::new(&chain, 4, 4, 3).unwrap();
    let mut mode = mode(&mut rng);
    if rng.below(4) == 0 {
        mode.mip = rng.pick(&[MipFilter::Nearest, MipFilter::Linear]);
        let lod = |rng: &mut Rng| match rng.below(3) {
            0 => rng.next() as i32,
            1 => (rng.next() as i32) >> 20,
            _ => rng.pick(&[i32::MIN, i32::MAX, 0]),
        };
        let (a, b) = (lod(&mut rng), lod(&mut rng));
        mode.lod = Lod {
            bias: lod(&mut rng),
            min: a.min(b),
            max: a.max(b),
            granularity: rng.pick(&[
                LodGranularity::Pixel,
                LodGranularity::Span,
                LodGranularity::Triangle,
            ]),
        };
    }
    // Mostly in or near the view volume (the far plane included), else anything.
    let in_view = rng.below(4) != 0;
    let tri: [ClipVertex; 3] = core::array::from_fn(|_| {
        let position = if in_view {
            let w = 0.01 + rng.unit() * 16.0;
            let z = match rng.below(4) {
                0 => w,
                1 => w * (1.0 - rng.unit() * 1e-3),
                _ => w * (rng.unit() * 2.4 - 1.2),
            };
            [
                w * (rng.unit() * 3.0 - 1.5),
                w * (rng.unit() * 3.0 - 1.5),
                z,
                w,
            ]
            .map(Fx::saturating_from_num)
        } else {
            [0; 4].map(|_| Fx::from_bits(rng.coord()))
        };
        let mut v = ClipVertex::new(position, [0; 2].map(|_| Fx::from_bits(rng.coord())));
        v.color = [0; 3].map(|_| rng.below(300) as u16);
        v
    });
    let draw = match Draw::dynamic_mip(mode, Some(mip), viewport) {
        Ok(d) => d.with_flat_color(Rgb565::new(3, 7, 11)),
        Err(_) => {
            c.refused += 1;
            return;
        }
    };
    c.triangles += 1;
    if std::env::var_os("FIXEL_FUZZ_VERBOSE").is_some() {
        let bits = tri.map(|v| v.position.map(|x| x.to_bits()));
        println!(
            "case {seed}: {w} x {h} frame, viewport {vp:?}, {mode:?}, clip-space bits {bits:?}"
        );
    }
    // 1. Into random old pixels: the depth rule against depth cleared or kept.
    let target = Target::new(w, h, vp, &mut rng);
    let rule = if mode.depth == DepthTest::Less {
        Rule::Less
    } else {
        Rule::Off
    };
    target.check(c, &rule, |frame| draw.clip_triangles(&[tri], frame));
    // 1b. A technique shader (typed span loop) with the same triangle's positions.
    shaded(&tri, w, h, vp, viewport, &mut rng, c);
    // 2. Bands equal the whole frame.
    bands_match(&draw, &tri, w, h, &mut rng, c);
    // 3. A random convex quad draws the pixels it covers.
    quad_plausible(&mut rng, w, h, c);
}

/// A frame of random old pixels (depth cleared or kept) with canaries around its buffers.
struct Target {
    w: u32,
    h: u32,
    vp: (u32, u32, u32, u32),
    cleared: bool,
    color: Vec<u16>,
    depth: Vec<u16>,
}

impl Target {
    fn new(w: u32, h: u32, vp: (u32, u32, u32, u32), rng: &mut Rng) -> Target {
        let n = (w * h) as usize;
        let cleared = rng.below(2) == 0;
        let color = padded(n, CANARY_COLOR, |_| rng.next() as u16);
        let depth = padded(n, CANARY_DEPTH, |_| {
            if cleared {
                65535
            } else {
                (rng.next() as u16) | (rng.below(2) as u16 * 0xFF00)
            }
        });
        Target {
            w,
            h,
            vp,
            cleared,
            color,
            depth,
        }
    }

    /// Runs `draw` on a copy and counts what it did wrong.
    /// Returns which pixels changed.
    fn check(
        &self,
        c: &mut Counts,
        rule: &Rule,
        draw: impl FnOnce(&mut Frame<'_, Rgb565>) -> Result<u32, fixel::Error>,
    ) -> Vec<bool> {
        let (w, h, vp) = (self.w, self.h, self.vp);
        let n = (w * h) as usize;
        let to565 = |x: u16| Rgb565::from(embedded_graphics_core::pixelcolor::raw::RawU16::new(x));
        let mut col565: Vec<Rgb565> = self.color.iter().map(|&x| to565(x)).collect();
        let mut dep = self.depth.clone();
        let written = {
            let frame = Frame::new(&mut col565[PAD..PAD + n], w, h).unwrap();
            let depth = &mut dep[PAD..PAD + n];
            let mut frame = if self.cleared {
                frame.with_depth(depth).unwrap()
            } else {
                frame.with_depth_kept(depth).unwrap()
            };
            draw(&mut frame)
        };
        let col: Vec<u16> = col565
            .iter()
            .map(|p| embedded_graphics_core::pixelcolor::IntoStorage::into_storage(*p))
            .collect();
        if !canaries_intact(&col, n, CANARY_COLOR) || !canaries_intact(&dep, n, CANARY_DEPTH) {
            c.out_of_bounds += 1;
        }
        let inside = |i: usize| {
            let (x, y) = ((i as u32) % w, (i as u32) / w);
            x >= vp.0 && x < vp.0 + vp.2 && y >= vp.1 && y < vp.1 + vp.3
        };
        let mut changed = 0u64;
        let mut mask = vec![false; n];
        for i in 0..n {
            let (oc, od) = (self.color[PAD + i], self.depth[PAD + i]);
            let (nc, nd) = (col[PAD + i], dep[PAD + i]);
            if oc == nc && od == nd {
                continue;
            }
            changed += 1;
            mask[i] = true;
            let broken = match rule {
                Rule::Off => od != nd,
                Rule::Less => nd >= od,
                Rule::Passed(pass) => od != nd || !pass[i],
            };
            if !inside(i) {
                c.out_of_bounds += 1;
            } else if broken {
                c.depth_violations += 1;
            }
            if (broken || !inside(i)) && std::env::var_os("FIXEL_FUZZ_VERBOSE").is_some() {
                println!(
                    "  pixel ({}, {}): colour {oc:#06x} -> {nc:#06x}, depth {od} -> {nd} (depth {})",
                    i as u32 % w,
                    i as u32 / w,
                    if self.cleared { "cleared" } else { "kept" }
                );
            }
        }
        match written {
            Ok(k) if u64::from(k) < changed => c.mismatches += 1,
            Ok(k) => {
                c.pixels += u64::from(k);
                c.drawn += u64::from(k > 0);
            }
            Err(_) => c.refused += 1,
        }
        mask
    }
}

/// The depth rule a draw must keep.
enum Rule {
    /// No depth test: depth untouched.
    Off,
    /// `GL_LESS` with depth writes: a written pixel's new depth is below the old.
    Less,
    /// A blending draw (tests depth, does not write it): it changes only the pixels where
    /// the same triangle drawn opaque passed (`true`), and no depth.
    Passed(Vec<bool>),
}

/// Draws `tri` (positions; random varyings) with a random technique shader, projection
/// and depth stage.
fn shaded(
    tri: &[ClipVertex; 3],
    w: u32,
    h: u32,
    vp: (u32, u32, u32, u32),
    viewport: Viewport,
    rng: &mut Rng,
    c: &mut Counts,
) {
    let texels: Vec<Rgb565> = (0..16)
        .map(|_| {
            Rgb565::from(embedded_graphics_core::pixelcolor::raw::RawU16::new(
                rng.next() as u16,
            ))
        })
        .collect();
    let tex = Texture::new(&texels, 4, 4).unwrap();
    let alpha: Vec<u8> = (0..16).map(|_| rng.next() as u8).collect();
    let faces = core::array::from_fn(|_| tex);
    let ramps = Ramps::new().unwrap();
    let flame = Ramp::from_keys(&FLAME_KEYS).unwrap();
    let cull = rng.pick(&[Cull::None, Cull::Back, Cull::Front]);
    let which = rng.below(8);
    let target = Target::new(w, h, vp, rng);
    c.shaded += 1;
    macro_rules! go {
        ($shader:expr, $n:literal) => {{
            let verts: [Vertex<$n>; 3] = core::array::from_fn(|k| {
                Vertex::new(tri[k].position, [0; $n].map(|_| rng.coord()))
            });
            let shader = $shader;
            match rng.below(4) {
                0 => run_shaded::<_, Exact, DepthLess, $n>(
                    shader, viewport, cull, &verts, &target, c, true,
                ),
                1 => run_shaded::<_, Affine, DepthLess, $n>(
                    shader, viewport, cull, &verts, &target, c, true,
                ),
                2 => run_shaded::<_, Exact, NoDepth, $n>(
                    shader, viewport, cull, &verts, &target, c, false,
                ),
                _ => run_shaded::<_, Affine, NoDepth, $n>(
                    shader, viewport, cull, &verts, &target, c, false,
                ),
            }
        }};
    }
    match which {
        0 => go!(Gouraud, 3),
        1 => go!(Flat(rng.next() as u16), 0),
        2 => go!(
            SolidShader::new(ramps.marble(), BandLimit::new(1 + rng.below(8) as u8)),
            4
        ),
        3 => go!(
            FlameShader {
                ramp: &flame,
                t: rng.next() as i32,
                octaves: rng.below(9) as u8,
            },
            2
        ),
        4 => match CubeMap::new(faces, Bilinear) {
            Ok(cube) => go!(ReflectPerPixel(cube), 6),
            Err(_) => c.refused += 1,
        },
        5 => match AlphaBlend::new(
            tex,
            AlphaSource::Plane(&alpha),
            rng.next() as u8,
            BlendMode::Over,
            Bilinear,
        ) {
            Ok(s) => go!(s, 3),
            Err(_) => c.refused += 1,
        },
        6 => match AlphaTest::new(
            tex,
            AlphaSource::Key(rng.next() as u16),
            1 + rng.below(255) as u8,
            Nearest,
        ) {
            Ok(s) => go!(s, 3),
            Err(_) => c.refused += 1,
        },
        _ => go!(fixel::shading::triplanar::Triplanar::new(tex, Nearest), 7),
    }
}

#[allow(clippy::too_many_arguments)]
fn run_shaded<S, P, D, const N: usize>(
    shader: S,
    viewport: Viewport,
    cull: Cull,
    verts: &[Vertex<N>; 3],
    target: &Target,
    c: &mut Counts,
    depth_less: bool,
) where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
    D: DepthStage,
{
    let Ok(draw) = ShadedDraw::<S, P, D>::new(shader, viewport, cull) else {
        c.refused += 1;
        return;
    };
    let rule = match (depth_less, S::BLENDS) {
        (false, _) => Rule::Off,
        (true, false) => Rule::Less,
        (true, true) => {
            // Where the same triangle drawn opaque (it writes depth) passes the test.
            let Ok(opaque) = ShadedDraw::<Flat, P, D>::new(Flat(0x1234), viewport, cull) else {
                c.refused += 1;
                return;
            };
            let flat = verts.map(|v| Vertex::new(v.position, []));
            Rule::Passed(target.check(c, &Rule::Less, |frame| {
                opaque.clip_triangles(&[flat], frame)
            }))
        }
    };
    target.check(c, &rule, |frame| draw.clip_triangles(&[*verts], frame));
}

fn bands_match(
    draw: &Draw<'_, Rgb565>,
    tri: &[ClipVertex; 3],
    w: u32,
    h: u32,
    rng: &mut Rng,
    c: &mut Counts,
) {
    let n = (w * h) as usize;
    let clear = Rgb565::new(1, 2, 3);
    let mut whole = vec![clear; n];
    let mut wdepth = vec![0u16; n];
    {
        let mut f = Frame::new(&mut whole, w, h)
            .unwrap()
            .with_depth(&mut wdepth)
            .unwrap();
        f.clear(clear);
        let _ = draw.clip_triangles(&[*tri], &mut f);
    }
    let rows = 1 + rng.below(u64::from(h)) as u32;
    let mut buf = vec![clear; (w * rows) as usize];
    let mut bdepth = vec![0u16; (w * rows) as usize];
    let mut bins = vec![Binned::default(); rng.below(4) as usize];
    let Ok(bands) = BandRenderer::new(&mut buf, w, rows, h) else {
        return;
    };
    let Ok(mut bands) = bands.with_depth(&mut bdepth) else {
        return;
    };
    let mut banded = vec![Rgb565::new(0, 0, 0); n];
    let r = bands.render(
        &[draw],
        &mut bins,
        clear,
        |sink| draw.project(tri, &mut |s| sink.push(0, s)),
        |band| {
            let y0 = band.first_row() as usize;
            let px = band.pixels();
            banded[y0 * w as usize..y0 * w as usize + px.len()].copy_from_slice(px);
            Ok::<(), core::convert::Infallible>(())
        },
    );
    if r.is_ok() && banded != whole {
        c.mismatches += 1;
    }
}

fn quad_plausible(rng: &mut Rng, w: u32, h: u32, c: &mut Counts) {
    let span = [64, 1 << 10, 1 << 15][rng.below(3) as usize] as f64;
    let mut p: Vec<[f64; 2]> = (0..4)
        .map(|_| [0, 1].map(|_| (rng.next() as f64 / u64::MAX as f64 - 0.25) * span))
        .collect();
    let cx = p.iter().map(|q| q[0]).sum::<f64>() / 4.0;
    let cy = p.iter().map(|q| q[1]).sum::<f64>() / 4.0;
    p.sort_by(|a, b| {
        (a[1] - cy)
            .atan2(a[0] - cx)
            .total_cmp(&(b[1] - cy).atan2(b[0] - cx))
    });
    let q: [[Fx; 2]; 4] = core::array::from_fn(|k| p[k].map(Fx::saturating_from_num));
    let white = [Rgb565::new(31, 63, 31)];
    let tex = Texture::new(&white, 1, 1).unwrap();
    let mode = DrawMode {
        shading: Shading::Replace,
        cull: Cull::None,
        depth: DepthTest::Off,
        ..DrawMode::default()
    };
    let draw = Draw::dynamic(mode, Some(tex), Viewport::new(0, 0, w, h).unwrap()).unwrap();
    let mut px = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    let mut frame = Frame::new(&mut px, w, h).unwrap();
    let Ok(k) = draw_quad(&draw, q, &mut frame) else {
        c.refused += 1;
        return;
    };
    c.quads += 1;
    let cq = q.map(|v| v.map(|x| x.to_num::<f64>()));
    let s = (0..4)
        .map(|k| cq[k][0] * cq[(k + 1) % 4][1] - cq[(k + 1) % 4][0] * cq[k][1])
        .sum::<f64>()
        .signum();
    let mut drawn = 0;
    for y in 0..h {
        for x in 0..w {
            let (fx, fy) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            let d = (0..4)
                .map(|k| {
                    let (a, b) = (cq[k], cq[(k + 1) % 4]);
                    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
                    s * (ex * (fy - a[1]) - ey * (fx - a[0])) / ex.hypot(ey)
                })
                .fold(f64::INFINITY, f64::min);
            let got = px[(y * w + x) as usize] != Rgb565::new(0, 0, 0);
            drawn += u32::from(got);
            if (d > 0.125 && !got) || (d < -0.125 && got) {
                c.mismatches += 1;
                return;
            }
        }
    }
    if drawn != k {
        c.mismatches += 1;
    }
}

/// Runs cases `seed..seed + n`, calling `progress` every 1024 cases with the counts so far.
pub fn run(n: u64, seed: u64, mut progress: impl FnMut(u64, &Counts)) -> Counts {
    let mut total = Counts::default();
    for i in 0..n {
        let s = seed.wrapping_add(i);
        total.add(&case(s), s);
        if i % 1024 == 1023 {
            progress(i + 1, &total);
        }
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A short run finds nothing (the CI run is longer: `cargo xtask fuzz`).
    #[test]
    fn short_run_is_clean() {
        let c = run(3000, 1, |_, _| {});
        assert!(c.clean(), "{c:?}");
        assert!(c.triangles > 1000 && c.quads > 1000, "{c:?}");
    }

    /// The canary check sees a write past the end.
    #[test]
    fn canaries_see_an_overrun() {
        let mut v = padded(10, 7u16, |i| i as u16);
        assert!(canaries_intact(&v, 10, 7));
        v[PAD + 10] = 0;
        assert!(!canaries_intact(&v, 10, 7));
    }
}
