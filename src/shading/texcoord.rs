//! A texture as a shader uses it: level 0 (and the mip chain), a filter and two wrap modes,
//! with the per-triangle texel-coordinate set-up and the per-pixel sample.
//!
//! Varying formats: a shader hands [`TexBinding::triangle`] the vertices' texture
//! coordinates as *normalized* I16F16 bits (1.0 = one whole texture); after the call they
//! are texel units, I16F16 bits (65536 = one texel), shifted right by
//! [`TexTriangle::shift`]. [`TexBinding::sample`] undoes the shift and samples.
//!
//! Texture coordinates are rebased per triangle: for the periodic wrap modes (repeat,
//! mirrored repeat) a whole number of periods is subtracted so that the smallest vertex value
//! lies in `[0, period)`; this keeps thousands of repeats exact. When a triangle's texel
//! coordinates still exceed `2^30` (16384 texels) they are shifted right, and the span loop
//! shifts the interpolated values back (wrapping: exact modulo the period, see
//! [`Shader::coord_shift`](super::Shader::coord_shift)). A clamp-mode axis is first
//! saturated to ±2^30 texel units: beyond 16384 texels every value samples the edge or the
//! border, so only triangles spanning more than that are interpolated inexactly (the hard
//! case `extreme_minification_thousands_of_repeats` checks the border still matches).

use super::Varyings;
use crate::math::wide;
use crate::texture::mip::footprints_needed;
use crate::texture::{Lod, MipTexture, TexSampler, Texture, Wrap, WrapMode};
use crate::Error;

/// Whether [`TexBinding::can_draw`] also requires footprints of a sampler that reads them.
/// The span loops test `can_draw` once per span, so LLVM drops the per-pixel test of
/// `BilinearFootprint`'s lookup (footprints present) from the loop: about 2 % of the
/// whole-frame sphere from footprints and 4-7 % of the bilinear floor on Cortex-M4F and
/// RV32IMC, the cube about even (measure with `cargo xtask mcu`). Not on ARMv6-M, where
/// the loop without the test allocates its registers worse and the sphere costs about 1 %
/// more, nor on 64-bit hosts, where it costs a little on every scene (`cargo xtask count`).
const HOIST_FOOTPRINT_TEST: bool = cfg!(target_pointer_width = "32")
    && !cfg!(all(target_arch = "arm", not(target_has_atomic = "32")));

/// A texture bound for sampling by a shader: level 0 by value (so its pointer and sizes stay
/// in registers through a span), the chain by reference, the filter `F` and wraps `WU`, `WV`.
#[derive(Clone, Copy, Debug)]
pub struct TexBinding<'a, F, WU, WV> {
    base: Texture<'a>,
    /// Level 0's footprints when `F` reads them ([`TexSampler::FOOTPRINTS`]), else empty.
    footprints: &'a [u64],
    chain: &'a MipTexture<'a>,
    sampler: F,
    wu: WU,
    wv: WV,
    lod: Lod,
}

/// Refuses a sampler that reads footprints ([`TexSampler::FOOTPRINTS`]) on a chain without
/// them ([`MipTexture::with_footprints`]), or one that mipmaps (levels past 0 have none).
///
/// A sampler built for one texture size ([`TexSampler::LEVEL0_SIZE`]) is refused on a
/// chain of another.
///
/// # Errors
/// [`Error::BadMode`], saying which; [`Error::TextureSizeMismatch`] for the size.
pub fn check_footprints_bound<F: TexSampler>(chain: &MipTexture<'_>) -> Result<(), Error> {
    if !F::FOOTPRINTS {
        return Ok(());
    }
    if F::LOD {
        return Err(Error::BadMode(
            "a footprint filter reads level 0 only: it cannot be part of a mipmapped sampler",
        ));
    }
    if chain.footprints().is_empty() {
        return Err(Error::BadMode(
            "BilinearFootprint needs a texture with footprints (MipTexture::with_footprints)",
        ));
    }
    match F::LEVEL0_SIZE {
        Some(size) => crate::texture::check_level0_size(chain, size),
        None => Ok(()),
    }
}

