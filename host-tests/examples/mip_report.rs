//! Mipmapping measurements, run by hand:
//!
//! ```text
//! cargo run --release -p host-tests --example mip_report            # all, incl. callgrind
//! cargo run --release -p host-tests --example mip_report -- --no-callgrind
//! ```
//!
//! Writes `target/mip-report.md`, per-filter PNGs in `target/mip-report/` and the README
//! pictures `docs/images/mip-floor-compare.png` (nearest | bilinear | trilinear | 8x8
//! supersampled reference, with each one's error against the reference below it).
//!
//! * Aliasing: the floor scene (320 x 240) with each filter against the f64 reference
//!   supersampled 8 x 8 per pixel (exact perspective texture coordinates, bilinear on
//!   level 0, box-filtered). Over pixels fully covered by the floor, for the whole floor and
//!   for its far half (the rows above the middle between the horizon row and the bottom).
//! * Cost: host ns per written pixel (median of repeated frames) for each filter and LOD
//!   granularity, with typed pipelines (`Pipeline<Exact, F, Repeat, Repeat, Replace,
//!   NoDepth>`, the way firmware builds them); x86-64 instructions per pixel from callgrind
//!   (difference of 1 and 5 frames, so set-up is excluded).
//! * Temporal: the floor translated along x by 1/8 pixel (at depth 10) per frame for 16
//!   frames; mean absolute frame-to-frame change over the far half (8-bit units, mean of
//!   the three channels), next to the supersampled reference's own change (the part of the
//!   change that is real motion).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{ClipVertex, Cull, Viewport};
use fixel::pipeline::{Draw, Exact, NoDepth, Pipeline, Replace};
use fixel::surface::Frame;
use fixel::texture::{chain_len, full_levels};
use fixel::texture::{
    generate_mips, Bilinear, LinearMipmapNearest, Lod, LodGranularity, MipTexture, Nearest,
    NearestMipmapLinear, NearestMipmapNearest, Repeat, Trilinear,
};
use host_tests::adapter;
use host_tests::metrics::compare_rgb565;
use host_tests::png_io::{rgb565_to_rgb8, write_png_rgb8};
use host_tests::reference::{self, RefFilter, RefImage, RefMip, RefMode};
use host_tests::scenes::{self, math, SceneDesc};

const W: u32 = 320;
const H: u32 = 240;
const SS: u32 = 8;

/// The filters measured: name, filter, mip filter, LOD granularity.
const CONFIGS: [(&str, RefFilter, RefMip, LodGranularity); 8] = [
    (
        "nearest",
        RefFilter::Nearest,
        RefMip::None,
        LodGranularity::Pixel,
    ),
    (
        "bilinear",
        RefFilter::Bilinear,
        RefMip::None,
        LodGranularity::Pixel,
    ),
    (
        "nearest-mipmap-nearest",
        RefFilter::Nearest,
        RefMip::Nearest,
        LodGranularity::Pixel,
    ),
    (
        "linear-mipmap-nearest",
        RefFilter::Bilinear,
        RefMip::Nearest,
        LodGranularity::Pixel,
    ),
    (
        "nearest-mipmap-linear",
        RefFilter::Nearest,
        RefMip::Linear,
        LodGranularity::Pixel,
    ),
    (
        "trilinear",
        RefFilter::Bilinear,
        RefMip::Linear,
        LodGranularity::Pixel,
    ),
    (
        "trilinear, LOD per span",
        RefFilter::Bilinear,
        RefMip::Linear,
        LodGranularity::Span,
    ),
    (
        "trilinear, LOD per triangle",
        RefFilter::Bilinear,
        RefMip::Linear,
        LodGranularity::Triangle,
    ),
];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn target_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root().join("target"), PathBuf::from)
}

fn file_name(name: &str) -> String {
    name.replace(", LOD per ", "-lod-")
}

/// The floor translated along x by `dx` world units.
fn floor_at(dx: f64) -> SceneDesc {
    SceneDesc {
        model: math::translation([dx, 0.0, 0.0]),
        ..scenes::floor()
    }
}

fn fixel_floor(
    s: &SceneDesc,
    filter: RefFilter,
    mip: RefMip,
    g: LodGranularity,
) -> (Vec<u16>, Vec<bool>) {
    let tris = adapter::clip_triangles(&scenes::to_ref_triangles(s));
    let mode = RefMode {
        filter,
        mip,
        ..s.mode
    };
    let mut dm = adapter::draw_mode(&mode, None, false);
    dm.lod.granularity = g;
    let f = adapter::render_mip(&tris, Some(&s.texture), None, dm, W, H);
    (f.pixels, f.covered)
}

