//! `cargo xtask report`, environment mapping: one row per variant of the
//! environment-mapped benchmark sphere (frame 0, the 64-texel procedural sky cube map,
//! exact perspective): reflection per pixel or per vertex, nearest or bilinear; then the
//! same sky as a 64 x 64 sphere map and a 128 x 64 latitude-longitude map; then the
//! textured sphere lit by the sky's irradiance and glossy maps (`EnvLit`); then the
//! real-time modes (sphere-map coordinates per vertex, a cube-map face per triangle).
//!
//! ```text
//! report_env --out DIR [--runs N] [--mcu mcu.tsv]
//! ```
//!
//! Columns: host ns/px (median of N whole-frame draws on this machine), exact M0+ and M4F
//! instructions per pixel of the firmware `report_env` (from `mcu.tsv`, checked against the
//! host's band frame checksum), and the error against the f64 reference with the reflection
//! per pixel (`host_tests::reference::env`). Per-vertex rows also give the error against
//! their own definition (interpolated `r`). A second table measures per-vertex `r` against
//! per-pixel `r` on both benchmark meshes (sphere and cube). Writes `DIR/env.md`.

#[path = "../../../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "../../../../examples/firmware/src/open_frame.rs"]
mod open_frame;

#[path = "../../../../examples/firmware/src/env.rs"]
#[allow(dead_code)]
mod env;

#[path = "../../../../examples/firmware/src/matcap_scene.rs"]
mod matcap_scene;

mod matcap;
mod measure;

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::Vertex;
use fixel::math::Vec3;
use fixel::pipeline::Exact;
use fixel::shading::env::{
    convolve_face, sky, CubeMap, CubeVertex, EnvLit, EnvVertices, LatLongMap, Lobe, MipCubeMap,
    ReflectPerPixel, ReflectPerPixelMip, ReflectPerVertex, SphereMap,
};
use fixel::shading::TexBinding;
use fixel::texture::{
    Bilinear, Lod, LodGranularity, MipTexture, Nearest, Repeat, Texture, Trilinear,
};
use host_tests::cost_plot::Point;
use host_tests::metrics::Report;
use host_tests::reference::env::{
    cube_sample, cube_sample_seamless, cube_sample_trilinear, cube_sample_trilinear_seamless,
    latlong_sample, reflect, render_varyings, render_varyings_with_derivatives, sphere_sample,
};
use host_tests::reference::{RefFilter, RefTexture};
use host_tests::report_args::ReportArgs;

use measure::{band_checksum, cmp, fmt_err, mesh, read_mcu, ref_pixel, ref_vertex, run};

const W: u32 = 320;
const H: u32 = 240;
const SIZE: u32 = 64;

