//! `cargo xtask size`: `size_open` without the clipper (`ShadedDraw::project_unclipped`: the
//! geometry stays in view). The minimal textured unlit firmware through the open stage:
//! `ShadedDraw<Replace<Nearest, Repeat, Repeat>, Affine, NoDepth>` fed two varyings per
//! vertex (`u, v`) by the firmware's own vertex function, drawn in 8-row bands.
#![no_std]
#![no_main]

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::demo;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::pipeline::{Affine, NoDepth, ShadedDraw};
use fixel::shading::{Replace, TexBinding};
use fixel::surface::Frame;
use fixel::texture::{Lod, MipTexture, Nearest, Repeat, Texture};
use fixel_firmware::scenes::{Fnv1a, H, ROWS, W};
use fixel_firmware::size::{INDICES, POSITIONS, UVS};
use fixel_firmware::{data, outln};

/// The 8 x 8 texture as a one-level chain, in flash.
static CHAIN: MipTexture<'static> =
    MipTexture::single(Texture::from_static(&data::T8_TEXELS, 8, 8));

fn run() -> bool {
    let Ok(tex) = TexBinding::new(
        core::hint::black_box(&CHAIN),
        Nearest,
        Repeat,
        Repeat,
        Lod::default(),
    ) else {
        return false;
    };
    let Ok(vp) = Viewport::new(0, 0, W, H) else {
        return false;
    };
    let Ok(draw) = ShadedDraw::<_, Affine, NoDepth>::new(Replace { tex }, vp, Cull::Back) else {
        return false;
    };
    // Model space is world space here: clip = projection * view * p.
    let camera = demo::camera(20);
    let mvp = camera.projection.mul(&camera.view);
    let vertex = |i: u16| {
        let i = usize::from(i);
        let p = mvp.transform_point(*POSITIONS.get(i)?)?;
        let [u, v] = *UVS.get(i)?;
        Some(Vertex::new(
            [p.x, p.y, p.z, p.w],
            [u.to_bits(), v.to_bits()],
        ))
    };
    let mut color = [Rgb565::new(0, 0, 0); (W * ROWS) as usize];
    let mut sum = Fnv1a::default();
    let mut pixels = 0;
    for band in 0..H / ROWS {
        let Ok(frame) = Frame::new(&mut color, W, ROWS) else {
            return false;
        };
        let mut frame = frame.at_row(band * ROWS);
        frame.clear(Rgb565::new(0, 0, 0));
        for tri in &INDICES {
            if let (Some(a), Some(b), Some(c)) = (vertex(tri[0]), vertex(tri[1]), vertex(tri[2])) {
                // The triangle stays in view: nothing is ever refused here.
                draw.project_unclipped(&[a, b, c], &mut |s| {
                    pixels += draw.screen_triangle(s, &mut frame).unwrap_or(0);
                });
            }
        }
        sum.pixels(frame.pixels());
    }
    outln!("checksum=0x{:08x} pixels={}", sum.0, pixels);
    true
}

fixel_firmware::entry!(run);