fn supersampled(s: &SceneDesc) -> RefImage {
    let tris = scenes::to_ref_triangles(s);
    let mode = RefMode {
        filter: RefFilter::Bilinear,
        mip: RefMip::None,
        ..s.mode
    };
    reference::render_supersampled(&tris, Some(&s.texture), &mode, W, H, SS)
}

/// Rows of the far half: from the floor's top row to the middle between it and the bottom.
fn far_rows(cov: &[bool]) -> (u32, u32) {
    let top = (0..H)
        .find(|&y| (0..W).any(|x| cov[(y * W + x) as usize]))
        .unwrap_or(0);
    (top, (top + H) / 2)
}

fn region(cov: &[bool], rows: Option<(u32, u32)>) -> Vec<bool> {
    cov.iter()
        .enumerate()
        .map(|(k, &c)| {
            let y = k as u32 / W;
            c && rows.is_none_or(|(a, b)| y >= a && y < b)
        })
        .collect()
}

/// Amplified error picture: grey = 4 x the largest 8-bit channel difference.
fn error_picture(a: &[u16], b: &[u16], cov: &[bool]) -> Vec<[u8; 3]> {
    a.iter()
        .zip(b)
        .zip(cov)
        .map(|((&p, &q), &c)| {
            if !c {
                return [0, 0, 0];
            }
            let (x, y) = (rgb565_to_rgb8(p), rgb565_to_rgb8(q));
            let d = (0..3).map(|k| x[k].abs_diff(y[k])).max().unwrap_or(0);
            let v = (u32::from(d) * 4).min(255) as u8;
            [v, v, v]
        })
        .collect()
}

/// Tiles of rows `Y0..H` (the floor; the sky above is empty), `cols` to a row.
fn write_grid(path: &Path, cols: usize, tiles: &[Vec<[u8; 3]>]) {
    const Y0: u32 = 112;
    let rows = tiles.len().div_ceil(cols);
    let th = H - Y0;
    let (gw, gh) = (cols as u32 * W, rows as u32 * th);
    let mut out = vec![0u8; (3 * gw * gh) as usize];
    for (t, tile) in tiles.iter().enumerate() {
        let (ox, oy) = ((t % cols) as u32 * W, (t / cols) as u32 * th);
        for y in 0..th {
            for x in 0..W {
                let o = (3 * ((oy + y) * gw + ox + x)) as usize;
                out[o..o + 3].copy_from_slice(&tile[((y + Y0) * W + x) as usize]);
            }
        }
    }
    write_png_rgb8(path, gw, gh, &out).expect("write png");
}

fn rgb(px: &[u16]) -> Vec<[u8; 3]> {
    px.iter().map(|&p| rgb565_to_rgb8(p)).collect()
}

// ---------------------------------------------------------------------------------------
// Cost
// ---------------------------------------------------------------------------------------

/// A generic helper over `M: Stages` cannot be written outside fixel: `Draw::new_mip`'s
/// bound `M::F: FromMode` names a trait fixel does not export. A macro instead.
macro_rules! frames {
    ($m:ty, $mips:expr, $g:expr, $n:expr, $tris:expr) => {{
        let vp = Viewport::new(0, 0, W, H).unwrap();
        let draw: Draw<'_, Rgb565> = Draw::new_mip::<$m>(Some($mips), vp, Cull::Back)
            .unwrap()
            .with_lod(Lod {
                granularity: $g,
                ..Lod::default()
            });
        let mut color = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
        let mut frame = Frame::new(&mut color, W, H).unwrap();
        let mut times = Vec::with_capacity($n);
        let mut written = 0;
        for _ in 0..$n {
            let t0 = Instant::now();
            written = std::hint::black_box(draw.clip_triangles($tris, &mut frame).unwrap());
            times.push(t0.elapsed().as_nanos() as f64);
        }
        (written, times)
    }};
}

type P<F> = Pipeline<Exact, F, Repeat, Repeat, Replace, NoDepth>;

struct Bench {
    tris: Vec<[ClipVertex; 3]>,
    chain: Vec<Rgb565>,
}

