//! One draw list for every shader: the band renderer's view of a draw.
//!
//! A banded frame is made of any number of draws, each with its own shader type,
//! projection and depth stage: the classic [`Draw`] (built-in shaders) and the open
//! [`ShadedDraw`] (any [`Shader`]) side by side in one `&[&dyn BandDraw<C>]`. The span loop
//! stays monomorphised per draw; the renderer reaches it through one dynamic call per
//! triangle piece, with no heap.
//!
//! Screen triangles carry the varyings their draw declares (`N` of [`ScreenTriangle<N>`],
//! 0 to [`BINNED_VARYINGS`], of the [`MAX_VARYINGS`] a shader may declare). The
//! bins store them as an [`AnyTriangle`], an enum with one variant per `N`: a bin is as
//! large as a triangle of 8 varyings (168 bytes on 32-bit
//! targets, against 128 for a classic triangle alone), and a band reads a binned triangle
//! in place, without copying it. A caller-provided word arena with a size per draw would
//! save up to 40 bytes per classic bin, at the price of a copy per triangle and band; a
//! variant of 9 varyings would cost every bin 12 bytes more, so a draw of 9 to 11 varyings
//! ([`Tinted`](crate::shading::env::Tinted)) fills whole frames or a frame per band.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::geometry::Vertex;
//! use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
//! use fixel::shading::{Flat, Gouraud};
//! use fixel::surface::{BandDraw, Binned};
//! use fixel::Rgb565;
//!
//! let vp = Viewport::new(0, 0, 32, 32)?;
//! let gouraud = ShadedDraw::<_, Exact, NoDepth>::new(Gouraud, vp, Cull::None)?;
//! let flat = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0xFFFF), vp, Cull::None)?;
//! // Two shader types, three and no varyings, in one list.
//! let draws: [&dyn BandDraw<Rgb565>; 2] = [&gouraud, &flat];
//! assert_eq!((draws[0].varyings(), draws[1].varyings()), (3, 0));
//! let one = 256 << 16;
//! let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
//! let colored = [
//!     Vertex::new(p(-0.9, -0.9), [one, 0, 0]),
//!     Vertex::new(p(0.9, -0.9), [0, one, 0]),
//!     Vertex::new(p(0.0, 0.9), [0, 0, one]),
//! ];
//! let plain = colored.map(|v| Vertex::new(v.position, []));
//! let mut color = [Rgb565::default(); 32 * 8];
//! let mut bins = [Binned::default(); 4];
//! let mut bands = BandRenderer::new(&mut color, 32, 8, 32)?;
//! let stats = bands.render(&draws, &mut bins, Rgb565::default(), |sink| {
//!     gouraud.project(&colored, &mut |s| sink.push(0, s));
//!     flat.project(&plain, &mut |s| sink.push(1, s));
//! }, |_band| Ok::<(), core::convert::Infallible>(()))?;
//! assert_eq!((stats.bands, stats.triangles), (4, 2));
//! # Ok::<(), fixel::Error>(())
//! ```

use super::RenderTarget;
use crate::color::TargetColor;
use crate::geometry::{ScreenTriangle, ScreenVertex};
use crate::pipeline::{DepthStage, Draw, KeptSetup, ProjectionStage, ShadedDraw};
use crate::shading::{Shader, MAX_VARYINGS};

/// The most varyings of a triangle the band renderer's bins hold ([`AnyTriangle`] has a
/// variant per count up to it): fewer than [`MAX_VARYINGS`], so that a bin stays the size
/// of a triangle of 8 varyings.
pub const BINNED_VARYINGS: usize = 8;

mod sealed {
    /// Only fixel's draws and screen triangles implement the band traits.
    pub trait Sealed {}
}

/// A draw as the band renderer sees it: how many varyings its screen triangles carry,
/// whether it tests depth, and how it draws one screen triangle into a band. Implemented by
/// [`Draw`] (5 varyings: `u, v, r, g, b`) and by every [`ShadedDraw`] whose shader has at
/// most [`BINNED_VARYINGS`]; object-safe, so draws of different shader types share one
/// `&[&dyn BandDraw<C>]`.
pub trait BandDraw<C: TargetColor>: sealed::Sealed {
    /// Varyings per vertex of this draw's screen triangles (`0..=BINNED_VARYINGS`).
    fn varyings(&self) -> usize;

