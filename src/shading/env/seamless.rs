//! Seamless cube-map filtering (GL's `TEXTURE_CUBE_MAP_SEAMLESS`, OpenGL 4.6):
//! bilinear taps that fall off the edge of a face are read from the face beyond that edge,
//! so a filtered cube map has no visible seams where faces meet.
//!
//! # Which texel lies beyond an edge
//!
//! A tap at texel `(i, j)` of face `f` with `i` or `j` one step outside `0..n` (bilinear
//! never reaches further) is the texel whose centre lies in the direction of that tap's
//! centre on the face's extended plane: `sc = 2i + 1 − n`, `tc = 2j + 1 − n`, `ma = n` (in
//! half-texel units), turned into a 3D direction by inverting GL's face table. Its major
//! axis is the one the tap crossed into (`|sc| = n + 1 > n`), and on that face the
//! coordinates are either the old major value `±n` (the edge row or column: index `0` or
//! `n − 1`) or an odd `c` in `(−n, n)` (index `(c + n − 1) / 2`, the same row or column,
//! possibly mirrored). All in `i32`, no division: `(c + n − 1) >> 1` clamped to `0..n`.
//!
//! **Corners**: a tap outside the face in both `i` and `j` has no unique neighbour; as the
//! GL specification recommends, it is the average of the three other taps (the three
//! texels that meet at the cube's corner), per channel, rounded.
//!
//! # Filters
//!
//! The filter chosen is kept: a nearest tap never leaves the face the direction selects,
//! so seamless nearest is GL's nearest, and a mipmapped map keeps its filter within a
//! level (nearest or seamless bilinear), on magnification, and between levels (nearest
//! level or linear blend), as [`TexSampler::filters`] reports them.
//!
//! # Cost
//!
//! Inside a face (all four taps on it, which is almost every pixel) the lookup is
//! [`CubeMap`]'s bilinear one plus four compares; a pixel whose taps straddle an edge
//! maps one or two taps (a few adds and compares each, one table-free projection), and a
//! corner adds a three-way average.
//!
//! # Example
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::shading::env::{CubeMap, EnvLookup};
//! use fixel::texture::Bilinear;
//!
//! // Six 4x4 faces of plain colours: +X red, +Y green, the others grey.
//! let grey = [Rgb565::new(16, 32, 16); 16];
//! let (red, green) = ([Rgb565::new(31, 0, 0); 16], [Rgb565::new(0, 63, 0); 16]);
//! let faces = [&red, &grey, &green, &grey, &grey, &grey].map(|t| Texture::new(t, 4, 4).unwrap());
//! let clamped = CubeMap::new(faces, Bilinear)?;
//! let seamless = clamped.seamless();
//! // On the edge between +X and +Y GL's clamped filter reads +X only; the seamless one
//! // blends both faces half and half.
//! let edge = [1 << 20, 1 << 20, 0];
//! assert_eq!(clamped.lookup(edge), 0xF800);
//! let c = seamless.lookup(edge);
//! assert_eq!((c >> 11, (c >> 5) & 63, c & 31), (16, 32, 0));
//! # Ok::<(), fixel::Error>(())
//! ```

use super::cube::{CubeMap, EnvLookup, FaceCoords};
use super::cube_mip::{EnvLookupLod, MipCubeMap};
use crate::texture::mip::linear_levels;
use crate::texture::sample::{blend_q8, split_half};
use crate::texture::{
    lerp565, Bilinear, ClampToEdge, Filter, MipFilter, MipTexture, Nearest, Sampler, TexSampler,
    Texture, Trilinear,
};

/// A cube map filtered across face edges (`TEXTURE_CUBE_MAP_SEAMLESS`) with filter `F`
/// (bilinear reads across edges; nearest never needs to). Made by [`CubeMap::seamless`];
/// copying it copies six references.
#[derive(Clone, Copy, Debug)]
pub struct SeamlessCubeMap<'a, F = Bilinear> {
    faces: [Texture<'a>; 6],
    log2_size: u8,
    filter: core::marker::PhantomData<F>,
}

