//! Height maps: 8-bit heights on a power-of-two grid, with an optional mip chain, for bump
//! mapping ([`crate::shading::bump`]) and displacement (`scene::displace`).
//!
//! # Storage and units
//! One contiguous row-major `&[u8]`, laid out like a texture's mip chain
//! ([`super::chain_len`]): level 0 (`w x h`), then level 1
//! (`max(1, w/2) x max(1, h/2)`), and so on. A height is `0..=255`; what one step means in
//! model units is the user's *scale* (displacement) or *strength* (bump). Row 0 is `t = 0`
//! and texel `(i, j)` has its centre at `((i + 0.5) / w, (j + 0.5) / h)`, as for textures.
//! Indices wrap (repeat) on every access, so no access is ever out of bounds.
//!
//! Coarser levels are 2 x 2 box averages, rounded (`(a + b + c + d + 2) >> 2`), built into
//! caller storage by [`generate_height_mips`].
//!
//! ```
//! use fixel::texture::{chain_len, generate_height_mips, HeightMap};
//! // A 4 x 4 ramp and its 3-level chain (16 + 4 + 1 heights).
//! let mut chain = [0u8; chain_len(4, 4, 3)];
//! for (i, h) in chain[..16].iter_mut().enumerate() {
//!     *h = (i % 4) as u8 * 80;
//! }
//! generate_height_mips(&mut chain, 4, 4, 3)?;
//! let map = HeightMap::new(&chain, 4, 4, 3)?;
//! assert_eq!(map.height(2, 0, 0), 120); // the 1 x 1 level is the mean
//! assert_eq!(map.height(0, 5, 0), 80); // i = 5 wraps to 1
//! # Ok::<(), fixel::Error>(())
//! ```

use super::mip::{chain_len, full_levels, level_side, MAX_LEVELS};
use crate::Error;

/// A borrowed height map with `levels` mip levels (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct HeightMap<'a> {
    chain: &'a [u8],
    /// `log2` of the base width and height.
    log2_w: u8,
    log2_h: u8,
    levels: u8,
    /// Offset of each level in `chain`.
    offsets: [u32; MAX_LEVELS],
}

/// Checks sides, level count and length like [`MipTexture::new`](super::MipTexture::new).
fn check(len: usize, width: u32, height: u32, levels: u32) -> Result<(), Error> {
    for s in [width, height] {
        if s == 0 || s > 1 << super::MAX_LOG2_SIZE {
            return Err(Error::BadSize(s));
        }
        if !s.is_power_of_two() {
            return Err(Error::NotPowerOfTwo(s));
        }
    }
    let full = full_levels(width, height);
    if levels == 0 || levels > full || levels as usize > MAX_LEVELS {
        return Err(Error::BadSize(levels));
    }
    let expected = chain_len(width, height, levels);
    if len != expected {
        return Err(Error::WrongLength {
            expected,
            actual: len,
        });
    }
    Ok(())
}

impl<'a> HeightMap<'a> {
    /// Views `chain` as a `width x height` base with `levels` levels.
    ///
    /// # Errors
    /// [`Error::BadSize`] for a zero or too large side or a level count of 0 or more than
    /// the full chain, [`Error::NotPowerOfTwo`], and [`Error::WrongLength`] when `chain` is
    /// not exactly [`chain_len`]`(width, height, levels)` long.
    pub fn new(chain: &'a [u8], width: u32, height: u32, levels: u32) -> Result<Self, Error> {
        check(chain.len(), width, height, levels)?;
        let mut offsets = [0u32; MAX_LEVELS];
        let mut off = 0u32;
        for (k, o) in offsets.iter_mut().enumerate().take(levels as usize) {
            *o = off;
            off += level_side(width, k as u32) * level_side(height, k as u32);
        }
        Ok(HeightMap {
            chain,
            log2_w: width.trailing_zeros() as u8,
            log2_h: height.trailing_zeros() as u8,
            levels: levels as u8,
            offsets,
        })
    }

    /// Base width in texels.
    pub fn width(&self) -> u32 {
        1 << self.log2_w
    }

    /// Base height in texels.
    pub fn height_texels(&self) -> u32 {
        1 << self.log2_h
    }

    /// `log2` of the base width and height.
    pub fn log2_size(&self) -> (u32, u32) {
        (u32::from(self.log2_w), u32::from(self.log2_h))
    }

    /// Number of levels.
    pub fn levels(&self) -> u32 {
        u32::from(self.levels)
    }

    /// `log2` of the width and height of level `k` (clamped to the last level).
    #[inline(always)]
    pub fn level_log2(&self, k: u32) -> (u32, u32) {
        let k = k.min(u32::from(self.levels) - 1);
        (
            u32::from(self.log2_w).saturating_sub(k),
            u32::from(self.log2_h).saturating_sub(k),
        )
    }

