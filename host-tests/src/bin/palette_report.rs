//! `cargo xtask report`, palette textures: the benchmark floor and cube with their
//! checker texture in RGB565 and as 8-bit and 4-bit palette bakes (`assets/palette/`,
//! `cargo xtask bake-palette`), through the firmware's own code
//! (`examples/firmware/src/palette_scene.rs`: the same open-stage path for all three, so
//! the rows differ in the texture read alone).
//!
//! ```text
//! palette_report --out DIR [--runs N] [--mcu mcu.tsv]
//! ```
//!
//! Columns: the texture's flash (texels, or indices and palette), host ns per drawn pixel
//! (median of N banded frames), exact M0+ and M4F instructions per drawn pixel of the
//! firmwares `floor_rgb565` ... `cube_palette4` (`docs/mcu.md`, written by `cargo xtask
//! mcu --docs`; their checksums checked against the host's), and the error against the
//! RGB565 source: of the frame (PSNR, largest channel difference in RGB565 LSB) and of the
//! texture itself (PSNR of the palette's texels against the RGB565 texels). Writes
//! `DIR/palette.md` and `DIR/palette.png`. (`--mcu` is accepted and unused: these
//! firmwares are `cargo xtask mcu`'s, not the report's.)

#[path = "../../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "../../../examples/firmware/src/palette_scene.rs"]
mod palette_scene;

#[allow(dead_code)]
mod palette {
    include!("../../../assets/palette/t64_p8.rs");
    include!("../../../assets/palette/t64_p4.rs");
    include!("../../../assets/palette/t128_p8.rs");
    include!("../../../assets/palette/t128_p4.rs");
}

use std::collections::HashMap;
use std::path::Path;
use std::time::Instant;

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::Vertex;
use fixel::pipeline::{DepthLess, ProjectionStage, QuadraticBy, ShadedDraw, SubdividedBy};
use fixel::prelude::*;
use fixel::shading::{
    ModulateIntensity, PaletteBinding, PaletteModulateIntensity, PaletteReplace, Replace, Shader,
    TexBinding,
};
use fixel::texture::{
    Bilinear, Index4, Index8, IndexFormat, Lod, MipTexture, Nearest, PaletteTexture, Repeat,
};
use fixel_scenes as demo;
use host_tests::report_args::ReportArgs;
use scenes::{Fnv1a, FrameResult, SmallBuffers};

/// One row of the table.
struct Row {
    name: &'static str,
    flash: usize,
    ns: f64,
    /// (M0+, M4F) instructions per pixel and the M4F firmware's flash.
    mcu: Option<(f64, f64, u64)>,
    /// Frame against the RGB565 frame: PSNR dB (infinite when equal), max LSB.
    psnr: f64,
    max_lsb: u16,
    /// Texture against the RGB565 texture, PSNR dB.
    tex_psnr: f64,
}

fn checker(w: u32, h: u32) -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    demo::checker_texture(w, h, &mut t).expect("checker");
    t
}

/// The RGB565 texels a palette texture expands to.
fn expand<I: IndexFormat>(t: &PaletteTexture<'_, I>) -> Vec<u16> {
    (0..t.width() * t.height()).map(|k| t.texel_at(k)).collect()
}

/// RGB565 channels widened to 8 bits.
fn rgb8(c: u16) -> [f64; 3] {
    let (r, g, b) = (c >> 11, (c >> 5) & 63, c & 31);
    [
        (r << 3) | (r >> 2),
        (g << 2) | (g >> 4),
        (b << 3) | (b >> 2),
    ]
    .map(f64::from)
}

/// PSNR (dB, 8-bit channels) of `b` against `a`, both raw RGB565 (infinite when equal).
fn psnr(a: &[u16], b: &[u16]) -> f64 {
    let se: f64 = a
        .iter()
        .zip(b)
        .map(|(&x, &y)| {
            let (x, y) = (rgb8(x), rgb8(y));
            (0..3).map(|k| (x[k] - y[k]).powi(2)).sum::<f64>()
        })
        .sum();
    if se == 0.0 {
        return f64::INFINITY;
    }
    10.0 * (255.0f64.powi(2) * 3.0 * a.len() as f64 / se).log10()
}

/// The largest channel difference, in each channel's own RGB565 LSB.
fn max_lsb(a: &[u16], b: &[u16]) -> u16 {
    let ch = |c: u16| [c >> 11, (c >> 5) & 63, c & 31];
    a.iter()
        .zip(b)
        .map(|(&x, &y)| {
            let (x, y) = (ch(x), ch(y));
            (0..3).map(|k| x[k].abs_diff(y[k])).max().unwrap_or(0)
        })
        .max()
        .unwrap_or(0)
}

