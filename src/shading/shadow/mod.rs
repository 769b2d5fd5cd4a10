//! Shadow mapping's lookup: light-space coordinates as varyings, a biased depth compare
//! against a [`ShadowMap`], and a wrapper shader that darkens any other shader's colour.
//!
//! The scene's depth is first drawn from the light into a small map
//! ([`DepthOnlyDraw`](crate::pipeline::DepthOnlyDraw)); then, for each visible pixel of the
//! lit pass, the point is carried into the light's space and its depth compared with the
//! map's, with a margin, the bias (L. Williams, "Casting curved shadows on curved
//! surfaces", SIGGRAPH 1978).
//!
//! # Light space and its formats
//!
//! A [`LightSpace`] is the light's world-to-clip matrix (view then projection). Each vertex
//! of the lit pass carries its light-space coordinates as extra varyings, after the inner
//! shader's own, computed from the model-space position in `i64` (no intermediate rounding):
//!
//! | light | varyings | format |
//! |---|---|---|
//! | [`Directional`] (orthographic, `w = 1`) | `s, t, d` | `s = (x + 1) / 2`, `t = (1 - y) / 2`: Q12.20 (`1 << 20` = the map's side); `d = 65535 (z + 1) / 2`: Q16.4 (16 = one depth step) |
//! | [`Spot`] (perspective) | `a, b, c, w` | `(x + w) / 2`, `(w - y) / 2`, `(z + w) / 2`, `w`: I16F16 |
//!
//! All are linear in the world position, so the lit pass's perspective-correct
//! interpolation gives them exactly at each pixel; the spot light divides per pixel
//! (`s = a / w`, with the span loop's table reciprocal
//! [`recip_q30`](crate::math::recip_q30::recip_q30)) into the directional formats.
//! Values saturate at `±2^30`, far outside any map.
//!
//! # The compare
//!
//! A point is *outside* the light's frustum when `s` or `t` is outside `[0, 1)`, its depth
//! is outside `[0, 65535]` or (spot) `w <= 0`; outside points get the caller's
//! [`Outside`] choice. Inside, a [`ShadowFilter`] compares
//! `d - bias` with map texels. The bias, per lit-pass triangle ([`Bias`]):
//!
//! ```text
//! bias = constant + min(max, slope * (|∂d/∂x| + |∂d/∂y|))
//! ```
//!
//! with the derivatives of depth per map texel on the triangle's plane in light space
//! (solved from its three vertices), which is how far the receiver's depth moves between
//! the point and a tap one texel away: a surface at a grazing angle to the light gets a
//! large bias, one facing it a small one.
//!
//! A lit-pass triangle turned away from the light, or edge-on to it, is in its own shade
//! whatever the map holds ([`LightKind::faces_light`], from the winding of its light-space
//! vertices): the light falls on its other side. Only triangles that face the light are
//! compared with the map, and with [`Bias::for_filter`] such a face of a convex solid does
//! not shadow itself (tested from 80 to 89 degrees to the light).
//!
//! # Both passes
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::pipeline::{DepthLess, DepthOnlyDraw, Exact};
//! use fixel::scene::{light_pass_mesh, shadowed_mesh_triangles};
//! use fixel::shading::pcf::Pcf2x2;
//! use fixel::shading::shadow::{with_light, Bias, Directional, LightSpace, Shadowed};
//! use fixel::shading::Gouraud;
//! use fixel::surface::DepthMap;
//! use fixel_scenes::{self as demo, shadow::floor};
//! use embedded_graphics_core::pixelcolor::Rgb565;
//!
//! // The benchmark cube over a floor, a light from above and to the left.
//! let (cube, floor) = (demo::cube(), floor());
//! let meshes = [(cube.mesh()?, demo::cube_model(0)), (floor.mesh()?, Mat4::IDENTITY)];
//! let centre = Vec3::new(Fx::ZERO, Fx::from_num(-1), Fx::from_num(-4));
//! let light = LightSpace::directional(centre + Vec3::from_num(-4, 8, 2), centre,
//!     Vec3::from_num(0, 1, 0), Fx::from_num(6), Fx::ONE, Fx::from_num(20))?;
//!
//! // 1. The light pass: depth only, into a 32 x 32 map (2 KiB).
//! let mut texels = [0u16; 32 * 32];
//! let mut map = DepthMap::new(&mut texels, 32)?;
//! map.clear();
//! let light_draw = DepthOnlyDraw::new(&map, Cull::Back)?;
//! for (mesh, model) in &meshes {
//!     light_pass_mesh(&light_draw, mesh, model, &light, &mut map)?;
//! }
//!
//! // 2. The lit pass: a Gouraud shader (r, g, b) shadowed: 3 + 3 varyings.
//! let shader = Shadowed::<_, Directional, Pcf2x2, 6>::new(Gouraud, map.view(),
//!                                                        Bias::for_filter::<Pcf2x2>())?;
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, Viewport::new(0, 0, 80, 60)?, Cull::Back)?;
//! let (mut color, mut depth) = ([Rgb565::default(); 80 * 60], [0u16; 80 * 60]);
//! let mut frame = Frame::new(&mut color, 80, 60)?.with_depth(&mut depth)?;
//! frame.clear(Rgb565::default());
//! let camera = demo::shadow::camera();
//! for (mesh, model) in &meshes {
//!     shadowed_mesh_triangles(mesh, model, &camera, None, &light, |cv, lv| {
//!         let tri = [0, 1, 2].map(|k| {
//!             let v = cv[k].to_vertex(); // u, v, r, g, b
//!             let rgb = Vertex::new(v.position, [v.varyings[2], v.varyings[3], v.varyings[4]]);
//!             with_light::<3, 6>(&rgb, lv[k])
//!         });
//!         draw.clip_triangles(&[tri], &mut frame);
//!     });
//! }
//! // White where lit, 0.4 grey in the cube's shadow.
//! let grey = frame.pixels().iter().filter(|c| **c == Rgb565::new(12, 25, 12)).count();
//! assert!(grey > 100, "{grey}");
//! # Ok::<(), fixel::Error>(())
//! ```

