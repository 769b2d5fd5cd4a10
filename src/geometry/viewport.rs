//! The viewport: where NDC lands on the screen, and the guard band that bounds it.
//!
//! Mapping (OpenGL, with y flipped so row 0 is the top of the framebuffer):
//! `x_s = x0 + (x_ndc + 1) * width / 2`, `y_s = y0 + (1 - y_ndc) * height / 2`,
//! `depth = (z_ndc + 1) / 2`, all rounded to the nearest 1/16 pixel
//! ([`crate::raster::SUBPIXEL_BITS`] = 4). The largest viewport side is
//! [`crate::raster::MAX_VIEWPORT_PX`] (2048); the clipper keeps every vertex within
//! `±GUARD_BAND_PX` (4096) pixels, which is what lets the raster set-up stay in `i64` and
//! its per-row stepping in `i32`.

use super::screen::{
    Rect, ATTR_SUBPIXEL_BITS, GUARD_BAND_PX, MAX_VIEWPORT_PX, SUBPIXEL_BITS, SUBPIXEL_ONE,
};
use crate::math::div::HW_DIVIDE;
use crate::math::recip32::Recip32;
use crate::math::{div_floor_i64, div_round_i64};
use crate::Error;

/// Which faces to skip. Front faces are counter-clockwise in NDC (OpenGL's default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Cull {
    /// Draw both faces.
    None,
    /// Skip faces seen from behind (the default).
    #[default]
    Back,
    /// Skip faces seen from the front.
    Front,
}

/// A validated viewport rectangle and its guard band.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    rect: Rect,
    /// Guard-band half-extent in NDC units per axis (integer, >= 1): the clipper keeps
    /// `|x| <= gx * w` and `|y| <= gy * w`.
    pub(crate) guard: (i32, i32),
}

