//! The run-time projection's interpolator: one chunk-filling span loop per shader for every
//! perspective mode of [`Draw::dynamic`](super::Draw::dynamic) (subdivided with `N < 16`,
//! quadratic, exact), the mode matched per span instead of a loop per mode.
//!
//! A host convenience: the match costs a few instructions per chunk, and the firmware that
//! names its projection as a type links the mode's own interpolator instead. Each arm is the
//! typed interpolator, so the pixels are the same bits.

use super::interp::{ExactInterp, Fill, FillSpec, Linear};
use super::quadratic::Quadratic;
use super::stages::ProjKind;
use super::tri_setup::TriSetup;
use crate::shading::Varyings;

/// One of the chunk-filling interpolators, chosen per span from the draw's projection.
#[derive(Clone, Copy, Debug)]
pub(crate) enum DynInterp<V> {
    /// [`ProjKind::Subdivided`].
    Subdivided(Linear<V, true>),
    /// [`ProjKind::Quadratic`] (its segment set-up shared out of line).
    Quadratic(Quadratic<V, true>),
    /// Every other perspective kind.
    Exact(ExactInterp<V>),
}

impl<V: Varyings> Fill<V> for DynInterp<V> {
    #[inline(always)]
    fn start(s: &TriSetup<V>, x: i32, y: i32, len: u32, log2_n: u32) -> Self {
        DynInterp::Exact(ExactInterp::start(s, x, y, len, log2_n))
    }

    #[inline(always)]
    fn start_as(s: &TriSetup<V>, x: i32, y: i32, len: u32, log2_n: u32, kind: ProjKind) -> Self {
        match kind {
            ProjKind::Subdivided => DynInterp::Subdivided(Fill::start(s, x, y, len, log2_n)),
            ProjKind::Quadratic => DynInterp::Quadratic(Fill::start(s, x, y, len, log2_n)),
            _ => DynInterp::Exact(Fill::start(s, x, y, len, log2_n)),
        }
    }

    #[inline(always)]
    fn lambda(&self, s: &TriSetup<V>, pair: (usize, usize)) -> i32 {
        match self {
            DynInterp::Subdivided(i) => Fill::lambda(i, s, pair),
            DynInterp::Quadratic(i) => i.lambda(s, pair),
            DynInterp::Exact(i) => i.lambda(s, pair),
        }
    }

    #[inline(always)]
    fn fill(
        &mut self,
        s: &TriSetup<V>,
        vals: &mut [V],
        lambdas: &mut [i32],
        mask: u32,
        spec: FillSpec,
    ) {
        match self {
            DynInterp::Subdivided(i) => i.fill(s, vals, lambdas, mask, spec),
            DynInterp::Quadratic(i) => i.fill(s, vals, lambdas, mask, spec),
            DynInterp::Exact(i) => i.fill(s, vals, lambdas, mask, spec),
        }
    }
}
