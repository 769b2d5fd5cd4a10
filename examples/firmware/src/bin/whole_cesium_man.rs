//! Scene `whole_cesium_man`: the glTF sample CesiumMan (4672 triangles) baked from glTF into flash by
//! `cargo xtask bake-gltf`, static pose, lit, bilinear, perspective-correct, depth-tested,
//! drawn into one whole 240x320 frame: the whole-frame twin of `cesium_man`.
#![no_std]
#![no_main]

use fixel::scene::Mesh;
use fixel::texture::MipTexture;
use fixel_firmware::data::cesium_man as model;
use fixel_firmware::model_scene::{self, ModelTarget};
use fixel_firmware::{report, scenes};

fn run() -> bool {
    let mut buf = scenes::Whole::new();
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
    report("whole_cesium_man", |pause, resume| {
        model_scene::render(
            ModelTarget::<0, 0>::Whole(&mut buf),
            texture,
            &mesh,
            &model_scene::cesium_man_model(),
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
