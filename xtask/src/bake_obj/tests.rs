//! Tests of the OBJ baker: loading, generated normals and coordinates, errors, and the
//! committed teapot.

use super::*;

fn opts() -> ObjOpts {
    ObjOpts {
        name: "T".into(),
        uv: UvSource::Keep,
        axis: Axis::Y,
        smooth_normals: false,
        tangents: true,
        scale: 1.0,
        krate: "fixel".into(),
    }
}

fn obj(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("fixel-bake-obj-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// A file with only positions gets unit normals and generated coordinates.
#[test]
fn missing_normals_and_uvs_are_generated() {
    let p = obj(
        "bare.obj",
        "v 0 0 1\nv 1 0 0\nv 0 1 0\nv 0 0 -1\nf 1 2 3\nf 2 4 3\n",
    );
    let m = load(&p, 1.0).unwrap();
    let b = bake(&m, &opts()).unwrap();
    assert_eq!(b.indices.len(), 2);
    assert_eq!(b.uvs.len(), b.positions.len());
    for n in &b.normals {
        let l = n.x.to_num::<f64>().hypot(n.y.to_num()).hypot(n.z.to_num());
        assert!((l - 1.0).abs() < 1e-3, "{n:?}");
    }
    assert_eq!(b.tangents.as_ref().map(Vec::len), Some(b.positions.len()));
    assert!(source(&b, "bare.obj", &opts()).contains("pub static T_INDICES: [[u16; 3]; 2]"));
}

/// Negative indices count back from the last vertex; a quad and a pentagon become 2 and
/// 3 triangles; comments, groups and unknown statements are skipped.
#[test]
fn relative_indices_and_polygons() {
    let text = "# a comment\no quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\ng side\ns 1\nusemtl none\nf -4 -3 -2 -1\n\
                v 2 0 0\nv 3 0 0\nv 3 1 0\nv 2.5 2 0\nv 2 1 0\nf 5 6 7 8 9\n";
    let m = load(&obj("poly.obj", text), 1.0).unwrap();
    assert_eq!(m.indices.len(), 5);
    assert_eq!(m.positions.len(), 9);
}

/// Texture coordinates are kept with `v` flipped to GL's `t` (OBJ's v = 0 is the bottom).
#[test]
fn file_uvs_are_flipped_to_gl_t() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
    let b = bake(&load(&obj("uv.obj", text), 1.0).unwrap(), &opts()).unwrap();
    assert_eq!(b.uvs[0], [Fx::ZERO, Fx::ONE]);
    assert_eq!(b.uvs[2], [Fx::ZERO, Fx::ZERO]);
}

/// A face that names a vertex that does not exist, and a malformed vertex, are errors
/// that name the file.
#[test]
fn bad_files_are_refused_with_the_file_name() {
    let e = load(&obj("range.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n"), 1.0).unwrap_err();
    assert!(e.contains("range.obj"), "{e}");
    let e = load(
        &obj("garbage.obj", "v 0 zero 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
        1.0,
    )
    .unwrap_err();
    assert!(e.contains("garbage.obj"), "{e}");
    let e = load(&obj("empty.obj", "# nothing\n"), 1.0).unwrap_err();
    assert!(e.contains("no vertices"), "{e}");
}

/// Degenerate triangles are dropped and counted; a coordinate outside I16F16 is named.
#[test]
fn degenerate_and_out_of_range() {
    let m = load(
        &obj("deg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 2\n"),
        1.0,
    )
    .unwrap();
    assert_eq!((m.indices.len(), m.dropped), (1, 1));
    let m = load(
        &obj("big.obj", "v 0 0 0\nv 40000 0 0\nv 0 1 0\nf 1 2 3\n"),
        1.0,
    )
    .unwrap();
    let e = bake(&m, &opts()).unwrap_err();
    assert!(e.contains("vertex 1") && e.contains("I16F16"), "{e}");
}

/// More vertices than a u16 index reaches: refused with the count.
#[test]
fn too_many_vertices_says_how_many() {
    let mut text = String::new();
    for k in 0..70_000 {
        text.push_str(&format!("v {} {} 0\n", k % 300, k / 300));
    }
    // Only vertices that faces use count.
    for k in 0..70_000 / 3 {
        text.push_str(&format!("f {} {} {}\n", 3 * k + 1, 3 * k + 2, 3 * k + 3));
    }
    let m = load(&obj("huge.obj", &text), 1.0).unwrap();
    let e = bake(&m, &opts()).unwrap_err();
    assert!(e.contains("69999 vertices"), "{e}");
}

/// The committed teapot OBJ is what `cargo xtask teapot` makes from the patch data.
#[test]
fn committed_teapot_is_reproducible() {
    let root = crate::cmd::root();
    let text = std::fs::read_to_string(root.join("assets/teapot/newell.txt")).unwrap();
    let (patches, points) = crate::teapot::parse(&text).unwrap();
    assert_eq!((patches.len(), points.len()), (32, 306));
    let (tris, pos) = crate::teapot::tessellate(&patches, &points, 5);
    let committed = std::fs::read_to_string(root.join("assets/teapot/teapot.obj")).unwrap();
    assert_eq!(crate::teapot::obj(&tris, &pos, 5), committed);
}

/// The committed teapot mesh is what the command in its header writes (the header names
/// every option that differs from its default).
#[test]
fn committed_teapot_mesh_is_what_its_header_says() {
    use clap::Parser;
    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        args: ObjArgs,
    }
    let root = crate::cmd::root();
    let committed = std::fs::read_to_string(root.join("assets/teapot/teapot_mesh.rs")).unwrap();
    let line = committed.lines().next().unwrap();
    let cmd = line
        .strip_prefix("// Generated by `cargo xtask bake-obj ")
        .and_then(|l| l.strip_suffix("`. Do not edit."))
        .unwrap_or_else(|| panic!("header: {line}"));
    let mut args = Cli::try_parse_from(std::iter::once("bake-obj").chain(cmd.split(' ')))
        .unwrap()
        .args;
    assert_eq!(args.command_line(), cmd);
    // Paths are relative to the workspace root, where `cargo xtask` runs.
    args.input = root.join(&args.input).display().to_string();
    let o = args.opts();
    let b = bake(&load(Path::new(&args.input), o.scale).unwrap(), &o).unwrap();
    let body = |s: &str| s.lines().skip(1).collect::<Vec<_>>().join("\n");
    assert_eq!(body(&source(&b, cmd, &o)), body(&committed));
}