/// `tris` drawn with `draw` into one whole frame: its raw pixels and checksum.
fn whole<S, P, const N: usize>(
    draw: &ShadedDraw<S, P, DepthLess>,
    tris: &[[Vertex<N>; 3]],
) -> (Vec<u16>, u32)
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
{
    let (w, h) = (scenes::W, scenes::H);
    let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    let mut depth = vec![0u16; (w * h) as usize];
    let mut frame = Frame::new(&mut color, w, h)
        .expect("frame")
        .with_depth(&mut depth)
        .expect("depth");
    frame.clear(Rgb565::new(0, 0, 0));
    draw.clip_triangles(tris, &mut frame).expect("draw");
    let mut f = Fnv1a::default();
    f.pixels(frame.pixels());
    (
        frame.pixels().iter().map(|c| c.into_storage()).collect(),
        f.0,
    )
}

/// The median ns per pixel of `runs` banded frames, and the last frame.
fn timed(runs: u32, mut frame: impl FnMut(&mut SmallBuffers) -> FrameResult) -> (f64, FrameResult) {
    let mut buf = Box::new(SmallBuffers::with_storage());
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..runs.max(1) {
        let t0 = Instant::now();
        let r = frame(&mut buf);
        times.push(t0.elapsed().as_secs_f64());
        last = Some(r);
    }
    times.sort_by(f64::total_cmp);
    let r = last.expect("one run");
    (
        times[times.len() / 2] * 1e9 / f64::from(r.stats.pixels.max(1)),
        r,
    )
}

/// `docs/mcu.md`'s rows: (firmware, target) -> (instructions per pixel, checksum, flash).
fn mcu_rows(md: &str) -> HashMap<(String, String), (f64, String, u64)> {
    let mut out = HashMap::new();
    for line in md.lines() {
        let f: Vec<&str> = line.split('|').map(str::trim).collect();
        if f.len() < 10 {
            continue;
        }
        let (Ok(ipp), Ok(flash)) = (f[3].parse::<f64>(), f[8].parse::<u64>()) else {
            continue;
        };
        out.entry((f[1].to_string(), f[2].to_string()))
            .or_insert((ipp, f[6].to_string(), flash));
    }
    out
}

/// (M0+, M4F) instructions per pixel of `scene` and the M4F firmware's flash; panics when
/// a firmware's checksum is not the host's (the table must not mix frames).
fn mcu_of(
    rows: &HashMap<(String, String), (f64, String, u64)>,
    scene: &str,
    checksum: u32,
) -> Option<(f64, f64, u64)> {
    let get = |t: &str| {
        rows.get(&(scene.to_string(), t.to_string())).map(|r| {
            assert_eq!(
                r.1,
                format!("0x{checksum:08x}"),
                "{scene} on {t}: docs/mcu.md's checksum is not the host's (run cargo xtask mcu --docs)"
            );
            (r.0, r.2)
        })
    };
    let (m0, _) = get("Cortex-M0+")?;
    let (m4, flash) = get("Cortex-M4F")?;
    Some((m0, m4, flash))
}

