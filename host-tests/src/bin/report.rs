//! Speed against error for every benchmark scene and mode. Run by
//! `cargo xtask report` (which first counts instructions on microcontrollers under QEMU and
//! hands them over with `--mcu`):
//!
//! ```text
//! report --out DIR [--runs N] [--mcu mcu.tsv]
//! ```
//!
//! * Modes: `examples/firmware/src/modes.rs` (shared with the report firmwares): projection
//!   Affine / Subdivided N=8, 16 / Exact / Adaptive (1/4 texel), filter Nearest / Bilinear
//!   (floor also nearest-mipmap-nearest and trilinear with LOD per pixel and per span), lit
//!   and unlit on the lit scenes; typed pipelines, repeat wrap, 16-bit depth, back-face cull.
//! * Host speed: all N frames of the scene (`docs/scenes.md`: clear + transform + draw,
//!   320 x 240, fixel's own fixed-point scene path, as `benches/scenes.rs` does), `N` runs
//!   after a warm-up; ns per pixel that passed the depth test: median, min, max.
//! * Microcontrollers: exact instructions per pixel of frame 0 (from `mcu.tsv`), checked
//!   against the checksum this program computes through the same band code.
//! * Error: the same typed draw fed the reference's clip-space triangles
//!   (`host_tests::adapter`), against the f64 reference with the mode's filter and lighting
//!   and exact perspective (implementation + projection error; PSNR, max, p99 in RGB565
//!   LSBs, coverage disagreement), and against the scene's ideal image (the bilinear
//!   reference on the cube and sphere, the 8 x 8 supersampled reference on the floor).
//! * Pareto: a mode is dominated when another with the same lighting is at most as slow and
//!   at least as accurate (PSNR against the ideal), one of them strictly.

#[path = "../../../examples/firmware/src/modes.rs"]
#[allow(dead_code)]
mod modes;
#[path = "../../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::demo;
use fixel::geometry::{ClipVertex, Cull, Viewport};
use fixel::math::Mat4;
use fixel::pipeline::{DepthTest, DrawMode, Shading};
use fixel::scene::{draw_mesh, DirectionalLight, Mesh};
use fixel::surface::Frame;
use fixel::texture::{chain_len, full_levels};
use fixel::texture::{generate_mips, write_footprints, MipTexture, Texture};
use host_tests::adapter;
use host_tests::metrics::{compare_rgb565, Report};
use host_tests::png_io::write_png_rgb8;
use host_tests::reference::{self, RefFilter, RefMip, RefMode, RefProjection, RefShading};
use host_tests::scenes as refscenes;
use indicatif::{ProgressBar, ProgressStyle};
use modes::{Filt, Mode, Proj};

const W: u32 = demo::WIDTH;
const H: u32 = demo::HEIGHT;
/// Supersampling of the floor's ideal reference.
const SS: u32 = 8;
/// Speed targets, in table order.
const TARGETS: [&str; 3] = ["host", "Cortex-M0+", "Cortex-M4F"];

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Scene {
    Cube,
    Sphere,
    Floor,
}

impl Scene {
    const ALL: [Scene; 3] = [Scene::Cube, Scene::Sphere, Scene::Floor];
    fn name(self) -> &'static str {
        match self {
            Scene::Cube => "cube",
            Scene::Sphere => "sphere",
            Scene::Floor => "floor",
        }
    }
    fn modes(self) -> &'static [Mode] {
        match self {
            Scene::Floor => &modes::FLOOR_MODES,
            Scene::Cube => &modes::CUBE_MODES,
            Scene::Sphere => &modes::SPHERE_MODES,
        }
    }
    fn frames(self) -> u32 {
        match self {
            Scene::Floor => 20,
            _ => 100,
        }
    }
    /// Frames whose errors are pooled.
    fn error_frames(self) -> &'static [u32] {
        match self {
            Scene::Cube => &[0, 25, 50, 75],
            Scene::Sphere => &[0, 50],
            Scene::Floor => &[0],
        }
    }
    fn tex_size(self) -> (u32, u32) {
        match self {
            Scene::Cube => (128, 128),
            Scene::Sphere => (256, 128),
            Scene::Floor => (64, 64),
        }
    }
    fn far(self) -> i32 {
        match self {
            Scene::Floor => 200,
            _ => 20,
        }
    }
    fn model(self, i: u32) -> Mat4 {
        match self {
            Scene::Cube => demo::cube_model(i),
            Scene::Sphere => demo::sphere_model(i),
            Scene::Floor => Mat4::IDENTITY,
        }
    }
    fn desc(self, i: u32) -> refscenes::SceneDesc {
        match self {
            Scene::Cube => refscenes::cube(i),
            Scene::Sphere => refscenes::sphere(i),
            Scene::Floor => refscenes::floor(),
        }
    }
    fn lit(self) -> bool {
        self != Scene::Floor
    }
    fn ideal(self) -> &'static str {
        match self {
            Scene::Floor => "8x8 supersampled reference",
            _ => "bilinear f64 reference",
        }
    }
}