impl<'a, F: Sampler> CubeMap<'a, F> {
    /// The same faces and filter, seamless across face edges.
    pub fn seamless(&self) -> SeamlessCubeMap<'a, F> {
        SeamlessCubeMap {
            faces: *self.faces(),
            log2_size: self.size().trailing_zeros() as u8,
            filter: core::marker::PhantomData,
        }
    }
}

/// The direction (in half-texel units, `|major| = n`) of the centre of texel `(i, j)` of
/// face `face` of side `n`, `i` and `j` possibly one step outside the face: GL's face table
/// inverted (see [`cube`](super::cube)).
#[inline(always)]
fn tap_direction(face: usize, i: i32, j: i32, n: i32) -> [i32; 3] {
    let (sc, tc) = (2 * i + 1 - n, 2 * j + 1 - n);
    match face {
        0 => [n, -tc, -sc],
        1 => [-n, -tc, sc],
        2 => [sc, n, tc],
        3 => [sc, -n, -tc],
        4 => [sc, -tc, n],
        _ => [-sc, -tc, -n],
    }
}

/// Face and texel indices of the texel whose centre is in direction `d` (half-texel units:
/// every component odd or `±n` or `±(n + 1)`, one strict major axis), faces of side `n`.
#[inline(always)]
fn texel_of(d: [i32; 3], n: i32) -> (usize, u32, u32) {
    let [x, y, z] = d;
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    // (face, sc, tc) from GL's table.
    let (face, sc, tc) = if ax >= ay && ax >= az {
        if x >= 0 {
            (0, -z, -y)
        } else {
            (1, z, -y)
        }
    } else if ay >= az {
        if y >= 0 {
            (2, x, z)
        } else {
            (3, x, -z)
        }
    } else if z >= 0 {
        (4, x, -y)
    } else {
        (5, -x, -y)
    };
    let idx = |c: i32| ((c + n - 1) >> 1).clamp(0, n - 1) as u32;
    (face, idx(sc), idx(tc))
}

/// Average of three RGB565 colours per channel, rounded.
#[inline(always)]
fn average3(a: u16, b: u16, c: u16) -> u16 {
    let ch = |sh: u32, mask: u32| {
        let s = ((u32::from(a) >> sh) & mask)
            + ((u32::from(b) >> sh) & mask)
            + ((u32::from(c) >> sh) & mask);
        // s / 3 rounded: s <= 189, and (s * 21846 + 32768) >> 16 is exact there.
        ((s * 21846 + 32768) >> 16) << sh
    };
    (ch(11, 31) | ch(5, 63) | ch(0, 31)) as u16
}

impl<F> SeamlessCubeMap<'_, F> {
    /// The side of every face in texels.
    pub fn size(&self) -> u32 {
        1 << self.log2_size
    }
}

/// The raw texel at `(i, j)` of `face` (faces of side `2^l` from `faces`), either index
/// possibly one step outside the face (read from the neighbouring face); `None` for a
/// corner tap.
#[inline(always)]
fn tap<'t>(
    faces: &impl Fn(usize) -> &'t Texture<'t>,
    l: u32,
    face: usize,
    i: i32,
    j: i32,
) -> Option<u16> {
    let n = 1i32 << l;
    let (ii, jj) = (i >= 0 && i < n, j >= 0 && j < n);
    let (f, ti, tj) = match (ii, jj) {
        (true, true) => (face, i as u32, j as u32),
        (false, false) => return None,
        _ => texel_of(tap_direction(face, i, j, n), n),
    };
    Some(faces(f % 6).texel_raw(ti, tj))
}

