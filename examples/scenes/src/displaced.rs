//! The displacement-mapping demos' inputs ([`fixel::scene::displace`]), procedural and
//! fixed point so the example, the tests, `cargo xtask bake-displaced` and the firmware
//! build the same bytes:
//!
//! * [`rock_heights`]: a 128 x 64 height map for the demo sphere's coordinates
//!   ([`super::uv_sphere`]: `u` around, `v` from pole to pole), fractal Perlin noise of
//!   the 3D point on the sphere (so it is continuous across the seam and at the poles): a
//!   rocky, cratered moon;
//! * [`wave_heights`]: a 64 x 64 tileable swell of four sine waves, for a water surface
//!   animated by moving the displacement's offset;
//! * [`grid`]: a flat square grid facing `+y`, the water's base mesh.
//!
//! ```
//! use fixel_scenes::displaced::{rock_heights, ROCK_HEIGHT, ROCK_WIDTH};
//! use fixel::texture::HeightMap;
//! let mut h = [0u8; (ROCK_WIDTH * ROCK_HEIGHT) as usize];
//! rock_heights(&mut h)?;
//! let map = HeightMap::new(&h, ROCK_WIDTH, ROCK_HEIGHT, 1)?;
//! assert!(h.iter().any(|&x| x > 160) && h.iter().any(|&x| x < 96));
//! # let _ = map;
//! # Ok::<(), fixel::Error>(())
//! ```

use super::MeshData;
use fixel::math::{Angle, Fx, Vec3};
use fixel::shading::noise::noise3;
use fixel::Error;

/// Width of [`rock_heights`] (around the sphere).
pub const ROCK_WIDTH: u32 = 128;
/// Height of [`rock_heights`] (pole to pole).
pub const ROCK_HEIGHT: u32 = 64;
/// Side of [`wave_heights`].
pub const WAVE_SIDE: u32 = 64;

fn check(out: &[u8], n: u32) -> Result<(), Error> {
    if out.len() == n as usize {
        Ok(())
    } else {
        Err(Error::WrongLength {
            expected: n as usize,
            actual: out.len(),
        })
    }
}

/// The rocky sphere's heights: texel `(i, j)` is the point at azimuth
/// `2π (i + 0.5) / 128` and polar angle `π (j + 0.5) / 64` on the unit sphere (as in
/// [`super::uv_sphere`]), its height 5 octaves of Perlin noise from 3 cells across plus
/// ridges where coarser noise crosses zero, mid-grey on average. `out` has 128 x 64 entries
/// ([`Error::WrongLength`] otherwise).
pub fn rock_heights(out: &mut [u8]) -> Result<(), Error> {
    rock_heights_sized(ROCK_WIDTH, ROCK_HEIGHT, out)
}

/// [`rock_heights`] sampled on a `width x height` grid (the same surface, finer or
/// coarser: for a bump map at the resolution of the screen), `width` and `height`
/// powers of two from 2 to 32768. `out` has `width x height` entries.
///
/// # Errors
/// [`Error::WrongLength`] for another length, [`Error::NotPowerOfTwo`] or
/// [`Error::BadSize`] for a bad side.
pub fn rock_heights_sized(width: u32, height: u32, out: &mut [u8]) -> Result<(), Error> {
    for side in [width, height] {
        if !(2..=1 << 15).contains(&side) {
            return Err(Error::BadSize(side));
        }
        if !side.is_power_of_two() {
            return Err(Error::NotPowerOfTwo(side));
        }
    }
    check(out, width * height)?;
    for j in 0..height {
        // Polar angle pi (j + 0.5) / height: (2 j + 1) / (4 height) turn.
        let (st, ct) = sin_cos(((2 * j + 1) << 14) / height);
        for i in 0..width {
            // Azimuth 2 pi (i + 0.5) / width: (2 i + 1) / (2 width) turn.
            let (sp, cp) = sin_cos(((2 * i + 1) << 15) / width);
            let n = [
                st.saturating_mul(cp).to_bits(),
                ct.to_bits(),
                st.saturating_mul(sp).saturating_neg().to_bits(),
            ];
            // Fractal noise, Q15: octaves at 1.5, 3, 6, 12, 24 cells per unit, halving.
            let mut sum = 0i32;
            for k in 0..5 {
                let f = 3 << k; // half-cells per unit
                let at = |c: i32, o: i32| (c >> 1).wrapping_mul(f).wrapping_add(o << 14);
                sum += noise3(at(n[0], 3 + k), at(n[1], 7), at(n[2], 11 - k)) >> k;
            }
            // Ridges where a coarser noise crosses zero.
            let rim = noise3(n[0] * 2, n[1] * 2 + (5 << 16), n[2] * 2);
            let rim = (6000 - rim.abs()).max(0);
            let h = 128 + ((sum * 150) >> 15) + ((rim * 60) >> 12) - 40;
            out[(j * width + i) as usize] = h.clamp(0, 255) as u8;
        }
    }
    Ok(())
}

