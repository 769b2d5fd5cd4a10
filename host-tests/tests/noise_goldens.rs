//! Golden images of the solid textures: the three test scenes (marble sphere, wooden cube,
//! granite floor) band-limited and with 6 fixed octaves, and a flame frame, compared bit for
//! bit with `host-tests/golden/noise_*.png`. Bless with `FIXEL_BLESS=1 cargo test -p
//! host-tests --test noise_goldens` after an intended change (and look at the images).

use fixel::shading::noise::{flame, Ramp, Ramps, FLAME_KEYS};
use fixel::texture::LodGranularity;
use host_tests::golden::assert_golden;
use host_tests::noise_scenes::{OctaveMode, SolidScene, H, W};

#[test]
fn noise_scenes() {
    let ramps = Ramps::new().unwrap();
    for scene in SolidScene::ALL {
        for (tag, mode) in [
            ("band6", OctaveMode::Band(6, LodGranularity::Span)),
            ("fixed6", OctaveMode::Fixed(6)),
        ] {
            let (px, _) = scene.draw(&ramps, mode);
            assert_golden(&format!("noise_{}_{tag}", scene.name()), W, H, &px);
        }
    }
}

#[test]
fn noise_flame_frame() {
    let ramp = Ramp::from_keys(&FLAME_KEYS).unwrap();
    let (w, h) = (64u32, 96u32);
    let mut px = Vec::new();
    for j in 0..h as i32 {
        for i in 0..w as i32 {
            let x = (i - 32) * 2662 + 1331;
            let y = (95 - j) * 1024 - 6554;
            px.push(flame(&ramp, x, y, 3 << 13, 5));
        }
    }
    assert_golden("noise_flame_t3", w, h, &px);
}
