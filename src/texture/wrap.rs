//! Texture wrap modes: map an integer texel index (any `i32`) onto a power-of-two axis.
//!
//! Units and conventions (OpenGL ES 3.2, coordinate wrapping): the input is an integer texel
//! index `i`
//! (already floored from the I16F16 texel coordinate by the sampler), the axis has
//! `size = 2^log2_size` texels, and the result is an index in `0..size`, or `None` meaning
//! "use the border colour". With `mirror(a) = if a >= 0 { a } else { -(1 + a) }`:
//!
//! - [`Repeat`]: `i mod size` (Euclidean, so `-1` maps to `size - 1`).
//! - [`MirroredRepeat`]: `(size - 1) - mirror((i mod 2size) - size)`, i.e. the axis repeats
//!   forward, then backward: `0, 1, .., size-1, size-1, .., 1, 0, 0, 1, ..`.
//! - [`ClampToEdge`]: `clamp(i, 0, size - 1)`.
//! - [`ClampToBorder`]: `i` if `0 <= i < size`, else `None`.
//!
//! Every mode is exact for every `i32`, including `i32::MIN` and `i32::MAX`: because `size`
//! divides 2^32, `i mod size` and `i mod 2size` are just the low bits of `i as u32`, so no
//! step can overflow. `log2_size` is taken modulo 16 (`log2_size & 15`), so any `u32` is
//! accepted without panicking; [`Texture`](super::Texture) always passes at most
//! [`MAX_LOG2_SIZE`](super::MAX_LOG2_SIZE) = 12, and every mode is exact for sides up to
//! 2^15.
//!
//! The zero-sized markers select the mode at compile time (the rasterizer's inner loop is
//! monomorphised per mode, and the markers are branch-free except for the clamps).
//! [`DynWrap`] carries a [`Wrap`] value and matches on it at run time (host convenience).

/// A wrap mode as a value (for run-time selection, see [`DynWrap`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Wrap {
    /// `GL_REPEAT`: the texture tiles.
    #[default]
    Repeat,
    /// `GL_MIRRORED_REPEAT`: the texture tiles, every other copy mirrored.
    MirroredRepeat,
    /// `GL_CLAMP_TO_EDGE`: indices outside the texture take the nearest edge texel.
    ClampToEdge,
    /// `GL_CLAMP_TO_BORDER`: indices outside the texture take the border colour.
    ClampToBorder,
}

/// A wrap mode: maps any integer texel index onto `0..2^log2_size`, or to the border.
///
/// Takes `self` so that [`DynWrap`] can carry its mode; the zero-sized markers ignore it.
pub trait WrapMode: Copy + Default + core::fmt::Debug {
    /// The mode as a value.
    const MODE: Wrap;

    /// Wraps texel index `i` onto an axis of `2^(log2_size & 15)` texels. Returns the
    /// in-range index, or `None` if the border colour should be used (only
    /// [`ClampToBorder`] returns `None`).
    fn wrap(self, i: i32, log2_size: u32) -> Option<u32>;
    /// True only for the [`Repeat`] marker: samplers then index with masks alone (the
    /// fast path of the benchmark scenes).
    const REPEAT: bool = false;
    /// True only for [`DynWrap`]: a run-time mode, used by draws that link every mode (the
    /// shaders then ask for the smallest span loops, see `Shader::SMALL`).
    const DYNAMIC: bool = false;
    /// The mode as a value (for [`DynWrap`], the one it carries).
    #[inline(always)]
    fn mode(self) -> Wrap {
        Self::MODE
    }
}

/// `GL_REPEAT` marker: `i mod size`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Repeat;

/// `GL_MIRRORED_REPEAT` marker: `(size - 1) - mirror((i mod 2size) - size)`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MirroredRepeat;

/// `GL_CLAMP_TO_EDGE` marker: `clamp(i, 0, size - 1)`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClampToEdge;

/// `GL_CLAMP_TO_BORDER` marker: `i` if in range, else the border colour.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClampToBorder;