use super::pcf::ShadowFilter;
use super::{Fragment, Shader, Varyings};
use crate::math::div_u64;
use crate::texture::ShadowMap;
use crate::Error;

mod light_space;
mod through_uv;

pub use light_space::{Directional, LightKind, LightSpace, Spot};
pub use through_uv::{UvLight, ABSOLUTE as UV_ABSOLUTE};

/// `1.0` of the normalized map coordinates `s, t` (Q12.20).
pub const ST_ONE: i32 = 1 << 20;
/// One 16-bit depth step in the lookup's depth format (Q16.4).
pub const DEPTH_STEP: i32 = 16;

/// What a point outside the light's frustum gets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Outside {
    /// Lit (the default: the light's map covers the shadow casters, not the whole world).
    #[default]
    Lit,
    /// In shadow (a spot light's cone: nothing outside it is lit).
    Shadowed,
}

/// The depth bias of the compare, per lit-pass triangle (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bias {
    /// Constant part, Q16.4 depth ([`DEPTH_STEP`] = one 16-bit depth step).
    pub constant: i32,
    /// Slope factor, Q8 (256 = 1.0), times `|∂d/∂x| + |∂d/∂y|` per map texel.
    pub slope: i32,
    /// Cap of the slope part, Q16.4 (also the bias of a triangle partly outside the light's
    /// frustum, whose slope is not solved).
    pub max: i32,
}

impl Bias {
    /// No bias: the acne baseline.
    pub const NONE: Bias = Bias {
        constant: 0,
        slope: 0,
        max: 0,
    };

    /// The bias a filter needs: 2 depth steps, plus the slope over the filter's reach
    /// ([`ShadowFilter::REACH_Q8`]) and a quarter texel for rounding, capped at 8192 steps
    /// (1/8 of the depth range). With it a face that faces the light does not shadow
    /// itself up to 1 degree from edge-on (tested at 80, 85 and 89 degrees on a 64 x 64
    /// map); a steeper face hardly reaches a texel centre of the map.
    pub fn for_filter<F: ShadowFilter>() -> Bias {
        Bias {
            constant: 2 * DEPTH_STEP,
            slope: F::REACH_Q8 + 64,
            max: 8192 * DEPTH_STEP,
        }
    }

