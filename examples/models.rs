//! The glTF sample models Fox and CesiumMan, baked by `cargo xtask bake-gltf`
//! (`assets/gltf/`), drawn at 240 x 320 in their static pose by the firmware's own scene code
//! (`examples/firmware/src/model_scene.rs`: the frames `cargo xtask mcu` checksums), whole.
//!
//! `cargo run --release --example models` (pictures in `target/pictures/fox.png` and
//! `target/pictures/cesium_man.png`).

#[path = "common/mod.rs"]
mod common;

#[path = "firmware/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

#[path = "firmware/src/model_scene.rs"]
#[allow(dead_code)]
mod model_scene;

#[allow(dead_code)]
mod fox {
    include!("../assets/gltf/fox.rs");
}

#[allow(dead_code)]
mod cesium_man {
    include!("../assets/gltf/cesium_man.rs");
}

use fixel::math::{Fx, Mat4, Vec3};
use fixel::scene::Mesh;
use fixel::texture::MipTexture;
use fixel::Error;
use model_scene::{ModelTarget, H, W};

/// Draws one model whole and writes `name.png`.
#[allow(clippy::too_many_arguments)]
fn picture(
    name: &str,
    positions: &[Vec3],
    normals: &[Vec3],
    uvs: &[[Fx; 2]],
    indices: &[[u16; 3]],
    texture: MipTexture<'_>,
    model: &Mat4,
) -> Result<(), Error> {
    let mesh = Mesh::new(positions, Some(normals), uvs, indices)?;
    let mut whole = Box::new(scenes::Whole::new());
    let r = model_scene::render::<0, 0>(
        ModelTarget::Whole(&mut whole),
        texture,
        &mesh,
        model,
        &mut || {},
        &mut || {},
    )?;
    let path = common::out_dir().join(format!("{name}.png"));
    common::write_png(&path, W, H, &whole.color[..(W * H) as usize]);
    println!(
        "wrote {} ({} triangles, {} pixels drawn, checksum 0x{:08x})",
        path.display(),
        mesh.triangles(),
        r.stats.pixels,
        r.checksum
    );
    Ok(())
}

fn main() -> Result<(), Error> {
    use cesium_man as c;
    use fox as f;
    picture(
        "fox",
        &f::FOX_POSITIONS,
        &f::FOX_NORMALS,
        &f::FOX_UVS,
        &f::FOX_INDICES,
        MipTexture::new(&f::FOX_TEXELS, f::FOX_WIDTH, f::FOX_HEIGHT, f::FOX_LEVELS)?,
        &model_scene::fox_model(),
    )?;
    picture(
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
        )?,
        &model_scene::cesium_man_model(),
    )
}
