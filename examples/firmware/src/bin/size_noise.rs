//! `cargo xtask size`: one lit triangle with a band-limited marble solid texture
//! (`SolidShader<Marble, BandLimit>`, exact perspective, no depth) in 8-row bands: the flash
//! of Perlin noise, turbulence, the marble pattern and its ramp. The other `size_*` images
//! do not link any of it (no `PERM` or `FADE_Q15` symbol in them).
#![no_std]
#![no_main]

use fixel::geometry::{Cull, Viewport};
use fixel::math::{Fx, Mat4};
use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
use fixel::scene::DirectionalLight;
use fixel::shading::noise::presets::{MARBLE_AMP, MARBLE_FREQ, MARBLE_KEYS};
use fixel::shading::noise::{BandLimit, Marble, Ramp, SolidMesh, SolidShader};
use fixel_firmware::outln;
use fixel_firmware::scenes::{H, W};
use fixel_scenes as demo;
// The same triangle as the other `size_*` firmwares.
use fixel_firmware::size::{INDICES, NORMALS, POSITIONS};

fn run() -> bool {
    let Ok(ramp) = Ramp::sine(core::hint::black_box(&MARBLE_KEYS)) else {
        return false;
    };
    let marble = Marble {
        ramp: &ramp,
        freq: MARBLE_FREQ,
        amp: MARBLE_AMP,
    };
    let shader = SolidShader::new(marble, BandLimit::new(core::hint::black_box(6)));
    let Ok(vp) = Viewport::new(0, 0, W, H) else {
        return false;
    };
    let Ok(draw) = ShadedDraw::<_, Exact, NoDepth>::new(shader, vp, Cull::Back) else {
        return false;
    };
    let Ok(mesh) = SolidMesh::new(&POSITIONS, Some(&NORMALS), &INDICES, Fx::from_num(2)) else {
        return false;
    };
    let sun = DirectionalLight::default();
    let r = fixel_firmware::size::in_bands(None, |frame| {
        draw.check_target(frame).ok()?;
        let mut pixels = 0;
        mesh.triangles(&Mat4::IDENTITY, &demo::camera(20), Some(&sun), |t| {
            // The target was checked above.
            pixels += draw.clip_triangles(&[*t], frame).unwrap_or(0);
        });
        Some(pixels)
    });
    let Some((sum, pixels)) = r else {
        return false;
    };
    outln!("checksum=0x{:08x} pixels={}", sum, pixels);
    true
}

fixel_firmware::entry!(run);