impl Viewport {
    /// A viewport at `(x0, y0)` of `width` x `height` pixels.
    ///
    /// Errors with [`Error::BadViewport`] when a side is zero or above 2048, and with
    /// [`Error::ViewportOutOfBounds`] (naming the axis, the offset and the limit) when the
    /// rectangle does not end within `0..=2048` on either axis.
    ///
    /// A viewport is independent of the target it is drawn into, as in GL. When it is
    /// larger than the target or lies partly outside it, the pixels outside the target are
    /// not drawn (they are cropped, never wrapped or written out of bounds), and those inside
    /// are exactly the pixels a target of the viewport's full size would get (tested in
    /// `host-tests/tests/misuse.rs`). To fill a 320x240 display, use a 320x240 viewport.
    ///
    /// ```
    /// use fixel::geometry::Viewport;
    /// let vp = Viewport::new(0, 0, 320, 240).unwrap();
    /// assert_eq!(vp.width(), 320);
    /// assert!(Viewport::new(0, 0, 0, 240).is_err());
    /// ```
    pub fn new(x0: u32, y0: u32, width: u32, height: u32) -> Result<Self, Error> {
        let max = MAX_VIEWPORT_PX;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(Error::BadViewport { width, height });
        }
        for (axis, offset, size) in [("x", x0, width), ("y", y0, height)] {
            if offset.saturating_add(size) > max {
                return Err(Error::ViewportOutOfBounds {
                    axis,
                    offset,
                    size,
                    limit: max,
                });
            }
        }
        let rect = Rect {
            x0: x0 as i32,
            y0: y0 as i32,
            x1: (x0 + width) as i32,
            y1: (y0 + height) as i32,
        };
        // Largest integer g with x0 + (g + 1) * width / 2 <= GUARD_BAND_PX, and the same on
        // the negative side (which is looser); below 2 GUARD_BAND_PX, so an `i32` (one
        // 32 x 32 -> 64-bit product per guard plane in the clipper's outcodes).
        let g = |start: u32, size: u32| {
            ((i64::from(GUARD_BAND_PX) - i64::from(start)) * 2 / i64::from(size) - 1).max(1) as i32
        };
        Ok(Viewport {
            rect,
            guard: (g(x0, width), g(y0, height)),
        })
    }

    /// The viewport's pixel rectangle.
    pub fn rect(&self) -> Rect {
        self.rect
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        (self.rect.x1 - self.rect.x0) as u32
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        (self.rect.y1 - self.rect.y0) as u32
    }

    /// Maps a clip-space point (I16F16 bits, `w` > 0) to sub-pixel screen `(x, y)`, their
    /// attribute offsets (see [`project_xy`](Self::project_xy)) and a depth in
    /// `0..=65535 << 14`: the exact roundings of the exact values, by division where the
    /// core has a divide instruction, through one reciprocal of `w` where it has not (see
    /// `project_recip`; the same integers).
    ///
    /// The cores with a divide instruction divide, although their 64-bit quotients are
    /// library divisions: the reciprocal would save the whole-frame sphere about one
    /// instruction per pixel on Cortex-M4F and two on RV32IMC, but on Cortex-M4F its 1 KB
    /// table takes the minimal open-stage firmware over its 10 KB bar, and on RV32IMC LLVM
    /// then inlines the vertex preparation into the mesh walk (about 7 KB more in every
    /// whole-frame firmware; measure with `cargo xtask size` and `cargo xtask mcu`).
    pub(crate) fn project(&self, x: i32, y: i32, z: i32, w: i32) -> (i32, i32, [i16; 2], i32) {
        if HW_DIVIDE {
            let (sx, sy, sub) = self.project_xy_div(x, y, w);
            (sx, sy, sub, depth_div(z, w))
        } else {
            let r = Recip32::at_least_one(w);
            let (sx, sy, sub) = self.project_xy_recip(x, y, &r);
            (sx, sy, sub, depth_recip(z, &r))
        }
    }

    /// Half the viewport's width and height and its centre, in 1/16 pixel.
    #[inline(always)]
    pub(crate) fn scales(&self) -> (i64, i64, i64, i64) {
        let one = i64::from(SUBPIXEL_ONE);
        let hw = i64::from(self.rect.x1 - self.rect.x0) * one / 2;
        let hh = i64::from(self.rect.y1 - self.rect.y0) * one / 2;
        let cx = i64::from(self.rect.x0) * one + hw;
        let cy = i64::from(self.rect.y0) * one + hh;
        (hw, hh, cx, cy)
    }

    /// The screen `(x, y)` part of [`project`](Self::project): the window position rounded
    /// to the nearest 1/16 pixel (ties towards +x and +y), and the offset of the position
    /// rounded to `2^-ATTR_SUBPIXEL_BITS` pixel from it, in that unit (at most half a
    /// sub-pixel either way).
    ///
    /// One quotient per axis gives the 1/16-pixel position `s = floor(n / w + 1/2)` and its
    /// remainder `r` (`n / w = s + (r - w) / 2w`); the offset is
    /// `floor(2^R (r - w) / 2w + 1/2)`, `R = ATTR_SUBPIXEL_BITS - SUBPIXEL_BITS`, a second,
    /// small quotient. Both are the exact roundings of the exact position: divisions where
    /// the core has a divide instruction, a reciprocal of `w` where it has not.
    pub(crate) fn project_xy(&self, x: i32, y: i32, w: i32) -> (i32, i32, [i16; 2]) {
        if HW_DIVIDE {
            self.project_xy_div(x, y, w)
        } else {
            self.project_xy_recip(x, y, &Recip32::at_least_one(w))
        }
    }

    /// [`project_xy`](Self::project_xy) by division (two per axis; one instruction each
    /// on cores with a divide instruction).
    ///
    /// Inlined on ARMv7-M, where that saves a fraction of an instruction per pixel of the
    /// Cortex-M4F whole-frame sphere and some flash. Out of line on RV32IMC: inlined there
    /// it saves about one instruction per pixel but takes 10 KB more flash.
    #[cfg_attr(all(target_arch = "arm", target_has_atomic = "32"), inline(always))]
    pub(crate) fn project_xy_div(&self, x: i32, y: i32, w: i32) -> (i32, i32, [i16; 2]) {
        let w = i64::from(w.max(1));
        let (hw, hh, cx, cy) = self.scales();
        // Ties round towards +x and +y (down) everywhere on the screen, as `floor(v + 1/2)`
        // of the window coordinate: rounding them away from the viewport centre instead
        // would snap a mesh moved by whole pixels to a different shape.
        let axis = |n: i64, c: i64| -> (i32, i16) {
            let num = 2 * n + w;
            let s = div_floor_i64(num, 2 * w);
            // 0 <= r < 2w < 2^32: exact modulo 2^32, so one 32-bit product.
            let r = i64::from((num as u32).wrapping_sub((s as u32).wrapping_mul(2 * w as u32)));
            let off = div_floor_i64(((r - w) << OFFSET_BITS) + w, 2 * w);
            let s = c + s;
            if s.abs() > LIM {
                // Clamped into the guard band (only vertices the clipper will cut).
                return (s.clamp(-LIM, LIM) as i32, 0);
            }
            (s as i32, off.clamp(-HALF_OFFSET, HALF_OFFSET) as i16)
        };
        let (sx, ox) = axis(mul_i32_i64(x, hw), cx);
        let (sy, oy) = axis(-mul_i32_i64(y, hh), cy);
        (sx, sy, [ox, oy])
    }

    /// The depth part of [`project`](Self::project) alone (the walker's binning pass
    /// needs only rows and winding, and completes the depth when a band needs it).
    pub(crate) fn project_z(&self, z: i32, w: i32) -> i32 {
        if HW_DIVIDE {
            depth_div(z, w)
        } else {
            depth_recip(z, &Recip32::at_least_one(w))
        }
    }
}

