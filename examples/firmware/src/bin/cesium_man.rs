//! Scene `cesium_man`: the glTF sample CesiumMan (4672 triangles) baked from glTF into flash by
//! `cargo xtask bake-gltf`, static pose, 240x320, lit, bilinear, perspective-correct,
//! depth-tested, in 240x8 bands through its band ranges and vertex cache.
#![no_std]
#![no_main]

use fixel::scene::Mesh;
use fixel::texture::MipTexture;
use fixel_firmware::data::cesium_man as model;
use fixel_firmware::model_scene::{self, ModelBuffers, ModelTarget};
use fixel_firmware::report;

fn run() -> bool {
    let mut buf = ModelBuffers::<
        { model_scene::CESIUM_MAN_RANGES },
        { model_scene::CESIUM_MAN_SETUPS },
    >::new();
    let Ok(mesh) = Mesh::new(
        core::hint::black_box(&model::CESIUM_MAN_POSITIONS),
        Some(&model::CESIUM_MAN_NORMALS),
        &model::CESIUM_MAN_UVS,
        &model::CESIUM_MAN_INDICES,
    ) else {
        return false;
    };
    let Ok(texture) = MipTexture::new(
        core::hint::black_box(&model::CESIUM_MAN_TEXELS),
        model::CESIUM_MAN_WIDTH,
        model::CESIUM_MAN_HEIGHT,
        model::CESIUM_MAN_LEVELS,
    ) else {
        return false;
    };
    report("cesium_man", |pause, resume| {
        model_scene::render(
            ModelTarget::Bands(&mut buf),
            texture,
            &mesh,
            &model_scene::cesium_man_model(),
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