/// Per-triangle data of one texture binding.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TexTriangle {
    /// Right shift applied to this triangle's texel coordinates (0 unless they exceed 2^30);
    /// the span loop undoes it on the shader's [`Shader::TEXCOORDS`](super::Shader::TEXCOORDS)
    /// pair before the shader runs. A second texture's pair is undone by the shader with
    /// [`TexTriangle::unshift`].
    pub shift: u8,
}

impl TexTriangle {
    /// `x` shifted back by [`TexTriangle::shift`] (wrapping: exact for the periodic wraps).
    #[inline(always)]
    pub fn unshift(self, x: i32) -> i32 {
        x.wrapping_shl(u32::from(self.shift))
    }
}

impl<'a, F: TexSampler, WU: WrapMode, WV: WrapMode> TexBinding<'a, F, WU, WV> {
    /// Binds `chain` with filter value `sampler` and wrap values `wu`, `wv` (the markers are
    /// zero-sized; [`DynWrap`](crate::texture::DynWrap) and
    /// [`DynMip`](crate::texture::DynMip) carry run-time choices).
    ///
    /// # Errors
    /// [`Error::BadMode`] when `F` is a mipmapping sampler and the level of detail's
    /// clamps are inverted (`lod.min > lod.max`), or when `F` reads footprints
    /// ([`BilinearFootprint`](crate::texture::BilinearFootprint)) and the chain has none or
    /// `F` mipmaps (see [`check_footprints_bound`]).
    pub fn new(
        chain: &'a MipTexture<'a>,
        sampler: F,
        wu: WU,
        wv: WV,
        lod: Lod,
    ) -> Result<Self, Error> {
        if F::LOD && lod.min > lod.max {
            return Err(Error::BadMode("lod.min must not exceed lod.max"));
        }
        check_footprints_bound::<F>(chain)?;
        Ok(Self::new_unchecked(chain, sampler, wu, wv, lod))
    }

    /// [`TexBinding::new`] without the checks (the classic draw validated its mode).
    #[inline(always)]
    pub(crate) fn new_unchecked(
        chain: &'a MipTexture<'a>,
        sampler: F,
        wu: WU,
        wv: WV,
        lod: Lod,
    ) -> Self {
        TexBinding {
            base: *chain.base(),
            footprints: if F::FOOTPRINTS {
                chain.footprints()
            } else {
                &[]
            },
            chain,
            sampler,
            wu,
            wv,
            lod,
        }
    }

    /// True when level 0 has texels and, for a sampler that reads footprints on
    /// 32-bit cores other than ARMv6-M, they are there: all `w x h` of them for a sampler
    /// built for a `w x h` level 0 ([`TexSampler::LEVEL0_SIZE`]), so that its masked index
    /// needs no bounds test per pixel (always true for a binding built from fixel's
    /// textures: [`TexBinding::new`] refuses a footprint sampler on a chain without them,
    /// or of another size).
    #[inline(always)]
    pub fn can_draw(&self) -> bool {
        !self.base.texels().is_empty()
            && (!F::FOOTPRINTS
                || !HOIST_FOOTPRINT_TEST
                || self.footprints.len() >= footprints_needed::<F>())
    }

