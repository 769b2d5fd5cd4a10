//! The solid-texture scene: a marble sphere (a 12 x 24 UV sphere, radius 1.5,
//! lattice scale 1.8 cells per unit) drawn with fixel's `SolidShader`, 320x240 in bands of
//! 8 rows, no depth buffer (one convex object, back faces culled).
//!
//! RAM: the band (5 KB), the lit clip-space vertices computed once (325 x 36 B), one band
//! range per triangle (528 x 2 B, fixel's `BandRenderer::render_spans`) and the 512-byte
//! colour ramp; the sphere itself is
//! computed, vertex by vertex, and its triangles are numbered, so no mesh is stored. Shared with the host test
//! `host-tests/tests/mcu_checksums.rs`, which renders the same frame and prints its checksum.

use crate::scenes::{Fnv1a, FrameResult, H, ROWS, W};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{sin_cos, Angle, Fx, Mat4, Vec3};
use fixel::pipeline::{Exact, NoDepth, ProjectionStage, ShadedDraw};
use fixel::scene::triangles_to_sink;
use fixel::scene::DirectionalLight;
use fixel::shading::noise::SolidMesh;
use fixel::shading::Shader;
use fixel::surface::BandStats;
use fixel::surface::{BandRange, BandRenderer, Binned, Frame};
use fixel::Error;
use fixel_scenes as demo;
use fixel_scenes::noise::{marble_sphere_model, SHOWCASE_SCALE};

/// Sphere stacks.
pub const STACKS: u16 = 12;
/// Sphere slices.
pub const SLICES: u16 = 24;
/// Sphere vertices.
pub const VERTS: usize = 13 * 25;
/// Sphere triangles.
pub const TRIS: usize = 2 * 24 * 11;
/// Bands per frame.
pub const BANDS: usize = (H / ROWS) as usize;

/// Sphere vertex `k` (stack `k / 25`, slice `k % 25`): position (radius 1.5) and unit
/// normal, polar angle `π i / 12` from `+y`, azimuth `2π j / 24`.
pub fn sphere_vertex(k: usize) -> (Vec3, Vec3) {
    let (i, j) = ((k / 25) as u32, (k % 25) as u32);
    let (st, ct) = sin_cos(Angle::from_turns((i * 65536 / 24) as u16));
    let (sp, cp) = sin_cos(Angle::from_turns((j * 65536 / 24) as u16));
    let n = Vec3::new(st.saturating_mul(cp), ct, -st.saturating_mul(sp));
    (n.scale(Fx::from_num(1.5)), n)
}

/// Sphere triangle `t`: one per slice in the two pole rows, two per quad elsewhere
/// (counter-clockwise from outside), as `demo::uv_sphere` numbers them.
pub fn sphere_triangle(t: usize) -> [u16; 3] {
    let s = usize::from(SLICES);
    let id = |i: usize, j: usize| (i * (s + 1) + j) as u16;
    let (i, j, second) = if t < s {
        (0, t, false)
    } else if t >= TRIS - s {
        (usize::from(STACKS) - 1, t - (TRIS - s), false)
    } else {
        let u = t - s;
        (1 + u / (2 * s), (u % (2 * s)) / 2, u % 2 == 1)
    };
    let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
    if i == 0 {
        [a, b, c]
    } else if i == usize::from(STACKS) - 1 {
        [a, b, d]
    } else if second {
        [a, c, d]
    } else {
        [a, b, c]
    }
}

/// The sphere's model matrix: the showcase's, moved to the middle of the frame.
pub fn model() -> Mat4 {
    Mat4::translation(Vec3::new(Fx::from_num(1.6), Fx::from_num(-0.5), Fx::ZERO))
        * marble_sphere_model()
}

/// Scratch of the scene.
pub struct NoiseBuffers {
    color: [Rgb565; (W * ROWS) as usize],
    verts: [Option<Vertex<4>>; VERTS],
    ranges: [BandRange; TRIS],
}

impl NoiseBuffers {
    /// Zeroed.
    pub const fn new() -> Self {
        NoiseBuffers {
            color: [Rgb565::new(0, 0, 0); (W * ROWS) as usize],
            verts: [None; VERTS],
            ranges: [BandRange::EMPTY; TRIS],
        }
    }
}

impl Default for NoiseBuffers {
    fn default() -> Self {
        Self::new()
    }
}

