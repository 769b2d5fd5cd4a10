//! The geometry of the benchmark scenes as `cargo xtask budget` counts it: for each banded
//! firmware scene (`examples/firmware/src/scenes.rs`, `model_scene.rs`, rendered here
//! through the very same code), the mesh's vertices and triangles, the screen triangles
//! binned (after culling and clipping), the band pieces (each binned triangle once per band
//! its rows cross), the pixels written and the bands.
//!
//! The budget's cost model is fitted to these counts and to the instructions `cargo xtask
//! mcu --docs` measured (`docs/mcu.md`); the counts are committed in
//! `xtask/budget/scenes.csv`, which this test compares with what the scenes draw now.
//! `FIXEL_BLESS=1 cargo test -p host-tests --test budget_counts` rewrites it after an
//! intended change (then check `cargo test -p xtask budget`).

#[path = "../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "../../examples/firmware/src/model_scene.rs"]
#[allow(dead_code)]
mod model_scene;

#[allow(dead_code)]
mod teapot {
    include!("../../assets/teapot/teapot_mesh.rs");
}

#[allow(dead_code)]
mod fox {
    include!("../../assets/gltf/fox.rs");
}

#[allow(dead_code)]
mod cesium_man {
    include!("../../assets/gltf/cesium_man.rs");
}

use std::fmt::Write as _;
use std::path::PathBuf;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::prelude::*;
use fixel::scene::Mesh;
use fixel::surface::BandRange;
use fixel::texture::MipTexture;
use fixel_scenes as demo;
use model_scene::{ModelBuffers, ModelTarget};
use scenes::{Buffers, FrameResult, SmallBuffers, Target};

/// One scene's counts (a row of `scenes.csv`).
struct Row {
    scene: &'static str,
    /// `bins` (screen triangles kept in bins: cube, floor) or `ranges` (each triangle
    /// re-projected in the bands its range covers: the meshes).
    binning: &'static str,
    width: u32,
    height: u32,
    rows: u32,
    vertices: usize,
    triangles: usize,
    binned: u32,
    pieces: u64,
    pixels: u32,
}

/// Band pieces: each range counted once per band it covers.
fn pieces(ranges: &[BandRange], bands: u32) -> u64 {
    ranges
        .iter()
        .map(|r| (0..bands).filter(|&b| r.covers(b)).count() as u64)
        .sum()
}

fn checker(w: u32, h: u32) -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    demo::checker_texture(w, h, &mut t).unwrap();
    t
}

fn footprints(tex: &Texture<'_>) -> Vec<u64> {
    let mut p = vec![0u64; tex.texels().len()];
    fixel::texture::write_footprints(tex, &mut p).unwrap();
    p
}

/// A mesh scene's row from its banded frame and band ranges.
fn row(
    scene: &'static str,
    binning: &'static str,
    (width, height): (u32, u32),
    mesh: &Mesh<'_>,
    r: &FrameResult,
    ranges: &[BandRange],
) -> Row {
    let bands = height.div_ceil(scenes::ROWS);
    assert_eq!(r.stats.bands, bands, "{scene}");
    assert!(!r.stats.rewalked, "{scene}: {:?}", r.stats);
    Row {
        scene,
        binning,
        width,
        height,
        rows: scenes::ROWS,
        vertices: mesh.vertices(),
        triangles: mesh.triangles(),
        binned: r.stats.triangles,
        pieces: pieces(&ranges[..mesh.triangles()], bands),
        pixels: r.stats.pixels,
    }
}

/// Storage for the binned scenes drawn through band ranges instead (no bins): the same
/// pixels, and each triangle's band range to count the pieces from.
type RangeBuffers = Buffers<64, 32, 0, 16>;

/// The sphere firmware's storage without kept set-ups: a triangle kept whole for the next
/// band ends its band range in the band that keeps it, so the pieces are counted from the
/// ranges of a frame that keeps none (the same pixels).
type PieceBuffers = Buffers<{ scenes::RANGES }, { scenes::CACHE }, 0, 0>;

