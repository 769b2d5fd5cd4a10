//! `cargo xtask bake` output compiles and equals fixel's run-time chain: `baked/checker.rs`
//! was baked from `baked/checker.png` (16 x 8, full chain) and is checked for freshness by
//! xtask's own test.

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::texture::chain_len;
use fixel::texture::{generate_mips, MipTexture};
use std::io::BufReader;

include!("baked/checker.rs");

/// The PNG decoded independently, rounded to RGB565 as the bake documents.
fn decode(path: &str) -> (u32, u32, Vec<Rgb565>) {
    let file = std::fs::File::open(path).unwrap();
    let mut reader = png::Decoder::new(BufReader::new(file)).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    let q = |v: u8, max: u32| ((u32::from(v) * max + 127) / 255) as u8;
    let px = buf[..info.buffer_size()]
        .chunks(3)
        .map(|p| Rgb565::new(q(p[0], 31), q(p[1], 63), q(p[2], 31)))
        .collect();
    (info.width, info.height, px)
}

#[test]
fn baked_chain_equals_generate_mips() {
    let (w, h, base) = decode(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/baked/checker.png"
    ));
    assert_eq!((w, h, CHECKER_LEVELS), (CHECKER_WIDTH, CHECKER_HEIGHT, 5));
    let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(w, h, CHECKER_LEVELS)];
    chain[..base.len()].copy_from_slice(&base);
    generate_mips(&mut chain, w, h, CHECKER_LEVELS).unwrap();
    assert_eq!(chain.len(), CHECKER_TEXELS.len());
    assert_eq!(chain.as_slice(), CHECKER_TEXELS.as_slice());
    let mips = MipTexture::new(
        &CHECKER_TEXELS,
        CHECKER_WIDTH,
        CHECKER_HEIGHT,
        CHECKER_LEVELS,
    )
    .unwrap();
    assert_eq!(mips.levels(), 5);
    assert_eq!((mips.level(4).width(), mips.level(4).height()), (1, 1));
    assert_eq!((mips.level(3).width(), mips.level(3).height()), (2, 1));
}

/// `cargo xtask bake-gltf` output: `baked/tiles.rs`, baked from the textured fixture
/// `baked/tiles.gltf` (two nodes, vertex colours, a 6 x 3 image), checked for freshness by
/// xtask's own test.
mod tiles {
    include!("baked/tiles.rs");

    #[test]
    fn baked_gltf_is_a_mesh_and_a_mip_chain() {
        let mesh = fixel::scene::Mesh::new(
            &TILES_POSITIONS,
            Some(&TILES_NORMALS),
            &TILES_UVS,
            &TILES_INDICES,
        )
        .unwrap();
        assert_eq!((mesh.vertices(), mesh.triangles()), (7, 3));
        assert_eq!(TILES_COLORS.len(), 7);
        let mips =
            fixel::texture::MipTexture::new(&TILES_TEXELS, TILES_WIDTH, TILES_HEIGHT, TILES_LEVELS)
                .unwrap();
        assert_eq!((TILES_WIDTH, TILES_HEIGHT, mips.levels()), (8, 4, 4));
    }

    mod packed {
        include!("baked/tiles_packed.rs");
    }

    /// `bake-gltf --packed` decodes, at compile time, to the text bake's arrays.
    #[test]
    fn packed_bake_equals_the_text_bake() {
        assert_eq!(packed::TILES_PACKED_POSITIONS, TILES_POSITIONS);
        assert_eq!(packed::TILES_PACKED_NORMALS, TILES_NORMALS);
        assert_eq!(packed::TILES_PACKED_UVS, TILES_UVS);
        assert_eq!(packed::TILES_PACKED_INDICES, TILES_INDICES);
        assert_eq!(packed::TILES_PACKED_COLORS, TILES_COLORS);
        assert_eq!(packed::TILES_PACKED_TEXELS, TILES_TEXELS);
        assert_eq!(
            (
                packed::TILES_PACKED_WIDTH,
                packed::TILES_PACKED_HEIGHT,
                packed::TILES_PACKED_LEVELS
            ),
            (TILES_WIDTH, TILES_HEIGHT, TILES_LEVELS)
        );
    }
}