/// Seamless bilinear lookup at face coordinates `(face, s, t)` (Q16) of six faces of side
/// `2^l` given by `faces`.
#[inline(always)]
fn seamless_bilinear<'t>(
    faces: &impl Fn(usize) -> &'t Texture<'t>,
    l: u32,
    face: usize,
    s: u32,
    t: u32,
) -> u16 {
    // Q16 s, t <= 2^16 and size <= 2^12: fits i32.
    let (i0, fu) = split_half((s << l) as i32);
    let (j0, fv) = split_half((t << l) as i32);
    let (a, b) = ((fu + 0x80) >> 8, (fv + 0x80) >> 8);
    let n = 1i32 << l;
    let taps = if i0 >= 0 && j0 >= 0 && i0 + 1 < n && j0 + 1 < n {
        let tex = faces(face);
        let (i, j) = (i0 as u32, j0 as u32);
        [
            tex.texel_raw(i, j),
            tex.texel_raw(i + 1, j),
            tex.texel_raw(i, j + 1),
            tex.texel_raw(i + 1, j + 1),
        ]
    } else {
        let t = [
            tap(faces, l, face, i0, j0),
            tap(faces, l, face, i0 + 1, j0),
            tap(faces, l, face, i0, j0 + 1),
            tap(faces, l, face, i0 + 1, j0 + 1),
        ];
        // At most one tap is a corner (the others are in the face or across one edge).
        let get = |k: usize| t[k].unwrap_or(0);
        core::array::from_fn(|k| match t[k] {
            Some(c) => c,
            None => average3(get((k + 1) % 4), get((k + 2) % 4), get((k + 3) % 4)),
        })
    };
    blend_q8(taps, a, b)
}

/// Nearest lookup at face coordinates `c` on `tex` (side `2^l`): the tap is on the face.
#[inline(always)]
fn nearest(tex: &Texture<'_>, l: u32, c: FaceCoords) -> u16 {
    // Q16 s, t <= 2^16 and size <= 2^12: fits i32.
    Nearest::sample(
        tex,
        ClampToEdge,
        ClampToEdge,
        (c.s << l) as i32,
        (c.t << l) as i32,
    )
}

impl<F: Sampler> EnvLookup for SeamlessCubeMap<'_, F> {
    #[inline(always)]
    fn lookup(&self, dir: [i32; 3]) -> u16 {
        let c = super::cube::face_coords(dir);
        let face = usize::from(c.face) % 6;
        let l = u32::from(self.log2_size);
        match F::FILTER {
            Filter::Nearest => nearest(&self.faces[face], l, c),
            Filter::Bilinear => {
                let faces = |f: usize| &self.faces[f % 6];
                seamless_bilinear(&faces, l, face, c.s, c.t)
            }
        }
    }
}

/// A mipmapped cube map filtered with the seamless rule on every level (for example GL's
/// `LINEAR_MIPMAP_LINEAR` with `TEXTURE_CUBE_MAP_SEAMLESS`), keeping the sampler's filters
/// ([`TexSampler::filters`]): made by [`MipCubeMap::seamless`]. At coarse levels (a 4 x 4
/// face is a quarter of the face per texel) GL's clamped bilinear filter shows the cube's
/// edges as lines; this does not.
#[derive(Clone, Copy, Debug)]
pub struct SeamlessMipCubeMap<'a, S = Trilinear> {
    faces: &'a [MipTexture<'a>; 6],
    log2_size: u8,
    sampler: S,
}

impl<'a, S: TexSampler> MipCubeMap<'a, S> {
    /// The same chains and filters, seamless across face edges on every level.
    pub fn seamless(&self) -> SeamlessMipCubeMap<'a, S> {
        SeamlessMipCubeMap {
            faces: self.chains(),
            log2_size: self.size().trailing_zeros() as u8,
            sampler: self.sampler(),
        }
    }
}

