//! `cargo xtask bake-gltf`: a glTF 2.0 model (`.glb`, or `.gltf` with its buffers and
//! images) to a Rust source file of `static` arrays in fixel's formats, the mesh as
//! `bake-obj` writes it and the base-colour texture as `bake` writes it.
//!
//! Input handling (through the `gltf` crate, pinned):
//! * the default scene (or the first) is walked from its root nodes; every node with a mesh
//!   adds each of its primitives, positions and normals carried by the node's world
//!   transform (normals by its inverse transpose; a mirroring transform flips the
//!   triangles' winding so they stay counter-clockwise from the front);
//! * skins and animations are not applied: a skinned mesh is baked in its bind pose (the
//!   static pose its vertices are stored in);
//! * a primitive must be made of triangles (mode 4), have `POSITION`, `TEXCOORD_0` when its
//!   material has a base-colour texture, and indices below its vertex count; otherwise the
//!   bake is refused with a message naming the node, mesh and primitive;
//! * no `NORMAL`: flat normals, as glTF asks; non-indexed primitives are indexed in order;
//! * vertices are welded (identical position, normal, uv and colour) and triangles with a
//!   repeated vertex dropped (counted in the summary);
//! * materials: the base-colour texture (one image per model) and the base-colour factor;
//!   `COLOR_0` times the factor becomes `NAME_COLORS` (RGB565), written only when some
//!   primitive has vertex colours or a factor other than white;
//! * texture coordinates keep glTF's convention, which is fixel's (`t = 0` at the image's
//!   first row);
//! * the texture: each side rounded to the nearest power of two (or `--texture-size` for the
//!   longer side), resampled by area averaging, rounded to RGB565 with `bake`'s rule, and
//!   its mip chain built with fixel's 2 x 2 box filter. A chain larger than
//!   `--max-texture-kib` is refused with the size that fits;
//! * with `--order-by-height`, the triangles from the model's top down and the vertices in
//!   first use ([`order`]): cheaper in bands for a model of many small triangles.

mod order;
mod packed;
mod texture;

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::Path;

use clap::Args;
use fixel::scene::Axis;

use crate::bake::{full_levels, BakeError, BakeOpts, Levels, DEFAULT_RGB565};
use crate::bake_obj::{self, F64Mesh, ObjOpts, UvSource};

pub use packed::packed;
pub use texture::{bake_texture, BakedTexture};

/// Options of one bake.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfOpts {
    /// Prefix of the generated items, upper case.
    pub name: String,
    /// Scale applied to the positions (after the node transforms).
    pub scale: f64,
    /// Move the bounding box's centre to the origin (before scaling).
    pub center: bool,
    /// Side of the texture's longer edge, a power of two (`None`: each side of the image
    /// rounded to the nearest power of two).
    pub texture_size: Option<u32>,
    /// Mip levels of the texture (`None`: the full chain).
    pub levels: Option<u32>,
    /// Largest texture chain accepted, in KiB of flash.
    pub max_texture_kib: u32,
    /// Path of the fixel crate in the generated code.
    pub krate: String,
    /// Path of the RGB565 type in the generated code.
    pub rgb565: String,
    /// Triangles from the top down, vertices in first use ([`order::order_by_height`]).
    pub order_by_height: bool,
}

/// A model read from a glTF file, in f64, before conversion.
#[derive(Clone, Debug, Default)]
pub struct Imported {
    /// Positions, normals, uvs and triangles of every primitive, welded.
    pub mesh: F64Mesh,
    /// Linear 0..=1 RGB per vertex (`COLOR_0` times the base-colour factor), when the model
    /// has any.
    pub colors: Option<Vec<[f64; 3]>>,
    /// The base-colour image as RGB8 (`width`, `height`, pixels row by row), with its index.
    pub image: Option<(usize, u32, u32, Vec<[u8; 3]>)>,
    /// Primitives baked.
    pub primitives: usize,
}

/// Reads a `.glb` or `.gltf` file (and the buffers and images it refers to).
pub fn load(path: &Path) -> Result<Imported, String> {
    let (doc, buffers, images) =
        gltf::import(path).map_err(|e| format!("{}: {e}", path.display()))?;
    import(&doc, &buffers, &images)
}