fn rows() -> Vec<Row> {
    let (mut n1, mut n2) = (|| {}, || {});
    let mut out = Vec::new();
    let wh = (scenes::W, scenes::H);

    // Cube and floor: drawn as their firmwares do (bins), then through band ranges for the
    // pieces; both frames write the same pixels.
    let t128 = checker(128, 128);
    let plain = Texture::new(&t128, 128, 128).unwrap();
    let f128 = footprints(&plain);
    let tex = MipTexture::single(plain).with_footprints(&f128).unwrap();
    let cube = demo::cube();
    let mut small = Box::new(SmallBuffers::with_storage());
    let binned = scenes::cube(Target::Bands(&mut *small), tex, 0, &mut n1, &mut n2).unwrap();
    let mut rb = Box::new(RangeBuffers::with_storage());
    let r = scenes::cube(Target::Bands(&mut *rb), tex, 0, &mut n1, &mut n2).unwrap();
    assert_eq!(r.checksum, binned.checksum, "cube");
    let mut cube_row = row("cube", "bins", wh, &cube.mesh().unwrap(), &r, &rb.ranges);
    cube_row.binned = binned.stats.triangles;
    out.push(cube_row);

    let t64 = checker(64, 64);
    let tex = MipTexture::single(Texture::new(&t64, 64, 64).unwrap());
    let floor = demo::floor();
    let binned = scenes::floor::<scenes::FloorNearest, _, _, _, _>(
        Target::Bands(&mut *small),
        tex,
        &mut n1,
        &mut n2,
    )
    .unwrap();
    let mut rb = Box::new(RangeBuffers::with_storage());
    let r = scenes::floor::<scenes::FloorNearest, _, _, _, _>(
        Target::Bands(&mut *rb),
        tex,
        &mut n1,
        &mut n2,
    )
    .unwrap();
    assert_eq!(r.checksum, binned.checksum, "floor");
    let mut floor_row = row("floor", "bins", wh, &floor.mesh().unwrap(), &r, &rb.ranges);
    floor_row.binned = binned.stats.triangles;
    out.push(floor_row);

    // The sphere and the teapot: band ranges, as their firmwares draw them.
    let t256 = checker(256, 128);
    let tex = Texture::new(&t256, 256, 128).unwrap();
    let mut buf = Box::new(PieceBuffers::with_storage());
    let sphere = Box::new(demo::sphere());
    let mesh = sphere.mesh().unwrap();
    let r = scenes::sphere(Target::Bands(&mut *buf), tex, &mesh, 0, &mut n1, &mut n2).unwrap();
    out.push(row("sphere", "ranges", wh, &mesh, &r, &buf.ranges));

    let mesh = Mesh::new(
        &teapot::TEAPOT_POSITIONS,
        Some(&teapot::TEAPOT_NORMALS),
        &teapot::TEAPOT_UVS,
        &teapot::TEAPOT_INDICES,
    )
    .unwrap();
    let mut buf = Box::new(PieceBuffers::with_storage());
    let r = scenes::teapot(Target::Bands(&mut *buf), tex, &mesh, 0, &mut n1, &mut n2).unwrap();
    out.push(row("teapot", "ranges", wh, &mesh, &r, &buf.ranges));

    // The glTF models, 240 x 320.
    let mwh = (model_scene::W, model_scene::H);
    let mesh = Mesh::new(
        &fox::FOX_POSITIONS,
        Some(&fox::FOX_NORMALS),
        &fox::FOX_UVS,
        &fox::FOX_INDICES,
    )
    .unwrap();
    let tex = MipTexture::new(
        &fox::FOX_TEXELS,
        fox::FOX_WIDTH,
        fox::FOX_HEIGHT,
        fox::FOX_LEVELS,
    )
    .unwrap();
    let mut mb = Box::new(ModelBuffers::<{ model_scene::FOX_RANGES }, 0>::new());
    let r = model_scene::render(
        ModelTarget::Bands(&mut mb),
        tex,
        &mesh,
        &model_scene::fox_model(),
        &mut n1,
        &mut n2,
    )
    .unwrap();
    out.push(row("fox", "ranges", mwh, &mesh, &r, &mb.ranges));

    use cesium_man as c;
    let mesh = Mesh::new(
        &c::CESIUM_MAN_POSITIONS,
        Some(&c::CESIUM_MAN_NORMALS),
        &c::CESIUM_MAN_UVS,
        &c::CESIUM_MAN_INDICES,
    )
    .unwrap();
    let tex = MipTexture::new(
        &c::CESIUM_MAN_TEXELS,
        c::CESIUM_MAN_WIDTH,
        c::CESIUM_MAN_HEIGHT,
        c::CESIUM_MAN_LEVELS,
    )
    .unwrap();
    let mut mb = Box::new(ModelBuffers::<{ model_scene::CESIUM_MAN_RANGES }, 0>::new());
    let r = model_scene::render(
        ModelTarget::Bands(&mut mb),
        tex,
        &mesh,
        &model_scene::cesium_man_model(),
        &mut n1,
        &mut n2,
    )
    .unwrap();
    out.push(row("cesium_man", "ranges", mwh, &mesh, &r, &mb.ranges));
    out
}

/// The committed counts.
fn csv_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("xtask")
        .join("budget")
        .join("scenes.csv")
}

fn csv(rows: &[Row]) -> String {
    let mut s = String::from(
        "# The benchmark scenes' geometry (host-tests/tests/budget_counts.rs; \
         FIXEL_BLESS=1 rewrites it)\n\
         scene,binning,width,height,rows,vertices,triangles,binned,pieces,pixels\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{}",
            r.scene,
            r.binning,
            r.width,
            r.height,
            r.rows,
            r.vertices,
            r.triangles,
            r.binned,
            r.pieces,
            r.pixels
        );
    }
    s
}

#[test]
fn benchmark_scene_counts_are_committed() {
    let now = csv(&rows());
    let path = csv_path();
    if std::env::var_os("FIXEL_BLESS").is_some() {
        std::fs::write(&path, &now).unwrap();
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert_eq!(
        committed,
        now,
        "{} is out of date: FIXEL_BLESS=1 cargo test -p host-tests --test budget_counts",
        path.display()
    );
}

/// A band piece is a binned triangle in one band: at least one per binned triangle, at
/// most one per band.
#[test]
fn pieces_lie_between_the_triangles_and_the_bands() {
    for r in rows() {
        let bands = u64::from(r.height.div_ceil(r.rows));
        assert!(r.pieces >= u64::from(r.binned), "{}", r.scene);
        assert!(r.pieces <= u64::from(r.binned) * bands, "{}", r.scene);
    }
}
