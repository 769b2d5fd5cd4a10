//! A procedural outdoor environment for examples, tests and firmware: a sky darkening
//! towards the zenith with a sun, a skyline of windowed buildings on the horizon, and a
//! checkered ground plane fading into haze. Something a person recognises in a reflection,
//! with no image assets.
//!
//! [`sky_face`] fills one face of a cube map (GL face order and orientation, see
//! [`cube`](super::cube)); [`sky_colour`] is the colour of one direction. Host-side
//! generators (build scripts, tests, examples) call them; the firmware bakes the faces into
//! flash at build time, so no float code runs on the target.

use embedded_graphics_core::pixelcolor::Rgb565;

use crate::Error;

/// The direction through the centre of texel `(i, j)` of face `face` (GL order) of a cube
/// map of side `size`: the inverse of the face table, `sc = 2 s - 1`, `tc = 2 t - 1` at
/// `s = (i + 0.5) / size`, `t = (j + 0.5) / size`.
pub fn texel_direction(face: usize, i: u32, j: u32, size: u32) -> [f32; 3] {
    let sc = 2.0 * (i as f32 + 0.5) / size as f32 - 1.0;
    let tc = 2.0 * (j as f32 + 0.5) / size as f32 - 1.0;
    match face {
        0 => [1.0, -tc, -sc],
        1 => [-1.0, -tc, sc],
        2 => [sc, 1.0, tc],
        3 => [sc, -1.0, -tc],
        4 => [sc, -tc, 1.0],
        _ => [-sc, -tc, -1.0],
    }
}

fn mix(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    let t = t.clamp(0.0, 1.0);
    [0, 1, 2].map(|k| a[k] + (b[k] - a[k]) * t)
}

fn floor(x: f32) -> i32 {
    let i = x as i32;
    if (i as f32) > x {
        i - 1
    } else {
        i
    }
}

/// Diamond angle of `(x, z)`: a monotonic stand-in for the azimuth, in `[0, 4)`.
fn diamond(x: f32, z: f32) -> f32 {
    let s = x.abs() + z.abs();
    if s == 0.0 {
        return 0.0;
    }
    match (x >= 0.0, z >= 0.0) {
        (true, true) => z / s,
        (false, true) => 1.0 - x / s,
        (false, false) => 2.0 - z / s,
        (true, false) => 3.0 + x / s,
    }
}

/// Building heights (tangent of the elevation of the roof) per sector; 0 = gap.
const HEIGHTS: [f32; 32] = [
    0.22, 0.35, 0.0, 0.18, 0.5, 0.3, 0.0, 0.0, 0.26, 0.42, 0.15, 0.0, 0.33, 0.6, 0.24, 0.0, 0.19,
    0.0, 0.38, 0.28, 0.0, 0.45, 0.2, 0.3, 0.0, 0.16, 0.52, 0.0, 0.27, 0.36, 0.0, 0.21,
];
/// Facade colours (RGB 0..1), picked per sector.
const FACADES: [[f32; 3]; 4] = [
    [0.62, 0.25, 0.18],
    [0.55, 0.56, 0.6],
    [0.82, 0.7, 0.45],
    [0.3, 0.36, 0.48],
];

/// The environment's colour in direction `d` (any length, not zero), RGB in `0..=1`.
pub fn sky_colour(d: [f32; 3]) -> [f32; 3] {
    let [x, y, z] = d;
    let h = x.abs().max(z.abs());
    let elev = if h > 0.0 { y / h } else { y.signum() * 1e6 };
    if y < 0.0 {
        // Ground plane y = -1: checker of 1-unit cells, fading into haze.
        let (px, pz) = (x / -y, z / -y);
        let dist = px.abs().max(pz.abs());
        let check = (floor(px) + floor(pz)) & 1 == 0;
        let ground = if check {
            [0.2, 0.55, 0.2]
        } else {
            [0.9, 0.88, 0.8]
        };
        return mix(ground, [0.72, 0.8, 0.86], dist / 25.0);
    }
    // Buildings on the horizon.
    let a = diamond(x, z) * 8.0; // 32 sectors
    let sector = (floor(a) as usize) % 32;
    let height = HEIGHTS[sector];
    if elev < height {
        let u = a - floor(a) as f32;
        let fac = FACADES[sector % 4];
        if !(0.08..=0.92).contains(&u) {
            return mix(fac, [0.0; 3], 0.4);
        }
        let wu = (u * 6.0) - floor(u * 6.0) as f32;
        let wv = (elev * 40.0) - floor(elev * 40.0) as f32;
        if (0.3..0.75).contains(&wu) && (0.35..0.8).contains(&wv) && elev > 0.03 {
            let lit = (sector * 7 + floor(elev * 40.0) as usize).is_multiple_of(3);
            return if lit {
                [1.0, 0.85, 0.4]
            } else {
                [0.15, 0.22, 0.35]
            };
        }
        return fac;
    }
    // Sky and sun.
    let sun = [0.45f32, 0.5, -0.74];
    let len2 = x * x + y * y + z * z;
    let sd = x * sun[0] + y * sun[1] + z * sun[2];
    // sin² of the elevation: no square root, no corners on the +Y face.
    let s2 = y * y / len2;
    let sky = mix([0.75, 0.85, 0.97], [0.12, 0.3, 0.72], s2 * 1.6);
    if sd > 0.0 {
        let c2 = sd * sd / len2; // cos² of the angle to the sun (|sun| ~ 1)
        if c2 > 0.9962 {
            return [1.0, 0.97, 0.82];
        }
        if c2 > 0.96 {
            return mix(sky, [1.0, 0.93, 0.7], (c2 - 0.96) / 0.0362);
        }
    }
    sky
}

