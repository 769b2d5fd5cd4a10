//! `cargo xtask report`: the environment-mapping frame (`env::env_frame`: the benchmark
//! sphere mirroring the 64-texel sky cube map, exact perspective, 8-row bands) once per
//! variant: reflection per pixel or per vertex, nearest or bilinear within a face, and a
//! face per triangle with its coordinates per vertex (`CubeVertex`); then the
//! same sky as a 64 x 64 sphere map and a 128 x 64 latitude-longitude map (per pixel,
//! bilinear); then the textured sphere lit by the sky's irradiance and glossy maps
//! (`EnvLit`, 6 x 16² each; report memory layout only, see `run`).
#![no_std]
#![no_main]

#[cfg(fixel_fw_report)]
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::pipeline::Exact;
#[cfg(fixel_fw_report)]
use fixel::shading::env::{CubeMap, EnvLit};
use fixel::shading::env::{
    EnvLookup, EnvVertices, LatLongMap, ReflectPerPixel, ReflectPerVertex, SphereMap,
};
#[cfg(fixel_fw_report)]
use fixel::shading::TexBinding;
use fixel::texture::{Bilinear, Nearest, Texture};
#[cfg(fixel_fw_report)]
use fixel::texture::{Lod, MipTexture, Repeat};
use fixel_firmware::env::{self, EnvBuffers};
use fixel_firmware::scenes::FrameResult;
use fixel_firmware::{bench_end, bench_mark, bench_start, data, outln, report_begin};

/// One counted frame, then a mark; prints the `mode` line `cargo xtask report` reads.
#[inline(never)]
fn mode(
    name: &str,
    frame: impl FnOnce(&mut dyn FnMut(), &mut dyn FnMut()) -> Result<FrameResult, fixel::Error>,
) -> bool {
    bench_start();
    let r = frame(&mut || bench_end(), &mut || bench_start());
    bench_end();
    bench_mark();
    match r {
        Ok(r) => {
            outln!(
                "mode scene=env mode={} checksum=0x{:08x} pixels={} rewalked=false",
                name,
                r.checksum,
                r.stats.pixels
            );
            true
        }
        Err(e) => {
            outln!("mode scene=env mode={} error={:?}", name, e);
            false
        }
    }
}

#[inline(never)]
fn per_pixel<M: EnvLookup>(buf: &mut EnvBuffers, name: &str, m: M) -> bool {
    let s = core::hint::black_box(&data::SPHERE);
    mode(name, |pause, resume| {
        env::env_frame::<_, Exact, 6>(
            buf,
            ReflectPerPixel(m),
            &s.positions,
            &s.normals,
            &s.indices,
            EnvVertices::per_pixel,
            pause,
            resume,
        )
    })
}

#[inline(never)]
fn per_vertex<M: EnvLookup>(buf: &mut EnvBuffers, name: &str, m: M) -> bool {
    let s = core::hint::black_box(&data::SPHERE);
    mode(name, |pause, resume| {
        env::env_frame::<_, Exact, 3>(
            buf,
            ReflectPerVertex(m),
            &s.positions,
            &s.normals,
            &s.indices,
            EnvVertices::per_vertex,
            pause,
            resume,
        )
    })
}

/// The textured sphere lit by the sky: `T(256, 128)` × irradiance + 0.5 × glossy.
#[cfg(fixel_fw_report)]
#[inline(never)]
fn env_lit(buf: &mut EnvBuffers) -> bool {
    let s = core::hint::black_box(&data::SPHERE);
    let maps = |m: &'static [Rgb565; 6 * 256]| {
        let f = |i: usize| Texture::new(m.get(i * 256..(i + 1) * 256).unwrap_or(&[]), 16, 16);
        match (f(0), f(1), f(2), f(3), f(4), f(5)) {
            (Ok(a), Ok(b), Ok(c), Ok(d), Ok(e), Ok(g)) => {
                CubeMap::new([a, b, c, d, e, g], Bilinear).ok()
            }
            _ => None,
        }
    };
    let base = MipTexture::single(core::hint::black_box(data::T256X128));
    let (Some(diffuse), Some(glossy), Ok(tex)) = (
        maps(core::hint::black_box(&data::SKY_IRR16)),
        maps(core::hint::black_box(&data::SKY_GLOSS16)),
        TexBinding::new(&base, Bilinear, Repeat, Repeat, Lod::default()),
    ) else {
        return false;
    };
    let shader = EnvLit {
        base: tex,
        diffuse,
        glossy,
        specular: 128,
    };
    mode("envlit-bilinear", |pause, resume| {
        env::env_frame_indexed::<_, Exact, 8>(
            buf,
            shader,
            &s.positions,
            &s.indices,
            |setup, i| env::lit_vertex(setup, &s.positions, &s.normals, &s.uvs, i),
            pause,
            resume,
        )
    })
}

