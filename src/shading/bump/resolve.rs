//! A bump-mapped sphere's lighting resolved into a texture for a light fixed in object
//! space: the real-time form of bump mapping. The per-pixel work of [`Bumped`](super::Bumped)
//! (a tangent-space normal fetched and renormalised, the light turned into the tangent
//! frame and renormalised, the material) is done once per texel of the sphere's texture,
//! at start-up into caller storage or at build time; drawing is then a plain unlit
//! textured draw (the lighting is in the texels), costing what any textured draw costs.
//! Valid while the light does not move relative to the object (a light fixed to a watch
//! face, or to a model that turns with its light); a moving light needs the resolve again.
//!
//! The sphere is the UV sphere's texture space ([`SphereSurface`](crate::shading::noise::SphereSurface)'s
//! convention): texel `(i, j)` of the `width x height` output has `s = (i + ½) / width`,
//! `t = (j + ½) / height`, polar angle `θ = π t` from `+y`, azimuth `φ = 2π s`, and the
//! orthonormal frame
//!
//! ```text
//! n = (sin θ cos φ, cos θ, −sin θ sin φ)     (outward)
//! t = (−sin φ, 0, −cos φ)                    (along ∂p/∂s)
//! b = (cos θ cos φ, −sin θ, −cos θ sin φ)    (along ∂p/∂t)
//! ```
//!
//! The colour tile and the normal source repeat across the output (`width` a multiple of
//! the tile's width, `height` of its height): texel `(i, j)` reads tile texel
//! `(i mod w, j mod h)`, as a mesh whose texture coordinates are scaled by
//! `(width / w, height / h)` does. Its colour is `lit_texel(colour, ka + kd max(0, n'·l), s)`
//! with `n'` the unit perturbed normal and `l` the unit light direction in that texel's
//! tangent frame; the specular term (usually set to 0 here) is for a view along the surface
//! normal.

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::Rgb565;

use super::normals::TangentNormals;
use crate::math::{sin_cos, unit_q14, Angle, Vec3};
use crate::shading::lighting::{lit_texel, Material};
use crate::shading::TexTriangle;
use crate::texture::{MipTexture, Texture};
use crate::Error;

/// Lights the sphere's `width x height` texture `out` (row 0 first) for the object-space
/// direction `light` towards a directional light (any length), from the colour tile
/// `colours` and the tangent-space normals `normals` (the tile's size, repeating).
///
/// # Errors
/// Those of [`MipTexture::new`] for `out` (sides not powers of two, or a length other
/// than `width · height`); [`Error::BadMode`] when the output is not a whole number of
/// tiles; [`Error::ZeroVector`] for a zero light direction.
pub fn resolve_sphere<N: TangentNormals>(
    colours: &Texture<'_>,
    normals: &N,
    material: &Material<'_>,
    light: Vec3,
    width: u32,
    height: u32,
    out: &mut [Rgb565],
) -> Result<(), Error> {
    MipTexture::new(out, width, height, 1)?;
    let (tw, th) = (colours.width(), colours.height());
    if !width.is_multiple_of(tw) || !height.is_multiple_of(th) {
        return Err(Error::BadMode(
            "the resolved texture must hold a whole number of colour tiles",
        ));
    }
    let l = unit_q14([light.x.to_bits(), light.y.to_bits(), light.z.to_bits()]);
    if l == [0; 3] {
        return Err(Error::ZeroVector("the light direction"));
    }
    // Q16 turns of a texel centre: (2k + 1) / (2 size) of a turn (half a turn for θ).
    let angle = |k: u32, size: u32, half: bool| {
        let q = ((u64::from(2 * k + 1)) << 15) / u64::from(size);
        Angle((if half { q >> 1 } else { q }) as u16)
    };
    // Q16 x Q14 products summed, back to Q14.
    let dot = |a: [i32; 3], b: [i32; 3]| {
        ((i64::from(a[0]) * i64::from(b[0])
            + i64::from(a[1]) * i64::from(b[1])
            + i64::from(a[2]) * i64::from(b[2]))
            >> 16) as i32
    };
    for j in 0..height {
        let (st, ct) = sin_cos(angle(j, height, true));
        let (st, ct) = (st.to_bits(), ct.to_bits());
        for i in 0..width {
            let (sp, cp) = sin_cos(angle(i, width, false));
            let (sp, cp) = (sp.to_bits(), cp.to_bits());
            let q = |a: i32, b: i32| ((i64::from(a) * i64::from(b)) >> 16) as i32;
            let n = [q(st, cp), ct, -q(st, sp)];
            let t = [-sp, 0, -cp];
            let b = [q(ct, cp), -st, -q(ct, sp)];
            let lt = unit_q14([dot(t, l), dot(b, l), dot(n, l)]);
            let (u, v) = ((i as i32) << 16 | 0x8000, (j as i32) << 16 | 0x8000);
            let nt = unit_q14(normals.normal(TexTriangle::default(), u, v, 0));
            let (d, s) = material.light(nt, lt, [0, 0, 1 << 14]);
            let c = colours.texel_raw(i % tw, j % th);
            if let Some(px) = out.get_mut((j * width + i) as usize) {
                *px = Rgb565::from(RawU16::new(lit_texel(c, d, s)));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Fx;
    use crate::shading::bump::HeightDifferences;
    use crate::shading::lighting::{Specular, SpecularTable};
    use crate::texture::HeightMap;

    #[test]
    fn flat_tile_is_lambert_and_sizes_are_checked() {
        let white = [Rgb565::new(31, 63, 31); 4];
        let tile = Texture::new(&white, 2, 2).unwrap();
        let heights = [0u8; 4];
        let map = HeightMap::new(&heights, 2, 2, 1).unwrap();
        let flat = HeightDifferences::new(map, Fx::from_num(0.5)).unwrap();
        let table = SpecularTable::new(8).unwrap();
        let m = Material::new(0, 256, 0, Specular::None, &table).unwrap();
        let mut out = [Rgb565::new(0, 0, 0); 8 * 4];
        // Light from +y: the top rows bright, the bottom rows dark.
        resolve_sphere(&tile, &flat, &m, Vec3::from_num(0, 1, 0), 8, 4, &mut out).unwrap();
        let g = |k: usize| {
            embedded_graphics_core::pixelcolor::IntoStorage::into_storage(out[k]) >> 5 & 63
        };
        assert!(g(0) > 50 && g(31) == 0, "{} {}", g(0), g(31));
        assert!(resolve_sphere(&tile, &flat, &m, Vec3::ZERO, 8, 4, &mut out).is_err());
        assert!(resolve_sphere(
            &tile,
            &flat,
            &m,
            Vec3::from_num(0, 1, 0),
            8,
            4,
            &mut out[..31]
        )
        .is_err());
        let big = [Rgb565::new(0, 0, 0); 16];
        let t4 = Texture::new(&big, 4, 4).unwrap();
        let mut o2 = [Rgb565::new(0, 0, 0); 2 * 2];
        assert!(resolve_sphere(&t4, &flat, &m, Vec3::from_num(0, 1, 0), 2, 2, &mut o2).is_err());
    }
}
