//! Colour formats and the per-pixel colour arithmetic: RGB565 packing, conversion to the
//! display's colour type, and modulation of a texel by a (Gouraud) intensity.
//!
//! Units and conventions:
//! - Raw RGB565 is a `u16` laid out `rrrrr gggggg bbbbb` (red in bits 15..=11, green in
//!   10..=5, blue in 4..=0), the same as `Rgb565::into_storage()` in embedded-graphics.
//!   Channel ranges: red and blue 0..=31, green 0..=63.
//! - Expansion to 8 bits replicates the top bits into the bottom (`r8 = r5 << 3 | r5 >> 2`,
//!   `g8 = g6 << 2 | g6 >> 4`), so 0 maps to 0 and full scale to 255 exactly.
//! - Intensities and modulation factors are unsigned Q8: `256` is 1.0, `0` is black. Values
//!   above 256 are clamped to 256 (modulation never brightens and never overflows a channel).
//!   Each channel becomes `(c * f + 128) >> 8`, i.e. `c * f / 256` rounded half up.
//! - All arithmetic is in `u16`/`u32`, at most one 32-bit multiply per channel pair; no
//!   division, no 64-bit multiply and no floating point (Cortex-M0+ friendly). Nothing here
//!   can panic or overflow for any input.

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor, Rgb565, Rgb888, RgbColor};

/// `out` as raw RGB565 values, for a span loop that stores them directly
/// ([`Shader::shade_piece_rgb565`](crate::shading::Shader::shade_piece_rgb565)): `Some` when
/// `C` is [`Rgb565`], `None` otherwise. Only on targets with such a loop (ARMv7E-M).
#[cfg(fixel_dsp)]
#[inline(always)]
#[allow(unsafe_code)]
pub(crate) fn raw_rgb565_mut<C: TargetColor>(out: &mut [C]) -> Option<&mut [u16]> {
    if core::any::TypeId::of::<C>() == core::any::TypeId::of::<Rgb565>() {
        // `Rgb565` is one `u16` field (its raw value, any value valid) and nothing else.
        const _: () =
            assert!(core::mem::size_of::<Rgb565>() == 2 && core::mem::align_of::<Rgb565>() == 2);
        // SAFETY: `C` is `Rgb565` (same `TypeId`), a struct whose only field is the raw
        // `u16` (embedded-graphics' `Rgb565(u16)`, storing `RawU16` values unchanged); its size
        // and alignment are 2 (asserted above), so that field fills it at offset 0, and every
        // `u16` is a valid `Rgb565`. The slice covers exactly `out`'s elements and borrows
        // `out` mutably for its lifetime. Tested: `raw_rgb565_is_the_storage`.
        return Some(unsafe {
            core::slice::from_raw_parts_mut(out.as_mut_ptr().cast::<u16>(), out.len())
        });
    }
    None
}

/// A colour type the rasterizer can write: built from a raw RGB565 value.
///
/// Implemented for:
/// - [`Rgb565`]: identity on the storage value.
/// - [`Rgb888`]: each channel expanded with bit replication
///   (`r8 = r5 << 3 | r5 >> 2`, `g8 = g6 << 2 | g6 >> 4`, `b8 = b5 << 3 | b5 >> 2`).
/// - [`Gray8`]: luma `(r8 * 77 + g8 * 150 + b8 * 29 + 128) >> 8` of the expanded 8-bit
///   channels (BT.601 weights in Q8, summing to 256; white maps to 255, black to 0).
pub trait TargetColor: Copy + Default + PartialEq + core::fmt::Debug + 'static {
    /// Converts a raw RGB565 value (`rrrrr gggggg bbbbb`) to this colour type.
    fn from_rgb565(raw: u16) -> Self;

    /// This colour as raw RGB565, for shaders that blend with what the target holds
    /// ([`Shader::BLENDS`](crate::shading::Shader::BLENDS)): exact for [`Rgb565`], rounded
    /// to nearest from [`Rgb888`], the grey level for [`Gray8`]. The default reads black.
    #[inline(always)]
    fn to_rgb565(self) -> u16 {
        0
    }
}

