//! The footprint words of a texture: for each texel, it and its right, lower and lower-right
//! neighbours (wrapping within the level) packed as four RGB565 values in one `u64`, built at
//! compile time into flash ([`footprint_texels`]) or at run time ([`write_footprints`]), and
//! checked against the texels they claim ([`MipTexture::with_footprints`](super::MipTexture::with_footprints)).
//! [`BilinearFootprint`](super::BilinearFootprint) reads them: one load per bilinear pixel.

use super::texture::Texture;
use crate::Error;
use embedded_graphics_core::pixelcolor::IntoStorage;

/// Indices of the four texels of texel `i`'s footprint in `n` texels of rows of `width`
/// (powers of two, `width` dividing `n`): `i`, right, below, below right.
#[inline(always)]
const fn footprint_of(i: usize, width: usize, n: usize) -> [usize; 4] {
    let below = (i + width) & (n - 1);
    [i, right_of(i, width), below, right_of(below, width)]
}

/// Index of the texel right of `k` in rows of `width` (a power of two), wrapping to the
/// row's first texel.
#[inline(always)]
const fn right_of(k: usize, width: usize) -> usize {
    (k & !(width - 1)) | ((k + 1) & (width - 1))
}

/// The footprints of raw RGB565 texels in rows of `width`, at compile time:
/// `static F: [u64; N] = footprint_texels(&RAW, W);` puts them in flash.
///
/// # Panics
/// If `width` or `N` is not a power of two, or `width > N` (a compile error in a `static`).
pub const fn footprint_texels<const N: usize>(raw: &[u16; N], width: u32) -> [u64; N] {
    let w = width as usize;
    assert!(
        width.is_power_of_two() && N.is_power_of_two() && w <= N,
        "width and the texel count must be powers of two, width at most the count"
    );
    let mut out = [0u64; N];
    let mut i = 0;
    while i < N {
        let k = footprint_of(i, w, N);
        out[i] = raw[k[0]] as u64
            | (raw[k[1]] as u64) << 16
            | (raw[k[2]] as u64) << 32
            | (raw[k[3]] as u64) << 48;
        i += 1;
    }
    out
}

/// Writes `tex`'s footprints into `out` (one word per texel), at run time.
///
/// # Errors
/// [`Error::WrongLength`] if `out.len() != width * height`.
pub fn write_footprints(tex: &Texture<'_>, out: &mut [u64]) -> Result<(), Error> {
    let texels = tex.texels();
    if out.len() != texels.len() {
        return Err(Error::WrongLength {
            expected: texels.len(),
            actual: out.len(),
        });
    }
    for (i, word) in out.iter_mut().enumerate() {
        *word = footprint_word(tex, i);
    }
    Ok(())
}

/// Footprint `i` of `tex` (`i < texels.len()`).
fn footprint_word(tex: &Texture<'_>, i: usize) -> u64 {
    let texels = tex.texels();
    let at = |k: usize| texels.get(k).map_or(0, |c| u64::from(c.into_storage()));
    let k = footprint_of(i, tex.width() as usize, texels.len());
    at(k[0]) | at(k[1]) << 16 | at(k[2]) << 32 | at(k[3]) << 48
}

/// Checks that `footprints` are `tex`'s ([`MipTexture::with_footprints`]).
pub(crate) fn check_footprints(tex: &Texture<'_>, footprints: &[u64]) -> Result<(), Error> {
    if footprints.len() != tex.texels().len() {
        return Err(Error::WrongLength {
            expected: tex.texels().len(),
            actual: footprints.len(),
        });
    }
    match (0..footprints.len()).find(|&i| footprints[i] != footprint_word(tex, i)) {
        Some(index) => Err(Error::FootprintMismatch { index }),
        None => Ok(()),
    }
}