/// A reference to render: error frame index, and (lighting, filter) or `None` for the
/// supersampled one.
type Job = (usize, Option<(bool, Filt)>);
/// RGB565 pixels and coverage.
type Image = (Vec<u16>, Vec<bool>);

fn mode_name(m: &Mode) -> String {
    let mut s = String::new();
    m.write_name(&mut s).expect("name");
    s
}

/// `T(w, h)` with a full mip chain (level 0 alone for the unmipmapped scenes), and level 0's
/// bilinear footprints (for `Filt::BilinearFootprint`).
struct Tex {
    chain: Vec<Rgb565>,
    footprints: Vec<u64>,
    w: u32,
    h: u32,
    levels: u32,
}

impl Tex {
    fn new(scene: Scene) -> Self {
        let (w, h) = scene.tex_size();
        let levels = if scene == Scene::Floor {
            full_levels(w, h)
        } else {
            1
        };
        let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(w, h, levels)];
        demo::checker_texture(w, h, &mut chain[..(w * h) as usize]).expect("texture");
        if levels > 1 {
            generate_mips(&mut chain, w, h, levels).expect("mips");
        }
        let mut footprints = vec![0u64; (w * h) as usize];
        let base = Texture::new(&chain[..(w * h) as usize], w, h).expect("texture");
        write_footprints(&base, &mut footprints).expect("footprints");
        Tex {
            chain,
            footprints,
            w,
            h,
            levels,
        }
    }
    /// The texture `m` samples: level 0 with its footprints for `Filt::BilinearFootprint`,
    /// else [`Tex::mip`].
    fn for_mode(&self, m: &Mode) -> MipTexture<'_> {
        if m.filter != Filt::BilinearFootprint {
            return self.mip();
        }
        let n = (self.w * self.h) as usize;
        let base = Texture::new(&self.chain[..n], self.w, self.h).expect("texture");
        MipTexture::single(base)
            .with_footprints(&self.footprints)
            .expect("footprints")
    }
    fn mip(&self) -> MipTexture<'_> {
        if self.levels > 1 {
            MipTexture::new(&self.chain, self.w, self.h, self.levels).expect("chain")
        } else {
            MipTexture::single(Texture::new(&self.chain, self.w, self.h).expect("texture"))
        }
    }
}

struct Meshes {
    cube: demo::MeshData<24, 12>,
    sphere: Box<demo::MeshData<{ demo::SPHERE_VERTICES }, { demo::SPHERE_TRIANGLES }>>,
    floor: demo::MeshData<4, 2>,
}

impl Meshes {
    fn mesh(&self, s: Scene) -> Mesh<'_> {
        match s {
            Scene::Cube => self.cube.mesh(),
            Scene::Sphere => self.sphere.mesh(),
            Scene::Floor => self.floor.mesh(),
        }
        .expect("mesh")
    }
}

/// Host timing of one mode: ns per drawn pixel of each run, and drawn pixels per run.
fn time_mode(scene: Scene, m: &Mode, tex: &Tex, meshes: &Meshes, runs: u32) -> (Vec<f64>, u64) {
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    let draw = m.draw(tex.for_mode(m), vp).expect("draw");
    let mesh = meshes.mesh(scene);
    let camera = demo::camera(scene.far());
    let light = DirectionalLight::default();
    let light = m.lit.then_some(&light);
    let n = (W * H) as usize;
    let mut color = vec![Rgb565::new(0, 0, 0); n];
    let mut depth = vec![0u16; n];
    let mut run = || {
        let mut px = 0u64;
        for i in 0..scene.frames() {
            let model = scene.model(i);
            let mut frame = Frame::new(&mut color, W, H)
                .expect("frame")
                .with_depth(&mut depth)
                .expect("depth");
            frame.clear(Rgb565::new(0, 0, 0));
            px += u64::from(draw_mesh(&draw, &mesh, &model, &camera, light, &mut frame).unwrap());
        }
        std::hint::black_box(px)
    };
    let pixels = run();
    let mut ns = Vec::new();
    for _ in 0..runs {
        let t0 = Instant::now();
        let px = run();
        ns.push(t0.elapsed().as_nanos() as f64 / px.max(1) as f64);
    }
    (ns, pixels)
}

/// Frame 0 through the firmware's band code: (checksum, pixels), as the MCU prints them.
fn band_checksum(scene: Scene, m: &Mode, tex: &Tex, meshes: &Meshes) -> (String, u64) {
    let mut buf = Box::new(scenes::Buffers::new());
    let (mut a, mut b) = (|| {}, || {});
    let vp = scenes::viewport().expect("viewport");
    let draw = m.draw(tex.for_mode(m), vp).expect("draw");
    let r = match scene {
        Scene::Cube => scenes::cube_with(
            scenes::Target::Bands(&mut buf),
            &draw,
            m.lit,
            0,
            &mut a,
            &mut b,
        ),
        Scene::Sphere => {
            let mesh = meshes.mesh(scene);
            scenes::sphere_with(
                scenes::Target::Bands(&mut buf),
                &draw,
                &mesh,
                m.lit,
                0,
                &mut a,
                &mut b,
            )
        }
        Scene::Floor => scenes::floor_with(scenes::Target::Bands(&mut buf), &draw, &mut a, &mut b),
    }
    .expect("band frame");
    (format!("0x{:08x}", r.checksum), u64::from(r.stats.pixels))
}

