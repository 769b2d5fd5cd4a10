//! Scene `fox`: the glTF sample Fox (576 triangles) baked from glTF into flash by
//! `cargo xtask bake-gltf`, static pose, 240x320, lit, bilinear, perspective-correct,
//! depth-tested, in 240x8 bands through its band ranges and vertex cache.
#![no_std]
#![no_main]

use fixel::scene::Mesh;
use fixel::texture::MipTexture;
use fixel_firmware::data::fox as model;
use fixel_firmware::model_scene::{self, ModelBuffers, ModelTarget};
use fixel_firmware::report;

fn run() -> bool {
    let mut buf = ModelBuffers::<{ model_scene::FOX_RANGES }, { model_scene::FOX_SETUPS }>::new();
    let Ok(mesh) = Mesh::new(
        core::hint::black_box(&model::FOX_POSITIONS),
        Some(&model::FOX_NORMALS),
        &model::FOX_UVS,
        &model::FOX_INDICES,
    ) else {
        return false;
    };
    let Ok(texture) = MipTexture::new(
        core::hint::black_box(&model::FOX_TEXELS),
        model::FOX_WIDTH,
        model::FOX_HEIGHT,
        model::FOX_LEVELS,
    ) else {
        return false;
    };
    report("fox", |pause, resume| {
        model_scene::render(
            ModelTarget::Bands(&mut buf),
            texture,
            &mesh,
            &model_scene::fox_model(),
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