    /// Level 0.
    #[inline(always)]
    pub fn base(&self) -> &Texture<'a> {
        &self.base
    }

    /// The level-of-detail controls.
    #[inline(always)]
    pub fn lod(&self) -> &Lod {
        &self.lod
    }

    /// Per triangle: turns the normalized I16F16 coordinates in varyings `pair = (u, v)`
    /// of the three vertices into rebased (and, rarely, shifted) texel units in place. See
    /// the module docs; a shader calls this from its [`Shader::triangle`](super::Shader::triangle)
    /// hook for each texture's coordinate pair.
    ///
    /// Indices past the shader's varyings read as 0 and are not written (a debug build
    /// asserts instead).
    pub fn triangle<V: Varyings>(&self, vary: &mut [V; 3], pair: (usize, usize)) -> TexTriangle {
        debug_assert!(
            pair.0 < V::N && pair.1 < V::N,
            "texture coordinate pair {pair:?} outside the shader's {} varyings",
            V::N
        );
        let get = |v: &V, k: usize| v.as_slice().get(k).copied().unwrap_or(0);
        let (u, v) = (
            vary.each_ref().map(|v| get(v, pair.0)),
            vary.each_ref().map(|v| get(v, pair.1)),
        );
        // The common case in 32-bit arithmetic (the same integers; the 64-bit path costs
        // library shifts on Cortex-M0+, once per triangle and band).
        // A sampler built for one size binds only a level 0 of that size (checked where the
        // binding is made): its sides are then constants, and the shifts below immediates.
        let (log2_w, log2_h) = match F::LEVEL0_SIZE {
            Some((w, h)) if w.is_power_of_two() && h.is_power_of_two() => {
                (w.trailing_zeros(), h.trailing_zeros())
            }
            _ => (self.base.log2_width(), self.base.log2_height()),
        };
        texel_triangle(
            vary,
            pair,
            (u, v),
            (log2_w, log2_h),
            (self.wu.mode(), self.wv.mode()),
        )
    }

    /// Samples at texel coordinates `u`, `v` (I16F16 texel units, as the span loop hands
    /// them to the shader) with level of detail `lambda` (Q8.8, from
    /// [`Fragment::lambda`](super::Fragment::lambda); the binding adds the triangle's shift,
    /// its bias and clamps). Returns raw RGB565. Never panics.
    #[inline(always)]
    pub fn sample(&self, tri: TexTriangle, u: i32, v: i32, lambda: i32) -> u16 {
        let k = u32::from(tri.shift);
        if F::LOD {
            let l = lambda
                .saturating_add(256 * k as i32)
                .saturating_add(self.lod.bias)
                .clamp(self.lod.min, self.lod.max.max(self.lod.min));
            self.sampler
                .sample_mip(self.chain, self.wu, self.wv, u, v, l)
        } else {
            self.sampler
                .sample_level0(&self.base, self.footprints, self.wu, self.wv, u, v)
        }
    }
}

impl<'a, F: TexSampler, WU: WrapMode, WV: WrapMode> TexBinding<'a, F, WU, WV> {
    /// [`TexBinding::sample`] times intensity `i` (Q8, `0..=256`; larger is 256): the lit
    /// texture of [`ModulateIntensity`](super::ModulateIntensity). Plain bilinear scales its
    /// exact channel sums by the intensity (one rounding); the others modulate the sample.
    #[inline(always)]
    pub fn sample_scaled(&self, tri: TexTriangle, u: i32, v: i32, lambda: i32, i: u16) -> u16 {
        if F::LOD {
            crate::color::modulate_scalar(self.sample(tri, u, v, lambda), i)
        } else {
            self.sampler.sample_level0_scaled(
                &self.base,
                self.footprints,
                self.wu,
                self.wv,
                u,
                v,
                i,
            )
        }
    }

    /// [`TexSampler::lit_span`] of this binding's sampler, wraps and footprints, for a
    /// sampler without a level of detail; false (nothing written) otherwise.
    #[inline(always)]
    pub(crate) fn lit_span(&self, start: &[i32; 3], slope: &[i32; 3], out: &mut [u16]) -> bool {
        !F::LOD
            && self
                .sampler
                .lit_span::<WU, WV>(&self.base, self.footprints, start, slope, out)
    }

    /// Whether [`TexBinding::lit_span_depth`] has a loop.
    pub(crate) const LIT_SPAN_DEPTH: bool =
        !F::LOD && F::LIT_SPAN_DEPTH && WU::REPEAT && WV::REPEAT;

