//! `cargo xtask report`: the environment-mapping frame (`env::env_frame`: the benchmark
//! sphere mirroring the 64-texel sky cube map, exact perspective, 8-row bands) once per
//! variant: reflection per pixel or per vertex, nearest or bilinear within a face; then the
//! same sky as a 64 x 64 sphere map and a 128 x 64 latitude-longitude map (per pixel,
//! bilinear).
#![no_std]
#![no_main]

use fixel::pipeline::Exact;
use fixel::shading::env::{
    EnvLookup, EnvVertices, LatLongMap, ReflectPerPixel, ReflectPerVertex, SphereMap,
};
use fixel::texture::{Bilinear, Nearest, Texture};
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
    ok
}

fixel_firmware::entry!(run);