/// Fills `out` (`size * size` texels, row 0 first) with face `face` (0..=5, GL order) of
/// the sky environment.
///
/// # Errors
/// [`Error::WrongLength`] if `out` is not `size * size` long, [`Error::BadCubeMap`] if
/// `face > 5`.
pub fn sky_face(face: usize, size: u32, out: &mut [Rgb565]) -> Result<(), Error> {
    let need = size as usize * size as usize;
    if out.len() != need {
        return Err(Error::WrongLength {
            expected: need,
            actual: out.len(),
        });
    }
    if face > 5 {
        return Err(Error::BadCubeMap {
            face: face as u8,
            width: size,
            height: size,
        });
    }
    for (k, px) in out.iter_mut().enumerate() {
        let (i, j) = ((k as u32) % size, (k as u32) / size);
        // 2 x 2 supersampling per texel, so the ground checker does not alias.
        let mut acc = [0.0f32; 3];
        for (di, dj) in [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)] {
            let d = texel_direction(face, 0, 0, size);
            let step = 2.0 / size as f32;
            let (si, sj) = (i as f32 + di - 0.5, j as f32 + dj - 0.5);
            let d = match face {
                0 => [d[0], d[1] - sj * step, d[2] - si * step],
                1 => [d[0], d[1] - sj * step, d[2] + si * step],
                2 => [d[0] + si * step, d[1], d[2] + sj * step],
                3 => [d[0] + si * step, d[1], d[2] - sj * step],
                4 => [d[0] + si * step, d[1] - sj * step, d[2]],
                _ => [d[0] - si * step, d[1] - sj * step, d[2]],
            };
            let c = sky_colour(d);
            for k in 0..3 {
                acc[k] += c[k] * 0.25;
            }
        }
        let q = |c: f32, max: f32| (c.clamp(0.0, 1.0) * max + 0.5) as u8;
        *px = Rgb565::new(q(acc[0], 31.0), q(acc[1], 63.0), q(acc[2], 31.0));
    }
    Ok(())
}

/// Fills `out` (`w * h`, row 0 first) with the sky as a latitude-longitude map (see
/// [`latlong`](super::latlong): column `i` at longitude `λ = ((i + 0.5) / w − 1/2) 2π`, row
/// `j` at latitude `β = (1/2 − (j + 0.5) / h) π`), one sample per texel.
///
/// # Errors
/// [`Error::WrongLength`] if `out` is not `w * h` long.
pub fn sky_latlong(w: u32, h: u32, out: &mut [Rgb565]) -> Result<(), Error> {
    use micromath::F32Ext as M;
    let need = w as usize * h as usize;
    if out.len() != need {
        return Err(Error::WrongLength {
            expected: need,
            actual: out.len(),
        });
    }
    let pi = core::f32::consts::PI;
    for (k, px) in out.iter_mut().enumerate() {
        let (i, j) = ((k as u32) % w, (k as u32) / w);
        let lam = ((i as f32 + 0.5) / w as f32 - 0.5) * 2.0 * pi;
        let beta = (0.5 - (j as f32 + 0.5) / h as f32) * pi;
        let (sb, cb, sl, cl) = (M::sin(beta), M::cos(beta), M::sin(lam), M::cos(lam));
        let d = [cb * sl, sb, -cb * cl];
        *px = quantize(sky_colour(d));
    }
    Ok(())
}

/// Fills `out` (`size * size`, row 0 first) with the sky as a sphere map (see
/// [`sphere`](super::sphere): texel centre `(s, t)`, `ρ = |(2s − 1, 2t − 1)|` = `sin(θ/2)`),
/// one sample per texel. Texels in the last half texel of the disc and outside it take the
/// colour at `ρ = 1 − 1/(2 size)` on their radius: the rim (`r` pointing away from the
/// viewer, a singularity where every `φ` meets) then filters to the colours around it
/// rather than to black.
///
/// # Errors
/// [`Error::WrongLength`] if `out` is not `size * size` long.
pub fn sky_spheremap(size: u32, out: &mut [Rgb565]) -> Result<(), Error> {
    use micromath::F32Ext as M;
    let need = size as usize * size as usize;
    if out.len() != need {
        return Err(Error::WrongLength {
            expected: need,
            actual: out.len(),
        });
    }
    for (k, px) in out.iter_mut().enumerate() {
        let (i, j) = ((k as u32) % size, (k as u32) / size);
        let mut sx = 2.0 * (i as f32 + 0.5) / size as f32 - 1.0;
        let mut ty = 2.0 * (j as f32 + 0.5) / size as f32 - 1.0;
        let mut rho2 = sx * sx + ty * ty;
        // Outside the disc: the colour just inside the rim on the same radius, so a
        // bilinear lookup at the rim blends neighbouring rim colours, not black.
        let inner = 1.0 - 0.5 / size as f32;
        if rho2 > inner * inner {
            let scale = inner / M::sqrt(rho2);
            sx *= scale;
            ty *= scale;
            rho2 = inner * inner;
        }
        // rho = sin(θ/2): cos θ = 1 − 2 ρ², sin θ = 2 ρ sqrt(1 − ρ²); (rx, ry) along (sx, ty).
        let cz = 1.0 - 2.0 * rho2;
        let k = 2.0 * M::sqrt((1.0 - rho2).max(0.0));
        *px = quantize(sky_colour([sx * k, ty * k, cz]));
    }
    Ok(())
}

fn quantize(c: [f32; 3]) -> Rgb565 {
    let q = |c: f32, max: f32| (c.clamp(0.0, 1.0) * max + 0.5) as u8;
    Rgb565::new(q(c[0], 31.0), q(c[1], 63.0), q(c[2], 31.0))
}