    /// [`TexSampler::lit_span_depth`] of this binding's sampler, wraps and footprints, for a
    /// sampler without a level of detail; `None` (nothing written) otherwise.
    #[inline(always)]
    pub(crate) fn lit_span_depth(
        &self,
        start: &[i32; 3],
        slope: &[i32; 3],
        (z, dz): (i32, i32),
        out: &mut [u16],
        zrow: &mut [u16],
    ) -> Option<u32> {
        if F::LOD {
            return None;
        }
        self.sampler.lit_span_depth::<WU, WV>(
            &self.base,
            self.footprints,
            start,
            slope,
            z,
            dz,
            out,
            zrow,
        )
    }
}

/// The texel-coordinate set-up of [`TexBinding::triangle`] for a level 0 of
/// `2^log2.0 x 2^log2.1` texels and wraps `wraps`: the vertices' normalized coordinates
/// `uv` (I16F16 bits) to rebased, rarely shifted, texel units written into varyings `pair`.
/// Shared with the palette textures' binding.
#[inline(always)]
pub(crate) fn texel_triangle<V: Varyings>(
    vary: &mut [V; 3],
    pair: (usize, usize),
    (u, v): ([i32; 3], [i32; 3]),
    (log2_w, log2_h): (u32, u32),
    (wu, wv): (Wrap, Wrap),
) -> TexTriangle {
    if let (Some(tu), Some(tv)) = (
        texel_coords_small(u, log2_w, wu),
        texel_coords_small(v, log2_h, wv),
    ) {
        write_pair(vary, pair, tu, tv);
        return TexTriangle { shift: 0 };
    }
    let mut tu = texel_coords(u, log2_w, wu);
    let mut tv = texel_coords(v, log2_h, wv);
    const LIM: i64 = 1 << 30;
    for (t, w) in [(&mut tu, wu), (&mut tv, wv)] {
        if !periodic(w) {
            for x in t.iter_mut() {
                *x = (*x).clamp(-LIM, LIM);
            }
        }
    }
    // The bit length of the largest magnitude is that of all magnitudes or-ed together.
    let bits = tu
        .iter()
        .chain(tv.iter())
        .fold(0u64, |m, x| m | x.unsigned_abs());
    let shift = (64 - wide::clz64(bits)).saturating_sub(30);
    let narrow = |t: [i64; 3]| t.map(|a| wide::sar(a, shift) as i32);
    write_pair(vary, pair, narrow(tu), narrow(tv));
    TexTriangle { shift: shift as u8 }
}

/// Writes the three vertices' texel coordinates `tu`, `tv` into varyings `pair` (indices
/// past the varyings are skipped).
#[inline(always)]
fn write_pair<V: Varyings>(vary: &mut [V; 3], pair: (usize, usize), tu: [i32; 3], tv: [i32; 3]) {
    for (v, (a, b)) in vary.iter_mut().zip(tu.into_iter().zip(tv)) {
        let s = v.as_mut_slice();
        if let Some(x) = s.get_mut(pair.0) {
            *x = a;
        }
        if let Some(x) = s.get_mut(pair.1) {
            *x = b;
        }
    }
}

fn periodic(w: Wrap) -> bool {
    matches!(w, Wrap::Repeat | Wrap::MirroredRepeat)
}

/// [`texel_coords`] when every coordinate is below 2^29 texel units and the rebased ones
/// below 2^30 (so no clamp or shift applies): the same integers in `i32`; `None` otherwise.
#[inline(always)]
fn texel_coords_small(uv: [i32; 3], log2_size: u32, wrap: Wrap) -> Option<[i32; 3]> {
    // Every |x| below the power of two `lim` exactly when their or is (one test instead of
    // two compares per value; `i32::MIN`'s magnitude is 2^31).
    let lim = 1u32 << 29u32.saturating_sub(log2_size);
    if uv.iter().fold(0, |m, x| m | x.unsigned_abs()) >= lim {
        return None;
    }
    // |x| < 2^(29 - log2_size): the shifted values are below 2^29 in magnitude.
    let mut t = uv.map(|x| x << log2_size.min(29));
    if periodic(wrap) {
        let period_log2 = 16 + log2_size + u32::from(wrap == Wrap::MirroredRepeat);
        if period_log2 > 29 {
            return None;
        }
        let min = t[0].min(t[1]).min(t[2]);
        // min - 2^29 < base <= min, and x - base < 2^30 + 2^29: no overflow.
        let base = (min >> period_log2) << period_log2;
        t = t.map(|x| x - base);
    }
    (t.iter().fold(0, |m, x| m | x.unsigned_abs()) < 1 << 30).then_some(t)
}