fn main() {
    let ReportArgs {
        out,
        runs,
        mcu: mcu_path,
    } = ReportArgs::parse(
        "report_env",
        "Speed against error for environment mapping (run by `cargo xtask report`)",
        "7",
    );
    let mcu = mcu_path.as_ref().map(read_mcu).unwrap_or_default();
    let faces: Vec<Vec<Rgb565>> = (0..6)
        .map(|f| {
            let mut t = vec![Rgb565::new(0, 0, 0); (SIZE * SIZE) as usize];
            sky::sky_face(f, SIZE, &mut t).expect("face");
            t
        })
        .collect();
    let rf: [RefTexture; 6] = core::array::from_fn(|i| RefTexture {
        width: SIZE,
        height: SIZE,
        texels: faces[i].iter().map(|c| c.into_storage()).collect(),
        border: 0,
    });
    let cube = CubeMap::new(
        core::array::from_fn(|i| Texture::new(&faces[i], SIZE, SIZE).expect("face")),
        Bilinear,
    )
    .expect("cube");
    let sphere = mesh(&fixel_scenes::sphere(), &fixel_scenes::sphere_model(0));
    let cubem = mesh(&fixel_scenes::cube(), &fixel_scenes::cube_model(0));

    let mut md = String::from(
        "## Environment mapping\n\n\
         Benchmark sphere, frame 0, mirroring the procedural sky cube map (six 64 x 64 faces), \
         exact perspective, depth-tested, 320 x 240. Host: median of the runs, whole frame. \
         MCU: exact instructions per pixel of `report_env` (QEMU, frame 0 in 8-row bands, \
         geometry included; ✓ = the MCU's frame checksum equals the host's band frame). \
         Error against the f64 reference with `r` per pixel, in RGB565 LSB: \
         mean / max / share > 1 LSB / PSNR.\n\n\
         | variant | host ns/px | M0+ instr/px | M4F instr/px | error vs f64 per-pixel r | \
         per-vertex: error vs own reference (interpolated r) |\n|---|---:|---:|---:|---|---|\n",
    );
    let mcu_cell = |name: &str, want: &(String, u64), t: &str| -> String {
        mcu.get(name)
            .and_then(|m| m.get(t))
            .map_or("-".into(), |(ipp, px, sum)| {
                let ok = *sum == want.0 && *px == want.1;
                format!(
                    "{ipp:.0}{}",
                    if ok {
                        " ✓"
                    } else {
                        " ✗ (checksum differs)"
                    }
                )
            })
    };
    let m4 = |name: &str, want: &(String, u64)| -> Option<f64> {
        mcu.get(name)
            .and_then(|m| m.get("Cortex-M4F"))
            .filter(|(_, px, sum)| *sum == want.0 && *px == want.1)
            .map(|(ipp, _, _)| *ipp)
    };
    let mut points: Vec<Point> = Vec::new();
    let mut point = |name: &str, ns: f64, want: &(String, u64), e: &Report| {
        points.push(Point {
            name: name.to_string(),
            host_ns: ns,
            m4f: m4(name, want),
            psnr: e.psnr_db,
        })
    };
    struct Variant {
        name: &'static str,
        per_pixel: bool,
        bilinear: bool,
    }
    let variants = [
        Variant {
            name: "pixel-bilinear",
            per_pixel: true,
            bilinear: true,
        },
        Variant {
            name: "pixel-nearest",
            per_pixel: true,
            bilinear: false,
        },
        Variant {
            name: "vertex-bilinear",
            per_pixel: false,
            bilinear: true,
        },
        Variant {
            name: "vertex-nearest",
            per_pixel: false,
            bilinear: false,
        },
    ];
    for v in &variants {
        let rfil = if v.bilinear {
            RefFilter::Bilinear
        } else {
            RefFilter::Nearest
        };
        let reference = ref_pixel(&sphere, &rf, rfil);
        let (img, ns, want, own) = match (v.per_pixel, v.bilinear) {
            (true, true) => {
                let (i, ns) = run(ReflectPerPixel(cube), &sphere.pixel, runs);
                (
                    i,
                    ns,
                    band_checksum(ReflectPerPixel(cube), EnvVertices::per_pixel),
                    None,
                )
            }
            (true, false) => {
                let c = cube.with_filter(Nearest);
                let (i, ns) = run(ReflectPerPixel(c), &sphere.pixel, runs);
                (
                    i,
                    ns,
                    band_checksum(ReflectPerPixel(c), EnvVertices::per_pixel),
                    None,
                )
            }
            (false, true) => {
                let (i, ns) = run(ReflectPerVertex(cube), &sphere.vertex, runs);
                let own = cmp(&i, &ref_vertex(&sphere, &rf, rfil));
                (
                    i,
                    ns,
                    band_checksum(ReflectPerVertex(cube), EnvVertices::per_vertex),
                    Some(own),
                )
            }
            (false, false) => {
                let c = cube.with_filter(Nearest);
                let (i, ns) = run(ReflectPerVertex(c), &sphere.vertex, runs);
                let own = cmp(&i, &ref_vertex(&sphere, &rf, rfil));
                (
                    i,
                    ns,
                    band_checksum(ReflectPerVertex(c), EnvVertices::per_vertex),
                    Some(own),
                )
            }
        };
        let e = cmp(&img, &reference);
        point(v.name, ns, &want, &e);
        md += &format!(
            "| {} | {:.1} | {} | {} | {} | {} |\n",
            v.name,
            ns,
            mcu_cell(v.name, &want, "Cortex-M0+"),
            mcu_cell(v.name, &want, "Cortex-M4F"),
            fmt_err(&e),
            own.as_ref().map_or("-".into(), fmt_err)
        );
    }

    // Seamless bilinear across face edges, against the reference's seamless filter.
    {
        let name = "pixel-seamless";
        let sm = cube.seamless();
        let reference = render_varyings(&sphere.pixel, W, H, |_, _, a| {
            cube_sample_seamless(&rf, reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]]))
        });
        let (img, ns) = run(ReflectPerPixel(sm), &sphere.pixel, runs);
        let want = band_checksum(ReflectPerPixel(sm), EnvVertices::per_pixel);
        let e = cmp(&img, &reference);
        point(name, ns, &want, &e);
        md += &format!(
            "| {name} (bilinear across face edges) | {ns:.1} | {} | {} | {} | - |\n",
            mcu_cell(name, &want, "Cortex-M0+"),
            mcu_cell(name, &want, "Cortex-M4F"),
            fmt_err(&e)
        );
    }

    // Trilinear mip chains per face (`generate_mips`, 7 levels), LOD per pixel from the
    // reflection's derivatives, against the reference's GL cube LOD (central differences
    // of r).
    {
        let levels = fixel::texture::full_levels(SIZE, SIZE);
        let chains = host_tests::env_scene::sky_chains(SIZE);
        let mips: [MipTexture<'_>; 6] = core::array::from_fn(|i| {
            MipTexture::new(&chains[i], SIZE, SIZE, levels).expect("chain")
        });
        let rc = host_tests::env_scene::ref_chains(&chains, SIZE);
        let tris: Vec<[Vertex<6>; 3]> = sphere.pixel.clone();
        let rr = |a: &[f64; 6]| reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]]);
        let reference = render_varyings_with_derivatives(&tris, W, H, |_, _, a, around| {
            cube_sample_trilinear(&rc, rr(&a), around.map(|b| rr(&b)))
        });
        // One row: the frame, its time, the firmware's band checksum, the error.
        macro_rules! mip_row {
            ($name:expr, $label:expr, $shader:expr, $reference:expr) => {{
                let (name, shader) = ($name, $shader);
                let (img, ns) = run(shader, &tris, runs);
                let want = band_checksum(shader, EnvVertices::per_pixel);
                let e = cmp(&img, $reference);
                point(name, ns, &want, &e);
                md += &format!(
                    "| {name} ({}) | {ns:.1} | {} | {} | {} | - |\n",
                    $label,
                    mcu_cell(name, &want, "Cortex-M0+"),
                    mcu_cell(name, &want, "Cortex-M4F"),
                    fmt_err(&e)
                );
            }};
        }
        let map = MipCubeMap::new(&mips, Trilinear::default()).expect("map");
        let lod = |granularity| Lod {
            granularity,
            ..Lod::default()
        };
        for (name, granularity, what) in [
            ("pixel-trilinear", LodGranularity::Pixel, "pixel"),
            ("pixel-trilinear-span", LodGranularity::Span, "span"),
        ] {
            mip_row!(
                name,
                format!("7-level chains per face, LOD per {what}; reference: GL's cube LOD"),
                ReflectPerPixelMip {
                    map,
                    lod: lod(granularity)
                },
                &reference
            );
        }
        // Seamless on every level, LOD per span, against the seamless reference.
        let levels: Vec<[RefTexture; 6]> = (0..rc[0].levels.len())
            .map(|k| core::array::from_fn(|f| rc[f].levels[k].clone()))
            .collect();
        let seamless_ref = render_varyings_with_derivatives(&tris, W, H, |_, _, a, around| {
            cube_sample_trilinear_seamless(&levels, rr(&a), around.map(|b| rr(&b)))
        });
        mip_row!(
            "pixel-trilinear-seamless-span",
            "the same, seamless on every level; reference: GL's seamless trilinear",
            ReflectPerPixelMip {
                map: map.seamless(),
                lod: lod(LodGranularity::Span)
            },
            &seamless_ref
        );
    }

    // The same sky as a sphere map and a lat-long map (per pixel, bilinear).
    let tex = |w: u32, h: u32, sphere: bool| -> Vec<Rgb565> {
        let mut t = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
        if sphere {
            sky::sky_spheremap(w, &mut t).expect("sphere map");
        } else {
            sky::sky_latlong(w, h, &mut t).expect("lat-long");
        }
        t
    };
    let (st, lt) = (tex(64, 64, true), tex(128, 64, false));
    let refmap = |t: &[Rgb565], w: u32, h: u32| RefTexture {
        width: w,
        height: h,
        texels: t.iter().map(|c| c.into_storage()).collect(),
        border: 0,
    };
    let (rst, rlt) = (refmap(&st, 64, 64), refmap(&lt, 128, 64));
    let sm = SphereMap::new(Texture::new(&st, 64, 64).expect("tex"), Bilinear);
    let ll = LatLongMap::new(Texture::new(&lt, 128, 64).expect("tex"), Bilinear);
    let rr = |a: [f64; 6]| reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]]);
    {
        let name = "sphere-pixel-bilinear";
        let reference = render_varyings(&sphere.pixel, W, H, |_, _, a| {
            sphere_sample(&rst, rr(a), RefFilter::Bilinear)
        });
        let (img, ns) = run(ReflectPerPixel(sm), &sphere.pixel, runs);
        let want = band_checksum(ReflectPerPixel(sm), EnvVertices::per_pixel);
        let e = cmp(&img, &reference);
        point(name, ns, &want, &e);
        md += &format!(
            "| {name} (64 x 64 sphere map) | {ns:.1} | {} | {} | {} | - |\n",
            mcu_cell(name, &want, "Cortex-M0+"),
            mcu_cell(name, &want, "Cortex-M4F"),
            fmt_err(&e)
        );
        let name = "latlong-pixel-bilinear";
        let reference = render_varyings(&sphere.pixel, W, H, |_, _, a| {
            latlong_sample(&rlt, rr(a), RefFilter::Bilinear)
        });
        let (img, ns) = run(ReflectPerPixel(ll), &sphere.pixel, runs);
        let want = band_checksum(ReflectPerPixel(ll), EnvVertices::per_pixel);
        let e = cmp(&img, &reference);
        point(name, ns, &want, &e);
        md += &format!(
            "| {name} (128 x 64 lat-long map) | {ns:.1} | {} | {} | {} | - |\n",
            mcu_cell(name, &want, "Cortex-M0+"),
            mcu_cell(name, &want, "Cortex-M4F"),
            fmt_err(&e)
        );
    }

    // The textured sphere lit by the sky: T(256, 128) x irradiance + 0.5 x glossy (e = 16),
    // maps of 6 x 16 x 16 baked from the 32 x 32 sky (as the firmware's build script does).
    {
        let src: Vec<Vec<u16>> = (0..6)
            .map(|f| {
                let mut t = vec![Rgb565::new(0, 0, 0); 32 * 32];
                sky::sky_face(f, 32, &mut t).expect("face");
                t.iter().map(|c| c.into_storage()).collect()
            })
            .collect();
        let srcs: [&[u16]; 6] = core::array::from_fn(|i| &src[i][..]);
        let bake = |lobe| -> Vec<Vec<Rgb565>> {
            (0..6)
                .map(|f| {
                    let mut o = vec![Rgb565::new(0, 0, 0); 16 * 16];
                    convolve_face(srcs, 32, lobe, f, 16, &mut o).expect("bake");
                    o
                })
                .collect()
        };
        let (diff, glos) = (bake(Lobe::Cosine), bake(Lobe::Phong(16)));
        fn cube16(m: &[Vec<Rgb565>]) -> CubeMap<'_, Bilinear> {
            CubeMap::new(
                core::array::from_fn(|i| Texture::new(&m[i], 16, 16).expect("face")),
                Bilinear,
            )
            .expect("cube")
        }
        let mut base = vec![Rgb565::new(0, 0, 0); 256 * 128];
        fixel_scenes::checker_texture(256, 128, &mut base).expect("texture");
        let mip = MipTexture::single(Texture::new(&base, 256, 128).expect("texture"));
        let shader = EnvLit {
            base: TexBinding::new(&mip, Bilinear, Repeat, Repeat, Lod::default()).expect("tex"),
            diffuse: cube16(&diff),
            glossy: cube16(&glos),
            specular: 128,
        };
        let m = Box::new(fixel_scenes::sphere());
        let cam = fixel_scenes::camera(20);
        let setup = EnvVertices::new(
            &fixel_scenes::sphere_model(0),
            &cam.projection.mul(&cam.view),
            Vec3::ZERO,
        );
        let tris: Vec<[Vertex<8>; 3]> = m
            .indices
            .iter()
            .map(|t| {
                t.map(|i| {
                    env::lit_vertex(&setup, &m.positions, &m.normals, &m.uvs, usize::from(i))
                        .expect("vertex")
                })
            })
            .collect();
        let to_ref = |t: &[Vec<Rgb565>]| -> [RefTexture; 6] {
            core::array::from_fn(|i| RefTexture {
                width: 16,
                height: 16,
                texels: t[i].iter().map(|c| c.into_storage()).collect(),
                border: 0,
            })
        };
        let (rd, rg) = (to_ref(&diff), to_ref(&glos));
        let rb = RefTexture {
            width: 256,
            height: 128,
            texels: base.iter().map(|c| c.into_storage()).collect(),
            border: 0,
        };
        let reference = render_varyings(&tris, W, H, |_, _, a| {
            let n = [a[0], a[1], a[2]];
            let e = cube_sample(&rd, n, RefFilter::Bilinear);
            let g = cube_sample(&rg, reflect(n, [a[3], a[4], a[5]]), RefFilter::Bilinear);
            let b = host_tests::reference::sample::sample(
                &rb,
                [a[6] / 65536.0, a[7] / 65536.0],
                RefFilter::Bilinear,
                host_tests::reference::RefWrap::Repeat,
                host_tests::reference::RefWrap::Repeat,
            );
            [0, 1, 2].map(|k| (b[k] * e[k] + 0.5 * g[k]).min(1.0))
        });
        let (img, ns) = run(shader, &tris, runs);
        let mut buf = Box::new(env::EnvBuffers::new());
        let (mut a, mut b) = (|| {}, || {});
        let r = env::env_frame_indexed::<_, Exact, 8>(
            &mut buf,
            shader,
            &m.positions,
            &m.indices,
            |s, i| env::lit_vertex(s, &m.positions, &m.normals, &m.uvs, i),
            &mut a,
            &mut b,
        )
        .expect("band frame");
        let want = (format!("0x{:08x}", r.checksum), u64::from(r.stats.pixels));
        let name = "envlit-bilinear";
        let e = cmp(&img, &reference);
        point(name, ns, &want, &e);
        md += &format!(
            "| {name} (T(256, 128) x irradiance + 0.5 glossy, 6 x 16² each) | {ns:.1} | {} | {} | {} | - |\n",
            mcu_cell(name, &want, "Cortex-M0+"),
            mcu_cell(name, &want, "Cortex-M4F"),
            fmt_err(&e)
        );
    }

    // The real-time mode: sphere-map coordinates per vertex, then a plain textured draw.
    {
        let name = "matcap-vertex-bilinear";
        let row = matcap::matcap_row(runs);
        let e = cmp(&row.image, &ref_pixel(&sphere, &rf, RefFilter::Bilinear));
        point(name, row.ns, &row.want, &e);
        md += &format!(
            "| {name} (128 x 128 sphere map, uv per vertex, plain textured draw) | {:.1} | {} | {} | {} | {} |\n",
            row.ns,
            mcu_cell(name, &row.want, "Cortex-M0+"),
            mcu_cell(name, &row.want, "Cortex-M4F"),
            fmt_err(&e),
            fmt_err(&cmp(&row.image, &row.own))
        );
    }

    // The real-time cube map: a face per triangle, its coordinates per vertex, a plain
    // textured draw (affine in 64-pixel pieces, as the `env_cube_vertex` scene).
    {
        let name = "cube-vertex-bilinear";
        let f = host_tests::env_scene::faces(SIZE);
        let chains: [MipTexture<'_>; 6] = core::array::from_fn(|k| {
            MipTexture::single(Texture::new(&f[k], SIZE, SIZE).expect("face"))
        });
        let shader = CubeVertex::new(&chains, Bilinear, Lod::default()).expect("faces");
        let (img, ns) =
            measure::run_in::<_, fixel::pipeline::SubdividedBy<6>, 3>(shader, &sphere.vertex, runs);
        let m = Box::new(fixel_scenes::sphere());
        let mut buf = Box::new(env::EnvBuffers::new());
        let (mut a, mut b) = (|| {}, || {});
        let r = env::cube_vertex_frame(
            &mut buf,
            [&f[0], &f[1], &f[2], &f[3], &f[4], &f[5]],
            &m.positions,
            &m.normals,
            &m.indices,
            &mut a,
            &mut b,
        )
        .expect("band frame");
        let want = (format!("0x{:08x}", r.checksum), u64::from(r.stats.pixels));
        let e = cmp(&img, &ref_pixel(&sphere, &rf, RefFilter::Bilinear));
        let own = host_tests::reference::cube_vertex::render_cube_vertex(&sphere.pixel, &rf, W, H);
        point(name, ns, &want, &e);
        md += &format!(
            "| {name} (face per triangle, its uv per vertex, plain textured draw, affine every 64 px) | {ns:.1} | {} | {} | {} | {} |\n",
            mcu_cell(name, &want, "Cortex-M0+"),
            mcu_cell(name, &want, "Cortex-M4F"),
            fmt_err(&e),
            fmt_err(&cmp(&img, &own))
        );
    }

    md += "\nPer-vertex against per-pixel `r` on the benchmark meshes (bilinear, frame 0; \
           error of the per-vertex frame against the f64 per-pixel reference, and the \
           per-pixel frame's own error for scale):\n\n\
           | mesh | per-vertex r vs f64 per-pixel | per-pixel r vs f64 per-pixel |\n|---|---|---|\n";
    for (name, m) in [
        ("sphere (24 x 48, 2208 triangles)", &sphere),
        ("cube (12 triangles)", &cubem),
    ] {
        let reference = ref_pixel(m, &rf, RefFilter::Bilinear);
        let (pv, _) = run(ReflectPerVertex(cube), &m.vertex, 1);
        let (pp, _) = run(ReflectPerPixel(cube), &m.pixel, 1);
        md += &format!(
            "| {name} | {} | {} |\n",
            fmt_err(&cmp(&pv, &reference)),
            fmt_err(&cmp(&pp, &reference))
        );
    }
    md += "\n![cost against error: one point per variant](env.png)\n";
    print!("{md}");
    std::fs::create_dir_all(&out).expect("out dir");
    std::fs::write(out.join("env.md"), md).expect("write env.md");
    if let Err(e) = host_tests::cost_plot::write(
        &points,
        "environment maps: cost against PSNR (benchmark sphere)",
        (20.0, 55.0),
        &out.join("env.png"),
    ) {
        eprintln!("report_env: no plot: {e}");
    }
}
