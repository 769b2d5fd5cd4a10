//! Cube-map filtering showcase: seams and mipmaps on the mirror sphere in the
//! procedural sky of `fixel::shading::env::sky`.
//!
//! ```text
//! cargo run --release --example envmap_filtering
//! ```
//!
//! Writes `target/pictures/envmap_filtering.png`, 640 x 480:
//! * top: the sphere close up in a 16-texel cube map, GL's clamped bilinear filter (left:
//!   a seam along every face edge) and the seamless filter (right, `CubeMap::seamless`);
//! * bottom: the sphere far away in a 256-texel cube map, cropped and enlarged 3x
//!   (nearest): level 0 (left: the skyline and the ground checker break into sparkle) and
//!   trilinear mipmaps with GL's cube-map LOD, seamless on every level (right,
//!   `MipCubeMap::seamless` + `ReflectPerPixelMip`).

mod common;
#[path = "common/sky.rs"]
mod sky_common;
use sky_common::{background, sky_faces};

use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{fx, Angle, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::env::{
    CubeMap, EnvLookup, EnvVertices, MipCubeMap, ReflectPerPixel, ReflectPerPixelMip,
};
use fixel::shading::Shader;
use fixel::surface::Frame;
use fixel::texture::{
    chain_len, full_levels, generate_mips, Bilinear, Lod, MipTexture, Texture, Trilinear,
};
use fixel::Rgb565;

const W: u32 = 320;
const H: u32 = 240;

/// The benchmark sphere at `model` with vertices from `vertex`.
fn sphere<const N: usize>(
    model: &Mat4,
    proj: &Mat4,
    vertex: impl Fn(&EnvVertices, Vec3, Vec3) -> Option<Vertex<N>>,
) -> Vec<[Vertex<N>; 3]> {
    let m = fixel_scenes::sphere();
    let s = EnvVertices::new(model, proj, Vec3::ZERO);
    m.indices
        .iter()
        .filter_map(|t| {
            let v = t.map(|i| vertex(&s, m.positions[usize::from(i)], m.normals[usize::from(i)]));
            Some([v[0]?, v[1]?, v[2]?])
        })
        .collect()
}

/// One 320 x 240 frame: `bg` behind, the sphere drawn with `shader`.
fn frame<S: Shader<Varyings = [i32; N]>, const N: usize, B: EnvLookup>(
    bg: &B,
    shader: S,
    tris: &[[Vertex<N>; 3]],
) -> Result<Vec<Rgb565>, fixel::Error> {
    let mut color = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    let mut depth = vec![0u16; (W * H) as usize];
    background(bg, &mut color, W, H, &Mat4::IDENTITY);
    let mut f = Frame::new(&mut color, W, H)?.with_depth(&mut depth)?;
    ShadedDraw::<_, Exact, DepthLess>::new(shader, Viewport::new(0, 0, W, H)?, Cull::Back)?
        .clip_triangles(tris, &mut f)?;
    Ok(color)
}

/// Copies `src` (320 x 240) into quadrant `(qx, qy)` of the 640 x 480 `out`.
fn place(out: &mut [Rgb565], src: &[Rgb565], qx: u32, qy: u32) {
    for y in 0..H {
        for x in 0..W {
            out[((qy * H + y) * 2 * W + qx * W + x) as usize] = src[(y * W + x) as usize];
        }
    }
}

/// The `W/3 x H/3` window of `src` centred on the frame, enlarged 3x (nearest).
fn zoom3(src: &[Rgb565]) -> Vec<Rgb565> {
    let (x0, y0) = (W / 3, H / 3);
    (0..W * H)
        .map(|k| {
            let (x, y) = (k % W, k / W);
            src[((y0 + y / 3) * W + x0 + x / 3) as usize]
        })
        .collect()
}

fn main() -> Result<(), fixel::Error> {
    let out = common::out_dir();
    let proj = Mat4::perspective(Angle::from_degrees(fx(45)), fx(4.0 / 3.0), fx(0.5), fx(40))?;
    let mut pic = vec![Rgb565::new(0, 0, 0); (4 * W * H) as usize];

    // Seams: 16-texel faces, the sphere close.
    let f16 = sky_faces(16);
    let cube16 = CubeMap::new(
        core::array::from_fn(|i| Texture::new(&f16[i], 16, 16).expect("face")),
        Bilinear,
    )?;
    let near = sphere(
        &Mat4::translation(Vec3::from_num(0, 0, -3.6)),
        &proj,
        EnvVertices::per_pixel,
    );
    place(
        &mut pic,
        &frame(&cube16, ReflectPerPixel(cube16), &near)?,
        0,
        0,
    );
    let seamless = cube16.seamless();
    place(
        &mut pic,
        &frame(&seamless, ReflectPerPixel(seamless), &near)?,
        1,
        0,
    );

    // Mipmaps: 256-texel faces with full chains, the sphere far.
    let size = 256;
    let levels = full_levels(size, size);
    let chains: Vec<Vec<Rgb565>> = sky_faces(size)
        .into_iter()
        .map(|base| {
            let mut c = vec![Rgb565::new(0, 0, 0); chain_len(size, size, levels)];
            c[..base.len()].copy_from_slice(&base);
            generate_mips(&mut c, size, size, levels).map(|()| c)
        })
        .collect::<Result<_, _>>()?;
    let mips: [MipTexture<'_>; 6] =
        core::array::from_fn(|i| MipTexture::new(&chains[i], size, size, levels).expect("chain"));
    let cube256 = CubeMap::new(core::array::from_fn(|i| *mips[i].base()), Bilinear)?;
    let model = Mat4::translation(Vec3::from_num(0, 0, -14));
    let far6 = sphere(&model, &proj, EnvVertices::per_pixel);
    let far8 = sphere(&model, &proj, EnvVertices::per_pixel);
    let level0 = frame(&cube256, ReflectPerPixel(cube256), &far6)?;
    place(&mut pic, &zoom3(&level0), 0, 1);
    let shader = ReflectPerPixelMip {
        map: MipCubeMap::new(&mips, Trilinear::default())?.seamless(),
        lod: Lod::default(),
    };
    let trilinear = frame(&cube256, shader, &far8)?;
    place(&mut pic, &zoom3(&trilinear), 1, 1);

    common::write_png(&out.join("envmap_filtering.png"), 2 * W, 2 * H, &pic);
    println!("wrote envmap_filtering.png to {}", out.display());
    Ok(())
}
