//! Scene `whole_fox`: the glTF sample Fox (576 triangles) baked from glTF into flash by
//! `cargo xtask bake-gltf`, static pose, lit, bilinear, perspective-correct, depth-tested,
//! drawn into one whole 240x320 frame: the whole-frame twin of `fox`.
#![no_std]
#![no_main]

use fixel::scene::Mesh;
use fixel::texture::MipTexture;
use fixel_firmware::data::fox as model;
use fixel_firmware::model_scene::{self, ModelTarget};
use fixel_firmware::{report, scenes};

fn run() -> bool {
    let mut buf = scenes::Whole::new();
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
    report("whole_fox", |pause, resume| {
        model_scene::render(
            ModelTarget::<0, 0>::Whole(&mut buf),
            texture,
            &mesh,
            &model_scene::fox_model(),
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