/// The reference state a mode's filter corresponds to.
fn ref_filter(f: Filt) -> (RefFilter, RefMip) {
    match f {
        Filt::Nearest => (RefFilter::Nearest, RefMip::None),
        Filt::Bilinear | Filt::BilinearFootprint => (RefFilter::Bilinear, RefMip::None),
        Filt::NearestMip => (RefFilter::Nearest, RefMip::Nearest),
        Filt::Trilinear | Filt::TrilinearSpan => (RefFilter::Bilinear, RefMip::Linear),
    }
}

/// One error frame of a scene: the reference's triangles (lit and unlit), fixel's clip
/// triangles, and fixel's coverage.
struct ErrFrame {
    desc: [refscenes::SceneDesc; 2],
    ref_tris: [Vec<reference::RefTriangle>; 2],
    clip: [Vec<[ClipVertex; 3]>; 2],
    covered: Vec<bool>,
}

impl ErrFrame {
    fn new(scene: Scene, i: u32) -> Self {
        let lit = scene.desc(i);
        let unlit = refscenes::SceneDesc {
            lit: false,
            ..lit.clone()
        };
        let ref_tris = [
            refscenes::to_ref_triangles(&unlit),
            refscenes::to_ref_triangles(&lit),
        ];
        let clip = [
            adapter::clip_triangles(&ref_tris[0]),
            adapter::clip_triangles(&ref_tris[1]),
        ];
        let cov_mode = DrawMode {
            shading: Shading::Flat,
            depth: DepthTest::Less,
            cull: Cull::Back,
            ..DrawMode::default()
        };
        let covered = adapter::render(&clip[0], None, cov_mode, W, H).covered;
        ErrFrame {
            desc: [unlit, lit],
            ref_tris,
            clip,
            covered,
        }
    }

    fn ref_mode(&self, lit: bool, f: Filt) -> RefMode {
        let (filter, mip) = ref_filter(f);
        RefMode {
            projection: RefProjection::Perspective,
            filter,
            mip,
            shading: if lit {
                RefShading::Modulate
            } else {
                RefShading::Replace
            },
            ..self.desc[usize::from(lit)].mode
        }
    }

    /// The f64 reference (RGB565-quantised pixels, coverage).
    fn reference(&self, lit: bool, f: Filt) -> (Vec<u16>, Vec<bool>) {
        let l = usize::from(lit);
        let r = reference::render(
            &self.ref_tris[l],
            Some(&self.desc[l].texture),
            &self.ref_mode(lit, f),
            W,
            H,
        );
        (r.quantize_rgb565(), r.covered)
    }

    /// The supersampled reference (bilinear on level 0, box filtered), unlit.
    fn supersampled(&self) -> (Vec<u16>, Vec<bool>) {
        let r = reference::render_supersampled(
            &self.ref_tris[0],
            Some(&self.desc[0].texture),
            &self.ref_mode(false, Filt::Bilinear),
            W,
            H,
            SS,
        );
        (r.quantize_rgb565(), r.covered)
    }

    /// fixel's frame with the typed draw of `m`.
    fn fixel(&self, m: &Mode, tex: &Tex) -> Vec<u16> {
        let vp = Viewport::new(0, 0, W, H).expect("viewport");
        let draw = m.draw(tex.for_mode(m), vp).expect("draw");
        let n = (W * H) as usize;
        let mut color = vec![Rgb565::new(0, 0, 0); n];
        let mut depth = vec![0u16; n];
        let mut frame = Frame::new(&mut color, W, H)
            .expect("frame")
            .with_depth(&mut depth)
            .expect("depth");
        frame.clear(Rgb565::new(0, 0, 0));
        draw.clip_triangles(&self.clip[usize::from(m.lit)], &mut frame)
            .unwrap();
        color
            .iter()
            .map(|&c| RawU16::from(c).into_inner())
            .collect()
    }
}

/// Everything measured for one (scene, mode).
struct Row {
    mode: Mode,
    name: String,
    host: Option<(f64, f64, f64)>,
    host_pixels: u64,
    /// Instructions per pixel by target label.
    mcu: BTreeMap<&'static str, f64>,
    /// (checksum matches the host's band frame) by target label.
    mcu_ok: BTreeMap<&'static str, bool>,
    err: Report,
    ideal: Report,
    /// Targets on which the mode is dominated.
    dominated: Vec<&'static str>,
}

impl Row {
    fn cost(&self, target: &str) -> Option<f64> {
        if target == "host" {
            self.host.map(|h| h.0)
        } else {
            self.mcu.get(target).copied()
        }
    }
}

