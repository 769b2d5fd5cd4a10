//! Speed against error for the solid textures, run by `cargo xtask report` after
//! the main report:
//!
//! ```text
//! noise_report --out DIR [--runs N] [--mcu mcu.tsv]
//! ```
//!
//! * The firmware scene (`examples/firmware/src/noise.rs`: the marble sphere, 320 x 240, 8-row
//!   bands), one row per variant of `report_noise`: marble with 0 to 6 fixed octaves, marble
//!   band-limited (at most 6, footprint per span or per pixel; and with the projection
//!   subdivided every 8 pixels instead of exact), wood and granite band-limited, and granite
//!   with marble selected by a third noise (`Select`). Host ns/px (the firmware's band
//!   code, median of N runs), exact instructions per pixel on Cortex-M0+ and M4F (from
//!   `mcu.tsv`, checksums checked against this program's), error against the f64
//!   reference with the same octave rule, and against the 6 x 6 supersampled, 8-octave f64
//!   reference (the ideal).
//! * The firmware scene `noise_light3d` (`examples/firmware/src/light3d_scene.rs`): the
//!   wooden cube lit per vertex and by the baked 3D light map, the same figures; the light
//!   map's reference multiplies by the f64 trilinear light, its ideal by the unbaked
//!   inverse-square light.
//! * The flame of `noise_flame` (4 frames of 80 x 96) with 1, 3 and 5 octaves against the
//!   f64 flame drawn on the same quad, and the flame from two baked layers
//!   (`noise_flame_baked`) against the f64 flame of its own definition.
//! * The granite floor running to the horizon (`host_tests::noise_scenes`, 160 x 120): fixed
//!   1 to 6 octaves against band-limited, same figures on the host, where band-limiting
//!   matters most.
//!
//! Writes `noise.md`, `noise_plot.png` (cost against PSNR to the ideal) and the frames
//! (`noise_marble.png`, `noise_light3d.png`, `noise_flame.png`, the floors).

#[path = "../../../../examples/firmware/src/flame_baked_scene.rs"]
#[allow(dead_code)] // the plain quad
mod flame_baked_scene;
#[path = "../../../../examples/firmware/src/light3d_scene.rs"]
#[allow(dead_code)] // the whole-frame size
mod light3d_scene;
#[path = "../../../../examples/firmware/src/noise.rs"]
#[allow(dead_code)]
mod noise;
#[path = "../../../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

mod frames;
mod plot;
mod rows;

use std::fmt::Write as _;
use std::time::Instant;

use fixel::geometry::Vertex;
use fixel::pipeline::{Exact, SubdividedBy};
use fixel::shading::noise::{
    BandLimit, Fixed, LitSolid, Ramps, Select, SolidShader, SELECT_OFFSET,
};
use fixel::texture::LodGranularity;
use host_tests::metrics::compare_rgb565;
use host_tests::noise_scenes::{OctaveMode, SolidScene};
use host_tests::png_io::write_png_rgb8;
use host_tests::reference::noise::{
    inverse_square, light_map_trilinear, render_solid, render_solid_lit, RefLight, RefOctaves,
    RefPattern,
};
use host_tests::report_args::ReportArgs;

use frames::{
    flame_baked_frames, flame_baked_reference, flame_frames, flame_reference, rgb8, sphere_frame,
    sphere_frame_in, sphere_tris, whole_frame,
};
use plot::plot;
use rows::{row, thousands, Row};

const W: u32 = scenes::W;
const H: u32 = scenes::H;