    /// The bias of a triangle whose vertices project to `p` (`(s, t, d)` as
    /// [`LightKind::project`]), `None` for a vertex outside the frustum, on a map of side
    /// `2^log2`.
    pub fn of_triangle(&self, p: [Option<(i32, i32, i32)>; 3], log2: u32) -> i32 {
        let slope_part = match p {
            [Some(a), Some(b), Some(c)] => {
                let sh = 12 - log2.min(12);
                // Texel units Q8, depth Q4; deltas from vertex 0, clamped to keep the
                // products in i64.
                let cl = |v: i32| i64::from(v).clamp(-(1 << 26), 1 << 26);
                let d = |q: (i32, i32, i32)| {
                    (
                        cl((q.0 >> sh) - (a.0 >> sh)),
                        cl((q.1 >> sh) - (a.1 >> sh)),
                        cl(q.2 - a.2),
                    )
                };
                let ((x1, y1, z1), (x2, y2, z2)) = (d(b), d(c));
                let det = x1 * y2 - x2 * y1;
                let ns = z1 * y2 - z2 * y1; // ∂d/∂x * det
                let nt = x1 * z2 - x2 * z1; // ∂d/∂y * det
                let num = (ns.unsigned_abs() + nt.unsigned_abs()).saturating_mul(256);
                let g = if det == 0 {
                    u64::MAX
                } else {
                    div_u64(num, det.unsigned_abs())
                };
                // Q4 depth per texel, times the Q8 factor.
                let part = g.min(1 << 40).saturating_mul(self.slope.max(0) as u64) >> 8;
                part.min(self.max.max(0) as u64) as i32
            }
            _ => self.max,
        };
        self.constant.saturating_add(slope_part)
    }
}

/// The bias of a triangle in its own shade: every tap of the map is nearer the light than
/// `d - OWN_SHADE` (saturated to `i32::MAX`).
const OWN_SHADE: i32 = i32::MIN;

/// How far inside the map (Q12.20) and the depth range (Q16.4) a triangle's vertices must
/// lie for its pixels to skip the frustum test: 1/16 texel of a 64 x 64 map, far above the
/// error of the interpolated varyings (the span loop's reciprocal, relative error near
/// 2^-14, on differences from vertex 0 below 2^21: under 2^7).
const INSIDE_MARGIN: i32 = 1 << 10;

/// Whether light-space point `p` (`s, t, d`) lies [`INSIDE_MARGIN`] inside the frustum.
#[inline]
fn well_inside(p: &[i32; 4]) -> bool {
    let inner = |v: i32, hi: i32| (INSIDE_MARGIN..=hi - INSIDE_MARGIN).contains(&v);
    inner(p[0], ST_ONE - 1) && inner(p[1], ST_ONE - 1) && inner(p[2], 65535 * DEPTH_STEP)
}

/// What [`Shadowed`] keeps per triangle: how its pixels are looked up, decided once.
#[derive(Clone, Copy, Debug)]
pub struct ShadowTriangle {
    /// The light varyings of vertex 0: the interpolated ones are differences from them.
    base: [i32; 4],
    /// The bias, Q16.4 ([`OWN_SHADE`] for a triangle in its own shade).
    bias: i32,
    /// [`LOOKUP`], [`IN_SHADE`] or [`GENERAL`].
    mode: u8,
    /// For [`LOOKUP`]: the biased depth of vertex 0, `base[2] - bias` (Q16.4).
    depth: i32,
    /// For [`ShadowedUv`]: the light coordinates from the texture coordinates.
    uv: UvLight,
}

/// Every pixel inside the frustum (an affine light, vertices inside by a margin): the
/// filter directly, the depth rebased on [`ShadowTriangle::depth`].
const LOOKUP: u8 = 0;
/// Every pixel inside the frustum and the triangle in its own shade: lit fraction 0.
const IN_SHADE: u8 = 1;
/// Anything else: the frustum test per pixel, then the filter.
const GENERAL: u8 = 2;