impl<S: TexSampler> EnvLookupLod for SeamlessMipCubeMap<'_, S> {
    #[inline(always)]
    fn log2_size(&self) -> u32 {
        u32::from(self.log2_size)
    }

    #[inline(always)]
    fn lookup_lod(&self, dir: [i32; 3], lambda: i32) -> u16 {
        let c = super::cube::face_coords(dir);
        let face = usize::from(c.face) % 6;
        let (min, mag, between) = self.sampler.filters();
        let at = |k: u32, filter: Filter| {
            let l = u32::from(self.log2_size).saturating_sub(k);
            match filter {
                Filter::Nearest => nearest(self.faces[face].level(k), l, c),
                Filter::Bilinear => {
                    let faces = |f: usize| self.faces[f % 6].level(k);
                    seamless_bilinear(&faces, l, face, c.s, c.t)
                }
            }
        };
        if lambda <= 0 {
            return at(0, mag);
        }
        let last = self.faces[0].levels().saturating_sub(1);
        match between {
            // Minification without mipmaps: the min filter on level 0.
            MipFilter::None => at(0, min),
            // GL's *_MIPMAP_NEAREST: level 0 up to lambda = 1/2, else
            // ceil(lambda + 1/2) - 1 (u32: lambda > 128 here).
            MipFilter::Nearest => {
                let d = if lambda <= 128 {
                    0
                } else {
                    ((lambda as u32 + 127) >> 8).min(last)
                };
                at(d, min)
            }
            // GL's *_MIPMAP_LINEAR: levels floor(lambda) and the next, blended by the
            // fraction; the last level alone beyond it.
            MipFilter::Linear => {
                let (d1, f) = linear_levels(lambda, last);
                let a = at(d1, min);
                if f == 0 {
                    return a;
                }
                lerp565(a, at(d1 + 1, min), f)
            }
        }
    }
}

impl<S: TexSampler> EnvLookup for SeamlessMipCubeMap<'_, S> {
    /// Level 0: [`EnvLookupLod::lookup_lod`] with `lambda = 0`.
    #[inline(always)]
    fn lookup(&self, dir: [i32; 3]) -> u16 {
        self.lookup_lod(dir, 0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_edge_tap_lands_on_the_adjacent_edge_texel() {
        // Walk each face's border one step outside: the neighbour texel's centre direction
        // must be the tap's direction nudged back onto the cube (same sign pattern, adjacent
        // face), and mapping back from it must return to the tap's own face edge.
        for n in [1i32, 2, 4, 16] {
            for face in 0..6 {
                for k in 0..n {
                    for (i, j) in [(-1, k), (n, k), (k, -1), (k, n)] {
                        let (f, ti, tj) = texel_of(tap_direction(face, i, j, n), n);
                        assert_ne!(f, face, "n={n} face={face} tap=({i},{j})");
                        // The neighbour texel is on its face's border.
                        let last = (n - 1) as u32;
                        assert!(
                            ti == 0 || ti == last || tj == 0 || tj == last,
                            "n={n} face={face} ({i},{j}) -> {f} ({ti},{tj})"
                        );
                        // Its centre direction and the tap's differ by one texel step in
                        // one component: they are adjacent across the edge.
                        let a = tap_direction(face, i, j, n);
                        let b = tap_direction(f, ti as i32, tj as i32, n);
                        let d: i32 = (0..3).map(|c| (a[c] - b[c]).abs()).sum();
                        assert_eq!(d, 2, "n={n} face={face} ({i},{j}): {a:?} vs {b:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn average3_rounds_per_channel() {
        let w = 0xFFFF;
        assert_eq!(average3(w, w, w), w);
        assert_eq!(average3(0, 0, 0), 0);
        // R: (31 + 0 + 0) / 3 = 10.33 -> 10; G: 63 / 3 = 21; B: (31 + 31) / 3 = 20.67 -> 21.
        let c = average3(0xF800 | 0x07E0, 0x001F, 0x001F);
        assert_eq!((c >> 11, (c >> 5) & 63, c & 31), (10, 21, 21));
    }
}
