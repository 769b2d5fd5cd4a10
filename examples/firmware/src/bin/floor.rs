//! Scene `floor`, nearest filtering, unlit, depth-tested: the fill-rate scene.
#![no_std]
#![no_main]

use fixel_firmware::{data, report, scenes};

fn run() -> bool {
    let mut buf = scenes::SmallBuffers::with_storage();
    report("floor", |pause, resume| {
        scenes::floor::<scenes::FloorNearest, _, _, _, _>(
            scenes::Target::Bands(&mut buf),
            fixel::texture::MipTexture::single(core::hint::black_box(data::T64)),
            pause,
            resume,
        )
    })
}

fixel_firmware::entry!(run);
