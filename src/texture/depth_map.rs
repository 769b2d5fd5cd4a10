//! A shadow map: a square, power-of-two `u16` depth image in caller memory, written by the
//! depth-only light pass ([`DepthOnlyDraw`](crate::pipeline::DepthOnlyDraw)) and read by the
//! shadow lookup ([`Shadowed`](crate::shading::shadow::Shadowed)).
//!
//! Texel `(x, y)` is `texels[y * size + x]`; row 0 is the map's top (light-space `+y` up,
//! as a frame). Values are window depths from the light, `0..=65535` (0 at the light's near
//! plane, 65535 = far plane, also the cleared "nothing here" value, so an empty texel lights
//! everything in front of the far plane). A 64 x 64 map is 8 KiB.

use crate::geometry::DEPTH_CLEAR;
use crate::Error;

/// Smallest supported side (texels).
pub const MIN_MAP_SIZE: u32 = 16;
/// Largest supported side (texels): texel coordinates keep 12 fraction bits in the lookup.
pub const MAX_MAP_SIZE: u32 = 256;

/// Checks a map side and slice length: `size` a power of two in
/// `MIN_MAP_SIZE..=MAX_MAP_SIZE`, `len == size * size`. Returns `log2(size)`.
fn check(size: u32, len: usize) -> Result<u8, Error> {
    if !size.is_power_of_two() {
        return Err(Error::NotPowerOfTwo(size));
    }
    if !(MIN_MAP_SIZE..=MAX_MAP_SIZE).contains(&size) {
        return Err(Error::BadSize(size));
    }
    let expected = (size * size) as usize;
    if len != expected {
        return Err(Error::WrongLength {
            expected,
            actual: len,
        });
    }
    Ok(size.trailing_zeros() as u8)
}

/// The writable shadow map the light pass draws into.
///
/// ```
/// use fixel::surface::DepthMap;
/// let mut texels = [0u16; 64 * 64]; // 8 KiB
/// let mut map = DepthMap::new(&mut texels, 64)?;
/// map.clear();
/// assert_eq!(map.size(), 64);
/// // Not a power of two, too small, or the wrong length: refused.
/// let mut odd = [0u16; 48 * 48];
/// assert!(DepthMap::new(&mut odd, 48).is_err());
/// let mut tiny = [0u16; 8 * 8];
/// assert!(DepthMap::new(&mut tiny, 8).is_err());
/// # Ok::<(), fixel::Error>(())
/// ```
#[derive(Debug)]
pub struct DepthMap<'a> {
    texels: &'a mut [u16],
    log2: u8,
}

impl<'a> DepthMap<'a> {
    /// A `size` x `size` map over `texels` (`size * size` long).
    ///
    /// # Errors
    /// [`Error::NotPowerOfTwo`] or [`Error::BadSize`] unless `size` is a power of two in
    /// `16..=256`; [`Error::WrongLength`] if `texels` is not `size * size` long.
    pub fn new(texels: &'a mut [u16], size: u32) -> Result<Self, Error> {
        let log2 = check(size, texels.len())?;
        Ok(DepthMap { texels, log2 })
    }

    /// Side in texels.
    pub fn size(&self) -> u32 {
        1 << self.log2
    }

    /// `log2` of the side.
    pub fn log2_size(&self) -> u8 {
        self.log2
    }

    /// Fills the map with [`DEPTH_CLEAR`] (the far plane: nothing casts a shadow).
    pub fn clear(&mut self) {
        crate::fill::fill(self.texels, DEPTH_CLEAR);
    }

    /// The texels, row-major.
    pub fn texels(&self) -> &[u16] {
        self.texels
    }

    /// Row `y` of the map, `None` outside.
    #[inline]
    pub(crate) fn row_mut(&mut self, y: i32) -> Option<&mut [u16]> {
        let n = 1usize << self.log2;
        let y = usize::try_from(y).ok().filter(|&y| y < n)?;
        self.texels.get_mut(y * n..(y + 1) * n)
    }

    /// The finished map, for the lookup.
    pub fn view(&self) -> ShadowMap<'_> {
        ShadowMap {
            texels: self.texels,
            log2: self.log2,
        }
    }
}

/// A read-only shadow map, as the lookup holds it (`Copy`: two words).
#[derive(Clone, Copy, Debug)]
pub struct ShadowMap<'a> {
    texels: &'a [u16],
    log2: u8,
}

impl<'a> ShadowMap<'a> {
    /// A finished map held elsewhere (for example baked into flash).
    ///
    /// # Errors
    /// As [`DepthMap::new`].
    pub fn new(texels: &'a [u16], size: u32) -> Result<Self, Error> {
        let log2 = check(size, texels.len())?;
        Ok(ShadowMap { texels, log2 })
    }

    /// `log2` of the side.
    #[inline(always)]
    pub fn log2_size(&self) -> u32 {
        u32::from(self.log2)
    }

    /// The texels, row-major.
    pub fn texels(&self) -> &'a [u16] {
        self.texels
    }

    /// The texel at `(x, y)`, both in `0..size`; [`DEPTH_CLEAR`] outside (never a panic).
    #[inline(always)]
    pub fn fetch(&self, x: i32, y: i32) -> u16 {
        self.texels
            .get(((y << self.log2) | x) as usize)
            .copied()
            .unwrap_or(DEPTH_CLEAR)
    }

    /// The texel at `(x, y)`, both in `0..size` (other values read some texel of the map:
    /// never a panic). The index is masked with the map's length (a power of two), so where the
    /// caller has checked the map is not empty (a shader's `can_draw`) the compiler drops
    /// the bounds test: the lookup of the filters' inner taps.
    #[inline(always)]
    pub fn fetch_wrapped(&self, x: i32, y: i32) -> u16 {
        let i = ((y << self.log2) | x) as usize;
        self.texels
            .get(i & self.texels.len().wrapping_sub(1))
            .copied()
            .unwrap_or(DEPTH_CLEAR)
    }

    /// The texel at `(x, y)` clamped to the map's edge (GL's `CLAMP_TO_EDGE`, as a shadow
    /// sampler uses); [`DEPTH_CLEAR`] if the slice is somehow short (never for a checked map).
    #[inline(always)]
    pub fn fetch_clamped(&self, x: i32, y: i32) -> u16 {
        let max = (1i32 << self.log2) - 1;
        let (x, y) = (x.clamp(0, max), y.clamp(0, max));
        self.texels
            .get(((y << self.log2) + x) as usize)
            .copied()
            .unwrap_or(DEPTH_CLEAR)
    }
}