impl TargetColor for Rgb565 {
    #[inline(always)]
    fn from_rgb565(raw: u16) -> Self {
        Rgb565::from(RawU16::new(raw))
    }
    #[inline(always)]
    fn to_rgb565(self) -> u16 {
        RawU16::from(self).into_inner()
    }
}

impl TargetColor for Rgb888 {
    #[inline(always)]
    fn from_rgb565(raw: u16) -> Self {
        let (r, g, b) = expand_565(raw);
        Rgb888::new(r, g, b)
    }
    #[inline(always)]
    fn to_rgb565(self) -> u16 {
        let q = |v: u8, max: u32| ((u32::from(v) * max + 127) / 255) as u8;
        rgb565(q(self.r(), 31), q(self.g(), 63), q(self.b(), 31))
    }
}

impl TargetColor for Gray8 {
    #[inline(always)]
    fn from_rgb565(raw: u16) -> Self {
        let (r, g, b) = expand_565(raw);
        // Max: 255 * 256 + 128 = 65408, >> 8 = 255: fits in u8.
        let luma = (r as u32 * 77 + g as u32 * 150 + b as u32 * 29 + 128) >> 8;
        Gray8::new(luma as u8)
    }
    #[inline(always)]
    fn to_rgb565(self) -> u16 {
        let l = self.luma();
        let q = |max: u32| ((u32::from(l) * max + 127) / 255) as u8;
        rgb565(q(31), q(63), q(31))
    }
}

/// Splits raw RGB565 into 8-bit channels expanded by bit replication.
#[inline(always)]
fn expand_565(raw: u16) -> (u8, u8, u8) {
    let r5 = (raw >> 11) as u8; // 0..=31
    let g6 = ((raw >> 5) & 0x3F) as u8; // 0..=63
    let b5 = (raw & 0x1F) as u8; // 0..=31
    (r5 << 3 | r5 >> 2, g6 << 2 | g6 >> 4, b5 << 3 | b5 >> 2)
}

/// Packs channels into raw RGB565. Out-of-range inputs are masked (`r5 & 31`, `g6 & 63`,
/// `b5 & 31`), as `Rgb565::new` does.
#[inline(always)]
pub const fn rgb565(r5: u8, g6: u8, b5: u8) -> u16 {
    ((r5 as u16 & 0x1F) << 11) | ((g6 as u16 & 0x3F) << 5) | (b5 as u16 & 0x1F)
}

/// Exact `x / 255` for `x <= 65534` without a divider.
#[inline(always)]
const fn div255(x: u32) -> u32 {
    (x + 1 + (x >> 8)) >> 8
}

/// Converts 8-bit channels to raw RGB565, rounding each to the nearest representable level:
/// `r5 = (r * 31 + 127) / 255`, `g6 = (g * 63 + 127) / 255`, `b5 = (b * 31 + 127) / 255`
/// (integer division; computed with an exact multiply-free `/ 255`). 0 maps to 0 and 255 to
/// full scale.
#[inline]
pub fn rgb888_to_565(r: u8, g: u8, b: u8) -> u16 {
    let r5 = div255(r as u32 * 31 + 127);
    let g6 = div255(g as u32 * 63 + 127);
    let b5 = div255(b as u32 * 31 + 127);
    ((r5 << 11) | (g6 << 5) | b5) as u16
}

/// Modulates a raw RGB565 texel by a Q8 intensity `i` (256 = 1.0; values above 256 are
/// treated as 256): every channel becomes `(c * i + 128) >> 8`.
///
/// Cost: two 32-bit multiplies. Red and blue share one `u32` (red moved to bit 16, blue at
/// bit 0; each product is at most 31 * 256 = 7936 < 2^13, so the lanes never touch) and green
/// takes the second.
#[inline(always)]
pub fn modulate_scalar(texel: u16, i: u16) -> u16 {
    let i = if i > 256 { 256 } else { i as u32 };
    let t = texel as u32;
    // R at bits 16..=20, B at bits 0..=4.
    let rb = ((t & 0xF800) << 5) | (t & 0x001F);
    let rb = ((rb * i + 0x0080_0080) >> 8) & 0x001F_001F;
    let g = ((((t >> 5) & 0x3F) * i + 128) >> 8) & 0x3F;
    (((rb >> 5) & 0xF800) | (g << 5) | (rb & 0x1F)) as u16
}