    /// Whether the draw tests depth (it then needs a depth band).
    fn tests_depth(&self) -> bool;

    /// Draws one screen triangle (already clipped, projected and culled) into `target`
    /// without checking the target (the renderer checked the draw list once); returns
    /// the pixels written, 0 when `tri` does not carry [`varyings`](Self::varyings).
    /// `slot` is a raster set-up kept across bands (`None`: build it).
    fn draw_piece(
        &self,
        tri: AnyTriangleRef<'_>,
        target: &mut dyn RenderTarget<Color = C>,
        slot: Option<&mut KeptSetup>,
    ) -> u32;

    /// Draws the triangle kept in `entry` (a resumable entry this draw filled in an
    /// earlier band) into `target`, without its screen triangle; returns the pixels written
    /// (0 for an entry that is not resumable).
    fn resume_piece(&self, entry: &mut KeptSetup, target: &mut dyn RenderTarget<Color = C>) -> u32;
}

/// A screen triangle of any varying count from 0 to [`BINNED_VARYINGS`], as stored in a
/// band renderer's bins.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // one variant per varying count
pub enum AnyTriangle {
    V0(ScreenTriangle<0>),
    V1(ScreenTriangle<1>),
    V2(ScreenTriangle<2>),
    V3(ScreenTriangle<3>),
    V4(ScreenTriangle<4>),
    V5(ScreenTriangle<5>),
    V6(ScreenTriangle<6>),
    V7(ScreenTriangle<7>),
    V8(ScreenTriangle<8>),
}

impl AnyTriangle {
    /// A triangle of no varyings at the origin (an empty bin's).
    pub const EMPTY: AnyTriangle = AnyTriangle::V0(
        [ScreenVertex {
            x: 0,
            y: 0,
            sub: [0; 2],
            z: 0,
            w: 0,
            varyings: [],
        }; 3],
    );
}

impl Default for AnyTriangle {
    fn default() -> Self {
        AnyTriangle::EMPTY
    }
}