fn median_min_max(mut v: Vec<f64>) -> (f64, f64, f64) {
    v.sort_by(f64::total_cmp);
    (v[v.len() / 2], v[0], v[v.len() - 1])
}

fn read_mcu(path: &Path) -> Vec<(String, String, String, f64, u64, String)> {
    let text = std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("could not read {}: {e}", path.display()));
    text.lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            if f.len() < 6 {
                return None;
            }
            let insns: f64 = f[3].parse().ok()?;
            let px: u64 = f[4].parse().ok()?;
            Some((
                f[0].to_string(),
                f[1].to_string(),
                f[2].to_string(),
                insns / px.max(1) as f64,
                px,
                f[5].to_string(),
            ))
        })
        .collect()
}

fn psnr(r: &Report) -> f64 {
    if r.psnr_db.is_finite() {
        r.psnr_db
    } else {
        99.0
    }
}

/// Marks dominated modes per target: same lighting, at most as slow and at least as
/// accurate, one of them strictly.
fn pareto(rows: &mut [Row]) {
    for t in TARGETS {
        let pts: Vec<Option<(f64, f64, bool)>> = rows
            .iter()
            .map(|r| r.cost(t).map(|c| (c, psnr(&r.ideal), r.mode.lit)))
            .collect();
        for i in 0..rows.len() {
            let Some((ci, pi, li)) = pts[i] else { continue };
            let dom = pts.iter().enumerate().any(|(j, p)| {
                matches!(*p, Some((cj, pj, lj)) if j != i && lj == li && cj <= ci && pj >= pi
                    && (cj < ci || pj > pi))
            });
            if dom {
                rows[i].dominated.push(t);
            }
        }
    }
}

/// The cheapest mode (with the scene's lighting) within `db` of the best PSNR on `t`.
fn pick<'r>(rows: &'r [Row], lit: bool, t: &str, db: f64) -> Option<&'r Row> {
    let cand: Vec<&Row> = rows
        .iter()
        .filter(|r| r.mode.lit == lit && r.cost(t).is_some())
        .collect();
    let best = cand.iter().map(|r| psnr(&r.ideal)).fold(f64::MIN, f64::max);
    cand.into_iter()
        .filter(|r| psnr(&r.ideal) >= best - db)
        .min_by(|a, b| {
            a.cost(t)
                .unwrap_or(0.0)
                .total_cmp(&b.cost(t).unwrap_or(0.0))
        })
}

fn cost_unit(t: &str) -> &'static str {
    if t == "host" {
        "ns/px"
    } else {
        "instructions/px"
    }
}

fn plot_file(scene: Scene, t: &str) -> String {
    let t = match t {
        "host" => "host",
        "Cortex-M0+" => "m0plus",
        _ => "m4f",
    };
    format!("{}-{t}.png", scene.name())
}

fn proj_colour(p: Proj) -> plotters::style::RGBColor {
    use plotters::style::RGBColor;
    match p {
        Proj::Affine => RGBColor(214, 39, 40),
        Proj::Sub4 => RGBColor(227, 119, 194),
        Proj::Sub8 => RGBColor(255, 127, 14),
        Proj::Sub16 => RGBColor(188, 160, 0),
        Proj::Sub32 => RGBColor(140, 86, 75),
        Proj::Sub64 => RGBColor(127, 127, 127),
        Proj::Quad16 => RGBColor(148, 103, 189),
        Proj::Quad32 => RGBColor(23, 190, 207),
        Proj::Exact => RGBColor(31, 119, 180),
        Proj::Adaptive => RGBColor(44, 160, 44),
    }
}

fn filt_short(f: Filt) -> &'static str {
    match f {
        Filt::Nearest => "N",
        Filt::Bilinear => "B",
        Filt::BilinearFootprint => "Bf",
        Filt::NearestMip => "NMN",
        Filt::Trilinear => "T",
        Filt::TrilinearSpan => "Ts",
    }
}