type Mat = [[f64; 4]; 4];

/// `a * b` for column-major matrices (`m[column][row]`).
fn mul(a: &Mat, b: &Mat) -> Mat {
    let mut r = [[0.0; 4]; 4];
    for (c, col) in r.iter_mut().enumerate() {
        for (row, v) in col.iter_mut().enumerate() {
            *v = (0..4).map(|k| a[k][row] * b[c][k]).sum();
        }
    }
    r
}

/// The cofactor matrix of the upper-left 3 x 3 (the inverse transpose times the
/// determinant: it carries normals) and the determinant.
fn normal_matrix(m: &Mat) -> ([[f64; 3]; 3], f64) {
    let a = |r: usize, c: usize| m[c][r];
    let mut cof = [[0.0; 3]; 3];
    for (r, row) in cof.iter_mut().enumerate() {
        for (c, v) in row.iter_mut().enumerate() {
            let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
            let (c1, c2) = ((c + 1) % 3, (c + 2) % 3);
            *v = a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1);
        }
    }
    let det = (0..3).map(|c| a(0, c) * cof[0][c]).sum();
    (cof, det)
}

/// Where a primitive is, for messages: `node 'n' (3), mesh 'm' (0), primitive 1`.
fn place(node: &gltf::Node, mesh: &gltf::Mesh, p: usize) -> String {
    let name = |n: Option<&str>| n.map_or(String::new(), |n| format!("'{n}' "));
    format!(
        "node {}({}), mesh {}({}), primitive {p}",
        name(node.name()),
        node.index(),
        name(mesh.name()),
        mesh.index()
    )
}

/// Walks the default scene and gathers every primitive into one welded mesh.
pub fn import(
    doc: &gltf::Document,
    buffers: &[gltf::buffer::Data],
    images: &[gltf::image::Data],
) -> Result<Imported, String> {
    let scene = doc
        .default_scene()
        .or_else(|| doc.scenes().next())
        .ok_or("the file has no scene")?;
    let mut w = Welder::default();
    let mut image: Option<usize> = None;
    let mut primitives = 0;
    let identity: Mat = [
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ];
    let mut stack: Vec<(gltf::Node, Mat)> = scene.nodes().map(|n| (n, identity)).collect();
    stack.reverse();
    while let Some((node, parent)) = stack.pop() {
        let local = node.transform().matrix().map(|c| c.map(f64::from));
        let world = mul(&parent, &local);
        let mut children: Vec<_> = node.children().map(|c| (c, world)).collect();
        children.reverse();
        stack.extend(children);
        let Some(mesh) = node.mesh() else { continue };
        for (pi, prim) in mesh.primitives().enumerate() {
            let at = place(&node, &mesh, pi);
            let base = prim.material().pbr_metallic_roughness();
            if let Some(t) = base.base_color_texture() {
                let src = t.texture().source().index();
                match image {
                    None => image = Some(src),
                    Some(i) if i != src => {
                        return Err(format!(
                            "{at}: its base-colour texture is image {src}, another primitive's \
                             image {i}; one base-colour image per model"
                        ))
                    }
                    Some(_) => {}
                }
                if t.tex_coord() != 0 {
                    return Err(format!(
                        "{at}: the base-colour texture reads TEXCOORD_{}; only TEXCOORD_0 is baked",
                        t.tex_coord()
                    ));
                }
            }
            w.primitive(&prim, buffers, &world, base.base_color_factor(), &at)?;
            primitives += 1;
        }
    }
    if primitives == 0 {
        return Err("the scene has no mesh primitive".into());
    }
    let image = match image {
        None => None,
        Some(i) => {
            let d = images
                .get(i)
                .ok_or_else(|| format!("image {i}: not loaded"))?;
            let px = texture::rgb8(d).map_err(|e| format!("image {i}: {e}"))?;
            Some((i, d.width, d.height, px))
        }
    };
    Ok(Imported {
        colors: w.any_color.then(|| w.colors.clone()),
        mesh: w.mesh,
        image,
        primitives,
    })
}

