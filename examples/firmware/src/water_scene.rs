//! The `water` scene (`cargo xtask mcu`): run-time displacement mapping
//! (`fixel::scene::displace`). A flat 6 x 6-quad grid subdivided once (169 vertices, 288
//! triangles, baked into flash by `cargo xtask bake-displaced --mesh water`) is displaced
//! every frame by the swell height map with an offset that moves with the frame number,
//! its normals recomputed, then drawn lit in 320 x 8 bands. The displaced positions and
//! normals are the only per-frame RAM the technique adds: 24 bytes per vertex, 4 KB.
//! Included by the firmware binaries and by the host's checksum test.

use crate::scenes::{render, Buffers, FrameResult, LitSphere, Target};
use fixel::math::{Angle, Fx, Mat4, Vec3};
use fixel::scene::{displace, displace_positions, recompute_normals, Displacement, Mesh};
use fixel::texture::{HeightMap, MipTexture, Texture};
use fixel::Error;

/// Vertices of the subdivided grid.
pub const WATER_VERTICES: usize = 169;
/// Triangles of the subdivided grid (band ranges: one per triangle).
pub const WATER_TRIANGLES: usize = 288;
/// Side of the swell height map.
pub const WAVE_SIDE: u32 = 64;

/// Set-ups kept across bands (100 B each): fewer than the sphere's, the water firmware keeps
/// its displaced mesh in RAM.
pub const WATER_SETUPS: usize = 17;

/// The band buffers: ranges for the grid's triangles, a 64-entry vertex cache,
/// [`WATER_SETUPS`] kept set-ups.
pub type WaterBuffers = Buffers<WATER_TRIANGLES, 64, 0, WATER_SETUPS>;

/// The swell of frame `i`: scale 0.6 units per 256 steps about mid-grey, the offset moving
/// `(i, 2 i) / 128` of the map per frame.
pub fn water_displacement(heights: &[u8], i: u32) -> Result<Displacement<'_>, Error> {
    let step = (i as i32).wrapping_mul(512);
    Ok(Displacement {
        map: HeightMap::new(heights, WAVE_SIDE, WAVE_SIDE, 1)?,
        scale: Fx::from_bits(39322),
        bias: Fx::from_bits(1 << 15),
        offset: [Fx::from_bits(step), Fx::from_bits(step.wrapping_mul(2))],
    })
}

/// The grid seen from above and in front: `T(0, -0.4, -6) Rx(35°)`.
pub fn water_model() -> Mat4 {
    Mat4::translation(Vec3::from_num(0, -0.4, -6))
        * Mat4::rotation_x(Angle::from_degrees(Fx::from_num(35)))
}

/// Only the displacement of frame `i` (positions, then normals) into `positions` and
/// `normals`: what `water_displace` counts per vertex.
pub fn water_displace_only(
    base: &Mesh<'_>,
    heights: &[u8],
    positions: &mut [Vec3],
    normals: &mut [Vec3],
    i: u32,
) -> Result<(), Error> {
    let d = water_displacement(heights, i)?;
    displace_positions(&d, base, None, positions)?;
    let fallback = base.normals().unwrap_or(&[]);
    recompute_normals(positions, base.indices(), fallback, None, normals)
}

/// Frame `i` of the scene: displace `base` (the flat grid) into `positions` and `normals`,
/// then draw it lit with `texture` (the checker `T(64, 64)`) into `buf` (in bands through
/// [`WaterBuffers`], or whole).
#[allow(clippy::too_many_arguments)]
pub fn water<const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    texture: Texture<'_>,
    base: &Mesh<'_>,
    heights: &[u8],
    positions: &mut [Vec3],
    normals: &mut [Vec3],
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let d = water_displacement(heights, i)?;
    let mesh = displace(&d, base, None, positions, normals)?;
    render::<LitSphere, R, V, B, S>(
        buf,
        MipTexture::single(texture),
        &mesh,
        &water_model(),
        20,
        true,
        pause,
        resume,
    )
}

/// A `water` firmware: frame 3 of the scene into `target` (bands or whole), counted and
/// reported as scene `name` (firmware only; the host tests include this file for the scene
/// code above).
#[cfg(target_os = "none")]
pub fn run_firmware<const R: usize, const V: usize, const B: usize, const S: usize>(
    name: &str,
    target: Target<'_, R, V, B, S>,
) -> bool {
    mod base {
        include!("../../../assets/displaced/water_base.rs");
    }
    static mut POSITIONS: [Vec3; WATER_VERTICES] = [Vec3::ZERO; WATER_VERTICES];
    static mut NORMALS: [Vec3; WATER_VERTICES] = [Vec3::ZERO; WATER_VERTICES];
    // SAFETY: the only references to these statics, taken once in this single-threaded
    // firmware (each firmware calls this function once).
    let (positions, normals) = unsafe {
        (
            &mut *core::ptr::addr_of_mut!(POSITIONS),
            &mut *core::ptr::addr_of_mut!(NORMALS),
        )
    };
    let Ok(mesh) = Mesh::new(
        core::hint::black_box(&base::WATER_POSITIONS),
        Some(&base::WATER_NORMALS),
        &base::WATER_UVS,
        &base::WATER_INDICES,
    ) else {
        return false;
    };
    let frame = core::hint::black_box(3);
    fixel_firmware::report(name, |pause, resume| {
        water(
            target,
            fixel_firmware::data::T64,
            &mesh,
            &base::WATER_HEIGHTS,
            positions,
            normals,
            frame,
            pause,
            resume,
        )
    })
}