/// Modulates a raw RGB565 texel by separate Q8 factors per channel (256 = 1.0; values above
/// 256 are treated as 256): `r' = (r * fr + 128) >> 8` and likewise for green and blue.
///
/// Cost: three 32-bit multiplies.
#[inline(always)]
pub fn modulate_rgb(texel: u16, r: u16, g: u16, b: u16) -> u16 {
    let fr = if r > 256 { 256 } else { r as u32 };
    let fg = if g > 256 { 256 } else { g as u32 };
    let fb = if b > 256 { 256 } else { b as u32 };
    let t = texel as u32;
    let r5 = (((t >> 11) * fr + 128) >> 8) & 0x1F;
    let g6 = ((((t >> 5) & 0x3F) * fg + 128) >> 8) & 0x3F;
    let b5 = (((t & 0x1F) * fb + 128) >> 8) & 0x1F;
    ((r5 << 11) | (g6 << 5) | b5) as u16
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use embedded_graphics_core::pixelcolor::{GrayColor, IntoStorage, RgbColor};

    fn chan(t: u16) -> (u32, u32, u32) {
        (
            (t >> 11) as u32,
            ((t >> 5) & 0x3F) as u32,
            (t & 0x1F) as u32,
        )
    }

    /// What `raw_rgb565_mut` relies on: an `Rgb565`'s two bytes are its raw value, for
    /// every value (read back through a byte copy, on the host as on the firmware's cores).
    #[test]
    fn raw_rgb565_is_the_storage() {
        assert_eq!(core::mem::size_of::<Rgb565>(), 2);
        assert_eq!(core::mem::align_of::<Rgb565>(), 2);
        for raw in 0..=u16::MAX {
            let c = Rgb565::from_rgb565(raw);
            #[allow(unsafe_code)]
            // SAFETY: `Rgb565` is 2 bytes (asserted above), as `u16`; any bytes are a `u16`.
            let bytes: u16 = unsafe { core::mem::transmute::<Rgb565, u16>(c) };
            assert_eq!(bytes, raw);
            assert_eq!(c.into_storage(), raw);
        }
    }

    fn reference_mod(c: u32, f: u32) -> u32 {
        (c * f.min(256) + 128) / 256
    }

    #[test]
    fn rgb565_packs_and_masks() {
        assert_eq!(rgb565(31, 63, 31), 0xFFFF);
        assert_eq!(rgb565(0, 0, 0), 0);
        assert_eq!(rgb565(1, 0, 0), 0x0800);
        assert_eq!(rgb565(0, 1, 0), 0x0020);
        assert_eq!(rgb565(0, 0, 1), 0x0001);
        assert_eq!(rgb565(0xFF, 0xFF, 0xFF), 0xFFFF);
        for r in 0..32u8 {
            for g in 0..64u8 {
                for b in 0..32u8 {
                    assert_eq!(rgb565(r, g, b), Rgb565::new(r, g, b).into_storage());
                }
            }
        }
    }

    #[test]
    fn div255_is_exact() {
        for x in 0..=65534u32 {
            assert_eq!(div255(x), x / 255, "x = {x}");
        }
    }

    #[test]
    fn rgb888_to_565_rounds_to_nearest() {
        for c in 0..=255u32 {
            let raw = rgb888_to_565(c as u8, c as u8, c as u8);
            let (r, g, b) = chan(raw);
            assert_eq!(r, (c * 31 + 127) / 255);
            assert_eq!(g, (c * 63 + 127) / 255);
            assert_eq!(b, (c * 31 + 127) / 255);
            // Nearest level: distance to the chosen level is at most half a step.
            let er = (r as f64 * 255.0 / 31.0 - c as f64).abs();
            let eg = (g as f64 * 255.0 / 63.0 - c as f64).abs();
            assert!(er <= 255.0 / 31.0 / 2.0 + 1e-9, "c = {c}");
            assert!(eg <= 255.0 / 63.0 / 2.0 + 1e-9, "c = {c}");
        }
        assert_eq!(rgb888_to_565(255, 255, 255), 0xFFFF);
        assert_eq!(rgb888_to_565(255, 0, 0), 0xF800);
        assert_eq!(rgb888_to_565(0, 255, 0), 0x07E0);
        assert_eq!(rgb888_to_565(0, 0, 255), 0x001F);
    }

    #[test]
    fn target_color_conversions() {
        for raw in 0..=u16::MAX {
            assert_eq!(Rgb565::from_rgb565(raw).into_storage(), raw);
            let (r5, g6, b5) = chan(raw);
            let c = Rgb888::from_rgb565(raw);
            assert_eq!(c.r() as u32, (r5 << 3) | (r5 >> 2));
            assert_eq!(c.g() as u32, (g6 << 2) | (g6 >> 4));
            assert_eq!(c.b() as u32, (b5 << 3) | (b5 >> 2));
            // Bit replication is within 1 of the exact c * 255 / max.
            assert!((c.r() as f64 - r5 as f64 * 255.0 / 31.0).abs() < 1.0);
            assert!((c.g() as f64 - g6 as f64 * 255.0 / 63.0).abs() < 1.0);
            let y = Gray8::from_rgb565(raw).luma() as u32;
            let yr = (c.r() as u32 * 77 + c.g() as u32 * 150 + c.b() as u32 * 29 + 128) / 256;
            assert_eq!(y, yr);
        }
        assert_eq!(Rgb888::from_rgb565(0xFFFF), Rgb888::WHITE);
        assert_eq!(Gray8::from_rgb565(0xFFFF), Gray8::WHITE);
        assert_eq!(Gray8::from_rgb565(0), Gray8::BLACK);
    }

    #[test]
    fn modulate_scalar_exhaustive() {
        for texel in 0..=u16::MAX {
            let (r, g, b) = chan(texel);
            for i in (0..=260u16).chain([511, 1000, u16::MAX]) {
                let m = modulate_scalar(texel, i);
                let (mr, mg, mb) = chan(m);
                let f = i as u32;
                assert_eq!(
                    (mr, mg, mb),
                    (
                        reference_mod(r, f),
                        reference_mod(g, f),
                        reference_mod(b, f)
                    ),
                    "texel {texel:#06x} i {i}"
                );
            }
        }
        assert_eq!(modulate_scalar(0xFFFF, 256), 0xFFFF);
        assert_eq!(modulate_scalar(0xFFFF, 0), 0);
    }

    #[test]
    fn modulate_rgb_exhaustive_per_channel() {
        // Every texel with every (equal) factor, plus every channel value with every factor
        // while the other two channels and factors vary (channels are independent).
        let mut seed = 0x1234_5678u32;
        let mut rnd = move || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        let check = |texel: u16, fr: u16, fg: u16, fb: u16| {
            let (r, g, b) = chan(texel);
            let (mr, mg, mb) = chan(modulate_rgb(texel, fr, fg, fb));
            assert_eq!(
                (mr, mg, mb),
                (
                    reference_mod(r, fr as u32),
                    reference_mod(g, fg as u32),
                    reference_mod(b, fb as u32)
                ),
                "texel {texel:#06x} f {fr} {fg} {fb}"
            );
        };
        for texel in 0..=u16::MAX {
            for f in (0..=257u16).step_by(3).chain([256, u16::MAX]) {
                check(texel, f, f, f);
            }
        }
        for f in (0..=300u16).chain([u16::MAX]) {
            for c in 0..64u16 {
                for _ in 0..4 {
                    let x = rnd();
                    let other = (x >> 16) as u16;
                    let fo = (x & 0x1FF) as u16;
                    if c < 32 {
                        check((other & 0x07FF) | (c << 11), f, fo, fo ^ 7);
                        check((other & 0xFFE0) | c, fo, fo ^ 5, f);
                    }
                    check((other & 0xF81F) | (c << 5), fo, f, fo ^ 3);
                }
            }
        }
    }

    #[test]
    fn modulate_agree() {
        for texel in (0..=u16::MAX).step_by(7) {
            for i in 0..=256u16 {
                assert_eq!(modulate_scalar(texel, i), modulate_rgb(texel, i, i, i));
            }
        }
    }
}
