//! The model scenes of the firmware (`fox`, `cesium_man` and their whole-frame twins:
//! `examples/firmware/src/model_scene.rs`, the glTF sample models baked by `cargo xtask
//! bake-gltf`) rendered on the host through the very same code, and their checksums.
//!
//! `cargo xtask mcu` runs this test with `--nocapture` and compares the `mcu-expected` lines
//! it prints with what each firmware prints under QEMU. The test itself checks that the
//! bands give the frame one whole-frame draw gives, pixel for pixel.

#[path = "../../examples/firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "../../examples/firmware/src/model_scene.rs"]
#[allow(dead_code)]
mod model_scene;

#[allow(dead_code)]
mod fox {
    include!("../../assets/gltf/fox.rs");
}

#[allow(dead_code)]
mod cesium_man {
    include!("../../assets/gltf/cesium_man.rs");
}

use fixel::math::{Fx, Mat4, Vec3};
use fixel::scene::Mesh;
use fixel::texture::MipTexture;
use model_scene::{ModelBuffers, ModelTarget};

/// Draws one model in bands and whole; prints both expected lines.
#[allow(clippy::too_many_arguments)]
fn check<const R: usize, const S: usize>(
    name: &str,
    positions: &[Vec3],
    normals: &[Vec3],
    uvs: &[[Fx; 2]],
    indices: &[[u16; 3]],
    texture: MipTexture<'_>,
    model: &Mat4,
) {
    let mesh = Mesh::new(positions, Some(normals), uvs, indices).unwrap();
    assert_eq!(mesh.triangles(), R, "{name}: one band range per triangle");
    let mut bands = Box::new(ModelBuffers::<R, S>::new());
    let b = model_scene::render(
        ModelTarget::Bands(&mut bands),
        texture,
        &mesh,
        model,
        &mut || {},
        &mut || {},
    )
    .unwrap();
    let mut whole = Box::new(scenes::Whole::new());
    let w = model_scene::render::<0, 0>(
        ModelTarget::Whole(&mut whole),
        texture,
        &mesh,
        model,
        &mut || {},
        &mut || {},
    )
    .unwrap();
    for (scene, r) in [(name.to_string(), &b), (format!("whole_{name}"), &w)] {
        println!(
            "mcu-expected scene={scene} checksum=0x{:08x} pixels={}",
            r.checksum, r.stats.pixels
        );
    }
    assert!(
        !b.stats.rewalked,
        "{name}: the band ranges hold every triangle"
    );
    assert_eq!(
        b.checksum, w.checksum,
        "{name}: bands differ from the whole frame"
    );
    assert_eq!(b.stats.pixels, w.stats.pixels, "{name}");
    // The model covers a good part of the frame (it is framed, not lost or clipped away).
    let covered = whole.color[..(model_scene::W * model_scene::H) as usize]
        .iter()
        .filter(|c| **c != embedded_graphics_core::pixelcolor::Rgb565::new(0, 0, 0))
        .count();
    assert!(covered > 9000, "{name}: {covered} pixels drawn");
}

#[test]
fn fox_frames() {
    use fox as f;
    check::<{ model_scene::FOX_RANGES }, { model_scene::FOX_SETUPS }>(
        "fox",
        &f::FOX_POSITIONS,
        &f::FOX_NORMALS,
        &f::FOX_UVS,
        &f::FOX_INDICES,
        MipTexture::new(&f::FOX_TEXELS, f::FOX_WIDTH, f::FOX_HEIGHT, f::FOX_LEVELS).unwrap(),
        &model_scene::fox_model(),
    );
}

#[test]
fn cesium_man_frames() {
    use cesium_man as c;
    check::<{ model_scene::CESIUM_MAN_RANGES }, { model_scene::CESIUM_MAN_SETUPS }>(
        "cesium_man",
        &c::CESIUM_MAN_POSITIONS,
        &c::CESIUM_MAN_NORMALS,
        &c::CESIUM_MAN_UVS,
        &c::CESIUM_MAN_INDICES,
        MipTexture::new(
            &c::CESIUM_MAN_TEXELS,
            c::CESIUM_MAN_WIDTH,
            c::CESIUM_MAN_HEIGHT,
            c::CESIUM_MAN_LEVELS,
        )
        .unwrap(),
        &model_scene::cesium_man_model(),
    );
}