/// Texel coordinates (I16F16 bits) of the three vertices on one axis, rebased: the rare
/// path (coordinates too large for [`texel_coords_small`]), out of line so both axes share
/// one copy of its 64-bit shifts (about 20 bytes each on Cortex-M4F).
#[inline(never)]
fn texel_coords(uv: [i32; 3], log2_size: u32, wrap: Wrap) -> [i64; 3] {
    let mut t = uv.map(|x| wide::shl(i64::from(x), log2_size));
    if periodic(wrap) {
        let period_log2 = 16 + log2_size + u32::from(wrap == Wrap::MirroredRepeat);
        let min = t[0].min(t[1]).min(t[2]);
        let base = wide::shl(wide::sar(min, period_log2), period_log2);
        for x in &mut t {
            *x -= base;
        }
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 32-bit path gives the 64-bit path's integers whenever it applies.
    #[test]
    fn small_texel_coords_equal_the_wide_ones() {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let mut taken = 0;
        for i in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let bits = 1 + (x % 32) as u32;
            let c = |k: u32| ((x.rotate_left(k * 21) as u32 as i32) >> (32 - bits)).wrapping_add(i);
            let uv = [c(1), c(2), c(3)];
            let l = (x >> 40) as u32 % 13;
            let wrap =
                [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge][(x >> 50) as usize % 3];
            if let Some(t) = texel_coords_small(uv, l, wrap) {
                taken += 1;
                let wide = texel_coords(uv, l, wrap);
                assert_eq!(t.map(i64::from), wide, "{uv:?} << {l} {wrap:?}");
            }
        }
        assert!(taken > 50_000, "{taken}");
    }

    /// A sized sampler's binding draws only with every footprint there: the span loop's
    /// `can_draw` test is then what keeps its masked index in bounds.
    #[test]
    fn a_sized_binding_needs_every_footprint() {
        use crate::texture::{BilinearFootprint, BilinearFootprintSized, Repeat};
        use crate::Rgb565;
        static TEXELS: [Rgb565; 8] = [Rgb565::new(1, 2, 3); 8];
        static ALL: [u64; 8] = [0; 8];
        let tex = Texture::from_static(&TEXELS, 4, 2);
        let full = MipTexture::single(tex).with_footprints_static(&ALL);
        // A 2 x 2 texture's four footprints: fewer than the sampler's 4 x 2 (a binding
        // refuses the size; an unchecked one must still not draw).
        let small = Texture::from_static(&TEXELS[..4], 2, 2);
        let short = MipTexture::single(small).with_footprints_static(&ALL[..4]);
        let bind = |chain| {
            TexBinding::new_unchecked(
                chain,
                BilinearFootprintSized::<2, 1>,
                Repeat,
                Repeat,
                Lod::default(),
            )
            .can_draw()
        };
        // What 32-bit targets test per span (hosts skip the test).
        assert_eq!(footprints_needed::<BilinearFootprintSized<2, 1>>(), 8);
        assert_eq!(footprints_needed::<BilinearFootprintSized<40, 1>>(), 1);
        assert_eq!(footprints_needed::<BilinearFootprint>(), 1);
        assert!(bind(&full));
        assert_eq!(bind(&short), !HOIST_FOOTPRINT_TEST);
        // The run-time-sized sampler needs one.
        let any = |chain| {
            TexBinding::new_unchecked(chain, BilinearFootprint, Repeat, Repeat, Lod::default())
                .can_draw()
        };
        assert!(any(&short));
        let none = MipTexture::single(tex);
        assert!(!any(&none) || !HOIST_FOOTPRINT_TEST);
        assert!(any(&full));
    }
}