/// A wrap mode chosen at run time: matches on the carried [`Wrap`] and defers to the marker.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DynWrap(pub Wrap);

impl WrapMode for Repeat {
    const MODE: Wrap = Wrap::Repeat;
    const REPEAT: bool = true;

    #[inline(always)]
    fn wrap(self, i: i32, log2_size: u32) -> Option<u32> {
        let mask = (1u32 << (log2_size & 15)) - 1;
        // Two's complement: the low bits of i are i mod size (Euclidean) since size | 2^32.
        Some(i as u32 & mask)
    }
}

impl WrapMode for MirroredRepeat {
    const MODE: Wrap = Wrap::MirroredRepeat;

    #[inline(always)]
    fn wrap(self, i: i32, log2_size: u32) -> Option<u32> {
        let k = log2_size & 15;
        let mask = (1u32 << k) - 1;
        // m = i mod 2size. If m < size the result is m; otherwise it is 2size - 1 - m,
        // which equals (size - 1) - (m mod size) = !m & mask. Select by bit k of m.
        let m = i as u32;
        let flip = 0u32.wrapping_sub((m >> k) & 1);
        Some((m ^ flip) & mask)
    }
}

impl WrapMode for ClampToEdge {
    const MODE: Wrap = Wrap::ClampToEdge;

    #[inline(always)]
    fn wrap(self, i: i32, log2_size: u32) -> Option<u32> {
        let max = (1i32 << (log2_size & 15)) - 1;
        Some(i.clamp(0, max) as u32)
    }
}

impl WrapMode for ClampToBorder {
    const MODE: Wrap = Wrap::ClampToBorder;

    #[inline(always)]
    fn wrap(self, i: i32, log2_size: u32) -> Option<u32> {
        // Negative i becomes >= 2^31 as u32, so one unsigned compare covers both ends.
        let u = i as u32;
        if u < (1u32 << (log2_size & 15)) {
            Some(u)
        } else {
            None
        }
    }
}

impl WrapMode for DynWrap {
    // Not meaningful for a run-time mode; `Repeat` is the default mode.
    const MODE: Wrap = Wrap::Repeat;
    const DYNAMIC: bool = true;

    #[inline(always)]
    fn mode(self) -> Wrap {
        self.0
    }