/// The lit clip-space vertices of the sphere, with the object-space point in lattice units.
pub fn vertices(verts: &mut [Option<Vertex<4>>; VERTS]) {
    let (model, camera, light) = (model(), demo::camera(20), DirectionalLight::default());
    for (k, slot) in verts.iter_mut().enumerate() {
        let (p, n) = sphere_vertex(k);
        let (p, n) = ([p], [n]);
        match SolidMesh::new(&p, Some(&n), &[], SHOWCASE_SCALE) {
            Ok(solid) => solid.vertices(&model, &camera, Some(&light), core::slice::from_mut(slot)),
            Err(_) => *slot = None,
        }
    }
}

/// Renders the frame with `shader`: vertices once (lit, object-space point as varyings),
/// then through fixel's band renderer: each triangle's band range once, then band by band
/// the triangles that meet the band.
/// `pause` / `resume` bracket the harness-only checksum of each band.
pub fn render<S: Shader<Varyings = [i32; 4]>>(
    shader: S,
    buf: &mut NoiseBuffers,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    render_in::<S, Exact>(shader, buf, pause, resume)
}

/// [`render`] with projection `P` (the scene uses [`Exact`]; `report_noise` also measures
/// `SubdividedBy<3>`, perspective-correct every 8 pixels).
pub fn render_in<S: Shader<Varyings = [i32; 4]>, P: ProjectionStage>(
    shader: S,
    buf: &mut NoiseBuffers,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let draw = ShadedDraw::<S, P, NoDepth>::new(shader, Viewport::new(0, 0, W, H)?, Cull::Back)?;
    vertices(&mut buf.verts);
    let tri = |verts: &[Option<Vertex<4>>; VERTS], t: &[u16; 3]| -> Option<[Vertex<4>; 3]> {
        let v = |k: usize| verts.get(usize::from(t[k])).copied().flatten();
        Some([v(0)?, v(1)?, v(2)?])
    };
    let verts = &buf.verts;
    let mut sum = Fnv1a::default();
    let mut bands = BandRenderer::new(&mut buf.color, W, ROWS, H)?;
    let stats = bands.render_spans(
        &[&draw],
        &mut [] as &mut [Binned],
        &mut buf.ranges,
        Rgb565::new(0, 0, 0),
        |sink| {
            triangles_to_sink(
                &draw,
                0,
                TRIS,
                0,
                |t, _| tri(verts, &sphere_triangle(t)),
                sink,
            );
            if sink.fresh() {
                crate::scenes::geometry_done();
            }
        },
        sum.band_flush::<core::convert::Infallible>(pause, resume),
    )?;
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}

/// [`render`] drawn into one whole 320 x 240 frame (`color`) with the same draw, triangle
/// by triangle: the figure the banded frame is compared with (the same checksum).
pub fn render_whole<S: Shader<Varyings = [i32; 4]>>(
    shader: S,
    color: &mut [Rgb565],
    verts: &mut [Option<Vertex<4>>; VERTS],
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let draw =
        ShadedDraw::<S, Exact, NoDepth>::new(shader, Viewport::new(0, 0, W, H)?, Cull::Back)?;
    vertices(verts);
    let mut frame = Frame::new(color, W, H)?;
    frame.clear(Rgb565::new(0, 0, 0));
    let mut pixels = 0u32;
    for t in 0..TRIS {
        let k = sphere_triangle(t);
        let v = |i: usize| verts.get(usize::from(k[i])).copied().flatten();
        if let (Some(a), Some(b), Some(c)) = (v(0), v(1), v(2)) {
            pixels = pixels.wrapping_add(draw.clip_triangles(&[[a, b, c]], &mut frame)?);
        }
    }
    pause();
    let mut sum = Fnv1a::default();
    sum.pixels(frame.pixels());
    resume();
    Ok(FrameResult {
        checksum: sum.0,
        stats: BandStats {
            bands: 1,
            pixels,
            ..BandStats::default()
        },
    })
}

/// Width of the flame firmware's frame.
pub const FLAME_W: u32 = 80;
/// Height of the flame firmware's frame.
pub const FLAME_H: u32 = 96;
/// Pixels of the flame frame.
pub const FLAME_PIXELS: usize = (FLAME_W * FLAME_H) as usize;

