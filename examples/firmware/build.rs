//! Link scripts per architecture, and the flash tables generated with fixel's own code:
//! the procedural textures `T(w, h)` (raw RGB565, little-endian) and the benchmark sphere.
use std::fmt::Write as _;
use std::{env, fs, path::Path, path::PathBuf};

use embedded_graphics_core::pixelcolor::IntoStorage;
use embedded_graphics_core::pixelcolor::Rgb565;

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").unwrap());
    let dir = env::var("CARGO_MANIFEST_DIR").unwrap();
    match env::var("CARGO_CFG_TARGET_ARCH").as_deref() {
        Ok("arm") => {
            // The report firmwares need a larger layout (see memory-report.x).
            let memory: &[u8] = match env::var("FIXEL_FW_MEMORY").as_deref() {
                Ok("report") => include_bytes!("memory-report.x"),
                Ok("whole") => include_bytes!("memory-whole.x"),
                _ => include_bytes!("memory-default.x"),
            };
            fs::write(out.join("memory.x"), memory).unwrap();
            println!("cargo:rustc-link-search={}", out.display());
            println!("cargo:rustc-link-arg=-Tlink.x");
        }
        Ok("riscv32") => {
            let script = if env::var("FIXEL_FW_MEMORY").as_deref() == Ok("whole") {
                "link-whole.ld"
            } else {
                "link.ld"
            };
            println!("cargo:rustc-link-arg=-T{dir}/{script}");
        }
        _ => {}
    }
    // (Not named memory.x in the crate root: the linker would find that one first, in its
    // working directory, whatever OUT_DIR holds.)
    println!("cargo:rerun-if-changed=memory-default.x");
    println!("cargo:rerun-if-changed=memory-report.x");
    println!("cargo:rerun-if-changed=memory-whole.x");
    println!("cargo:rerun-if-changed=link-whole.ld");
    println!("cargo:rerun-if-env-changed=FIXEL_FW_MEMORY");
    // The report layout (1M of flash) links the largest report modes (`report_env`'s
    // textured, environment-lit sphere); the 256K default layout leaves them out.
    println!("cargo::rustc-check-cfg=cfg(fixel_fw_report)");
    if env::var("FIXEL_FW_MEMORY").as_deref() == Ok("report") {
        println!("cargo:rustc-cfg=fixel_fw_report");
    }
    println!("cargo:rerun-if-changed=link.ld");
    println!("cargo:rerun-if-changed=build.rs");

    for (w, h) in [(8, 8), (64, 64), (128, 128), (256, 128)] {
        let mut t = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
        fixel_scenes::checker_texture(w, h, &mut t).unwrap();
        let bytes: Vec<u8> = t
            .iter()
            .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
            .collect();
        fs::write(out.join(format!("t{w}x{h}.bin")), bytes).unwrap();
    }

    // `T(64, 64)` with its full mip chain (7 levels, fixel's `generate_mips`: each level
    // from level 0, rounded once).
    {
        use fixel::texture::{chain_len, full_levels};
        let levels = full_levels(64, 64);
        let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(64, 64, levels)];
        fixel_scenes::checker_texture(64, 64, &mut chain[..64 * 64]).unwrap();
        fixel::texture::generate_mips(&mut chain, 64, 64, levels).unwrap();
        let bytes: Vec<u8> = chain
            .iter()
            .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
            .collect();
        fs::write(out.join("t64x64-mips.bin"), bytes).unwrap();
    }

    let s = fixel_scenes::sphere();
    fs::write(out.join("sphere.rs"), mesh_source(&s)).unwrap();
    // The geometry benchmark's ~10k-triangle mesh (flash: ~230 KB; whole-layout builds only
    // link it).
    let f = Box::new(fixel_scenes::fine_sphere());
    fs::write(out.join("fine_sphere.rs"), mesh_source(&f)).unwrap();

    // The bump scene's brick sphere (texture coordinates 4 x 2 around), its tangents and
    // the 64 x 64 brick maps: colours, and the derivative map of the heights' mip chain.
    {
        let (sphere, tangents) = fixel_scenes::surface::sphere().unwrap();
        fs::write(out.join("brick_sphere.rs"), mesh_source(&sphere)).unwrap();
        let mut src = String::from("[");
        for t in &tangents {
            let d = t.direction;
            let _ = write!(
                src,
                "tangent({},{},{},{}),",
                d.x.to_bits(),
                d.y.to_bits(),
                d.z.to_bits(),
                t.handedness
            );
        }
        src.push(']');
        fs::write(out.join("brick_tangents.rs"), src).unwrap();
        let (n, levels) = (64u32, 7u32);
        let chain = fixel::texture::chain_len(n, n, levels);
        let mut colours = vec![Rgb565::new(0, 0, 0); (n * n) as usize];
        let mut heights = vec![0u8; chain];
        let mut derivs = vec![Rgb565::new(0, 0, 0); chain];
        let scale =
            fixel_scenes::surface::brick_maps(n, levels, &mut colours, &mut heights, &mut derivs)
                .unwrap();
        for (name, t) in [("brick-colours", &colours), ("brick-derivs", &derivs)] {
            let bytes: Vec<u8> = t
                .iter()
                .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
                .collect();
            fs::write(out.join(format!("{name}.bin")), bytes).unwrap();
        }
        fs::write(out.join("brick_scale.rs"), format!("{}", scale.to_bits())).unwrap();
    }

    // The environment-mapping scene's cube map: the procedural sky, six 64 x 64 faces.
    for face in 0..6 {
        let mut t = vec![Rgb565::new(0, 0, 0); 64 * 64];
        fixel::shading::env::sky::sky_face(face, 64, &mut t).unwrap();
        let bytes: Vec<u8> = t
            .iter()
            .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
            .collect();
        fs::write(out.join(format!("sky64-{face}.bin")), bytes).unwrap();
        // Its full mip chain (7 levels, 5461 texels), for the mipmapped mode of the report.
        let mut chain = vec![Rgb565::new(0, 0, 0); fixel::texture::chain_len(64, 64, 7)];
        chain[..64 * 64].copy_from_slice(&t);
        fixel::texture::generate_mips(&mut chain, 64, 64, 7).unwrap();
        let bytes: Vec<u8> = chain
            .iter()
            .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
            .collect();
        fs::write(out.join(format!("sky64mip-{face}.bin")), bytes).unwrap();
    }
    // The same sky as a 64 x 64 sphere map and a 128 x 64 latitude-longitude map.
    let mut t = vec![Rgb565::new(0, 0, 0); 64 * 64];
    fixel::shading::env::sky::sky_spheremap(64, &mut t).unwrap();
    let bytes: Vec<u8> = t
        .iter()
        .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
        .collect();
    fs::write(out.join("sky-sphere64.bin"), bytes).unwrap();
    // The marble, wood and granite baked for the benchmark sphere's texture coordinates
    // (256 x 128, band-limited turbulence of at most 6 octaves): the textures of the
    // `noise_baked`, `noise_baked_wood` and `noise_baked_granite` scenes.
    {
        use fixel::shading::noise::{bake, BandLimit, Pattern, Ramps};
        fn baked(pattern: &impl Pattern, name: &str, out: &Path) {
            let mut t = vec![Rgb565::new(0, 0, 0); 256 * 128];
            let surface = fixel_scenes::noise::baked_sphere_surface();
            bake(pattern, &BandLimit::new(6), &surface, 256, 128, &mut t).unwrap();
            let bytes: Vec<u8> = t
                .iter()
                .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
                .collect();
            fs::write(out.join(name), bytes).unwrap();
        }
        let ramps = Ramps::new().unwrap();
        baked(&ramps.marble(), "marble256x128.bin", &out);
        baked(&ramps.wood(), "wood256x128.bin", &out);
        baked(&ramps.granite(), "granite256x128.bin", &out);
    }
    // The two layers of the flame from baked layers (64 x 64 Q15 partial turbulence each,
    // `fixel::shading::noise::FLAME_LAYERS`): the `noise_flame_baked` scene's tiles.
    {
        use fixel::shading::noise::{bake_flame_layer, FLAME_LAYERS, FLAME_LAYER_SIDE};
        for (l, layer) in FLAME_LAYERS.iter().enumerate() {
            let n = (FLAME_LAYER_SIDE * FLAME_LAYER_SIDE) as usize;
            let mut t = vec![0u16; n];
            bake_flame_layer(layer, FLAME_LAYER_SIDE, &mut t).unwrap();
            let bytes: Vec<u8> = t.iter().flat_map(|v| v.to_le_bytes()).collect();
            fs::write(out.join(format!("flame-layer{l}.bin")), bytes).unwrap();
        }
    }
    // The brick sphere's bump-mapped lighting resolved into a 256 x 128 texture for the
    // light fixed in object space (`demo::surface::resolve_light`, Lambert + ambient):
    // the `bump_fast` scene's texture.
    {
        use fixel::texture::{chain_len, HeightMap, Texture};
        let (n, levels) = (64, 7);
        let mut colours = vec![Rgb565::new(0, 0, 0); 64 * 64];
        let mut heights = vec![0u8; chain_len(n, n, levels)];
        let mut derivs = vec![Rgb565::new(0, 0, 0); chain_len(n, n, levels)];
        fixel_scenes::surface::brick_maps(n, levels, &mut colours, &mut heights, &mut derivs)
            .unwrap();
        let tile = Texture::new(&colours, n, n).unwrap();
        let map = HeightMap::new(&heights, n, n, levels).unwrap();
        let normals = fixel::shading::bump::HeightDifferences::new(
            map,
            fixel::math::Fx::from_bits(fixel_scenes::surface::RESOLVE_STRENGTH),
        )
        .unwrap();
        let material = fixel::shading::lighting::Material {
            specular: 0,
            ..fixel_scenes::surface::material(fixel::shading::lighting::Specular::None)
        };
        let mut t = vec![Rgb565::new(0, 0, 0); 256 * 128];
        fixel::shading::bump::resolve_sphere(
            &tile,
            &normals,
            &material,
            fixel_scenes::surface::resolve_light(),
            256,
            128,
            &mut t,
        )
        .unwrap();
        let bytes: Vec<u8> = t
            .iter()
            .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
            .collect();
        fs::write(out.join("bricks-lit256x128.bin"), bytes).unwrap();
    }
    // A 128 x 128 sphere map baked from the 64-texel sky cube map (bilinear): the
    // `env_matcap` scene's texture, the environment the per-pixel scenes read.
    let sky: Vec<Vec<Rgb565>> = (0..6)
        .map(|f| {
            let mut t = vec![Rgb565::new(0, 0, 0); 64 * 64];
            fixel::shading::env::sky::sky_face(f, 64, &mut t).unwrap();
            t
        })
        .collect();
    let cube = fixel::shading::env::CubeMap::new(
        core::array::from_fn(|i| fixel::texture::Texture::new(&sky[i], 64, 64).unwrap()),
        fixel::texture::Bilinear,
    )
    .unwrap();
    let mut t = vec![Rgb565::new(0, 0, 0); 128 * 128];
    fixel::shading::env::bake_sphere_map(&cube, 128, &mut t).unwrap();
    let bytes: Vec<u8> = t
        .iter()
        .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
        .collect();
    fs::write(out.join("sky-sphere128.bin"), bytes).unwrap();
    let mut t = vec![Rgb565::new(0, 0, 0); 128 * 64];
    fixel::shading::env::sky::sky_latlong(128, 64, &mut t).unwrap();
    let bytes: Vec<u8> = t
        .iter()
        .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
        .collect();
    fs::write(out.join("sky-latlong128x64.bin"), bytes).unwrap();
    // Irradiance and glossy (Phong e = 16) maps, 6 x 16 x 16, baked from the 32 x 32 sky.
    let src: Vec<Vec<u16>> = (0..6)
        .map(|f| {
            let mut t = vec![Rgb565::new(0, 0, 0); 32 * 32];
            fixel::shading::env::sky::sky_face(f, 32, &mut t).unwrap();
            t.iter().map(|c| IntoStorage::into_storage(*c)).collect()
        })
        .collect();
    let srcs: [&[u16]; 6] = core::array::from_fn(|i| &src[i][..]);
    for (name, lobe) in [
        ("irr16", fixel::shading::env::Lobe::Cosine),
        ("gloss16", fixel::shading::env::Lobe::Phong(16)),
    ] {
        let mut bytes = Vec::new();
        for f in 0..6 {
            let mut t = vec![Rgb565::new(0, 0, 0); 16 * 16];
            fixel::shading::env::convolve_face(srcs, 32, lobe, f, 16, &mut t).unwrap();
            bytes.extend(
                t.iter()
                    .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes()),
            );
        }
        fs::write(out.join(format!("sky-{name}.bin")), bytes).unwrap();
    }
}

/// A `MeshData { … }` literal of `s` (I16F16 bits through `v`/`uv`).
fn mesh_source<const V: usize, const T: usize>(s: &fixel_scenes::MeshData<V, T>) -> String {
    let mut src = String::from("MeshData {\n positions: [");
    for p in &s.positions {
        let _ = write!(
            src,
            "v({},{},{}),",
            p.x.to_bits(),
            p.y.to_bits(),
            p.z.to_bits()
        );
    }
    src.push_str("],\n normals: [");
    for p in &s.normals {
        let _ = write!(
            src,
            "v({},{},{}),",
            p.x.to_bits(),
            p.y.to_bits(),
            p.z.to_bits()
        );
    }
    src.push_str("],\n uvs: [");
    for [u, v] in &s.uvs {
        let _ = write!(src, "uv({},{}),", u.to_bits(), v.to_bits());
    }
    src.push_str("],\n indices: [");
    for [a, b, c] in &s.indices {
        let _ = write!(src, "[{a},{b},{c}],");
    }
    src.push_str("],\n}\n");
    src
}