fn main() {
    let ReportArgs { out, runs, .. } = ReportArgs::parse(
        "palette_report",
        "Flash, speed and error of palette textures (run by `cargo xtask report`)",
        "7",
    );
    std::fs::create_dir_all(&out).expect("output directory");
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/mcu.md");
    let mcu = mcu_rows(&std::fs::read_to_string(&docs).unwrap_or_default());
    let (nop1, nop2) = (&mut || {}, &mut || {});
    let vp = Viewport::new(0, 0, scenes::W, scenes::H).expect("viewport");
    let mut rows = Vec::new();

    // The floor: nearest, unlit, T(64, 64).
    let t64 = checker(64, 64);
    let raw64: Vec<u16> = t64.iter().map(|c| c.into_storage()).collect();
    let m = MipTexture::single(Texture::new(&t64, 64, 64).expect("texture"));
    let (tris, n) = palette_scene::floor_tris().expect("floor");
    let tris = &tris[..n];
    let (ns, r) = timed(runs, |b| {
        palette_scene::floor_rgb565(b, &m, nop1, nop2).expect("floor")
    });
    let tex = TexBinding::new(&m, Nearest, Repeat, Repeat, Lod::default()).expect("binding");
    let d = ShadedDraw::<_, SubdividedBy<6>, DepthLess>::new(Replace { tex }, vp, Cull::Back)
        .expect("draw");
    let (floor_px, sum) = whole(&d, tris);
    assert_eq!(sum, r.checksum, "floor_rgb565: bands differ from whole");
    rows.push(Row {
        name: "floor_rgb565",
        flash: t64.len() * 2,
        ns,
        mcu: mcu_of(&mcu, "floor_rgb565", r.checksum),
        psnr: f64::INFINITY,
        max_lsb: 0,
        tex_psnr: f64::INFINITY,
    });
    fn floor_row<I: IndexFormat>(
        name: &'static str,
        t: PaletteTexture<'_, I>,
        flash: usize,
        ctx: (&[[Vertex<2>; 3]], &[u16], &[u16], Viewport, u32),
        mcu: &HashMap<(String, String), (f64, String, u64)>,
    ) -> Row {
        let (tris, rgb_frame, rgb_tex, vp, runs) = ctx;
        let (ns, r) = timed(runs, |b| {
            palette_scene::floor_palette(b, t, &mut || {}, &mut || {}).expect("floor")
        });
        let pal = PaletteReplace {
            tex: PaletteBinding::new(t, Nearest, Repeat, Repeat),
        };
        let d =
            ShadedDraw::<_, SubdividedBy<6>, DepthLess>::new(pal, vp, Cull::Back).expect("draw");
        let (px, sum) = whole(&d, tris);
        assert_eq!(sum, r.checksum, "{name}: bands differ from whole");
        Row {
            name,
            flash,
            ns,
            mcu: mcu_of(mcu, name, r.checksum),
            psnr: psnr(rgb_frame, &px),
            max_lsb: max_lsb(rgb_frame, &px),
            tex_psnr: psnr(rgb_tex, &expand(&t)),
        }
    }
    let p8 =
        PaletteTexture::<Index8>::new(&palette::T64_P8_INDICES, &palette::T64_P8_PALETTE, 64, 64)
            .expect("p8");
    let p4 =
        PaletteTexture::<Index4>::new(&palette::T64_P4_INDICES, &palette::T64_P4_PALETTE, 64, 64)
            .expect("p4");
    let ctx = (tris, &floor_px[..], &raw64[..], vp, runs);
    rows.push(floor_row(
        "floor_palette8",
        p8,
        palette::T64_P8_INDICES.len() + 2 * palette::T64_P8_PALETTE.len(),
        ctx,
        &mcu,
    ));
    rows.push(floor_row(
        "floor_palette4",
        p4,
        palette::T64_P4_INDICES.len() + 2 * palette::T64_P4_PALETTE.len(),
        ctx,
        &mcu,
    ));

    // The cube: bilinear, lit per vertex, T(128, 128).
    let t128 = checker(128, 128);
    let raw128: Vec<u16> = t128.iter().map(|c| c.into_storage()).collect();
    let m = MipTexture::single(Texture::new(&t128, 128, 128).expect("texture"));
    let (tris, n) = palette_scene::cube_tris().expect("cube");
    let tris = &tris[..n];
    let (ns, r) = timed(runs, |b| {
        palette_scene::cube_rgb565(b, &m, nop1, nop2).expect("cube")
    });
    let tex = TexBinding::new(&m, Bilinear, Repeat, Repeat, Lod::default()).expect("binding");
    let d =
        ShadedDraw::<_, QuadraticBy<4>, DepthLess>::new(ModulateIntensity { tex }, vp, Cull::Back)
            .expect("draw");
    let (cube_px, sum) = whole(&d, tris);
    assert_eq!(sum, r.checksum, "cube_rgb565: bands differ from whole");
    rows.push(Row {
        name: "cube_rgb565",
        flash: t128.len() * 2,
        ns,
        mcu: mcu_of(&mcu, "cube_rgb565", r.checksum),
        psnr: f64::INFINITY,
        max_lsb: 0,
        tex_psnr: f64::INFINITY,
    });
    fn cube_row<I: IndexFormat>(
        name: &'static str,
        t: PaletteTexture<'_, I>,
        flash: usize,
        ctx: (&[[Vertex<3>; 3]], &[u16], &[u16], Viewport, u32),
        mcu: &HashMap<(String, String), (f64, String, u64)>,
    ) -> Row {
        let (tris, rgb_frame, rgb_tex, vp, runs) = ctx;
        let (ns, r) = timed(runs, |b| {
            palette_scene::cube_palette(b, t, &mut || {}, &mut || {}).expect("cube")
        });
        let pal = PaletteModulateIntensity {
            tex: PaletteBinding::new(t, Bilinear, Repeat, Repeat),
        };
        let d = ShadedDraw::<_, QuadraticBy<4>, DepthLess>::new(pal, vp, Cull::Back).expect("draw");
        let (px, sum) = whole(&d, tris);
        assert_eq!(sum, r.checksum, "{name}: bands differ from whole");
        Row {
            name,
            flash,
            ns,
            mcu: mcu_of(mcu, name, r.checksum),
            psnr: psnr(rgb_frame, &px),
            max_lsb: max_lsb(rgb_frame, &px),
            tex_psnr: psnr(rgb_tex, &expand(&t)),
        }
    }
    let p8 = PaletteTexture::<Index8>::new(
        &palette::T128_P8_INDICES,
        &palette::T128_P8_PALETTE,
        128,
        128,
    )
    .expect("p8");
    let p4 = PaletteTexture::<Index4>::new(
        &palette::T128_P4_INDICES,
        &palette::T128_P4_PALETTE,
        128,
        128,
    )
    .expect("p4");
    let ctx = (tris, &cube_px[..], &raw128[..], vp, runs);
    rows.push(cube_row(
        "cube_palette8",
        p8,
        palette::T128_P8_INDICES.len() + 2 * palette::T128_P8_PALETTE.len(),
        ctx,
        &mcu,
    ));
    rows.push(cube_row(
        "cube_palette4",
        p4,
        palette::T128_P4_INDICES.len() + 2 * palette::T128_P4_PALETTE.len(),
        ctx,
        &mcu,
    ));

    let db = |v: f64| {
        if v.is_finite() {
            format!("{v:.1}")
        } else {
            "exact".into()
        }
    };
    let mut md = String::from(
        "# Palette textures: flash, speed and error against RGB565\n\n\
         The benchmark floor (`T(64, 64)`, nearest, unlit) and cube (`T(128, 128)`, bilinear, lit per \
         vertex, frame 0) at 320 x 240 in bands of 8 rows, their checker texture in RGB565 and as \
         8-bit and 4-bit palette bakes (`cargo xtask bake-palette`: median cut refined by k-means), through \
         the same open-stage path (`examples/firmware/src/palette_scene.rs`). Per drawn pixel. Flash: \
         the texture's texels, or its indices and RGB565 palette. Error against the RGB565 source: \
         the frame against the RGB565 frame, and the palette's texels against the RGB565 texels.\n\n\
         | scene | texture flash B | host ns/px | M0+ instr/px | M4F instr/px | M4F firmware flash B | frame PSNR dB | frame max LSB | texture PSNR dB |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in &rows {
        let (m0, m4, fl) = r
            .mcu
            .map_or(("-".into(), "-".into(), "-".into()), |(a, b, f)| {
                (format!("{a:.2}"), format!("{b:.2}"), f.to_string())
            });
        md.push_str(&format!(
            "| `{}` | {} | {:.1} | {m0} | {m4} | {fl} | {} | {} | {} |\n",
            r.name,
            r.flash,
            r.ns,
            db(r.psnr),
            r.max_lsb,
            db(r.tex_psnr)
        ));
    }
    md.push_str(
        "\nInstructions per pixel: `cargo xtask mcu`'s firmwares of the same names (docs/mcu.md, \
         checksums equal to the host's). Reproduce: `cargo xtask report` (or `cargo run --release -p \
         host-tests --bin palette_report -- --out target/report`).\n\n![cost against error](palette.png)\n",
    );
    std::fs::write(out.join("palette.md"), md).expect("palette.md");
    let points: Vec<host_tests::cost_plot::Point> = rows
        .iter()
        .map(|r| host_tests::cost_plot::Point {
            name: r.name.to_string(),
            host_ns: r.ns,
            m4f: r.mcu.map(|m| m.1),
            psnr: r.psnr,
        })
        .collect();
    if let Err(e) = host_tests::cost_plot::write(
        &points,
        "palette textures: cost against PSNR vs the RGB565 frame (exact plotted at 60)",
        (20.0, 62.0),
        &out.join("palette.png"),
    ) {
        eprintln!("palette_report: no plot: {e}");
    }
    println!("palette_report: wrote {}", out.join("palette.md").display());
}