/// Gathers primitives, welding identical vertices.
#[derive(Default)]
struct Welder {
    mesh: F64Mesh,
    colors: Vec<[f64; 3]>,
    any_color: bool,
    seen: HashMap<[u64; 11], u32>,
}

impl Welder {
    fn vertex(&mut self, p: [f64; 3], n: [f64; 3], uv: [f64; 2], c: [f64; 3]) -> u32 {
        let mut key = [0u64; 11];
        for (k, v) in p.iter().chain(&n).chain(&uv).chain(&c).enumerate() {
            // +0.0 and -0.0 weld.
            key[k] = (v + 0.0).to_bits();
        }
        let next = self.mesh.positions.len() as u32;
        *self.seen.entry(key).or_insert_with(|| {
            self.mesh.positions.push(p);
            self.mesh.normals.push(n);
            self.mesh.uvs.push(uv);
            self.colors.push(c);
            next
        })
    }

    fn primitive(
        &mut self,
        prim: &gltf::Primitive,
        buffers: &[gltf::buffer::Data],
        world: &Mat,
        factor: [f32; 4],
        at: &str,
    ) -> Result<(), String> {
        use gltf::mesh::Mode;
        if prim.mode() != Mode::Triangles {
            return Err(format!(
                "{at}: mode {:?}; only triangle lists (mode 4) are baked",
                prim.mode()
            ));
        }
        let textured = prim
            .material()
            .pbr_metallic_roughness()
            .base_color_texture()
            .is_some();
        let r = prim.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
        let pos: Vec<[f64; 3]> = r
            .read_positions()
            .ok_or_else(|| format!("{at}: no POSITION attribute"))?
            .map(|p| p.map(f64::from))
            .collect();
        let n = pos.len();
        let normals: Option<Vec<[f64; 3]>> = r
            .read_normals()
            .map(|i| i.map(|v| v.map(f64::from)).collect());
        let uvs: Option<Vec<[f64; 2]>> = r
            .read_tex_coords(0)
            .map(|i| i.into_f32().map(|v| v.map(f64::from)).collect());
        let colors: Option<Vec<[f64; 3]>> = r
            .read_colors(0)
            .map(|i| i.into_rgb_f32().map(|v| v.map(f64::from)).collect());
        if textured && uvs.is_none() {
            return Err(format!(
                "{at}: its material has a base-colour texture but the primitive has no \
                 TEXCOORD_0 attribute"
            ));
        }
        for (what, len) in [
            ("NORMAL", normals.as_ref().map(Vec::len)),
            ("TEXCOORD_0", uvs.as_ref().map(Vec::len)),
            ("COLOR_0", colors.as_ref().map(Vec::len)),
        ] {
            if let Some(l) = len.filter(|&l| l != n) {
                return Err(format!("{at}: {what} has {l} entries, POSITION {n}"));
            }
        }
        let indices: Vec<u32> = match r.read_indices() {
            Some(i) => i.into_u32().collect(),
            None => (0..n as u32).collect(),
        };
        if !indices.len().is_multiple_of(3) {
            return Err(format!(
                "{at}: {} indices, not a multiple of 3",
                indices.len()
            ));
        }
        if let Some((k, i)) = indices.iter().enumerate().find(|(_, &i)| i as usize >= n) {
            return Err(format!(
                "{at}: index {i} (entry {k} of the indices) is out of range: the primitive has \
                 {n} vertices"
            ));
        }
        let factor = [factor[0], factor[1], factor[2]].map(f64::from);
        if colors.is_some() || factor != [1.0; 3] {
            self.any_color = true;
        }
        let (cof, det) = normal_matrix(world);
        let xform = |p: [f64; 3]| -> [f64; 3] {
            core::array::from_fn(|r| (0..3).map(|c| world[c][r] * p[c]).sum::<f64>() + world[3][r])
        };
        let xnormal = |v: [f64; 3]| -> [f64; 3] {
            let t: [f64; 3] = core::array::from_fn(|r| (0..3).map(|c| cof[r][c] * v[c]).sum());
            unit(t.map(|x| x * det.signum()))
        };
        let wp: Vec<[f64; 3]> = pos.iter().map(|&p| xform(p)).collect();
        for tri in indices.chunks_exact(3) {
            let mut t = [tri[0], tri[1], tri[2]].map(|i| i as usize);
            if det < 0.0 {
                t.swap(1, 2);
            }
            let flat = unit(cross(sub(wp[t[1]], wp[t[0]]), sub(wp[t[2]], wp[t[0]])));
            let ids = t.map(|i| {
                let nrm = normals.as_ref().map_or(flat, |v| xnormal(v[i]));
                let uv = uvs.as_ref().map_or([0.0; 2], |v| v[i]);
                let c = colors.as_ref().map_or([1.0; 3], |v| v[i]);
                let c: [f64; 3] = core::array::from_fn(|k| c[k] * factor[k]);
                self.vertex(wp[i], nrm, uv, c)
            });
            if ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2] {
                self.mesh.dropped += 1;
            } else {
                self.mesh.indices.push(ids);
            }
        }
        Ok(())
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `v` normalised, `+y` when it has no length (a degenerate triangle's normal).
fn unit(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if l > 1e-12 {
        v.map(|c| c / l)
    } else {
        [0.0, 1.0, 0.0]
    }
}

/// Centres (when asked) and scales the positions in place.
pub fn place_mesh(m: &mut F64Mesh, o: &GltfOpts) {
    let (mut lo, mut hi) = ([f64::MAX; 3], [f64::MIN; 3]);
    for p in &m.positions {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let c: [f64; 3] = if o.center {
        core::array::from_fn(|k| 0.5 * (lo[k] + hi[k]))
    } else {
        [0.0; 3]
    };
    for p in &mut m.positions {
        *p = core::array::from_fn(|k| (p[k] - c[k]) * o.scale);
    }
}

/// The generated Rust source: the mesh (`bake-obj`'s writer), the vertex colours when
/// there are some, the texture (`bake`'s writer).
pub fn source(
    b: &bake_obj::Baked,
    colors: Option<&[[u8; 3]]>,
    tex: Option<&BakedTexture>,
    cmdline: &str,
    o: &GltfOpts,
) -> String {
    let mut s = bake_obj::source_as("bake-gltf", b, cmdline, &obj_opts(o));
    let n = &o.name;
    if let Some(c) = colors {
        let _ = writeln!(
            s,
            "/// Vertex colours (`COLOR_0` times the base-colour factor), RGB565 rounded to nearest."
        );
        let _ = writeln!(s, "pub static {n}_COLORS: [{}; {}] = [", o.rgb565, c.len());
        for c in c {
            let _ = writeln!(s, "    {}::new({}, {}, {}),", o.rgb565, c[0], c[1], c[2]);
        }
        s.push_str("];\n");
    }
    if let Some(t) = tex {
        let _ = writeln!(
            s,
            "// Base-colour texture: image {} ({} x {}) resampled to {} x {} by area averaging,\n\
             // {} mip levels made with a 2 x 2 box filter. View it with\n\
             // `{k}::texture::MipTexture::new(&{n}_TEXELS, {n}_WIDTH, {n}_HEIGHT, {n}_LEVELS)`.",
            t.image,
            t.source_size.0,
            t.source_size.1,
            t.width,
            t.height,
            t.levels,
            k = o.krate
        );
        let bo = BakeOpts {
            name: o.name.clone(),
            levels: Some(t.levels),
            rgb565: o.rgb565.clone(),
        };
        s.push_str(&crate::bake::texel_items(
            &t.texels,
            t.width,
            t.height,
            t.levels,
            &format!("image {}", t.image),
            &bo,
        ));
    }
    s
}

/// The mesh options `bake-obj`'s converter takes: the file's normals and coordinates.
fn obj_opts(o: &GltfOpts) -> ObjOpts {
    ObjOpts {
        name: o.name.clone(),
        uv: UvSource::Keep,
        axis: Axis::Y,
        smooth_normals: false,
        tangents: false,
        scale: 1.0,
        krate: o.krate.clone(),
    }
}

/// Linear 0..=1 colours to RGB565 channels, rounded to nearest.
pub fn colors_565(c: &[[f64; 3]]) -> Vec<[u8; 3]> {
    c.iter()
        .map(|c| {
            let q = |v: f64, max: f64| (v.clamp(0.0, 1.0) * max).round() as u8;
            [q(c[0], 31.0), q(c[1], 63.0), q(c[2], 31.0)]
        })
        .collect()
}

/// Everything a bake produces.
pub struct Bake {
    /// The converted mesh.
    pub mesh: bake_obj::Baked,
    /// Vertex colours, RGB565 channels.
    pub colors: Option<Vec<[u8; 3]>>,
    /// The texture with its chain.
    pub texture: Option<BakedTexture>,
    /// Primitives read.
    pub primitives: usize,
}

/// Converts an imported model with the options `o`.
pub fn bake(mut m: Imported, o: &GltfOpts) -> Result<Bake, String> {
    place_mesh(&mut m.mesh, o);
    if o.order_by_height {
        order::order_by_height(&mut m);
    }
    let mesh = bake_obj::bake(&m.mesh, &obj_opts(o))?;
    let texture = match &m.image {
        None => None,
        Some((i, w, h, px)) => Some(bake_texture(*i, *w, *h, px, o)?),
    };
    Ok(Bake {
        mesh,
        colors: m.colors.as_deref().map(colors_565),
        texture,
        primitives: m.primitives,
    })
}

/// Arguments of `cargo xtask bake-gltf`.
#[derive(Args, Clone, Debug)]
pub struct GltfArgs {
    /// The glTF 2.0 model (.glb, or .gltf with its buffers and images)
    #[arg(value_name = "MODEL.glb|.gltf")]
    pub input: String,
    /// The Rust source file to write (its folder is created)
    #[arg(value_name = "output.rs")]
    pub output: String,
    /// Prefix of the generated items, letters, digits and `_` [default: the input's file stem in upper case]
    #[arg(long, value_name = "NAME", value_parser = crate::bake::parse_name)]
    pub name: Option<String>,
    /// Scale applied to the positions, after the node transforms (coordinates must then fit I16F16)
    #[arg(long, value_name = "S", default_value = "1", value_parser = parse_scale)]
    pub scale: f64,
    /// Move the model's bounding-box centre to the origin before scaling
    #[arg(long)]
    pub center: bool,
    /// Longer side of the baked texture, a power of two up to 4096 [default: each side of the image rounded to the nearest power of two]
    #[arg(long, value_name = "N", value_parser = parse_size)]
    pub texture_size: Option<u32>,
    /// Mip levels of the texture, a number or `full` (down to 1x1)
    #[arg(long, value_name = "N|full", default_value = "full", value_parser = crate::bake::parse_levels)]
    pub levels: Levels,
    /// Largest texture (with its mip chain) accepted, in KiB of flash
    #[arg(long, value_name = "KIB", default_value_t = 256)]
    pub max_texture_kib: u32,
    /// Path of the fixel crate in the generated code
    #[arg(long = "crate", value_name = "PATH", default_value = "fixel")]
    pub krate: String,
    /// Write the arrays' data to a binary file beside the output (output.bin), read by
    /// `include_bytes!` and decoded at compile time: about 30 times smaller than text
    #[arg(long)]
    pub packed: bool,
    /// Order the triangles from the model's top down (by their highest corner, y after
    /// placement) and number the vertices in the order they are first used: a band
    /// renderer's passes then meet neighbouring triangles and its vertex cache keeps their
    /// corners. Pays for upright models of many small triangles sharing vertices
    /// (CesiumMan); measure with `cargo xtask mcu`
    #[arg(long)]
    pub order_by_height: bool,
}

fn parse_scale(v: &str) -> Result<f64, String> {
    v.parse()
        .ok()
        .filter(|s: &f64| s.is_finite() && *s > 0.0)
        .ok_or_else(|| "needs a positive number".to_string())
}

fn parse_size(v: &str) -> Result<u32, String> {
    v.parse()
        .ok()
        .filter(|s: &u32| s.is_power_of_two() && *s <= 4096)
        .ok_or_else(|| "needs a power of two from 1 to 4096".to_string())
}

impl GltfArgs {
    /// The bake's options (the default name from the input's file stem).
    pub fn opts(&self) -> GltfOpts {
        GltfOpts {
            name: self
                .name
                .clone()
                .unwrap_or_else(|| crate::bake::default_name(Path::new(&self.input))),
            scale: self.scale,
            center: self.center,
            texture_size: self.texture_size,
            levels: match self.levels {
                Levels::Full => None,
                Levels::Count(l) => Some(l),
            },
            max_texture_kib: self.max_texture_kib,
            krate: self.krate.clone(),
            rgb565: DEFAULT_RGB565.into(),
            order_by_height: self.order_by_height,
        }
    }

    /// The arguments as a command line for the generated file's header (options not at
    /// their defaults, then the input and output).
    pub fn command_line(&self) -> String {
        let mut s = String::new();
        if let Some(n) = &self.name {
            let _ = write!(s, "--name {n} ");
        }
        if self.scale != 1.0 {
            let _ = write!(s, "--scale {} ", self.scale);
        }
        if self.center {
            s.push_str("--center ");
        }
        if let Some(t) = self.texture_size {
            let _ = write!(s, "--texture-size {t} ");
        }
        if let Levels::Count(l) = self.levels {
            let _ = write!(s, "--levels {l} ");
        }
        if self.max_texture_kib != 256 {
            let _ = write!(s, "--max-texture-kib {} ", self.max_texture_kib);
        }
        if self.krate != "fixel" {
            let _ = write!(s, "--crate {} ", self.krate);
        }
        if self.order_by_height {
            s.push_str("--order-by-height ");
        }
        if self.packed {
            s.push_str("--packed ");
        }
        let _ = write!(s, "{} {}", self.input, self.output);
        s
    }
}

/// Bakes `args.input` into `args.output`.
pub fn run(args: &GltfArgs) -> Result<(), BakeError> {
    let (input, output) = (&args.input, &args.output);
    let o = args.opts();
    let m = load(Path::new(input))?;
    let b = bake(m, &o).map_err(|e| format!("{input}: {e}"))?;
    let outp = Path::new(output);
    if let Some(dir) = outp.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    let src = if args.packed {
        let binp = outp.with_extension("bin");
        let bin_name = binp
            .file_name()
            .map(|f| f.to_string_lossy().into_owned())
            .unwrap_or_default();
        let (bin, src) = packed(
            &b.mesh,
            b.colors.as_deref(),
            b.texture.as_ref(),
            &args.command_line(),
            &bin_name,
            &o,
        );
        std::fs::write(&binp, bin).map_err(|e| format!("{}: {e}", binp.display()))?;
        src
    } else {
        source(
            &b.mesh,
            b.colors.as_deref(),
            b.texture.as_ref(),
            &args.command_line(),
            &o,
        )
    };
    std::fs::write(outp, src).map_err(|e| format!("{output}: {e}"))?;
    println!(
        "bake-gltf: {input} -> {output}: {} primitives, {} vertices, {} triangles ({} degenerate dropped)",
        b.primitives,
        b.mesh.positions.len(),
        b.mesh.indices.len(),
        b.mesh.dropped
    );
    let mut f = bake_obj::flash(&b.mesh);
    if let Some(c) = &b.colors {
        f.push(("colors", c.len() * 2));
    }
    if let Some(t) = &b.texture {
        println!(
            "  texture: image {} {} x {} -> {} x {}, {} levels (full chain {})",
            t.image,
            t.source_size.0,
            t.source_size.1,
            t.width,
            t.height,
            t.levels,
            full_levels(t.width, t.height)
        );
        f.push(("texture", t.texels.len() * 2));
    }
    let total: usize = f.iter().map(|x| x.1).sum();
    for (what, bytes) in &f {
        println!("  {what:<10} {bytes:>7} B");
    }
    println!("  {:<10} {total:>7} B of flash", "total");
    Ok(())
}

#[cfg(test)]
mod tests;