/// A shader `S` darkened where the shadow map says its pixel is hidden from the light.
///
/// Varyings: `S`'s, then the light's ([`LightKind::VARYINGS`]): `M` must be their sum (a
/// compile-time check when the shader is built). The inner shader's light is multiplied by
/// `dark + (1 - dark) * lit` (`lit` the filter's lit fraction, `dark` the shadow's
/// brightness, Q8) through [`Shader::shade_dimmed`]: one multiply of the intensity for a
/// lit texture, of the colour otherwise; a fully lit pixel is the inner shader's colour.
/// Per-triangle data: `S`'s and a [`ShadowTriangle`], which decides once per triangle
/// whether its pixels need the frustum test (not for a directional light's triangle wholly
/// inside the map and depth range) and whether they need the map at all (not for such a
/// triangle in its own shade).
///
/// ```
/// use fixel::prelude::*;
/// use fixel::shading::shadow::{Bias, Directional, Shadowed};
/// use fixel::shading::pcf::Pcf2x2;
/// use fixel::shading::Flat;
/// use fixel::surface::ShadowMap;
///
/// let texels = [u16::MAX; 16 * 16]; // an empty map: everything lit
/// let map = ShadowMap::new(&texels, 16)?;
/// // Flat has no varyings: 0 + 3 for the directional light.
/// let shader = Shadowed::<_, Directional, Pcf2x2, 3>::new(Flat(0xFFFF), map,
///                                                        Bias::for_filter::<Pcf2x2>())?;
/// assert_eq!(shader.darkness(), 102);
/// # Ok::<(), fixel::Error>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Shadowed<'a, S, K, F, const M: usize, const UV: bool = false> {
    inner: S,
    map: ShadowMap<'a>,
    bias: Bias,
    dark: u16,
    outside: u16,
    _kinds: core::marker::PhantomData<(K, F)>,
}

/// [`Shadowed`] in its real-time form: the light coordinates of each pixel come from its
/// texture coordinates ([`UvLight`], solved per triangle), so the span loop interpolates
/// only the inner shader's varyings. The vertices still carry the light varyings (`M` as for
/// [`Shadowed`]); `S` must have texture coordinates ([`Shader::TEXCOORDS`]). Pixels may differ
/// from [`Shadowed`]'s where a point lies within rounding of a texel's edge or of the
/// biased depth (see [`UvLight`] for the error).
pub type ShadowedUv<'a, S, K, F, const M: usize> = Shadowed<'a, S, K, F, M, true>;

impl<'a, S: Shader, K: LightKind, F: ShadowFilter, const M: usize, const UV: bool>
    Shadowed<'a, S, K, F, M, UV>
{
    const VARYINGS_ADD_UP: () = assert!(
        M == <S::Varyings as Varyings>::N + K::VARYINGS,
        "Shadowed<S, K, F, M>: M must be S's varyings plus the light's (3 directional, 4 spot)"
    );
    const UV_NEEDS_TEXCOORDS: () = assert!(
        !UV || S::TEXCOORDS.is_some(),
        "ShadowedUv<S, ..>: S must have texture coordinates (Shader::TEXCOORDS)"
    );

    /// `inner` shadowed by `map` with `bias`; shadows at brightness 0.4 (102 / 256), points
    /// outside the light's frustum lit.
    ///
    /// # Errors
    /// None today (the map and bias are valid by construction); kept for later checks.
    pub fn new(inner: S, map: ShadowMap<'a>, bias: Bias) -> Result<Self, Error> {
        #[allow(clippy::let_unit_value)]
        let () = Self::VARYINGS_ADD_UP;
        #[allow(clippy::let_unit_value)]
        let () = Self::UV_NEEDS_TEXCOORDS;
        Ok(Shadowed {
            inner,
            map,
            bias,
            dark: 102,
            outside: 256,
            _kinds: core::marker::PhantomData,
        })
    }

    /// With shadows at brightness `dark` (Q8, `0..=256`: 0 black, 256 no shadow).
    ///
    /// # Errors
    /// [`Error::BadMode`] if `dark > 256`.
    pub fn with_darkness(mut self, dark: u16) -> Result<Self, Error> {
        if dark > 256 {
            return Err(Error::BadMode("shadow darkness must be in 0..=256 (Q8)"));
        }
        self.dark = dark;
        Ok(self)
    }

    /// With points outside the light's frustum lit or shadowed.
    pub fn with_outside(mut self, outside: Outside) -> Self {
        self.outside = match outside {
            Outside::Lit => 256,
            Outside::Shadowed => 0,
        };
        self
    }

    /// Shadow brightness, Q8.
    pub fn darkness(&self) -> u16 {
        self.dark
    }

    /// The inner shader.
    pub fn inner(&self) -> &S {
        &self.inner
    }

    /// The lit fraction (Q8) of a pixel with light varyings `v` and triangle bias `bias`.
    #[inline(always)]
    pub fn lit(&self, v: [i32; 4], bias: i32) -> u16 {
        match K::project(v) {
            Some((s, t, d)) => F::lit(&self.map, s, t, d.saturating_sub(bias)),
            None => self.outside,
        }
    }
}

