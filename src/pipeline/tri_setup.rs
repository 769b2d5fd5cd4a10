//! The planes of one set-up triangle, as the span loop steps them: depth, `q` and one plane
//! per varying, each an `i32` value at a reference pixel and its steps per pixel and per row
//! (formats in [`setup`](super::setup)). Built by the set-up, kept between bands by the
//! set-up cache, read by the span loops.

use crate::raster::Plane;
use crate::shading::Varyings;

/// Everything the span loop needs for one triangle: depth, `q` and one plane per varying
/// (held as three `V` values: at the reference pixel, per pixel right, per row down).
#[derive(Clone, Copy, Debug)]
pub(crate) struct TriSetup<V> {
    pub px_ref: i32,
    pub py_ref: i32,
    pub z: Plane,
    /// `q` (perspective only).
    pub q: Plane,
    /// Varyings (times `q` for perspective) at the reference pixel centre.
    pub at_ref: V,
    /// Change per pixel to the right.
    pub dx: V,
    /// Change per row down.
    pub dy: V,
    /// True when the planes are affine (varyings) rather than perspective (varyings times
    /// `q`, and `q`): always for [`ProjKind::Affine`](super::stages::ProjKind::Affine), per triangle for
    /// [`ProjKind::Adaptive`](super::stages::ProjKind::Adaptive).
    pub affine: bool,
}

impl<V: Varyings> TriSetup<V> {
    /// The varying planes at the centre of pixel `(x, y)`.
    #[inline(always)]
    pub fn at(&self, x: i32, y: i32) -> V {
        let mut out = self.at_ref;
        let (ox, oy) = (x.wrapping_sub(self.px_ref), y.wrapping_sub(self.py_ref));
        for k in 0..V::N {
            out.as_mut_slice()[k] = self.at_ref.as_slice()[k]
                .wrapping_add(ox.wrapping_mul(self.dx.as_slice()[k]))
                .wrapping_add(oy.wrapping_mul(self.dy.as_slice()[k]));
        }
        out
    }

    /// A plane value at the centre of pixel `(x, y)`.
    #[inline(always)]
    pub fn plane_at(&self, p: &Plane, x: i32, y: i32) -> i32 {
        p.at((self.px_ref, self.py_ref), x, y)
    }
}