/// Window depth of clip `z` at `w` (raised to 1) by division: `(z/w + 1)/2 * 65535` with
/// 14 fraction bits, `k (z/w + 1)` with `k = 65535 * 2^13`, `z k / w` rounded to nearest
/// (ties away from zero), clamped to `0..=65535 << 14`.
#[inline]
pub(crate) fn depth_div(z: i32, w: i32) -> i32 {
    let d = div_round_i64(mul_i32_i64(z, DEPTH_K), i64::from(w.max(1)));
    (d + DEPTH_K).clamp(0, 65535 << 14) as i32
}

/// The guard band's half-extent in 1/16 pixel: window positions beyond it are clamped
/// (only vertices the clipper will cut). A constant, not a captured local: the closure
/// that uses it may be out of line, and its clamp must still see `-LIM <= LIM` (else it
/// links a panic with i64 formatting).
pub(crate) const LIM: i64 = GUARD_BAND_PX as i64 * SUBPIXEL_ONE as i64;
/// Bits of the attribute offset below the 1/16-pixel position.
pub(crate) const OFFSET_BITS: u32 = ATTR_SUBPIXEL_BITS - SUBPIXEL_BITS;
/// The offset's bound, half a 1/16 pixel in 1/4096-pixel units.
pub(crate) const HALF_OFFSET: i64 = 1 << (OFFSET_BITS - 1);
/// `65535 * 2^13`: depth `(z/w + 1)/2 * 65535` with 14 fraction bits is `k (z/w + 1)`.
pub(crate) const DEPTH_K: i64 = 65535i64 << 13;

/// The window depth of clip `z`: `(z/w + 1)/2 * 65535` with 14 fraction bits,
/// `k (z/w + 1)` with `k = 65535 * 2^13`, where `z k / w` is rounded to nearest, ties away
/// from zero; clamped to `0..=2k` (`65535 << 14`).
///
/// `|z| >= w` lands on the clamps; inside, the rounded fraction `|z| / w` of `k` from the
/// reciprocal, in 32-bit arithmetic, below `w = 2^28` (4096.0); beyond, a 64-bit division.
#[inline(always)]
pub(crate) fn depth_recip(z: i32, r: &Recip32) -> i32 {
    let w = r.divisor();
    let a = z.unsigned_abs();
    let k = DEPTH_K as i32;
    if a >= w {
        return if z > 0 { 2 * k } else { 0 };
    }
    if w >= 1 << 28 {
        // Beyond the reciprocal form's range: the 64-bit quotient.
        return depth_div(z, w as i32);
    }
    let q = r.fraction_of(a, k as u32, w / 2) as i32;
    if z < 0 {
        k - q
    } else {
        k + q
    }
}

