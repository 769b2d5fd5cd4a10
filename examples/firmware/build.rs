//! Link scripts per architecture, and the flash tables generated with fixel's own code:
//! the procedural textures `T(w, h)` (raw RGB565, little-endian) and the benchmark sphere.
use std::fmt::Write as _;
use std::{env, fs, path::PathBuf};

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
        fixel::demo::checker_texture(w, h, &mut t).unwrap();
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
        fixel::demo::checker_texture(64, 64, &mut chain[..64 * 64]).unwrap();
        fixel::texture::generate_mips(&mut chain, 64, 64, levels).unwrap();
        let bytes: Vec<u8> = chain
            .iter()
            .flat_map(|c| IntoStorage::into_storage(*c).to_le_bytes())
            .collect();
        fs::write(out.join("t64x64-mips.bin"), bytes).unwrap();
    }

    let s = fixel::demo::sphere();
    fs::write(out.join("sphere.rs"), mesh_source(&s)).unwrap();
    // The geometry benchmark's ~10k-triangle mesh (flash: ~230 KB; whole-layout builds only
    // link it).
    let f = Box::new(fixel::demo::fine_sphere());
    fs::write(out.join("fine_sphere.rs"), mesh_source(&f)).unwrap();

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
fn mesh_source<const V: usize, const T: usize>(s: &fixel::demo::MeshData<V, T>) -> String {
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