/// The light varyings of a lit-pass vertex array: the 3 or 4 after the first `n`.
#[inline(always)]
fn light_part<const M: usize>(v: &[i32; M], n: usize) -> [i32; 4] {
    core::array::from_fn(|k| v.get(n + k).copied().unwrap_or(0))
}

impl<S: Shader, K: LightKind, F: ShadowFilter, const M: usize, const UV: bool> Shader
    for Shadowed<'_, S, K, F, M, UV>
{
    type Varyings = [i32; M];
    /// The inner shader's, and the lookup's ([`ShadowTriangle`]: the light varyings of
    /// vertex 0, the bias, and whether the frustum test or the map can be skipped).
    type Triangle = (S::Triangle, ShadowTriangle);
    const TEXCOORDS: Option<(usize, usize)> = S::TEXCOORDS;
    const DISCARDS: bool = S::DISCARDS;
    const SMALL: bool = S::SMALL;
    const LOD: bool = S::LOD;
    const LOD_DIRECTION: Option<usize> = S::LOD_DIRECTION;
    const LOD_REFLECTION: Option<usize> = S::LOD_REFLECTION;
    const INTERPOLATED: usize = if UV {
        <S::Varyings as Varyings>::N
    } else {
        usize::MAX
    };

    #[inline(always)]
    fn lod_granularity(&self) -> crate::texture::LodGranularity {
        self.inner.lod_granularity()
    }

    #[inline(always)]
    fn coord_shift(t: &Self::Triangle) -> u32 {
        S::coord_shift(&t.0)
    }

    #[inline(always)]
    fn can_draw(&self) -> bool {
        // A map is never empty (its constructors check); said here, it lets the compiler
        // drop the bounds test of the filters' inner taps.
        self.inner.can_draw() && !self.map.texels().is_empty()
    }

    fn triangle(&self, v: &mut [[i32; M]; 3]) -> Self::Triangle {
        let n = <S::Varyings as Varyings>::N;
        let mut inner = [S::Varyings::zero(); 3];
        for (iv, ov) in inner.iter_mut().zip(v.iter()) {
            for (a, b) in iv.as_mut_slice().iter_mut().zip(ov.iter()) {
                *a = *b;
            }
        }
        let t = self.inner.triangle(&mut inner);
        for (iv, ov) in inner.iter().zip(v.iter_mut()) {
            for (a, b) in iv.as_slice().iter().zip(ov.iter_mut()) {
                *b = *a;
            }
        }
        let light = [0, 1, 2].map(|k| light_part(&v[k], n));
        let uv = if UV {
            let (pu, pv) = S::TEXCOORDS.unwrap_or((0, 1));
            let at = |k: usize| {
                let s = inner.get(k).map(|x| x.as_slice()).unwrap_or(&[]);
                [
                    s.get(pu).copied().unwrap_or(0),
                    s.get(pv).copied().unwrap_or(0),
                ]
            };
            UvLight::solve(
                [at(0), at(1), at(2)],
                S::coord_shift(&t),
                light,
                K::VARYINGS,
            )
        } else {
            UvLight::default()
        };
        let p = light.map(K::project);
        // A triangle turned away from the light, or edge-on to it, is in its own shade: a
        // bias of `i32::MIN` takes its depth past every texel (`d - bias` saturates).
        let bias = if K::faces_light(&light) {
            self.bias.of_triangle(p, self.map.log2_size())
        } else {
            OWN_SHADE
        };
        // Interpolate differences from vertex 0: the span loop's perspective division has a
        // relative error near 2^-14, too much for depths near 2^20 (5 depth steps), fine for
        // the depth range across one triangle.
        let base = light_part(&v[0], n);
        for vk in v.iter_mut() {
            for (k, b) in base.iter().enumerate().take(K::VARYINGS) {
                if let Some(x) = vk.get_mut(n + k) {
                    *x = x.wrapping_sub(*b);
                }
            }
        }
        // A triangle wholly inside the frustum of an affine light needs no test per pixel;
        // in its own shade, no lookup either. The biased depth must keep `d + depth` in
        // `i32` (`|d| < 2^21`): a bias beyond 2^29 takes the general path.
        let inside = K::AFFINE && light.iter().all(well_inside);
        let (mode, depth) = if !inside {
            (GENERAL, 0)
        } else if bias == OWN_SHADE {
            (IN_SHADE, 0)
        } else if (-(1 << 29)..=1 << 29).contains(&bias) {
            (LOOKUP, base[2] - bias)
        } else {
            (GENERAL, 0)
        };
        (
            t,
            ShadowTriangle {
                base,
                bias,
                mode,
                depth,
                uv,
            },
        )
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; M], Self::Triangle>) -> Option<u16> {
        let n = <S::Varyings as Varyings>::N;
        let tri = f.triangle.1;
        // The light coordinates, for the pixels that read the map (not those of a triangle
        // in its own shade).
        let light = || {
            if UV {
                let (pu, pv) = S::TEXCOORDS.unwrap_or((0, 1));
                let get = |k: usize| f.varyings.get(k).copied().unwrap_or(0);
                tri.uv.at(get(pu), get(pv), K::VARYINGS)
            } else {
                light_part(&f.varyings, n)
            }
        };
        // Vertex 0's value to add back: none for the coordinates `UvLight` gives absolute.
        let base = |k: usize| {
            if UV && k < through_uv::ABSOLUTE {
                0
            } else {
                tri.base.get(k).copied().unwrap_or(0)
            }
        };
        let lit = match tri.mode {
            LOOKUP => {
                let d = light();
                F::lit(
                    &self.map,
                    d[0].wrapping_add(base(0)),
                    d[1].wrapping_add(base(1)),
                    d[2].wrapping_add(tri.depth),
                )
            }
            IN_SHADE => 0,
            _ => {
                let d = light();
                self.lit(
                    core::array::from_fn(|k| d[k].wrapping_add(base(k))),
                    tri.bias,
                )
            }
        };
        let mut iv = S::Varyings::zero();
        for (a, b) in iv.as_mut_slice().iter_mut().zip(f.varyings.iter()) {
            *a = *b;
        }
        let inner = Fragment {
            varyings: iv,
            x: f.x,
            y: f.y,
            depth: f.depth,
            lambda: f.lambda,
            triangle: f.triangle.0,
        };
        if lit >= 256 {
            self.inner.shade(&inner)
        } else {
            // The inner shader's light times `dark + (1 - dark) lit` (Q8).
            let k = u32::from(self.dark);
            self.inner
                .shade_dimmed(&inner, (k + (((256 - k) * u32::from(lit)) >> 8)) as u16)
        }
    }
}

/// A lit-pass vertex: the inner shader's vertex `v` with light varyings `light` appended
/// (the first `M - N` of them).
pub fn with_light<const N: usize, const M: usize>(
    v: &crate::geometry::Vertex<N>,
    light: [i32; 4],
) -> crate::geometry::Vertex<M> {
    crate::geometry::Vertex {
        position: v.position,
        varyings: core::array::from_fn(|k| {
            if k < N {
                v.varyings.get(k).copied().unwrap_or(0)
            } else {
                light.get(k - N).copied().unwrap_or(0)
            }
        }),
    }
}

#[cfg(test)]
mod tests;