/// Sine and cosine of `a / 65536` turn (wrapping), I16F16.
fn sin_cos(a: u32) -> (Fx, Fx) {
    let a = Angle(a as u16);
    (a.sin(), a.cos())
}

/// The water's heights: a tileable swell of four sine waves (whole numbers of periods
/// across the map, so it repeats without a seam), `128 ± 120`. `out` has 64 x 64 entries.
pub fn wave_heights(out: &mut [u8]) -> Result<(), Error> {
    check(out, WAVE_SIDE * WAVE_SIDE)?;
    // (periods along u, periods along v, amplitude in steps).
    const WAVES: [(i32, i32, i32); 4] = [(1, 2, 50), (3, -1, 35), (-2, 5, 20), (7, 4, 12)];
    for j in 0..WAVE_SIDE as i32 {
        for i in 0..WAVE_SIDE as i32 {
            let mut h = 128i32;
            for (fu, fv, amp) in WAVES {
                // Phase in 1/65536 turns: (fu i + fv j) / 64 turn.
                let phase = (fu * i + fv * j) * 1024;
                h += (Angle(phase as u16).sin().to_bits() * amp) >> 16;
            }
            out[(j * WAVE_SIDE as i32 + i) as usize] = h.clamp(0, 255) as u8;
        }
    }
    Ok(())
}

/// A flat `n x n`-quad grid on `y = 0`, `x` and `z` in `[-half, half]`, normals `+y`,
/// uv = `((x + half) / 2 half, (z + half) / 2 half)`, counter-clockwise seen from above.
/// `V` must be `(n + 1)^2` and `T` `2 n^2`; what does not fit is left out (never a panic).
pub fn grid<const V: usize, const T: usize>(n: u16, half: Fx) -> MeshData<V, T> {
    let mut m = MeshData {
        positions: [Vec3::ZERO; V],
        normals: [Vec3::new(Fx::ZERO, Fx::ONE, Fx::ZERO); V],
        uvs: [[Fx::ZERO; 2]; V],
        indices: [[0; 3]; T],
    };
    let n = n.max(1);
    let side = usize::from(n) + 1;
    for j in 0..side {
        for i in 0..side {
            let k = j * side + i;
            if k >= V {
                continue;
            }
            let f = |c: usize| Fx::from_bits(((c as i64) << 16) as i32 / i32::from(n));
            let (u, v) = (f(i), f(j));
            let at = |t: Fx| (t.saturating_mul(Fx::from_num(2)) - Fx::ONE).saturating_mul(half);
            m.positions[k] = Vec3::new(at(u), Fx::ZERO, at(v));
            m.uvs[k] = [u, v];
        }
    }
    let id = |i: usize, j: usize| (j * side + i) as u16;
    let mut t = 0;
    for j in 0..usize::from(n) {
        for i in 0..usize::from(n) {
            let (a, b, c, d) = (id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j));
            for tri in [[a, b, c], [a, c, d]] {
                if let Some(slot) = m.indices.get_mut(t) {
                    *slot = tri;
                }
                t += 1;
            }
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_faces_up_and_maps_whole() {
        let g: MeshData<9, 8> = grid(2, Fx::ONE);
        assert_eq!(g.positions[8], Vec3::from_num(1, 0, 1));
        assert_eq!(g.uvs[8], [Fx::ONE, Fx::ONE]);
        for t in g.indices {
            let p = t.map(|i| g.positions[usize::from(i)]);
            let n = p[1].sub(p[0]).cross(p[2].sub(p[0]));
            assert!(n.y > Fx::ZERO);
        }
        assert!(g.mesh().is_ok());
    }

    #[test]
    fn waves_tile() {
        let mut h = [0u8; 64 * 64];
        wave_heights(&mut h).unwrap();
        assert!(h.iter().any(|&x| x > 200) && h.iter().any(|&x| x < 56));
        assert!(rock_heights(&mut h).is_err());
    }
}