/// The sphere with 64-texel mipmapped faces, trilinear, LOD per pixel or per span, GL's
/// clamped filter or seamless on every level.
#[cfg(fixel_fw_report)]
#[inline(never)]
fn mipmapped(
    buf: &mut EnvBuffers,
    name: &str,
    granularity: fixel::texture::LodGranularity,
    seamless: bool,
) -> bool {
    use fixel::shading::env::{MipCubeMap, ReflectPerPixelMip};
    use fixel::texture::Trilinear;
    let c = core::hint::black_box(&data::SKY64_MIPS);
    let chain = |i: usize| MipTexture::new(&c[i], 64, 64, 7);
    let (Ok(a), Ok(b), Ok(d), Ok(e), Ok(f), Ok(g)) =
        (chain(0), chain(1), chain(2), chain(3), chain(4), chain(5))
    else {
        return false;
    };
    let faces = [a, b, d, e, f, g];
    let Ok(map) = MipCubeMap::new(&faces, Trilinear::default()) else {
        return false;
    };
    let lod = Lod {
        granularity,
        ..Lod::default()
    };
    if seamless {
        mip_mode(
            buf,
            name,
            ReflectPerPixelMip {
                map: map.seamless(),
                lod,
            },
        )
    } else {
        mip_mode(buf, name, ReflectPerPixelMip { map, lod })
    }
}

/// One frame of the sphere with a mipmapped cube-map shader.
#[cfg(fixel_fw_report)]
fn mip_mode<M: fixel::shading::env::EnvLookupLod>(
    buf: &mut EnvBuffers,
    name: &str,
    shader: fixel::shading::env::ReflectPerPixelMip<M>,
) -> bool {
    let s = core::hint::black_box(&data::SPHERE);
    mode(name, |pause, resume| {
        env::env_frame::<_, Exact, 6>(
            buf,
            shader,
            &s.positions,
            &s.normals,
            &s.indices,
            EnvVertices::per_pixel,
            pause,
            resume,
        )
    })
}

/// The real-time mode: the sphere through per-vertex sphere-map coordinates and the
/// 128 x 128 sky sphere map, a plain textured draw (the `env_matcap` scene).
#[cfg(fixel_fw_report)]
#[inline(never)]
fn matcap() -> bool {
    use fixel_firmware::{matcap_scene, scenes};
    let mut buf = scenes::SphereBuffers::with_storage();
    let (Ok(mesh), Ok(map)) = (
        core::hint::black_box(&data::SPHERE)
            .mesh()
            .and_then(|m| m.with_face_planes(&data::SPHERE_FACES)),
        Texture::new(core::hint::black_box(&data::SKY_SPHERE128), 128, 128),
    ) else {
        return false;
    };
    mode("matcap-vertex-bilinear", |pause, resume| {
        matcap_scene::env_matcap(
            scenes::Target::Bands(&mut buf),
            map,
            &mesh,
            0,
            pause,
            resume,
        )
    })
}

fn run() -> bool {
    let mut buf = EnvBuffers::new();
    let f = core::hint::black_box(&data::SKY64);
    let Ok(cube) = env::env_cube([&f[0], &f[1], &f[2], &f[3], &f[4], &f[5]]) else {
        return false;
    };
    report_begin();
    let mut ok = per_pixel(&mut buf, "pixel-bilinear", cube);
    ok &= per_pixel(&mut buf, "pixel-nearest", cube.with_filter(Nearest));
    ok &= per_vertex(&mut buf, "vertex-bilinear", cube.with_filter(Bilinear));
    ok &= per_vertex(&mut buf, "vertex-nearest", cube.with_filter(Nearest));
    let (Ok(sm), Ok(ll)) = (
        Texture::new(core::hint::black_box(&data::SKY_SPHERE64), 64, 64),
        Texture::new(core::hint::black_box(&data::SKY_LATLONG128X64), 128, 64),
    ) else {
        return false;
    };
    ok &= per_pixel(
        &mut buf,
        "sphere-pixel-bilinear",
        SphereMap::new(sm, Bilinear),
    );
    ok &= per_pixel(
        &mut buf,
        "latlong-pixel-bilinear",
        LatLongMap::new(ll, Bilinear),
    );
    // Only in the report layout (`cargo xtask report`): with `T(256, 128)`, the mip chains
    // and the seamless filter's code these modes do not fit the default 256K of flash next
    // to the others (`CubeVertex` alone overflows it by 2.4 KB on Cortex-M0+).
    #[cfg(fixel_fw_report)]
    {
        ok &= per_pixel(&mut buf, "pixel-seamless", cube.seamless());
        ok &= env_lit(&mut buf);
        use fixel::texture::LodGranularity;
        ok &= mipmapped(&mut buf, "pixel-trilinear", LodGranularity::Pixel, false);
        ok &= mipmapped(
            &mut buf,
            "pixel-trilinear-span",
            LodGranularity::Span,
            false,
        );
        ok &= mipmapped(
            &mut buf,
            "pixel-trilinear-seamless-span",
            LodGranularity::Span,
            true,
        );
        ok &= matcap();
        let s = core::hint::black_box(&data::SPHERE);
        ok &= mode("cube-vertex-bilinear", |pause, resume| {
            env::cube_vertex_frame(
                &mut buf,
                [&f[0], &f[1], &f[2], &f[3], &f[4], &f[5]],
                &s.positions,
                &s.normals,
                &s.indices,
                pause,
                resume,
            )
        });
    }
    ok
}

fixel_firmware::entry!(run);