/// One plot: cost on x, PSNR against the ideal on y, one point per mode.
fn plot(scene: Scene, t: &str, rows: &[Row], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    let pts: Vec<(&Row, f64, f64)> = rows
        .iter()
        .filter_map(|r| r.cost(t).map(|c| (r, c, psnr(&r.ideal))))
        .collect();
    if pts.is_empty() {
        return Ok(());
    }
    let (w, h) = (960u32, 640u32);
    let mut buf = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (area, legend) = root.split_horizontally(w - 120);
        let (x0, x1) = pts
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
        let (y0, y1) = pts
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.2), b.max(p.2)));
        let (dx, dy) = ((x1 - x0).max(1e-9) * 0.08, (y1 - y0).max(0.5) * 0.08);
        let title = format!(
            "{}: {} cost vs PSNR against the {}",
            scene.name(),
            t,
            scene.ideal()
        );
        let mut chart = ChartBuilder::on(&area)
            .caption(title, ("sans-serif", 20))
            .margin(12)
            .margin_bottom(30)
            .x_label_area_size(44)
            .y_label_area_size(56)
            .build_cartesian_2d((x0 - dx).max(0.0)..x1 + dx * 2.0, y0 - dy..y1 + dy)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc(format!(
                "{} ({}, lower is faster)",
                cost_unit(t),
                if t == "host" {
                    "median".to_string()
                } else {
                    format!("exact, QEMU, frame 0, {t}")
                }
            ))
            .y_desc("PSNR, dB (higher is more accurate)")
            .label_style(("sans-serif", 14))
            .draw()
            .map_err(|e| e.to_string())?;
        // Pareto fronts, one per lighting.
        for lit in [true, false] {
            let mut front: Vec<(f64, f64)> = pts
                .iter()
                .filter(|p| p.0.mode.lit == lit && !p.0.dominated.contains(&t))
                .map(|p| (p.1, p.2))
                .collect();
            front.sort_by(|a, b| a.0.total_cmp(&b.0));
            if front.len() > 1 {
                let style = if lit {
                    RGBColor(120, 120, 120).stroke_width(2)
                } else {
                    RGBColor(190, 190, 190).stroke_width(2)
                };
                chart
                    .draw_series(LineSeries::new(front, style))
                    .map_err(|e| e.to_string())?;
            }
        }
        // Points first, then labels placed where they overlap no other label and no point
        // (in pixels): beside the point, above, below or to its left; a label equal to one
        // already drawn within a few pixels is left out (the report's table has every mode).
        let mut boxes: Vec<(i32, i32, i32, i32)> = vec![];
        for (r, x, y) in &pts {
            let c = proj_colour(r.mode.proj);
            let style = if r.mode.lit || !scene.lit() {
                c.filled()
            } else {
                c.stroke_width(2)
            };
            chart
                .draw_series(std::iter::once(Circle::new((*x, *y), 6, style)))
                .map_err(|e| e.to_string())?;
            let (px, py) = chart.backend_coord(&(*x, *y));
            boxes.push((px - 7, py - 7, px + 7, py + 7));
        }
        let overlaps = |a: &(i32, i32, i32, i32), b: &(i32, i32, i32, i32)| {
            a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
        };
        let mut placed: Vec<(String, i32, i32)> = vec![];
        for (r, x, y) in &pts {
            let label = format!(
                "{}{}",
                filt_short(r.mode.filter),
                if scene.lit() && !r.mode.lit {
                    " unlit"
                } else if r.mode.facet {
                    " facet"
                } else {
                    ""
                }
            );
            let (px, py) = chart.backend_coord(&(*x, *y));
            let near_same = placed
                .iter()
                .any(|(l, qx, qy)| *l == label && (qx - px).abs() < 16 && (qy - py).abs() < 10);
            if near_same {
                continue;
            }
            let lw = 7 * label.len() as i32 + 2;
            let spot = [
                (9, -7),
                (9, -20),
                (9, 6),
                (-lw - 9, -7),
                (-lw / 2, -24),
                (-lw / 2, 10),
            ]
            .into_iter()
            .map(|(dx, dy)| (px + dx, py + dy, px + dx + lw, py + dy + 14))
            .find(|b| !boxes.iter().any(|o| overlaps(b, o)));
            let Some(b) = spot else {
                continue;
            };
            boxes.push(b);
            placed.push((label.clone(), px, py));
            let colour = if r.dominated.contains(&t) {
                RGBColor(150, 150, 150)
            } else {
                RGBColor(0, 0, 0)
            };
            let font = ("sans-serif", 13).into_font().color(&colour);
            area.draw(&Text::new(label, (b.0, b.1), font))
                .map_err(|e| e.to_string())?;
        }
        // Legend: the colours of the projections that have a point here.
        let shown = modes::PROJS
            .into_iter()
            .filter(|p| pts.iter().any(|(r, _, _)| r.mode.proj == *p));
        for (k, p) in shown.enumerate() {
            let m = Mode {
                lit: false,
                facet: false,
                filter: Filt::Nearest,
                proj: p,
            };
            let y = 60 + 20 * k as i32;
            legend
                .draw(&Circle::new((12, y), 6, proj_colour(p).filled()))
                .map_err(|e| e.to_string())?;
            legend
                .draw(&Text::new(m.proj_name(), (24, y - 7), ("sans-serif", 14)))
                .map_err(|e| e.to_string())?;
        }
        let notes = if scene.lit() {
            "N nearest, B bilinear, Bf bilinear from footprints, facet = light per triangle; filled = lit, ring = unlit; grey label = dominated; lines = Pareto fronts"
        } else {
            "N nearest, B bilinear, Bf from footprints, NMN nearest-mipmap-nearest, T trilinear (LOD per pixel), Ts (per span); grey label = dominated"
        };
        root.draw(&Text::new(notes, (70, h as i32 - 16), ("sans-serif", 13)))
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    write_png_rgb8(path, w, h, &buf).map_err(|e| e.to_string())
}