/// `a b` for a `b` that is normally within `i32` (viewport scales): on ARMv6-M a
/// 16-bit-split product instead of an `__aeabi_lmul` call; elsewhere, and for a larger `b`,
/// the `i64` product. Exact either way.
#[inline(always)]
pub(crate) fn mul_i32_i64(a: i32, b: i64) -> i64 {
    if cfg!(all(target_arch = "arm", not(target_has_atomic = "32"))) {
        if let Ok(b) = i32::try_from(b) {
            return crate::math::wide::mul_wide_signed(a, b);
        }
    }
    i64::from(a) * b
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn maps_ndc_corners_to_pixel_edges() {
        let vp = Viewport::new(0, 0, 320, 240).unwrap();
        let one = 1 << 16;
        assert_eq!(vp.project(-one, one, -one, one), (0, 0, [0, 0], 0));
        assert_eq!(
            vp.project(one, -one, one, one),
            (320 * 16, 240 * 16, [0, 0], 65535 << 14)
        );
        assert_eq!(
            vp.project(0, 0, 0, 2 * one),
            (160 * 16, 120 * 16, [0, 0], 65535 << 13)
        );
    }

    #[test]
    fn ties_round_the_same_way_everywhere() {
        // 64 x 64: 512 sub-pixels per NDC unit. NDC 0.6337890625 is 324.5 sub-pixels from
        // the centre: window y 187.5 sub-pixels rounds down the screen to 188 (and the
        // mirrored x tie rounds right), exactly as the tie 1/32 px further on does.
        let vp = Viewport::new(0, 0, 64, 64).unwrap();
        let t = 41536; // 0.6337890625 in I16F16
        let one = 1 << 16;
        assert_eq!(vp.project(t, t, 0, one).0, 512 + 325);
        assert_eq!(vp.project(t, t, 0, one).1, 512 - 324);
        assert_eq!(vp.project(-t, -t, 0, one).0, 512 - 324);
        assert_eq!(vp.project(-t, -t, 0, one).1, 512 + 325);
    }

    #[test]
    fn snapped_position_is_the_rounding_of_the_exact_one_and_sub_the_finer_one() {
        // Against exact rational rounding, over many random points and w.
        let vp = Viewport::new(0, 0, 320, 240).unwrap();
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let floor_div = |n: i128, d: i128| n.div_euclid(d);
        for _ in 0..200_000 {
            let w = (next() % (1 << 20)) as i32 + 256;
            let x = ((next() % (1 << 22)) as i32 - (1 << 21)) * (w >> 16).max(1);
            let y = ((next() % (1 << 22)) as i32 - (1 << 21)) * (w >> 16).max(1);
            let (sx, sy, sub) = vp.project_xy(x, y, w);
            // Window x in 1/16 px: 160*16 + x * 160*16 / w; exactly rounded, ties up.
            let n16 = i128::from(x) * 160 * 16;
            let want_x = 160 * 16 + floor_div(2 * n16 + i128::from(w), 2 * i128::from(w));
            let k = 1i128 << (ATTR_SUBPIXEL_BITS - SUBPIXEL_BITS);
            let nf = n16 * k;
            let fine_x = 160 * 16 * k + floor_div(2 * nf + i128::from(w), 2 * i128::from(w));
            if want_x.abs() < 4096 * 16 {
                assert_eq!(i128::from(sx), want_x, "x {x} w {w}");
                assert_eq!(
                    i128::from(sx) * k + i128::from(sub[0]),
                    fine_x,
                    "x {x} w {w}"
                );
            }
            let ny16 = -i128::from(y) * 120 * 16;
            let want_y = 120 * 16 + floor_div(2 * ny16 + i128::from(w), 2 * i128::from(w));
            if want_y.abs() < 4096 * 16 {
                assert_eq!(i128::from(sy), want_y, "y {y} w {w}");
            }
            let half = 1 << (ATTR_SUBPIXEL_BITS - SUBPIXEL_BITS - 1);
            assert!((-half..=half).contains(&sub[0]) && (-half..=half).contains(&sub[1]));
        }
    }

    #[test]
    fn rejects_bad_viewports() {
        assert!(Viewport::new(0, 0, 0, 1).is_err());
        assert!(Viewport::new(0, 0, 2049, 1).is_err());
        assert!(Viewport::new(2000, 0, 100, 1).is_err());
        assert!(Viewport::new(0, 0, 2048, 2048).is_ok());
    }

    #[test]
    fn guard_band_stays_inside_raster_limits() {
        for (w, h) in [(1, 1), (320, 240), (2048, 2048), (2047, 3)] {
            let vp = Viewport::new(0, 0, w, h).unwrap();
            let (gx, gy) = vp.guard;
            assert!((i64::from(gx) + 1) * i64::from(w) / 2 <= i64::from(GUARD_BAND_PX) + 1);
            assert!((i64::from(gy) + 1) * i64::from(h) / 2 <= i64::from(GUARD_BAND_PX) + 1);
        }
    }
}