impl Bench {
    fn new() -> Self {
        let s = scenes::floor();
        let t = &s.texture;
        let levels = full_levels(t.width, t.height);
        let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(t.width, t.height, levels)];
        chain[..t.texels.len()].copy_from_slice(&adapter::texels(t));
        generate_mips(&mut chain, t.width, t.height, levels).unwrap();
        Bench {
            tris: adapter::clip_triangles(&scenes::to_ref_triangles(&s)),
            chain,
        }
    }

    /// Renders `frames` frames with config `i`; returns (written pixels per frame, ns per
    /// frame for each frame).
    fn run(&self, i: usize, frames: usize) -> (u32, Vec<f64>) {
        let mips = MipTexture::new(&self.chain, 64, 64, 7).unwrap();
        let g = CONFIGS[i].3;
        match i {
            0 => frames!(P<Nearest>, mips, g, frames, &self.tris),
            1 => frames!(P<Bilinear>, mips, g, frames, &self.tris),
            2 => frames!(P<NearestMipmapNearest>, mips, g, frames, &self.tris),
            3 => frames!(P<LinearMipmapNearest>, mips, g, frames, &self.tris),
            4 => frames!(P<NearestMipmapLinear>, mips, g, frames, &self.tris),
            _ => frames!(P<Trilinear>, mips, g, frames, &self.tris),
        }
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Instructions of `--cost-only i frames` under callgrind.
fn callgrind(i: usize, frames: usize) -> Option<u64> {
    let exe = std::env::current_exe().ok()?;
    let out = target_dir().join(format!("mip-report/callgrind.{i}.{frames}.out"));
    let o = Command::new("valgrind")
        .arg("--tool=callgrind")
        .arg(format!("--callgrind-out-file={}", out.display()))
        .arg(&exe)
        .args(["--cost-only", &i.to_string(), &frames.to_string()])
        .output()
        .ok()?;
    let text = String::from_utf8_lossy(&o.stderr);
    let line = text.lines().find(|l| l.contains("Collected :"))?;
    line.rsplit(':')
        .next()?
        .trim()
        .replace(',', "")
        .parse()
        .ok()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--cost-only") {
        let i: usize = args[1].parse().unwrap();
        let n: usize = args[2].parse().unwrap();
        let b = Bench::new();
        let (w, _) = b.run(i, n);
        println!("{w}");
        return;
    }
    let use_callgrind = !args.iter().any(|a| a == "--no-callgrind");
    let dir = target_dir().join("mip-report");
    std::fs::create_dir_all(&dir).unwrap();
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# Mipmapping report\n\nGenerated by `cargo run --release -p host-tests \
         --example mip_report`. Floor scene, 320 x 240, `T(64, 64)` with a full 7-level chain.\n"
    );

    // (a) aliasing
    let s = scenes::floor();
    let t0 = Instant::now();
    let ss = supersampled(&s);
    eprintln!(
        "supersampled reference: {:.1} s",
        t0.elapsed().as_secs_f64()
    );
    let ss_q = ss.quantize_rgb565();
    let rows = far_rows(&ss.covered);
    let _ = writeln!(
        md,
        "## Aliasing against the {SS}x{SS} supersampled reference\n\nPixels fully covered by the \
         floor; far half = rows {}..{} (horizon to the middle of the floor). Errors in RGB565 \
         LSBs, PSNR over 8-bit values.\n\n| filter | far half PSNR | far mean | far max | whole \
         PSNR | whole mean | whole max |\n|---|---|---|---|---|---|---|",
        rows.0, rows.1
    );
    let mut pics = vec![];
    for (name, filter, mip, g) in CONFIGS {
        let (px, cov) = fixel_floor(&s, filter, mip, g);
        let far = compare_rgb565(
            &px,
            &region(&cov, Some(rows)),
            &ss_q,
            &region(&ss.covered, Some(rows)),
        );
        let all = compare_rgb565(&px, &cov, &ss_q, &ss.covered);
        let _ = writeln!(
            md,
            "| {name} | {:.2} dB | {:.3} | {} | {:.2} dB | {:.3} | {} |",
            far.psnr_db, far.mean, far.max, all.psnr_db, all.mean, all.max
        );
        let both: Vec<bool> = cov.iter().zip(&ss.covered).map(|(a, b)| *a && *b).collect();
        let err = error_picture(&px, &ss_q, &both);
        write_grid(
            &dir.join(format!("floor-{}.png", file_name(name))),
            1,
            &[rgb(&px), err.clone()],
        );
        pics.push((name, rgb(&px), err));
    }
    write_grid(&dir.join("floor-supersampled.png"), 1, &[rgb(&ss_q)]);
    let pick = |n: &str| pics.iter().find(|p| p.0 == n).unwrap();
    let (a, b, c) = (pick("nearest"), pick("bilinear"), pick("trilinear"));
    let blank = vec![[0u8; 3]; (W * H) as usize];
    let docs = root().join("docs/images");
    std::fs::create_dir_all(&docs).unwrap();
    write_grid(
        &docs.join("mip-floor-compare.png"),
        4,
        &[
            a.1.clone(),
            b.1.clone(),
            c.1.clone(),
            rgb(&ss_q),
            a.2.clone(),
            b.2.clone(),
            c.2.clone(),
            blank,
        ],
    );
    let _ = writeln!(
        md,
        "\n`docs/images/mip-floor-compare.png`: nearest | bilinear | trilinear | reference \
         {SS}x{SS}; below each, 4 x its largest 8-bit channel error against the reference.\n"
    );

    // (b) cost
    let bench = Bench::new();
    let _ = writeln!(
        md,
        "## Cost per pixel\n\nTyped pipelines `Pipeline<Exact, F, Repeat, Repeat, Replace, \
         NoDepth>`, host ({}), release; median of 41 frames after 5 warm-up frames; callgrind: \
         x86-64 instructions per written pixel, (Ir(5 frames) - Ir(1 frame)) / (4 x pixels), \
         so it includes triangle set-up and clipping (2 triangles per frame).\n\n| filter | \
         pixels | ns/pixel | x86 instr/pixel |\n|---|---|---|---|",
        std::env::consts::ARCH
    );
    for (i, cfg) in CONFIGS.iter().enumerate() {
        bench.run(i, 5);
        let (wr, times) = bench.run(i, 41);
        let ns = median(times) / f64::from(wr);
        let ir = if use_callgrind {
            match (callgrind(i, 1), callgrind(i, 5)) {
                (Some(a), Some(b)) => format!("{:.1}", (b - a) as f64 / (4.0 * f64::from(wr))),
                _ => "n/a".into(),
            }
        } else {
            "-".into()
        };
        eprintln!("{}: {ns:.2} ns/px, {ir} instr/px", cfg.0);
        let _ = writeln!(md, "| {} | {wr} | {ns:.2} | {ir} |", cfg.0);
    }

    // (c) temporal
    let step = 2.0 * 10.0 * (22.5f64).to_radians().tan() / f64::from(H) / 8.0;
    let _ = writeln!(
        md,
        "\n## Temporal stability\n\nThe floor translated along x by {step:.5} world units per \
         frame (1/8 pixel at depth 10), 16 frames; mean absolute frame-to-frame change over the \
         far half (pixels covered in both frames), 8-bit units, mean of the three channels. The \
         supersampled reference's own change is the part that is real motion.\n\n| filter | \
         mean abs change | excess over the reference |\n|---|---|---|"
    );
    let frames: Vec<SceneDesc> = (0..16).map(|k| floor_at(step * f64::from(k))).collect();
    let flicker = |imgs: &[(Vec<u16>, Vec<bool>)]| -> f64 {
        let (mut sum, mut n) = (0.0, 0u64);
        for p in imgs.windows(2) {
            for k in 0..(W * H) as usize {
                let y = k as u32 / W;
                if p[0].1[k] && p[1].1[k] && y >= rows.0 && y < rows.1 {
                    let (a, b) = (rgb565_to_rgb8(p[0].0[k]), rgb565_to_rgb8(p[1].0[k]));
                    sum += (0..3).map(|c| f64::from(a[c].abs_diff(b[c]))).sum::<f64>() / 3.0;
                    n += 1;
                }
            }
        }
        sum / n as f64
    };
    let t0 = Instant::now();
    let ref_imgs: Vec<(Vec<u16>, Vec<bool>)> = frames
        .iter()
        .map(|f| {
            let r = supersampled(f);
            (r.quantize_rgb565(), r.covered)
        })
        .collect();
    eprintln!("temporal reference: {:.1} s", t0.elapsed().as_secs_f64());
    let ref_flicker = flicker(&ref_imgs);
    for (name, filter, mip, g) in CONFIGS {
        let imgs: Vec<(Vec<u16>, Vec<bool>)> = frames
            .iter()
            .map(|f| fixel_floor(f, filter, mip, g))
            .collect();
        let fl = flicker(&imgs);
        let _ = writeln!(md, "| {name} | {fl:.2} | {:+.2} |", fl - ref_flicker);
    }
    let _ = writeln!(md, "| reference {SS}x{SS} | {ref_flicker:.2} | 0 |");

    let path = target_dir().join("mip-report.md");
    std::fs::write(&path, &md).unwrap();
    print!("{md}");
    eprintln!("wrote {}", path.display());
}
