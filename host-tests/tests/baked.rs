//! `cargo xtask bake` output compiles and is the full-precision chain of its 8-bit image: `baked/checker.rs`
//! was baked from `baked/checker.png` (16 x 8, full chain) and is checked for freshness by
//! xtask's own test.

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use fixel::texture::chain_len;
use fixel::texture::{generate_mips, MipTexture};
use std::io::BufReader;

include!("baked/checker.rs");

/// The PNG decoded independently: 8-bit RGB pixels.
fn decode(path: &str) -> (u32, u32, Vec<[u8; 3]>) {
    let file = std::fs::File::open(path).unwrap();
    let mut reader = png::Decoder::new(BufReader::new(file)).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    let px = buf[..info.buffer_size()]
        .chunks(3)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    (info.width, info.height, px)
}

/// The baked chain against an f64 chain from the 8-bit image: level 0 rounded to RGB565,
/// every level `k` the mean of the source pixels it covers, rounded once. The run-time
/// `generate_mips` (from the RGB565 level 0) agrees within one LSB.
#[test]
fn baked_chain_is_the_full_precision_mean() {
    let (w, h, src) = decode(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/baked/checker.png"
    ));
    assert_eq!((w, h, CHECKER_LEVELS), (CHECKER_WIDTH, CHECKER_HEIGHT, 5));
    let mut want = Vec::new();
    for k in 0..CHECKER_LEVELS {
        let (dw, dh) = ((w >> k).max(1), (h >> k).max(1));
        let (bw, bh) = (w / dw, h / dh);
        for j in 0..dh {
            for i in 0..dw {
                let mut sum = [0f64; 3];
                for y in j * bh..(j + 1) * bh {
                    for x in i * bw..(i + 1) * bw {
                        for c in 0..3 {
                            sum[c] += f64::from(src[(y * w + x) as usize][c]);
                        }
                    }
                }
                let q = |c: usize, max: f64| {
                    (sum[c] / f64::from(bw * bh) * max / 255.0 + 0.5).floor() as u8
                };
                want.push(Rgb565::new(q(0, 31.0), q(1, 63.0), q(2, 31.0)));
            }
        }
    }
    assert_eq!(CHECKER_TEXELS.as_slice(), want.as_slice());
    let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(w, h, CHECKER_LEVELS)];
    chain[..(w * h) as usize].copy_from_slice(&want[..(w * h) as usize]);
    generate_mips(&mut chain, w, h, CHECKER_LEVELS).unwrap();
    for (a, b) in chain.iter().zip(CHECKER_TEXELS.iter()) {
        let ch = |c: &Rgb565| [c.r(), c.g(), c.b()].map(i16::from);
        let (a, b) = (ch(a), ch(b));
        assert!((0..3).all(|c| (a[c] - b[c]).abs() <= 1), "{a:?} {b:?}");
    }
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
