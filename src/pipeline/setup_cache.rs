//! Raster set-ups kept from one band for the next.
//!
//! A band renderer draws a triangle that crosses a band boundary once per band it meets,
//! and each time builds the same set-up: the set-up depends on the screen triangle, the
//! draw and the viewport, never on the band (see [`setup`](super::setup)). On the
//! benchmark sphere in 8-row bands half of the set-ups are such repeats, about 2,900
//! instructions each on Cortex-M0+. A [`KeptSetup`] holds one built set-up (up to
//! [`KEPT_VARYINGS`] varyings) so the next band can take it instead of building it again;
//! the band renderer decides which ones to keep
//! ([`BandRenderer::with_setup_cache`](crate::surface::BandRenderer::with_setup_cache)).
//!
//! A kept set-up is a copy of the one the triangle would build, so the pixels are the same
//! with or without it.
//!
//! An entry may also hold what the rest of the triangle's raster needs besides its set-up
//! (corners, the shader's per-triangle data, the level of detail and the range proof:
//! [`KeptSetup::resumable`]): the next band then draws the triangle from the entry alone,
//! without projecting it again.

use super::tri_setup::TriSetup;
use crate::raster::first_row_at_or_below;
use crate::raster::Plane;
use crate::shading::{Shader, Varyings};

/// Varyings a [`KeptSetup`] holds at most: shaders with more always build their set-up.
pub const KEPT_VARYINGS: usize = 4;

/// `held` of an entry that holds no set-up (zero, so arrays of empty entries start
/// zeroed in place rather than copied from a template).
const NONE: u8 = 0;

/// One raster set-up kept across bands, 100 bytes on 32-bit targets. `Default` and
/// [`KeptSetup::EMPTY`] are an empty entry (all zero bits); give a band renderer an array
/// of them.
#[derive(Clone, Copy, Debug)]
pub struct KeptSetup {
    /// Which screen triangle: its id times 256 plus its index among the screen triangles
    /// its mesh triangle produced (clipped pieces), set by the band renderer.
    pub(crate) key: u32,
    /// The band (counted modulo 256) that stored it.
    pub(crate) band: u8,
    /// The index of its draw in the band renderer's list.
    pub(crate) draw: u8,
    /// Varyings held plus one, or [`NONE`].
    held: u8,
    /// [`AFFINE`], [`RESUMABLE`], [`PROVEN`].
    flags: u8,
    /// The reference pixel (in the viewport, so within `i16`; a set-up whose reference
    /// is not is not kept).
    px_ref: i16,
    py_ref: i16,
    z: Plane,
    q: Plane,
    at_ref: [i32; KEPT_VARYINGS],
    dx: [i32; KEPT_VARYINGS],
    dy: [i32; KEPT_VARYINGS],
    /// The screen triangle's corners (`x, y` in sub-pixel units), when resumable.
    corners: [i16; 6],
    /// The shader's per-triangle data ([`Shader::pack_triangle`]), when resumable.
    tri: u32,
}

/// `flags`: the planes are affine.
const AFFINE: u8 = 1;
/// `flags`: the entry holds what [`KeptSetup::resume`] returns.
const RESUMABLE: u8 = 2;
/// `flags`: the triangle's range-checked varying is proven in range.
const PROVEN: u8 = 4;

/// What a band needs to draw a kept triangle without its screen triangle: corners
/// (sub-pixel units), the shader's per-triangle data, its level of detail (Q8.8; only a
/// triangle whose level is 0 is kept resumable, so an entry needs no room for it) and
/// whether its range-checked varying is proven in range.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Resume<T> {
    pub corners: [(i32, i32); 3],
    pub triangle: T,
    pub lambda: i32,
    pub proven: bool,
}

impl Default for KeptSetup {
    fn default() -> Self {
        KeptSetup::EMPTY
    }
}

impl KeptSetup {
    /// An entry holding nothing.
    pub const EMPTY: KeptSetup = KeptSetup {
        key: 0,
        band: 0,
        draw: 0,
        held: NONE,
        flags: 0,
        px_ref: 0,
        py_ref: 0,
        z: Plane {
            at_ref: 0,
            dx: 0,
            dy: 0,
        },
        q: Plane {
            at_ref: 0,
            dx: 0,
            dy: 0,
        },
        at_ref: [0; KEPT_VARYINGS],
        dx: [0; KEPT_VARYINGS],
        dy: [0; KEPT_VARYINGS],
        corners: [0; 6],
        tri: 0,
    };

    /// Whether the entry holds a set-up with `V`'s number of varyings.
    #[inline]
    pub(crate) fn holds<V: Varyings>(&self) -> bool {
        usize::from(self.held) == V::N + 1
    }