    /// Height of texel `(i, j)` of level `k` (clamped to the last level); `i` and `j` wrap
    /// (repeat). Never panics.
    #[inline(always)]
    pub fn height(&self, k: u32, i: i32, j: i32) -> u8 {
        let k = k.min(u32::from(self.levels) - 1);
        let (lw, lh) = self.level_log2(k);
        let i = (i as u32) & ((1 << lw) - 1);
        let j = (j as u32) & ((1 << lh) - 1);
        let off = self.offsets.get(k as usize).copied().unwrap_or(0);
        let idx = off as usize + ((j << lw) | i) as usize;
        self.chain.get(idx).copied().unwrap_or(0)
    }

    /// Bilinear height of level 0 at normalized coordinates `(s, t)` (I16F16 bits, 65536 =
    /// the whole map, repeating), texel centres at `(i + 0.5) / size`: Q8.8 (`256` = one
    /// height step, `0..=255 * 256`). Used per vertex by displacement.
    pub fn bilinear(&self, s: i32, t: i32) -> u32 {
        // Texel units, Q16, minus the half-texel offset of the centres.
        let tu = (i64::from(s) << self.log2_w) - (1 << 15);
        let tv = (i64::from(t) << self.log2_h) - (1 << 15);
        let (i, j) = ((tu >> 16) as i32, (tv >> 16) as i32);
        let (fu, fv) = ((tu & 0xFFFF) as u32 >> 8, (tv & 0xFFFF) as u32 >> 8);
        let h =
            |di: i32, dj: i32| u32::from(self.height(0, i.wrapping_add(di), j.wrapping_add(dj)));
        let top = h(0, 0) * (256 - fu) + h(1, 0) * fu;
        let bottom = h(0, 1) * (256 - fu) + h(1, 1) * fu;
        (top * (256 - fv) + bottom * fv + 128) >> 8
    }
}

/// Fills levels `1..levels` of `chain` from level 0 (written by the caller) with the 2 x 2
/// box filter of the module docs. Same errors as [`HeightMap::new`].
pub fn generate_height_mips(
    chain: &mut [u8],
    width: u32,
    height: u32,
    levels: u32,
) -> Result<(), Error> {
    check(chain.len(), width, height, levels)?;
    let mut src_off = 0usize;
    for k in 1..levels {
        let (sw, sh) = (level_side(width, k - 1), level_side(height, k - 1));
        let (dw, dh) = (level_side(width, k), level_side(height, k));
        let dst_off = src_off + (sw * sh) as usize;
        let (src_part, dst_part) = chain.split_at_mut(dst_off);
        let src = src_part.get(src_off..).unwrap_or(&[]);
        for j in 0..dh {
            for i in 0..dw {
                let at = |x: u32, y: u32| {
                    u32::from(
                        src.get((y.min(sh - 1) * sw + x.min(sw - 1)) as usize)
                            .copied()
                            .unwrap_or(0),
                    )
                };
                let sum = at(2 * i, 2 * j)
                    + at(2 * i + 1, 2 * j)
                    + at(2 * i, 2 * j + 1)
                    + at(2 * i + 1, 2 * j + 1);
                if let Some(d) = dst_part.get_mut((j * dw + i) as usize) {
                    *d = ((sum + 2) >> 2) as u8;
                }
            }
        }
        src_off = dst_off;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_sizes_are_refused() {
        let c = [0u8; 21];
        assert_eq!(
            HeightMap::new(&c, 3, 4, 1).err(),
            Some(Error::NotPowerOfTwo(3))
        );
        assert_eq!(HeightMap::new(&c, 4, 4, 4).err(), Some(Error::BadSize(4)));
        assert_eq!(
            HeightMap::new(&c[..20], 4, 4, 3).err(),
            Some(Error::WrongLength {
                expected: 21,
                actual: 20
            })
        );
        assert!(HeightMap::new(&c, 4, 4, 3).is_ok());
    }

    #[test]
    fn bilinear_hits_texel_centres_and_wraps() {
        let c = [0u8, 100, 200, 40];
        let m = HeightMap::new(&c, 4, 1, 1).unwrap();
        // Centre of texel 1: s = 1.5 / 4.
        assert_eq!(m.bilinear(3 << 13, 0), 100 << 8);
        // Halfway between texel 3 and texel 0 (wrapping): s = 0 -> (40 + 0) / 2.
        assert_eq!(m.bilinear(0, 0), 20 << 8);
        assert_eq!(m.bilinear(-(1 << 16), 1 << 20), 20 << 8);
    }
}