fn main() {
    let ReportArgs {
        out,
        runs,
        mcu: mcu_path,
    } = ReportArgs::parse(
        "noise_report",
        "Speed against error for the solid textures (run by `cargo xtask report`)",
        "5",
    );
    std::fs::create_dir_all(&out).expect("output directory");
    let font_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    match std::fs::read(font_path) {
        Ok(font) => {
            let _ = plotters::style::register_font(
                "sans-serif",
                plotters::style::FontStyle::Normal,
                Box::leak(font.into_boxed_slice()),
            );
        }
        Err(e) => eprintln!("noise_report: {font_path}: {e}; no plot"),
    }
    let mcu = mcu_path
        .as_deref()
        .map(|p| host_tests::report_mcu::read(p, "noise"))
        .unwrap_or_default();
    let ramps = Ramps::new().expect("ramps");
    let tris = sphere_tris();
    let [marble, wood, granite] = RefPattern::presets();

    // ---- The firmware scene.
    let mut rows = Vec::new();
    let ideal_cache = |p: RefPattern| render_solid(&tris, p, RefOctaves::Fixed(8), 6, W, H);
    let ideal_marble = ideal_cache(marble);
    let mut measure = |name: &str,
                       res: (Vec<u16>, Vec<bool>, u32, f64),
                       pattern: RefPattern,
                       oct: RefOctaves,
                       ideal: &host_tests::reference::noise::RefSolidImage| {
        let (px, cov, sum, ns) = res;
        let r = render_solid(&tris, pattern, oct, 1, W, H);
        let vs_ref = compare_rgb565(&px, &cov, &r.rgb565(), &r.covered);
        let vs_ideal = compare_rgb565(&px, &cov, &ideal.rgb565(), &ideal.covered);
        let get = |t: &str| {
            mcu.iter()
                .find(|(m, tt, _, _)| m == name && tt == t)
                .map(|(_, _, ipp, c)| (*ipp, *c == format!("0x{sum:08x}")))
        };
        if name == "marble-band6-span" {
            let _ = write_png_rgb8(out.join("noise_marble.png"), W, H, &rgb8(&px));
        }
        eprintln!("noise_report: {name}: {ns:.1} ns/px, {vs_ref}");
        rows.push(Row {
            name: name.to_string(),
            pixels: cov.iter().filter(|&&c| c).count(),
            ns_px: ns,
            m0: get("Cortex-M0+"),
            m4: get("Cortex-M4F"),
            vs_ref,
            vs_ideal,
        });
    };
    for k in 0..=6u8 {
        let res = sphere_frame(SolidShader::new(ramps.marble(), Fixed(k)), &tris, runs);
        measure(
            &format!("marble-fixed{k}"),
            res,
            marble,
            RefOctaves::Fixed(u32::from(k)),
            &ideal_marble,
        );
    }
    let band = BandLimit::new(6);
    let rband = RefOctaves::Band { max: 6, bias: 0.0 };
    let res = sphere_frame(SolidShader::new(ramps.marble(), band), &tris, runs);
    measure("marble-band6-span", res, marble, rband, &ideal_marble);
    let mut px_shader = SolidShader::new(ramps.marble(), band);
    px_shader.granularity = LodGranularity::Pixel;
    let res = sphere_frame(px_shader, &tris, runs);
    measure("marble-band6-pixel", res, marble, rband, &ideal_marble);
    let res =
        sphere_frame_in::<_, SubdividedBy<3>>(SolidShader::new(ramps.marble(), band), &tris, runs);
    measure("marble-band6-span-sub8", res, marble, rband, &ideal_marble);
    let ideal_wood = ideal_cache(wood);
    let res = sphere_frame(SolidShader::new(ramps.wood(), band), &tris, runs);
    measure("wood-band6-span", res, wood, rband, &ideal_wood);
    let ideal_granite = ideal_cache(granite);
    let res = sphere_frame(SolidShader::new(ramps.granite(), band), &tris, runs);
    measure("granite-band6-span", res, granite, rband, &ideal_granite);
    // Composition by selection: granite, and marble where a third noise passes 0.1.
    let select = RefPattern::Select {
        a: Box::leak(Box::new(granite)),
        b: Box::leak(Box::new(marble)),
        threshold: 0.1,
        width: 0.2,
        shift: 1,
        offset: SELECT_OFFSET.map(|v| f64::from(v) / 65536.0),
    };
    let ideal_select = ideal_cache(select);
    let sel = Select::new(
        ramps.granite(),
        ramps.marble(),
        3277,
        6554,
        1,
        SELECT_OFFSET,
    )
    .expect("select");
    let res = sphere_frame(SolidShader::new(sel, band), &tris, runs);
    let _ = write_png_rgb8(out.join("noise_select.png"), W, H, &rgb8(&res.0));
    measure(
        "select-granite-marble-band6-span",
        res,
        select,
        rband,
        &ideal_select,
    );

    // ---- The wooden cube: per-vertex light against the baked 3D light map
    // (`noise_light3d`). Reference: the f64 pattern times the f64 light with the same rule
    // (per-vertex intensity, or f64 trilinear of the same texels); ideal: 6 x 6 samples of
    // 8 octaves times the unbaked inverse-square light for the light map.
    let mut cube_rows = Vec::new();
    let mut cube4 = [[Vertex::new([fixel::math::Fx::ZERO; 4], [0; 4]); 3]; light3d_scene::TRIS];
    let n = light3d_scene::triangles(&mut cube4);
    let cube_tris = &cube4[..n];
    let cube3: Vec<[Vertex<3>; 3]> = cube_tris
        .iter()
        .map(|t| t.map(|v| Vertex::new(v.position, [v.varyings[0], v.varyings[1], v.varyings[2]])))
        .collect();
    let texel = f64::from(1u32 << light3d_scene::CUBE_LIGHT_LOG2_TEXEL) / 65536.0;
    let origin = light3d_scene::CUBE_LIGHT_ORIGIN.map(|b| f64::from(b) / 65536.0);
    let baked = |p: [f64; 3]| {
        light_map_trilinear(
            &light3d_scene::CUBE_LIGHT_TEXELS,
            light3d_scene::CUBE_LIGHT_SIDE,
            origin,
            texel,
            p,
        )
    };
    let unbaked = |p: [f64; 3]| {
        inverse_square(
            &light3d_scene::CUBE_LIGHT_LIGHTS,
            light3d_scene::CUBE_LIGHT_AMBIENT,
            p,
        )
    };
    let mut cbuf = Box::new(light3d_scene::Light3dBuffers::new());
    let vshader = SolidShader::new(ramps.wood(), band);
    let res = whole_frame::<_, Exact, 4>(vshader, cube_tris, runs, &mut || {
        light3d_scene::render_vertex_lit(vshader, &mut cbuf, &mut || {}, &mut || {}).unwrap()
    });
    let r = render_solid(cube_tris, wood, rband, 1, W, H);
    let ideal = render_solid(cube_tris, wood, RefOctaves::Fixed(8), 6, W, H);
    cube_rows.push(row(
        "cube-wood-vertex-band6-span",
        res,
        &mcu,
        &r.rgb565(),
        &r.covered,
        &ideal.rgb565(),
        &ideal.covered,
    ));
    let lshader = LitSolid {
        pattern: ramps.wood(),
        octaves: band,
        light: light3d_scene::light_map().expect("light map"),
        granularity: LodGranularity::Span,
    };
    let res = whole_frame::<_, Exact, 3>(lshader, &cube3, runs, &mut || {
        light3d_scene::render_light_map(lshader, &mut cbuf, &mut || {}, &mut || {}).unwrap()
    });
    let _ = write_png_rgb8(out.join("noise_light3d.png"), W, H, &rgb8(&res.0));
    let r = render_solid_lit(cube_tris, wood, rband, 1, W, H, RefLight::At(&baked));
    let ideal = render_solid_lit(
        cube_tris,
        wood,
        RefOctaves::Fixed(8),
        6,
        W,
        H,
        RefLight::At(&unbaked),
    );
    cube_rows.push(row(
        "cube-wood-light3d-band6-span",
        res,
        &mcu,
        &r.rgb565(),
        &r.covered,
        &ideal.rgb565(),
        &ideal.covered,
    ));

    // ---- The flame (`noise_flame`): 1, 3 and 5 octaves. Reference: the f64 flame with the
    // same octaves; ideal: 6 x 6 samples of 8 octaves.
    let mut flame_rows = Vec::new();
    let flame_ideal = flame_reference(8, 6);
    let all = vec![true; flame_ideal.len()];
    for k in [1u8, 3, 5] {
        let res = flame_frames(k, runs);
        if k == 5 {
            let _ = write_png_rgb8(
                out.join("noise_flame.png"),
                noise::FLAME_W,
                noise::FLAME_H,
                &rgb8(&res.0[..noise::FLAME_PIXELS]),
            );
        }
        let r = flame_reference(u32::from(k), 1);
        flame_rows.push(row(
            &format!("flame-oct{k}"),
            res,
            &mcu,
            &r,
            &all,
            &flame_ideal,
            &all,
        ));
    }
    // The flame from two baked layers (`noise_flame_baked`): reference, its own definition
    // read at the nearest texel centres; ideal, the per-pixel flame's.
    let baked_ref = flame_baked_reference();
    flame_rows.push(row(
        "flame-baked",
        flame_baked_frames(runs),
        &mcu,
        &baked_ref,
        &all,
        &flame_ideal,
        &all,
    ));
    for r in cube_rows.iter().chain(&flame_rows) {
        eprintln!(
            "noise_report: {}: {:.1} ns/px, {}",
            r.name, r.ns_px, r.vs_ref
        );
    }

    // ---- The granite floor (host only).
    let mut floor_rows = Vec::new();
    let floor_ideal = SolidScene::Granite.reference(RefOctaves::Fixed(8), 6);
    let floor_ideal565 = floor_ideal.rgb565();
    let modes: Vec<(String, OctaveMode)> = (1..=6u8)
        .map(|k| (format!("granite-fixed{k}"), OctaveMode::Fixed(k)))
        .chain([
            (
                "granite-band6-span".to_string(),
                OctaveMode::Band(6, LodGranularity::Span),
            ),
            (
                "granite-band6-pixel".to_string(),
                OctaveMode::Band(6, LodGranularity::Pixel),
            ),
        ])
        .collect();
    for (name, mode) in modes {
        let mut times = Vec::new();
        let mut res = (Vec::new(), Vec::new());
        for _ in 0..runs {
            let t0 = Instant::now();
            res = SolidScene::Granite.draw(&ramps, mode);
            times.push(t0.elapsed().as_secs_f64());
        }
        times.sort_by(f64::total_cmp);
        let (px, cov) = res;
        let n = cov.iter().filter(|&&c| c).count().max(1);
        let r = SolidScene::Granite.reference(mode.reference(), 1);
        let vs_ref = compare_rgb565(&px, &cov, &r.rgb565(), &r.covered);
        let vs_ideal = compare_rgb565(&px, &cov, &floor_ideal565, &floor_ideal.covered);
        if name == "granite-fixed6" || name == "granite-band6-span" {
            let _ = write_png_rgb8(
                out.join(format!("noise_floor_{name}.png")),
                160,
                120,
                &rgb8(&px),
            );
        }
        floor_rows.push(Row {
            name,
            pixels: n,
            ns_px: times[times.len() / 2] * 1e9 / n as f64,
            m0: None,
            m4: None,
            vs_ref,
            vs_ideal,
        });
    }
    let _ = write_png_rgb8(
        out.join("noise_floor_ideal.png"),
        160,
        120,
        &rgb8(&floor_ideal565),
    );

    // ---- Markdown.
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# Solid textures (Perlin noise): speed against error\n\n\
         Reproduce: `cargo xtask report` (or `cargo run --release -p host-tests --bin noise_report -- --out target/report [--mcu target/report/mcu.tsv]`).\n\n\
         Error columns: RGB565 LSBs and PSNR of fixel's frame against the f64 reference with the \
         same octave rule (`ref`: fixed-point error) and against a 6 x 6 supersampled, 8-octave \
         f64 reference (`ideal`: fixed-point plus aliasing and truncation error). Instructions \
         per pixel: exact (QEMU), frame 0, pixels written, geometry and set-up included.\n"
    );
    let table = |md: &mut String, title: &str, rows: &[Row]| {
        let _ = writeln!(md, "## {title}\n");
        let _ = writeln!(
            md,
            "| variant | host ns/px | M0+ instr/px | M4F instr/px | PSNR ref | max ref | p99 ref | PSNR ideal | mean ideal |\n|---|---|---|---|---|---|---|---|---|"
        );
        for r in rows {
            let f = |v: Option<(f64, bool)>| {
                v.map_or("-".to_string(), |(x, ok)| {
                    format!("{x:.0}{}", if ok { "" } else { " (**checksum!**)" })
                })
            };
            let _ = writeln!(
                md,
                "| `{}` | {:.1} | {} | {} | {:.2} | {} | {} | {:.2} | {:.2} |",
                r.name,
                r.ns_px,
                f(r.m0),
                f(r.m4),
                r.vs_ref.psnr_db,
                r.vs_ref.max,
                r.vs_ref.p99,
                r.vs_ideal.psnr_db,
                r.vs_ideal.mean
            );
        }
        let _ = writeln!(md);
    };
    table(
        &mut md,
        "Firmware scene: the marble sphere, 320 x 240 (17,306 pixels)",
        &rows,
    );
    table(
        &mut md,
        &format!(
            "Firmware scene `noise_light3d`: the wooden cube, 320 x 240 ({} pixels), lit per vertex and by the baked 3D light map (16³ texels, trilinear)",
            thousands(cube_rows.first().map_or(0, |r| r.pixels))
        ),
        &cube_rows,
    );
    let _ = writeln!(
        md,
        "`ref` for the light map: the f64 pattern times the f64 trilinear interpolation of the \
         same texels; `ideal`: 6 x 6 samples of 8 octaves times the unbaked inverse-square \
         light the map was baked from (so it includes the bake's quantization and the \
         trilinear error). The per-vertex row's light is its interpolated intensity in both.\n"
    );
    table(
        &mut md,
        "Firmware scenes `noise_flame` and `noise_flame_baked`: 4 frames of 80 x 96 (t = 0, 1/8, 2/8, 3/8 s), 1, 3 and 5 octaves per pixel (the firmware: 5), and from two baked layers (`flame-baked`: `ref` is its own definition read at the nearest texel centres, `ideal` the per-pixel flame's)",
        &flame_rows,
    );
    table(
        &mut md,
        "The granite floor to the horizon, 160 x 120 (host)",
        &floor_rows,
    );
    std::fs::write(out.join("noise.md"), &md).expect("write noise.md");
    if let Err(e) = plot(&rows, &floor_rows, &out.join("noise_plot.png")) {
        eprintln!("noise_report: plot: {e}");
    }
    print!("{md}");
}