/// A reference to a screen triangle of any varying count (see [`AnyTriangle`]).
#[derive(Clone, Copy, Debug)]
#[allow(missing_docs)] // one variant per varying count
pub enum AnyTriangleRef<'t> {
    V0(&'t ScreenTriangle<0>),
    V1(&'t ScreenTriangle<1>),
    V2(&'t ScreenTriangle<2>),
    V3(&'t ScreenTriangle<3>),
    V4(&'t ScreenTriangle<4>),
    V5(&'t ScreenTriangle<5>),
    V6(&'t ScreenTriangle<6>),
    V7(&'t ScreenTriangle<7>),
    V8(&'t ScreenTriangle<8>),
}

/// A screen triangle the band renderer can take: [`ScreenTriangle<N>`] for `N` in
/// `0..=BINNED_VARYINGS`.
pub trait Binnable: sealed::Sealed + Sized {
    /// Its varyings per vertex.
    const VARYINGS: usize;
    /// The triangle by reference, its varying count as the variant.
    fn as_any(&self) -> AnyTriangleRef<'_>;
    /// A copy of the triangle for the bins.
    fn to_any(&self) -> AnyTriangle;
    /// The triangle, if `t` carries this many varyings.
    fn from_any(t: AnyTriangleRef<'_>) -> Option<&Self>;
}

macro_rules! binnable {
    ($($n:literal => $v:ident),*) => {$(
        impl sealed::Sealed for ScreenTriangle<$n> {}
        impl Binnable for ScreenTriangle<$n> {
            const VARYINGS: usize = $n;
            #[inline(always)]
            fn as_any(&self) -> AnyTriangleRef<'_> {
                AnyTriangleRef::$v(self)
            }
            #[inline(always)]
            fn to_any(&self) -> AnyTriangle {
                AnyTriangle::$v(*self)
            }
            #[inline(always)]
            fn from_any(t: AnyTriangleRef<'_>) -> Option<&Self> {
                match t {
                    AnyTriangleRef::$v(t) => Some(t),
                    _ => None,
                }
            }
        }
    )*};
}
binnable!(0 => V0, 1 => V1, 2 => V2, 3 => V3, 4 => V4, 5 => V5, 6 => V6, 7 => V7, 8 => V8);

/// Runs `$body` with `$t` bound to the triangle of any variant of `$e` (a generic
/// `ScreenTriangle<N>` in each arm).
macro_rules! each_variant {
    ($enum:ident, $e:expr, $t:ident => $body:expr) => {
        match $e {
            $enum::V0($t) => $body,
            $enum::V1($t) => $body,
            $enum::V2($t) => $body,
            $enum::V3($t) => $body,
            $enum::V4($t) => $body,
            $enum::V5($t) => $body,
            $enum::V6($t) => $body,
            $enum::V7($t) => $body,
            $enum::V8($t) => $body,
        }
    };
}
pub(super) use each_variant;

impl AnyTriangle {
    /// The triangle by reference.
    #[inline]
    pub fn as_ref(&self) -> AnyTriangleRef<'_> {
        each_variant!(AnyTriangle, self, t => t.as_any())
    }

    /// Varyings per vertex.
    pub fn varyings(&self) -> usize {
        self.as_ref().varyings()
    }
}

impl AnyTriangleRef<'_> {
    /// Varyings per vertex.
    pub fn varyings(&self) -> usize {
        fn n<T: Binnable>(_: &T) -> usize {
            T::VARYINGS
        }
        each_variant!(AnyTriangleRef, self, t => n(*t))
    }
}

impl<C: TargetColor> sealed::Sealed for Draw<'_, C> {}

impl<C: TargetColor> BandDraw<C> for Draw<'_, C> {
    fn varyings(&self) -> usize {
        crate::geometry::CLASSIC_VARYINGS
    }

    fn tests_depth(&self) -> bool {
        self.mode().depth == crate::pipeline::DepthTest::Less
    }

    #[inline]
    fn draw_piece(
        &self,
        tri: AnyTriangleRef<'_>,
        target: &mut dyn RenderTarget<Color = C>,
        slot: Option<&mut KeptSetup>,
    ) -> u32 {
        match tri {
            AnyTriangleRef::V5(t) => self.screen_triangle_slot(Some(t), target, slot),
            _ => 0,
        }
    }

    #[inline]
    fn resume_piece(&self, entry: &mut KeptSetup, target: &mut dyn RenderTarget<Color = C>) -> u32 {
        self.screen_triangle_slot(None, target, Some(entry))
    }
}

impl<S, P, D> sealed::Sealed for ShadedDraw<S, P, D> {}

impl<S, P, D, C, const N: usize> BandDraw<C> for ShadedDraw<S, P, D>
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
    D: DepthStage,
    C: TargetColor,
    ScreenTriangle<N>: Binnable,
{
    fn varyings(&self) -> usize {
        N
    }

    fn tests_depth(&self) -> bool {
        D::TEST
    }

    #[inline]
    fn draw_piece(
        &self,
        tri: AnyTriangleRef<'_>,
        target: &mut dyn RenderTarget<Color = C>,
        slot: Option<&mut KeptSetup>,
    ) -> u32 {
        match <ScreenTriangle<N> as Binnable>::from_any(tri) {
            Some(t) => self.raster_slot(Some(t), target, slot),
            None => 0,
        }
    }

    #[inline]
    fn resume_piece(&self, entry: &mut KeptSetup, target: &mut dyn RenderTarget<Color = C>) -> u32 {
        self.raster_slot::<N, C>(None, target, Some(entry))
    }
}

const _: () = assert!(
    BINNED_VARYINGS == 8 && BINNED_VARYINGS <= MAX_VARYINGS,
    "AnyTriangle has a variant per varying count"
);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_triangle_comes_back_only_as_its_own_varying_count() {
        let t: ScreenTriangle<3> = [ScreenVertex {
            x: 1,
            varyings: [4, 5, 6],
            ..ScreenVertex::default()
        }; 3];
        let any = t.to_any();
        assert_eq!(any.varyings(), 3);
        assert_eq!(<ScreenTriangle<3>>::from_any(any.as_ref()), Some(&t));
        assert!(<ScreenTriangle<4>>::from_any(any.as_ref()).is_none());
        assert_eq!(AnyTriangle::default().varyings(), 0);
    }

    #[test]
    fn a_bin_holds_a_triangle_of_eight_varyings() {
        // 3 x (5 + 8) words and the variant's tag.
        assert!(core::mem::size_of::<AnyTriangle>() <= 3 * 13 * 4 + 8);
    }
}