    #[inline]
    fn wrap(self, i: i32, log2_size: u32) -> Option<u32> {
        match self.0 {
            Wrap::Repeat => Repeat.wrap(i, log2_size),
            Wrap::MirroredRepeat => MirroredRepeat.wrap(i, log2_size),
            Wrap::ClampToEdge => ClampToEdge.wrap(i, log2_size),
            Wrap::ClampToBorder => ClampToBorder.wrap(i, log2_size),
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec;

    /// Independent reference: straight from the spec formulas, in i64.
    fn reference(mode: Wrap, i: i32, log2: u32) -> Option<u32> {
        let size = 1i64 << log2;
        let i = i as i64;
        let r = match mode {
            Wrap::Repeat => i.rem_euclid(size),
            Wrap::MirroredRepeat => {
                let a = i.rem_euclid(2 * size) - size;
                let mirror = if a >= 0 { a } else { -(1 + a) };
                (size - 1) - mirror
            }
            Wrap::ClampToEdge => i.clamp(0, size - 1),
            Wrap::ClampToBorder => {
                if (0..size).contains(&i) {
                    i
                } else {
                    return None;
                }
            }
        };
        assert!((0..size).contains(&r));
        Some(r as u32)
    }

    const MODES: [Wrap; 4] = [
        Wrap::Repeat,
        Wrap::MirroredRepeat,
        Wrap::ClampToEdge,
        Wrap::ClampToBorder,
    ];

    fn by_marker(mode: Wrap, i: i32, log2: u32) -> Option<u32> {
        match mode {
            Wrap::Repeat => Repeat.wrap(i, log2),
            Wrap::MirroredRepeat => MirroredRepeat.wrap(i, log2),
            Wrap::ClampToEdge => ClampToEdge.wrap(i, log2),
            Wrap::ClampToBorder => ClampToBorder.wrap(i, log2),
        }
    }

    fn test_indices() -> Vec<i32> {
        let mut v: Vec<i32> = (-20_000..20_000).collect();
        for k in 0..32 {
            let p = 1i64 << k;
            for d in -3..=3 {
                for s in [p + d, -p + d] {
                    if let Ok(x) = i32::try_from(s) {
                        v.push(x);
                    }
                }
            }
        }
        v.extend([i32::MIN, i32::MIN + 1, i32::MAX, i32::MAX - 1, -1, 0, 1]);
        let mut seed = 0x9E37_79B9u32;
        for _ in 0..20_000 {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            v.push(seed as i32);
        }
        v
    }

    #[test]
    fn markers_and_dyn_match_reference() {
        let idx = test_indices();
        for log2 in 0..=15 {
            for mode in MODES {
                for &i in &idx {
                    let want = reference(mode, i, log2);
                    assert_eq!(by_marker(mode, i, log2), want, "{mode:?} i={i} log2={log2}");
                    assert_eq!(DynWrap(mode).wrap(i, log2), want, "dyn {mode:?} i={i}");
                }
            }
        }
    }

    #[test]
    fn spot_values() {
        // size 4
        let mirrored: Vec<u32> = (-6..10)
            .map(|i| MirroredRepeat.wrap(i, 2).unwrap())
            .collect();
        // i = -6..10: -6 mod 8 = 2 -> a = -2 -> mirror 1 -> 3 - 1 = 2; i = -1 and 0 both give 0.
        assert_eq!(mirrored, [2, 3, 3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0, 1]);
        let repeat: Vec<u32> = (-6..6).map(|i| Repeat.wrap(i, 2).unwrap()).collect();
        assert_eq!(repeat, [2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1]);
        assert_eq!(ClampToEdge.wrap(i32::MIN, 12), Some(0));
        assert_eq!(ClampToEdge.wrap(i32::MAX, 12), Some(4095));
        assert_eq!(ClampToBorder.wrap(-1, 12), None);
        assert_eq!(ClampToBorder.wrap(4096, 12), None);
        assert_eq!(ClampToBorder.wrap(4095, 12), Some(4095));
        assert_eq!(Repeat.wrap(i32::MIN, 12), Some(0));
        assert_eq!(Repeat.wrap(i32::MAX, 12), Some(4095));
        assert_eq!(MirroredRepeat.wrap(i32::MIN, 12), Some(0));
        assert_eq!(MirroredRepeat.wrap(i32::MAX, 12), Some(0));
        // Size 1: everything maps to 0 except the border outside [0, 1).
        for i in [i32::MIN, -1, 0, 1, i32::MAX] {
            assert_eq!(Repeat.wrap(i, 0), Some(0));
            assert_eq!(MirroredRepeat.wrap(i, 0), Some(0));
            assert_eq!(ClampToEdge.wrap(i, 0), Some(0));
            assert_eq!(ClampToBorder.wrap(i, 0), (i == 0).then_some(0));
        }
    }

    #[test]
    fn huge_log2_does_not_panic() {
        for log2 in [16, 31, 32, 33, u32::MAX] {
            for i in [i32::MIN, -1, 0, 1, i32::MAX] {
                for mode in MODES {
                    let got = DynWrap(mode).wrap(i, log2);
                    assert_eq!(got, reference(mode, i, log2 & 15));
                }
            }
        }
    }

    #[test]
    fn mode_consts() {
        assert_eq!(Repeat::MODE, Wrap::Repeat);
        assert_eq!(MirroredRepeat::MODE, Wrap::MirroredRepeat);
        assert_eq!(ClampToEdge::MODE, Wrap::ClampToEdge);
        assert_eq!(ClampToBorder::MODE, Wrap::ClampToBorder);
        assert_eq!(Wrap::default(), Wrap::Repeat);
    }
}