    /// The kept set-up, when it holds one with `V`'s number of varyings.
    #[inline]
    pub(crate) fn load<V: Varyings>(&self) -> Option<TriSetup<V>> {
        if !self.holds::<V>() {
            return None;
        }
        let (mut at_ref, mut dx, mut dy) = (V::zero(), V::zero(), V::zero());
        at_ref
            .as_mut_slice()
            .copy_from_slice(self.at_ref.get(..V::N)?);
        dx.as_mut_slice().copy_from_slice(self.dx.get(..V::N)?);
        dy.as_mut_slice().copy_from_slice(self.dy.get(..V::N)?);
        Some(TriSetup {
            px_ref: i32::from(self.px_ref),
            py_ref: i32::from(self.py_ref),
            z: self.z,
            q: self.q,
            at_ref,
            dx,
            dy,
            affine: self.flags & AFFINE != 0,
        })
    }

    /// Whether the entry holds a set-up and what [`resume`](Self::resume) returns.
    #[inline]
    pub(crate) fn resumable(&self) -> bool {
        self.held != NONE && self.flags & RESUMABLE != 0
    }

    /// The rest of a resumable entry's triangle (see [`Resume`]), for shader `S`.
    #[inline]
    pub(crate) fn resume<S: Shader>(&self) -> Option<Resume<S::Triangle>> {
        if !self.resumable() {
            return None;
        }
        let c = self.corners.map(i32::from);
        Some(Resume {
            corners: [(c[0], c[1]), (c[2], c[3]), (c[4], c[5])],
            triangle: S::unpack_triangle(self.tri)?,
            lambda: 0,
            proven: self.flags & PROVEN != 0,
        })
    }

    /// Adds to an entry that holds a set-up the rest of its triangle: it becomes
    /// resumable when the shader packs its per-triangle data ([`Shader::pack_triangle`])
    /// and the corners fit `i16`.
    #[inline]
    pub(crate) fn keep_rest<S: Shader>(&mut self, rest: &Resume<S::Triangle>) {
        self.flags &= !(RESUMABLE | PROVEN);
        if self.held == NONE || rest.lambda != 0 {
            return;
        }
        let Some(bits) = S::pack_triangle(&rest.triangle) else {
            return;
        };
        if S::unpack_triangle(bits).is_none() {
            return;
        }
        let mut corners = [0i16; 6];
        for (k, &(x, y)) in rest.corners.iter().enumerate() {
            match (i16::try_from(x), i16::try_from(y)) {
                (Ok(x), Ok(y)) => (corners[2 * k], corners[2 * k + 1]) = (x, y),
                _ => return,
            }
        }
        (self.corners, self.tri) = (corners, bits);
        self.flags |= RESUMABLE | if rest.proven { PROVEN } else { 0 };
    }

    /// The pixel rows `r0..r1` (`r1` excluded) a resumable entry's triangle draws, as
    /// the band renderer's bins count them.
    #[inline]
    pub(crate) fn rows(&self) -> (i32, i32) {
        let y = [self.corners[1], self.corners[3], self.corners[5]].map(i32::from);
        let (top, bot) = (y[0].min(y[1]).min(y[2]), y[0].max(y[1]).max(y[2]));
        (first_row_at_or_below(top), first_row_at_or_below(bot))
    }

    /// Keeps `setup` (`None`, a triangle that builds none, or too many varyings: empties
    /// the entry).
    #[inline]
    pub(crate) fn store<V: Varyings>(&mut self, setup: Option<&TriSetup<V>>) {
        (self.held, self.flags) = (NONE, 0);
        let Some(s) = setup.filter(|_| V::N <= KEPT_VARYINGS) else {
            return;
        };
        let (Ok(px_ref), Ok(py_ref)) = (i16::try_from(s.px_ref), i16::try_from(s.py_ref)) else {
            return;
        };
        for (to, from) in [
            (&mut self.at_ref, &s.at_ref),
            (&mut self.dx, &s.dx),
            (&mut self.dy, &s.dy),
        ] {
            for (t, f) in to.iter_mut().zip(from.as_slice()) {
                *t = *f;
            }
        }
        (self.px_ref, self.py_ref, self.z, self.q) = (px_ref, py_ref, s.z, s.q);
        self.flags = if s.affine { AFFINE } else { 0 };
        self.held = V::N as u8 + 1;
    }

    /// Marks the entry empty.
    pub(crate) fn clear(&mut self) {
        self.held = NONE;
        self.flags = 0;
    }

    /// Whether the entry holds a set-up.
    #[cfg(test)]
    pub(crate) fn is_empty(&self) -> bool {
        self.held == NONE
    }

    /// Marks the entry as holding a set-up without varyings (tests of the band queue).
    #[cfg(test)]
    pub(crate) fn fill_for_test(&mut self) {
        self.held = 1;
    }
}

/// What the raster stage does with a triangle's set-up: `None`, build it; an entry that
/// holds a set-up, take it (an earlier band built it); an empty entry, build it and keep it
/// there for the next band. One word, so the raster function's argument costs no register
/// pressure worth measuring.
pub(crate) type SetupSlot<'s> = Option<&'s mut KeptSetup>;