/// `frames` frames of the flame (t = i/8 s, 5 octaves) into `color`, FNV-1a over all of
/// them in order; `pause` / `resume` bracket the checksum.
pub fn flame_frames(
    color: &mut [Rgb565; FLAME_PIXELS],
    frames: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    flame_frames_with(color, frames, 5, pause, resume)
}

/// Pixels of a band of the flame frame (80 x 8).
pub const FLAME_BAND_PIXELS: usize = (FLAME_W * ROWS) as usize;

/// [`flame_frames`] drawn in bands of [`ROWS`] rows through `band` (1.25 KB instead of the
/// frame's 15 KB): each frame's quad binned once, then each band drawn from the bins. The
/// same pixels and checksum.
pub fn flame_bands(
    band: &mut [Rgb565; FLAME_BAND_PIXELS],
    frames: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    use fixel::shading::noise::{FlameShader, Ramp, FLAME_KEYS};
    let ramp = Ramp::from_keys(&FLAME_KEYS)?;
    let vp = Viewport::new(0, 0, FLAME_W, FLAME_H)?;
    let quad = flame_quad();
    let mut sum = Fnv1a::default();
    let mut stats = BandStats::default();
    for i in 0..frames {
        let shader = FlameShader {
            ramp: &ramp,
            t: (i as i32) << 13,
            octaves: 5,
        };
        let draw = ShadedDraw::<_, Exact, NoDepth>::new(shader, vp, Cull::None)?;
        let mut bins = [Binned::EMPTY; 4];
        let mut bands = BandRenderer::new(&mut band[..], FLAME_W, ROWS, FLAME_H)?;
        let s = bands.render(
            &[&draw],
            &mut bins,
            Rgb565::new(0, 0, 0),
            |sink| {
                for t in &quad {
                    draw.project(t, &mut |s| sink.push(0, s));
                }
                if sink.fresh() {
                    crate::scenes::geometry_done();
                }
            },
            sum.band_flush::<core::convert::Infallible>(pause, resume),
        )?;
        stats.pixels = stats.pixels.saturating_add(s.pixels);
        stats.bands = stats.bands.saturating_add(s.bands);
    }
    Ok(FrameResult {
        checksum: sum.0,
        stats,
    })
}

/// The flame's quad over the whole viewport, as two triangles with flame-unit varyings.
fn flame_quad() -> [[Vertex<2>; 3]; 2] {
    let v = |xn: i32, yn: i32, x: i32, y: i32| {
        Vertex::new(
            [Fx::from_num(xn), Fx::from_num(yn), Fx::ZERO, Fx::ONE],
            [x, y],
        )
    };
    let (x0, x1, y0, y1) = FLAME_QUAD;
    let (a, b, c, d) = (
        v(-1, -1, x0, y0),
        v(1, -1, x1, y0),
        v(1, 1, x1, y1),
        v(-1, 1, x0, y1),
    );
    [[a, b, c], [a, c, d]]
}

/// Flame units of the quad's corners: `x` in `-1.3..1.3`, `y` in `-0.1..1.4` (I16F16), as
/// `(x0, x1, y0, y1)`; `y0` at the bottom row.
pub const FLAME_QUAD: (i32, i32, i32, i32) = (-85_197, 85_197, -6_554, 91_750);

/// [`flame_frames`] with `octaves` of turbulence (`report_noise` measures several).
pub fn flame_frames_with(
    color: &mut [Rgb565; FLAME_PIXELS],
    frames: u32,
    octaves: u8,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    use fixel::shading::noise::{FlameShader, Ramp, FLAME_KEYS};
    let ramp = Ramp::from_keys(&FLAME_KEYS)?;
    let vp = Viewport::new(0, 0, FLAME_W, FLAME_H)?;
    let quad = flame_quad();
    let mut sum = Fnv1a::default();
    let mut pixels = 0;
    for i in 0..frames {
        let shader = FlameShader {
            ramp: &ramp,
            t: (i as i32) << 13,
            octaves,
        };
        let draw = ShadedDraw::<_, Exact, NoDepth>::new(shader, vp, Cull::None)?;
        let mut frame = Frame::new(color, FLAME_W, FLAME_H)?;
        pixels += draw.clip_triangles(&quad, &mut frame)?;
        pause();
        sum.pixels(frame.pixels());
        resume();
    }
    Ok(FrameResult {
        checksum: sum.0,
        stats: BandStats {
            bands: frames,
            pixels,
            ..BandStats::default()
        },
    })
}
