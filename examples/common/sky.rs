//! Shared by the environment-mapping examples: the procedural sky's cube-map faces and the
//! environment drawn behind the scene along each pixel's view ray.

use fixel::math::Mat4;
use fixel::shading::env::{sky, EnvLookup};
use fixel::Rgb565;

/// The six faces (GL order) of the procedural sky, `size` texels a side.
pub fn sky_faces(size: u32) -> Vec<Vec<Rgb565>> {
    (0..6)
        .map(|f| {
            let mut t = vec![Rgb565::new(0, 0, 0); (size * size) as usize];
            sky::sky_face(f, size, &mut t).expect("face");
            t
        })
        .collect()
}

/// Raw RGB565 as a colour.
pub(crate) fn raw(c: u16) -> Rgb565 {
    Rgb565::new((c >> 11) as u8, ((c >> 5) & 63) as u8, (c & 31) as u8)
}

/// Fills the `w x h` `frame` with `env` along each pixel's view ray: camera at the origin
/// looking down -z, 45 degrees vertically, rotated by `view` (world direction = the view
/// rotation transposed times the eye direction).
pub fn background<M: EnvLookup>(env: &M, frame: &mut [Rgb565], w: u32, h: u32, view: &Mat4) {
    let f = f64::from(h) / 2.0 / (22.5f64).to_radians().tan();
    for y in 0..h {
        for x in 0..w {
            let d = [
                (f64::from(x) + 0.5 - f64::from(w) / 2.0) / f,
                -(f64::from(y) + 0.5 - f64::from(h) / 2.0) / f,
                -1.0,
            ];
            let m = &view.m;
            let dw = [0, 1, 2].map(|c| (0..3).map(|r| m[r][c].to_num::<f64>() * d[r]).sum::<f64>());
            frame[(y * w + x) as usize] = raw(env.lookup(dw.map(|c| (c * 16384.0) as i32)));
        }
    }
}