#[cfg(test)]
mod tests {
    use super::*;

    fn sample<const N: usize>(seed: i32) -> TriSetup<[i32; N]> {
        let plane = |k: i32| Plane {
            at_ref: seed.wrapping_mul(7).wrapping_add(k),
            dx: k.wrapping_sub(seed),
            dy: seed ^ k,
        };
        TriSetup {
            px_ref: seed % 4096,
            py_ref: (seed % 4096).wrapping_neg(),
            z: plane(1),
            q: plane(2),
            at_ref: core::array::from_fn(|i| seed.wrapping_add(i as i32)),
            dx: core::array::from_fn(|i| seed.wrapping_mul(3).wrapping_sub(i as i32)),
            dy: core::array::from_fn(|i| (seed << 4).wrapping_add(i as i32)),
            affine: seed % 2 == 0,
        }
    }

    fn same<const N: usize>(a: &TriSetup<[i32; N]>, b: &TriSetup<[i32; N]>) -> bool {
        (a.px_ref, a.py_ref, a.z, a.q, a.at_ref, a.dx, a.dy, a.affine)
            == (b.px_ref, b.py_ref, b.z, b.q, b.at_ref, b.dx, b.dy, b.affine)
    }

    #[test]
    fn a_kept_set_up_loads_as_it_was_stored() {
        let mut k = KeptSetup::default();
        assert!(k.load::<[i32; 3]>().is_none());
        for seed in [0, 1, -5, i32::MAX, i32::MIN] {
            let s3 = sample::<3>(seed);
            k.store(Some(&s3));
            assert!(same(&k.load::<[i32; 3]>().unwrap(), &s3));
            // Another varying count is not this entry's.
            assert!(k.load::<[i32; 2]>().is_none());
            let s4 = sample::<4>(seed);
            k.store(Some(&s4));
            assert!(same(&k.load::<[i32; 4]>().unwrap(), &s4));
            let s0 = sample::<0>(seed);
            k.store(Some(&s0));
            assert!(same(&k.load::<[i32; 0]>().unwrap(), &s0));
        }
    }

    #[test]
    fn a_reference_pixel_past_i16_is_not_kept() {
        let mut k = KeptSetup::default();
        let mut s = sample::<3>(7);
        s.px_ref = 40_000;
        k.store(Some(&s));
        assert!(k.load::<[i32; 3]>().is_none());
    }

    #[test]
    fn an_entry_is_resumable_only_with_all_of_its_triangle() {
        use crate::shading::TexTriangle;
        use crate::texture::{Bilinear, Repeat};
        type Tex = crate::shading::ModulateIntensity<'static, Bilinear, Repeat, Repeat>;
        let rest = |corners: [(i32, i32); 3], shift: u8, lambda: i32| Resume {
            corners,
            triangle: TexTriangle { shift },
            lambda,
            proven: true,
        };
        let corners = [(5, -7), (300, 16), (-32768, 32767)];
        let mut k = KeptSetup::default();
        // No set-up held: nothing to resume.
        k.keep_rest::<Tex>(&rest(corners, 3, 0));
        assert!(!k.resumable());
        k.store(Some(&sample::<3>(9)));
        k.keep_rest::<Tex>(&rest(corners, 3, 0));
        let r = k.resume::<Tex>().unwrap();
        assert_eq!(
            (r.corners, r.triangle.shift, r.lambda, r.proven),
            (corners, 3, 0, true)
        );
        assert_eq!(k.rows(), (0, 2048));
        // A corner past i16, or a level of detail, is not kept: the entry keeps its set-up.
        k.keep_rest::<Tex>(&rest([(0, 0), (1 << 15, 0), (0, 1)], 3, 0));
        assert!(!k.resumable() && k.load::<[i32; 3]>().is_some());
        k.keep_rest::<Tex>(&rest(corners, 3, 256));
        assert!(!k.resumable());
        // A new set-up is not resumable until its triangle is kept too.
        k.keep_rest::<Tex>(&rest(corners, 3, 0));
        k.store(Some(&sample::<3>(10)));
        assert!(!k.resumable());
    }

    #[test]
    fn nothing_or_too_many_varyings_empties_the_entry() {
        let mut k = KeptSetup::default();
        k.store(Some(&sample::<3>(9)));
        k.store::<[i32; 3]>(None);
        assert!(k.load::<[i32; 3]>().is_none());
        k.store(Some(&sample::<3>(9)));
        k.store(Some(&sample::<5>(9)));
        assert!(k.load::<[i32; 5]>().is_none());
        assert!(k.load::<[i32; 3]>().is_none());
        k.store(Some(&sample::<3>(9)));
        k.clear();
        assert!(k.load::<[i32; 3]>().is_none());
    }
}
