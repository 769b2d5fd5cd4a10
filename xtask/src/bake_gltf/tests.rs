//! Tests of the glTF baker: the textured fixture (made here, committed under
//! `host-tests/tests/baked/`), node transforms, welding, and every refusal.

use super::*;

/// glTF JSON with one embedded buffer, assembled from typed arrays.
#[derive(Default)]
struct Gl {
    bin: Vec<u8>,
    views: Vec<String>,
    accessors: Vec<String>,
}

/// Standard base64 (RFC 4648, padded), for `data:` URIs.
fn base64(b: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::new();
    for c in b.chunks(3) {
        let n = (u32::from(c[0]) << 16)
            | (u32::from(*c.get(1).unwrap_or(&0)) << 8)
            | u32::from(*c.get(2).unwrap_or(&0));
        for k in 0..4 {
            if k <= c.len() {
                s.push(A[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

impl Gl {
    fn view(&mut self, bytes: &[u8]) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        self.views.push(format!(
            r#"{{"buffer":0,"byteOffset":{},"byteLength":{}}}"#,
            self.bin.len(),
            bytes.len()
        ));
        self.bin.extend_from_slice(bytes);
        self.views.len() - 1
    }

    /// A float accessor of `VECN` (with min and max, as `POSITION` needs).
    fn vecs<const N: usize>(&mut self, v: &[[f32; N]]) -> usize {
        let bytes: Vec<u8> = v.iter().flatten().flat_map(|f| f.to_le_bytes()).collect();
        let view = self.view(&bytes);
        let (mut lo, mut hi) = ([f32::MAX; N], [f32::MIN; N]);
        for p in v {
            for k in 0..N {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        self.accessors.push(format!(
            r#"{{"bufferView":{view},"componentType":5126,"count":{},"type":"VEC{N}","min":{lo:?},"max":{hi:?}}}"#,
            v.len()
        ));
        self.accessors.len() - 1
    }

    fn indices(&mut self, v: &[u16]) -> usize {
        let bytes: Vec<u8> = v.iter().flat_map(|i| i.to_le_bytes()).collect();
        let view = self.view(&bytes);
        self.accessors.push(format!(
            r#"{{"bufferView":{view},"componentType":5123,"count":{},"type":"SCALAR"}}"#,
            v.len()
        ));
        self.accessors.len() - 1
    }

    /// The document: `rest` holds `meshes`, `nodes`, `scenes` and the material keys.
    fn finish(&self, rest: &str) -> String {
        format!(
            "{{\"asset\":{{\"version\":\"2.0\",\"generator\":\"fixel xtask tests\"}},\n\
             \"buffers\":[{{\"byteLength\":{},\"uri\":\"data:application/octet-stream;base64,{}\"}}],\n\
             \"bufferViews\":[{}],\n\"accessors\":[{}],\n{rest}}}\n",
            self.bin.len(),
            base64(&self.bin),
            self.views.join(","),
            self.accessors.join(",\n")
        )
    }
}

/// A 6 x 3 RGB PNG: red to blue across, darker down.
fn png_6x3() -> Vec<u8> {
    let mut out = Vec::new();
    {
        let mut e = png::Encoder::new(&mut out, 6, 3);
        e.set_color(png::ColorType::Rgb);
        let mut w = e.write_header().unwrap();
        let px: Vec<u8> = (0..3u8)
            .flat_map(|y| {
                (0..6u8).flat_map(move |x| [255 - 40 * x, 60 * y, 40 * x + 20 * y].into_iter())
            })
            .collect();
        w.write_image_data(&px).unwrap();
    }
    out
}

/// The material part: material 0 textured with the 6 x 3 PNG, material 1 a plain
/// base-colour factor.
fn materials() -> String {
    format!(
        "\"materials\":[{{\"pbrMetallicRoughness\":{{\"baseColorTexture\":{{\"index\":0}}}}}},\
         {{\"pbrMetallicRoughness\":{{\"baseColorFactor\":[1.0,0.5,0.25,1.0]}}}}],\n\
         \"samplers\":[{{\"magFilter\":9729,\"minFilter\":9987}}],\n\
         \"textures\":[{{\"sampler\":0,\"source\":0}}],\n\
         \"images\":[{{\"uri\":\"data:image/png;base64,{}\"}}]",
        base64(&png_6x3())
    )
}

/// The fixture `tiles.gltf`: node `tile` (a textured quad, indexed, with normals,
/// coordinates and vertex colours) and its child `roof` (moved, turned a quarter about y
/// and mirrored in x: a non-indexed triangle, no normals, material 1).
fn fixture() -> String {
    let mut g = Gl::default();
    let quad_p = g.vecs(&[
        [-1.0, -1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
    ]);
    let quad_n = g.vecs(&[[0.0, 0.0, 1.0f32]; 4]);
    let quad_t = g.vecs(&[[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0f32]]);
    let quad_c = g.vecs(&[
        [1.0, 1.0, 1.0f32],
        [1.0, 0.5, 0.5],
        [0.5, 1.0, 0.5],
        [0.5, 0.5, 1.0],
    ]);
    let quad_i = g.indices(&[0, 1, 2, 0, 2, 3]);
    let roof_p = g.vecs(&[[-1.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.0, 2.0, 0.0f32]]);
    g.finish(&format!(
        "\"meshes\":[\
         {{\"name\":\"quad\",\"primitives\":[{{\"attributes\":{{\"POSITION\":{quad_p},\"NORMAL\":{quad_n},\
         \"TEXCOORD_0\":{quad_t},\"COLOR_0\":{quad_c}}},\"indices\":{quad_i},\"material\":0}}]}},\n\
         {{\"name\":\"roof\",\"primitives\":[{{\"attributes\":{{\"POSITION\":{roof_p}}},\"material\":1}}]}}],\n\
         \"nodes\":[{{\"name\":\"tile\",\"mesh\":0,\"children\":[1]}},\
         {{\"name\":\"roof\",\"mesh\":1,\"translation\":[0.0,0.5,0.25],\
         \"rotation\":[0.0,0.7071067811865476,0.0,0.7071067811865476],\"scale\":[-1.0,1.0,1.0]}}],\n\
         \"scenes\":[{{\"nodes\":[0]}}],\"scene\":0,\n{}",
        materials()
    ))
}

/// A one-primitive document: `attrs` (attribute JSON, from the accessors made in `g`),
/// optional `indices`, `mode`.
fn one(g: &Gl, attrs: &str, indices: Option<usize>, mode: u32, material: usize) -> String {
    let ix = indices.map_or(String::new(), |i| format!(",\"indices\":{i}"));
    g.finish(&format!(
        "\"meshes\":[{{\"name\":\"part\",\"primitives\":[{{\"attributes\":{{{attrs}}}{ix},\
         \"mode\":{mode},\"material\":{material}}}]}}],\n\
         \"nodes\":[{{\"name\":\"body\",\"mesh\":0}}],\"scenes\":[{{\"nodes\":[0]}}],\n{}",
        materials()
    ))
}

/// Writes `doc` to a file of its own and loads it as `bake-gltf` does.
fn load_doc(doc: &[u8]) -> Result<Imported, String> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static N: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!("fixel-bake-gltf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(format!("{}.gltf", N.fetch_add(1, Ordering::Relaxed)));
    std::fs::write(&p, doc).unwrap();
    load(&p).map_err(|e| e.replace(&format!("{}: ", p.display()), ""))
}

fn opts() -> GltfOpts {
    GltfOpts {
        name: "TILES".into(),
        scale: 1.0,
        center: false,
        texture_size: None,
        levels: None,
        max_texture_kib: 256,
        krate: "fixel".into(),
        rgb565: DEFAULT_RGB565.into(),
        order_by_height: false,
    }
}

fn fixture_dir() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../host-tests/tests/baked")
}

const TRI: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];

#[test]
fn fixture_imports_with_transforms_colours_and_texture() {
    let m = load_doc(fixture().as_bytes()).unwrap();
    assert_eq!(m.primitives, 2);
    assert_eq!(m.mesh.indices.len(), 3);
    // Quad: 4 welded vertices; roof: 3 (flat normal).
    assert_eq!(m.mesh.positions.len(), 7);
    // The roof's apex (0, 2, 0): mirrored in x, turned about y, moved by (0, 0.5, 0.25).
    // (The mirror swapped the roof's last two corners: the apex is its second vertex.)
    let apex = m.mesh.positions[5];
    for (a, b) in apex.iter().zip([0.0, 2.5, 0.25]) {
        assert!((a - b).abs() < 1e-6, "{apex:?}");
    }
    // The roof's corner (-1, 1, 0): x -> -x, then a quarter turn about y takes x to -z.
    let c0 = m.mesh.positions[4];
    assert!((c0[2] - (-1.0 + 0.25)).abs() < 1e-6, "{c0:?}");
    // Every triangle still faces its normal (the mirror flipped the winding back).
    for t in &m.mesh.indices {
        let p = t.map(|i| m.mesh.positions[i as usize]);
        let f = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        let n = m.mesh.normals[t[0] as usize];
        assert!(f[0] * n[0] + f[1] * n[1] + f[2] * n[2] > 0.0, "{t:?}");
    }
    let c = m.colors.as_ref().unwrap();
    assert_eq!(c[1], [1.0, 0.5, 0.5]);
    assert_eq!(c[5], [1.0, 0.5, 0.25]); // the roof's base-colour factor
    let b = bake(m, &opts()).unwrap();
    let t = b.texture.unwrap();
    assert_eq!((t.width, t.height, t.levels), (8, 4, 4));
    assert_eq!(t.source_size, (6, 3));
    assert_eq!(t.texels.len(), 32 + 8 + 2 + 1);
}

/// With `FIXEL_BLESS=1`, rewrites both files instead.
#[test]
fn committed_fixture_and_its_bake_are_current() {
    let dir = fixture_dir();
    let bless = std::env::var_os("FIXEL_BLESS").is_some();
    if bless {
        std::fs::write(dir.join("tiles.gltf"), fixture()).unwrap();
    }
    let got = std::fs::read_to_string(dir.join("tiles.gltf")).unwrap_or_default();
    assert!(
        got == fixture(),
        "host-tests/tests/baked/tiles.gltf is stale: rerun this test with FIXEL_BLESS=1"
    );
    let args = GltfArgs {
        input: "host-tests/tests/baked/tiles.gltf".into(),
        output: "host-tests/tests/baked/tiles.rs".into(),
        name: Some("TILES".into()),
        scale: 1.0,
        center: false,
        texture_size: None,
        levels: Levels::Full,
        max_texture_kib: 256,
        krate: "fixel".into(),
        packed: false,
        order_by_height: false,
    };
    let b = bake(load(&dir.join("tiles.gltf")).unwrap(), &args.opts()).unwrap();
    let want = source(
        &b.mesh,
        b.colors.as_deref(),
        b.texture.as_ref(),
        &args.command_line(),
        &args.opts(),
    );
    if bless {
        std::fs::write(dir.join("tiles.rs"), &want).unwrap();
    }
    let got = std::fs::read_to_string(dir.join("tiles.rs")).unwrap_or_default();
    assert!(
        got == want,
        "host-tests/tests/baked/tiles.rs is stale: run `cargo xtask bake-gltf {}`",
        args.command_line()
    );
    // The same bake, packed (host-tests checks that it decodes to the same arrays).
    let args = GltfArgs {
        output: "host-tests/tests/baked/tiles_packed.rs".into(),
        name: Some("TILES_PACKED".into()),
        packed: true,
        ..args
    };
    let (bin, src) = packed(
        &b.mesh,
        b.colors.as_deref(),
        b.texture.as_ref(),
        &args.command_line(),
        "tiles_packed.bin",
        &args.opts(),
    );
    if bless {
        std::fs::write(dir.join("tiles_packed.rs"), &src).unwrap();
        std::fs::write(dir.join("tiles_packed.bin"), &bin).unwrap();
    }
    let got = std::fs::read_to_string(dir.join("tiles_packed.rs")).unwrap_or_default();
    let got_bin = std::fs::read(dir.join("tiles_packed.bin")).unwrap_or_default();
    assert!(
        got == src && got_bin == bin,
        "host-tests/tests/baked/tiles_packed.{{rs,bin}} are stale: run `cargo xtask bake-gltf {}`",
        args.command_line()
    );
}

#[test]
fn missing_position_is_refused() {
    let mut g = Gl::default();
    let n = g.vecs(&[[0.0, 0.0, 1.0f32]; 3]);
    let e = load_doc(one(&g, &format!("\"NORMAL\":{n}"), None, 4, 1).as_bytes()).unwrap_err();
    // The gltf crate's validation refuses it first, naming the attribute.
    assert!(
        e.contains("meshes[0].primitives[0].attributes[\"POSITION\"]: Missing data"),
        "{e}"
    );
}

#[test]
fn missing_texcoords_on_a_textured_primitive_are_refused() {
    let mut g = Gl::default();
    let p = g.vecs(&TRI);
    let e = load_doc(one(&g, &format!("\"POSITION\":{p}"), None, 4, 0).as_bytes()).unwrap_err();
    assert!(e.contains("no TEXCOORD_0"), "{e}");
    assert!(e.contains("mesh 'part' (0), primitive 0"), "{e}");
}

#[test]
fn indices_out_of_range_are_refused() {
    let mut g = Gl::default();
    let p = g.vecs(&TRI);
    let i = g.indices(&[0, 1, 2, 2, 1, 7]);
    let e = load_doc(one(&g, &format!("\"POSITION\":{p}"), Some(i), 4, 1).as_bytes()).unwrap_err();
    assert!(
        e.contains("index 7 (entry 5 of the indices) is out of range"),
        "{e}"
    );
    assert!(e.contains("3 vertices"), "{e}");
    assert!(e.contains("primitive 0"), "{e}");
}

#[test]
fn non_triangle_primitives_are_refused() {
    for (mode, name) in [
        (0, "Points"),
        (1, "Lines"),
        (3, "LineStrip"),
        (5, "TriangleStrip"),
    ] {
        let mut g = Gl::default();
        let p = g.vecs(&TRI);
        let e =
            load_doc(one(&g, &format!("\"POSITION\":{p}"), None, mode, 1).as_bytes()).unwrap_err();
        assert!(e.contains(&format!("mode {name}")), "{e}");
        assert!(e.contains("only triangle lists"), "{e}");
    }
}

#[test]
fn textures_too_big_are_refused_with_the_size_that_fits() {
    let m = load_doc(fixture().as_bytes()).unwrap();
    let o = GltfOpts {
        texture_size: Some(64),
        max_texture_kib: 1,
        ..opts()
    };
    let e = bake(m.clone(), &o).err().unwrap();
    assert!(e.contains("image 0 (6 x 3)"), "{e}");
    assert!(e.contains("64 x 32 with 7 levels"), "{e}");
    assert!(e.contains("--texture-size 16 fits"), "{e}");
    // The size it names fits.
    let o = GltfOpts {
        texture_size: Some(16),
        ..o
    };
    let t = bake(m.clone(), &o).unwrap().texture.unwrap();
    assert_eq!((t.width, t.height), (16, 8));
    // Sides beyond fixel's 4096.
    let e = bake_texture(0, 9000, 10, &vec![[0; 3]; 90_000], &opts()).unwrap_err();
    assert!(e.contains("sides up to 4096"), "{e}");
}

#[test]
fn an_empty_scene_is_refused() {
    let g = Gl::default();
    let doc = g.finish("\"nodes\":[{\"name\":\"empty\"}],\"scenes\":[{\"nodes\":[0]}]");
    let e = load_doc(doc.as_bytes()).unwrap_err();
    assert!(e.contains("no mesh primitive"), "{e}");
}

#[test]
fn sizes_round_to_the_nearest_power_of_two_and_resampling_keeps_the_mean() {
    assert_eq!(texture::baked_size(1024, 1024, None), (1024, 1024));
    assert_eq!(texture::baked_size(6, 3, None), (8, 4));
    assert_eq!(texture::baked_size(5, 11, None), (4, 8));
    assert_eq!(texture::baked_size(1000, 600, Some(128)), (128, 64));
    let px: Vec<[u8; 3]> = (0..6 * 3).map(|i| [(i * 10) as u8, 7, 200]).collect();
    let r = texture::resample(&px, 6, 3, 2, 1);
    // Left half: columns 0..3 of every row; right half: 3..6.
    let mean = |x0: u32| {
        let s: u32 = (0..3)
            .flat_map(|y| (x0..x0 + 3).map(move |x| (y * 6 + x) * 10))
            .sum();
        (f64::from(s) / 9.0).round() as u8
    };
    assert_eq!(r, vec![[mean(0), 7, 200], [mean(3), 7, 200]]);
}

/// The committed sample-model bakes (`assets/gltf/`) are what `bake-gltf` makes today.
#[test]
fn committed_sample_models_are_current() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let bless = std::env::var_os("FIXEL_BLESS").is_some();
    for (glb, out, name, scale, levels, order_by_height) in [
        ("Fox.glb", "fox.rs", "FOX", 0.02, Levels::Full, false),
        (
            "CesiumMan.glb",
            "cesium_man.rs",
            "CESIUM_MAN",
            2.0,
            Levels::Count(1),
            true,
        ),
    ] {
        let args = GltfArgs {
            input: format!("assets/gltf/{glb}"),
            output: format!("assets/gltf/{out}"),
            name: Some(name.into()),
            scale,
            center: true,
            texture_size: Some(128),
            levels,
            max_texture_kib: 256,
            krate: "fixel".into(),
            packed: true,
            order_by_height,
        };
        let b = bake(load(&root.join(&args.input)).unwrap(), &args.opts()).unwrap();
        let bin_name = out.replace(".rs", ".bin");
        let (bin, src) = packed(
            &b.mesh,
            b.colors.as_deref(),
            b.texture.as_ref(),
            &args.command_line(),
            &bin_name,
            &args.opts(),
        );
        let dir = root.join("assets/gltf");
        if bless {
            std::fs::write(dir.join(out), &src).unwrap();
            std::fs::write(dir.join(&bin_name), &bin).unwrap();
        }
        let got = std::fs::read_to_string(dir.join(out)).unwrap_or_default();
        let got_bin = std::fs::read(dir.join(&bin_name)).unwrap_or_default();
        assert!(
            got == src && got_bin == bin,
            "assets/gltf/{out} is stale: run `cargo xtask bake-gltf {}`",
            args.command_line()
        );
    }
}