fn sh(cmd: &str, args: &[&str]) -> String {
    std::process::Command::new(cmd)
        .args(args)
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_default()
}

fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let n = std::thread::available_parallelism().map_or(0, |n| n.get());
    format!("{cpu}, {n} cores ({})", std::env::consts::ARCH)
}

fn fmt_host(h: Option<(f64, f64, f64)>) -> String {
    h.map_or("-".into(), |(m, a, b)| format!("{m:.2} ({a:.2}-{b:.2})"))
}

fn fmt_psnr(r: &Report) -> String {
    if r.psnr_db.is_finite() {
        format!("{:.1}", r.psnr_db)
    } else {
        "inf".into()
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut out = PathBuf::from("target/report");
    let mut runs = 7u32;
    let mut mcu_path: Option<PathBuf> = None;
    let mut only: Option<String> = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--out" => out = PathBuf::from(it.next().expect("--out DIR")),
            "--runs" => runs = it.next().and_then(|n| n.parse().ok()).expect("--runs N"),
            "--mcu" => mcu_path = Some(PathBuf::from(it.next().expect("--mcu FILE"))),
            "--scene" => only = Some(it.next().expect("--scene NAME").clone()),
            other => {
                eprintln!(
                    "usage: report --out DIR [--runs N] [--mcu mcu.tsv] [--scene cube|sphere|floor] (got `{other}`)"
                );
                std::process::exit(2);
            }
        }
    }
    std::fs::create_dir_all(&out).expect("output directory");
    if let Err(e) = host_tests::plot_font::register() {
        eprintln!("report: {e}");
        std::process::exit(1)
    }

    let chosen: Vec<Scene> = Scene::ALL
        .into_iter()
        .filter(|s| only.as_deref().is_none_or(|o| o == s.name()))
        .collect();
    if chosen.is_empty() {
        eprintln!("report: no scene named {only:?} (cube, sphere, floor)");
        std::process::exit(2);
    }
    let t_start = Instant::now();
    let mcu = mcu_path.as_deref().map(read_mcu).unwrap_or_default();
    let meshes = Meshes {
        cube: demo::cube(),
        sphere: Box::new(demo::sphere()),
        floor: demo::floor(),
    };
    let texes: BTreeMap<Scene, Tex> = chosen.iter().map(|&s| (s, Tex::new(s))).collect();

    let n_modes: usize = chosen.iter().map(|s| s.modes().len()).sum();
    let n_ref: usize = chosen
        .iter()
        .map(|&s| {
            let filters = if s == Scene::Floor { 4 } else { 2 };
            let lights = if s.lit() { 2 } else { 1 };
            s.error_frames().len() * (filters * lights + usize::from(s == Scene::Floor))
        })
        .sum();
    let style =
        ProgressStyle::with_template("{elapsed_precise} [{bar:40.cyan/blue}] {pos}/{len} {msg}")
            .expect("template")
            .progress_chars("=> ");
    let pb = ProgressBar::new((n_modes * 2 + n_ref) as u64).with_style(style);

    // 1. Host timing first, alone (no other thread of ours running).
    let mut rows: BTreeMap<Scene, Vec<Row>> = BTreeMap::new();
    for &scene in &chosen {
        for m in scene.modes() {
            let name = mode_name(m);
            pb.set_message(format!("timing {}/{name}", scene.name()));
            let (ns, pixels) = time_mode(scene, m, &texes[&scene], &meshes, runs);
            let mut row = Row {
                mode: *m,
                name,
                host: Some(median_min_max(ns)),
                host_pixels: pixels,
                mcu: BTreeMap::new(),
                mcu_ok: BTreeMap::new(),
                err: compare_rgb565(&[], &[], &[], &[]),
                ideal: compare_rgb565(&[], &[], &[], &[]),
                dominated: Vec::new(),
            };
            for (s, mode, target, ipp, px, sum) in &mcu {
                if s == scene.name() && *mode == row.name {
                    let t = TARGETS.iter().copied().find(|t| t == target).unwrap_or("?");
                    row.mcu.insert(t, *ipp);
                    let (want, want_px) = band_checksum(scene, m, &texes[&scene], &meshes);
                    row.mcu_ok.insert(t, *sum == want && *px == want_px);
                }
            }
            rows.entry(scene).or_default().push(row);
            pb.inc(1);
        }
    }

    // 2. Errors: references (two threads), then fixel's frames.
    let mut problems = Vec::new();
    for &scene in &chosen {
        let tex = &texes[&scene];
        let frames: Vec<ErrFrame> = scene
            .error_frames()
            .iter()
            .map(|&i| ErrFrame::new(scene, i))
            .collect();
        let filters: &[Filt] = if scene == Scene::Floor {
            &[
                Filt::Nearest,
                Filt::Bilinear,
                Filt::NearestMip,
                Filt::Trilinear,
            ]
        } else {
            &[Filt::Nearest, Filt::Bilinear]
        };
        let lights: &[bool] = if scene.lit() {
            &[true, false]
        } else {
            &[false]
        };
        // Jobs: (frame, Some((lit, filter)) | None = supersampled).
        let mut jobs: Vec<Job> = Vec::new();
        for k in 0..frames.len() {
            for &l in lights {
                for &f in filters {
                    jobs.push((k, Some((l, f))));
                }
            }
            if scene == Scene::Floor {
                jobs.push((k, None));
            }
        }
        pb.set_message(format!("f64 references of {}", scene.name()));
        let results: Vec<(Job, Image)> = std::thread::scope(|sc| {
            let chunks: Vec<Vec<Job>> = (0..2)
                .map(|t| jobs.iter().copied().skip(t).step_by(2).collect())
                .collect();
            let handles: Vec<_> = chunks
                .into_iter()
                .map(|chunk| {
                    let (frames, pb) = (&frames, &pb);
                    sc.spawn(move || {
                        chunk
                            .into_iter()
                            .map(|(k, j)| {
                                let img = match j {
                                    Some((l, f)) => frames[k].reference(l, f),
                                    None => frames[k].supersampled(),
                                };
                                pb.inc(1);
                                ((k, j), img)
                            })
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            handles
                .into_iter()
                .flat_map(|h| h.join().expect("reference thread"))
                .collect()
        });
        let find = |k: usize, j: Option<(bool, Filt)>| {
            &results.iter().find(|r| r.0 == (k, j)).expect("reference").1
        };
        for row in rows.get_mut(&scene).expect("rows") {
            pb.set_message(format!("errors {}/{}", scene.name(), row.name));
            // Modes that differ only in cost share their filter's reference.
            let f = match row.mode.filter {
                Filt::TrilinearSpan => Filt::Trilinear,
                Filt::BilinearFootprint => Filt::Bilinear,
                f => f,
            };
            let (mut c, mut cc, mut r, mut rc, mut i, mut ic) =
                (vec![], vec![], vec![], vec![], vec![], vec![]);
            for (k, fr) in frames.iter().enumerate() {
                let px = fr.fixel(&row.mode, tex);
                c.extend_from_slice(&px);
                cc.extend_from_slice(&fr.covered);
                let re = find(k, Some((row.mode.lit, f)));
                r.extend_from_slice(&re.0);
                rc.extend_from_slice(&re.1);
                let id = if scene == Scene::Floor {
                    find(k, None)
                } else {
                    find(k, Some((row.mode.lit, Filt::Bilinear)))
                };
                i.extend_from_slice(&id.0);
                ic.extend_from_slice(&id.1);
            }
            row.err = compare_rgb565(&c, &cc, &r, &rc);
            row.ideal = compare_rgb565(&c, &cc, &i, &ic);
            pb.inc(1);
        }
        for row in rows.get(&scene).expect("rows") {
            for (t, ok) in &row.mcu_ok {
                if !ok {
                    problems.push(format!(
                        "{}/{} on {t}: the MCU's frame differs from the host's band frame",
                        scene.name(),
                        row.name
                    ));
                }
            }
        }
    }
    pb.set_message("plots");
    for (scene, rs) in rows.iter_mut() {
        pareto(rs);
        for t in TARGETS {
            let p = out.join(plot_file(*scene, t));
            if let Err(e) = plot(*scene, t, rs, &p) {
                problems.push(format!("plot {}: {e}", p.display()));
            }
        }
    }
    pb.finish_with_message("done");

    let md = markdown(&rows, runs, mcu_path.is_some(), &problems, t_start);
    let path = out.join("report.md");
    std::fs::write(&path, &md).expect("write report.md");
    println!("{md}");
    eprintln!(
        "report: wrote {} and the plots in {}",
        path.display(),
        out.display()
    );
    if !problems.is_empty() {
        for p in &problems {
            eprintln!("report: PROBLEM: {p}");
        }
        std::process::exit(1);
    }
}

fn markdown(
    rows: &BTreeMap<Scene, Vec<Row>>,
    runs: u32,
    have_mcu: bool,
    problems: &[String],
    t_start: Instant,
) -> String {
    let mut md = String::new();
    let date = sh("date", &["-u", "+%Y-%m-%d %H:%M UTC"]);
    let rustc = sh("rustc", &["--version"]);
    let commit = sh("git", &["rev-parse", "--short", "HEAD"]);
    let _ = writeln!(
        md,
        "# fixel: speed against error, per scene and mode\n\n\
         Generated {date} by `cargo xtask report` (commit {commit}), {rustc}, on {}. \
         Reproduce: `cargo xtask report` (host + QEMU; `--no-mcu` for the host only, \
         `--docs` to copy the result here).\n",
        machine()
    );
    let _ = writeln!(
        md,
        "**Speed.** *host*: x86-64 ns per pixel that passed the depth test, all N frames of \
         the scene (`docs/scenes.md`; clear + transform + draw, 320 x 240 RGB565, 16-bit depth, \
         fixel's fixed-point scene path), median of {runs} runs after a warm-up, (min-max). \
         *M0+ / M4F*: exact instructions per pixel of frame 0 under QEMU (the report \
         firmwares, 8-row bands, as `cargo xtask mcu`), checked against the host's frame \
         checksum.{}\n\n\
         **Error.** The same typed draw fed the reference's clip-space triangles. *ref*: \
         against the f64 reference with the mode's filter (and mip filter) and lighting and \
         exact perspective: implementation + projection error. PSNR in dB over 8-bit \
         values; max and p99 of the per-pixel largest channel error, in RGB565 LSBs; cov = \
         pixels covered by only one of the two, % of covered. *ideal*: against the scene's \
         ideal image (cube, sphere: the bilinear f64 reference with the mode's lighting; \
         floor: the {SS} x {SS} supersampled reference, i.e. what filtering should give). \
         Errors pooled over frames {} of the cube, {} of the sphere, {} of the floor.\n\n\
         **Pareto.** A mode is *dominated* on a target when another mode with the same \
         lighting is at most as slow there and at least as accurate (PSNR against the \
         ideal), one of them strictly. The column lists the targets where it is.\n",
        if have_mcu {
            ""
        } else {
            " (Not measured in this run: `--no-mcu`.)"
        },
        fmt_frames(Scene::Cube),
        fmt_frames(Scene::Sphere),
        fmt_frames(Scene::Floor),
    );
    // Recommendations.
    let _ = writeln!(
        md,
        "## Recommended modes\n\nPer scene and target, among the modes with the scene's \
         lighting: *best* = the cheapest within 0.5 dB of the most accurate, *balanced* = \
         the cheapest within 3 dB of it, *fastest* = the cheapest. Figures: cost, PSNR \
         against the ideal.\n\n| scene | target | best | balanced | fastest |\n|---|---|---|---|---|"
    );
    for (scene, rs) in rows {
        for t in TARGETS {
            if rs.iter().all(|r| r.cost(t).is_none()) {
                continue;
            }
            let cell = |r: Option<&Row>| {
                r.map_or("-".to_string(), |r| {
                    format!(
                        "`{}` ({:.1} {}, {} dB)",
                        r.name,
                        r.cost(t).unwrap_or(0.0),
                        cost_unit(t),
                        fmt_psnr(&r.ideal)
                    )
                })
            };
            let lit = scene.lit();
            let _ = writeln!(
                md,
                "| {} | {t} | {} | {} | {} |",
                scene.name(),
                cell(pick(rs, lit, t, 0.5)),
                cell(pick(rs, lit, t, 3.0)),
                cell(pick(rs, lit, t, f64::INFINITY)),
            );
        }
    }
    for (scene, rs) in rows {
        let _ = writeln!(
            md,
            "\n## {}\n\nN = {} frames; {:.0} pixels drawn per frame on the host. Ideal: the {}.\n",
            scene.name(),
            scene.frames(),
            rs.first()
                .map_or(0.0, |r| r.host_pixels as f64 / f64::from(scene.frames())),
            scene.ideal()
        );
        let _ = writeln!(
            md,
            "| mode | host ns/px | M0+ insns/px | M4F insns/px | ref PSNR | ref max | ref p99 | cov % | ideal PSNR | ideal p99 | dominated on |\n\
             |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
        );
        for r in rs {
            let mcu = |t: &str| {
                r.mcu.get(t).map_or("-".to_string(), |v| {
                    let ok = r.mcu_ok.get(t).copied().unwrap_or(true);
                    format!("{v:.1}{}", if ok { "" } else { " (**checksum!**)" })
                })
            };
            let cov = 100.0 * (r.err.only_candidate + r.err.only_reference) as f64
                / (r.err.both_covered + r.err.only_reference).max(1) as f64;
            let dom = if r.dominated.is_empty() {
                "-".to_string()
            } else {
                r.dominated
                    .iter()
                    .map(|t| t.replace("Cortex-", ""))
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            let _ = writeln!(
                md,
                "| `{}` | {} | {} | {} | {} | {} | {} | {cov:.2} | {} | {} | {dom} |",
                r.name,
                fmt_host(r.host),
                mcu("Cortex-M0+"),
                mcu("Cortex-M4F"),
                fmt_psnr(&r.err),
                r.err.max,
                r.err.p99,
                fmt_psnr(&r.ideal),
                r.ideal.p99,
            );
        }
        let _ = writeln!(md);
        for t in TARGETS {
            if rs.iter().any(|r| r.cost(t).is_some()) {
                let f = plot_file(*scene, t);
                let _ = writeln!(md, "![{} on {t}]({f})", scene.name());
            }
        }
    }
    if !problems.is_empty() {
        let _ = writeln!(md, "\n## Problems\n");
        for p in problems {
            let _ = writeln!(md, "* {p}");
        }
    }
    let _ = writeln!(
        md,
        "\n(host part of the report: {:.0} s)",
        t_start.elapsed().as_secs_f64()
    );
    md
}

fn fmt_frames(s: Scene) -> String {
    s.error_frames()
        .iter()
        .map(u32::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}
