//! Two-stage texture mapping (Bier & Sloan, "Two-Part Texture Mappings", IEEE CG&A 1986): the
//! texture is first put on a simple intermediate surface with an analytic map (the
//! *S-mapping*: plane, cylinder, sphere or box), then each point of the object is matched to
//! a point of that surface (the *O-mapping*) by one of four rules:
//!
//! | rule | the ray that finds the surface point |
//! |---|---|
//! | [`OMapping::ReflectedRay`] | from the point along the view ray reflected about the normal (this is environment mapping) |
//! | [`OMapping::ObjectNormal`] | from the point along the object's normal |
//! | [`OMapping::Centroid`] | from the object's centroid through the point |
//! | [`OMapping::SurfaceNormal`] | the surface point whose own normal passes through the point |
//!
//! The ray leaves from inside the surface (the object sits inside it) and the exit point
//! counts. The S-mappings are [`UvMapping`]'s: planar; cylindrical and spherical around the
//! surface's axis (so they share its seam and poles, fixed per triangle by
//! [`map_mesh_with`](super::map_mesh_with)); the box maps the whole texture onto each face,
//! face `X` as `(z, −y)`, `Y` as `(x, z)`, `Z` as `(x, −y)`, scaled to the face.
//!
//! Everything is per vertex, in fixed point: I16F16 positions, `i128` intermediates, one
//! integer square root per ray for the cylinder and the sphere, one division per ray. A ray
//! that misses (parallel to a plane or to the cylinder's axis, a plane behind the ray, a
//! hit beyond the I16F16 range, or a zero normal) gives the surface-normal rule's point
//! instead, so every vertex gets coordinates.

use crate::math::{Fx, Vec3};
use crate::shading::uv_mapping::{Axis, ReadyMapping, UvAt, UvGenerator, UvMapping};
use crate::Error;

/// The intermediate surface and its S-mapping (model units, I16F16).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Intermediate {
    /// The plane through `origin` spanned by `s` and `t`, mapped as
    /// [`UvMapping::Planar`].
    Plane {
        /// Where `u = v = 0`.
        origin: Vec3,
        /// The `u` direction, scaled (textures per unit).
        s: Vec3,
        /// The `v` direction, scaled.
        t: Vec3,
    },
    /// A cylinder of `radius` around `axis` through `center`, mapped as
    /// [`UvMapping::Cylindrical`] (`v` from `top` to `bottom`).
    Cylinder {
        /// A point on the axis.
        center: Vec3,
        /// The axis.
        axis: Axis,
        /// Radius (> 0).
        radius: Fx,
        /// Height of `v = 0` from `center`.
        top: Fx,
        /// Height of `v = 1` (differs from `top`).
        bottom: Fx,
    },
    /// A sphere of `radius` around `center`, mapped as [`UvMapping::Spherical`].
    Sphere {
        /// Centre.
        center: Vec3,
        /// Polar axis.
        axis: Axis,
        /// Radius (> 0).
        radius: Fx,
    },
    /// The axis-aligned box `center ± half`, the whole texture on each face.
    Box {
        /// Centre.
        center: Vec3,
        /// Half extents (each > 0).
        half: Vec3,
    },
}

/// How an object point finds its intermediate-surface point (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OMapping {
    /// Along the view ray from `eye` (model space) reflected about the normal.
    ReflectedRay {
        /// The eye, in model space.
        eye: Vec3,
    },
    /// Along the object's normal.
    ObjectNormal,
    /// From the object's centroid (model space) through the point.
    Centroid(Vec3),
    /// The surface point whose normal passes through the point.
    SurfaceNormal,
}

/// A two-stage mapping: an intermediate surface and an O-mapping rule. A
/// [`UvGenerator`] (use it with [`map_mesh_with`](super::map_mesh_with)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TwoStage {
    /// The intermediate surface.
    pub surface: Intermediate,
    /// The O-mapping rule.
    pub rule: OMapping,
}

/// A checked [`TwoStage`].
#[derive(Clone, Copy, Debug)]
pub struct ReadyTwoStage {
    two: TwoStage,
    /// The S-mapping of the surface's points.
    s_map: ReadyMapping,
}

type V = [i128; 3];

fn v(p: Vec3) -> V {
    [p.x, p.y, p.z].map(|c| i128::from(c.to_bits()))
}

fn vec3(a: V) -> Option<Vec3> {
    let c = |x: i128| i32::try_from(x).ok().map(Fx::from_bits);
    Some(Vec3::new(c(a[0])?, c(a[1])?, c(a[2])?))
}

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: V, b: V) -> i128 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `d` scaled by a power of two so its largest component has 20 to 24 bits (a direction:
/// only its way matters), or `None` for zero.
fn direction(d: V) -> Option<V> {
    let big = d.iter().map(|c| c.unsigned_abs()).max()?;
    if big == 0 {
        return None;
    }
    let len = 128 - big.leading_zeros();
    Some(if len > 24 {
        d.map(|c| c >> (len - 24))
    } else {
        d.map(|c| c << (20u32.saturating_sub(len)))
    })
}

/// `o + d n / den` (`den > 0`), rounded.
fn along(o: V, d: V, n: i128, den: i128) -> V {
    core::array::from_fn(|k| o[k] + (2 * d[k] * n + den).div_euclid(2 * den))
}

/// The far root of `a λ² + 2 b λ + c = 0` (`a > 0`) as `(numerator, a)`: `λ = num / a`.
fn far_root(a: i128, b: i128, c: i128) -> Option<(i128, i128)> {
    // Operands below 2^100 for coordinates in I16F16 and 24-bit directions... reduce first.
    let disc = b.checked_mul(b)?.checked_sub(a.checked_mul(c)?)?;
    if disc < 0 {
        return None;
    }
    let s = disc.unsigned_abs().isqrt() as i128;
    Some((s - b, a))
}

/// Shifts three quadratic coefficients right together so their products fit `i128`.
fn reduce(a: i128, b: i128, c: i128) -> (i128, i128, i128) {
    let big = a.unsigned_abs().max(b.unsigned_abs()).max(c.unsigned_abs());
    let len = 128 - big.leading_zeros();
    let k = len.saturating_sub(60);
    (a >> k, b >> k, c >> k)
}

impl ReadyTwoStage {
    /// The surface point for the rule's ray from `o` along `d` (both I16F16 bits), or the
    /// surface-normal point when the ray misses.
    fn exit(&self, o: V, d: V, p: V) -> V {
        // A hit outside the I16F16 range (a grazing ray) counts as a miss.
        self.hit(o, d)
            .filter(|q| vec3(*q).is_some())
            .unwrap_or_else(|| self.normal_point(p))
    }

    fn hit(&self, o: V, d: V) -> Option<V> {
        let d = direction(d)?;
        match self.two.surface {
            Intermediate::Plane { origin, s, t } => {
                let m = cross(v(s), v(t));
                let den = dot(d, m);
                if den == 0 {
                    return None;
                }
                let num = dot(sub(v(origin), o), m);
                let (num, den) = if den < 0 { (-num, -den) } else { (num, den) };
                // Behind the ray: a miss.
                (num >= 0).then(|| along(o, d, num, den))
            }
            Intermediate::Sphere { center, radius, .. } => {
                let oc = sub(o, v(center));
                let r = i128::from(radius.to_bits());
                let (a, b, c) = reduce(dot(d, d), dot(oc, d), dot(oc, oc) - r * r);
                let (num, den) = far_root(a, b, c)?;
                (num >= 0 && den > 0).then(|| along(o, d, num, den))
            }
            Intermediate::Cylinder {
                center,
                axis,
                radius,
                ..
            } => {
                let oc = sub(o, v(center));
                let flat = |x: V| match axis {
                    Axis::X => [0, x[1], x[2]],
                    Axis::Y => [x[0], 0, x[2]],
                    Axis::Z => [x[0], x[1], 0],
                };
                let (o2, d2) = (flat(oc), flat(d));
                let r = i128::from(radius.to_bits());
                let (a, b, c) = reduce(dot(d2, d2), dot(o2, d2), dot(o2, o2) - r * r);
                if a == 0 {
                    return None;
                }
                let (num, den) = far_root(a, b, c)?;
                (num >= 0 && den > 0).then(|| along(o, d, num, den))
            }
            Intermediate::Box { center, half } => {
                let oc = sub(o, v(center));
                let h = v(half);
                // Exit: the smallest positive t_k = (±h_k − oc_k) / d_k over the axes.
                let mut best: Option<(i128, i128)> = None;
                for k in 0..3 {
                    if d[k] == 0 {
                        continue;
                    }
                    let (num, den) = if d[k] > 0 {
                        (h[k] - oc[k], d[k])
                    } else {
                        (oc[k] + h[k], -d[k])
                    };
                    if num < 0 {
                        continue;
                    }
                    // num / den < bn / bd  <=>  num bd < bn den (denominators positive).
                    if best.is_none_or(|(bn, bd)| num * bd < bn * den) {
                        best = Some((num, den));
                    }
                }
                let (num, den) = best?;
                Some(along(o, d, num, den))
            }
        }
    }

    /// The surface point whose normal passes through `p` (the point itself for the plane,
    /// cylinder and sphere, whose S-mappings only read its direction or projection; for the
    /// box, `p` pushed out along its largest relative coordinate).
    fn normal_point(&self, p: V) -> V {
        match self.two.surface {
            Intermediate::Box { center, half } => {
                let (oc, h) = (sub(p, v(center)), v(half));
                // Face: the largest |oc_k| / h_k.
                let mut f = 0;
                for k in 1..3 {
                    if oc[k].abs() * h[f] > oc[f].abs() * h[k] {
                        f = k;
                    }
                }
                if oc[f] == 0 {
                    return p;
                }
                let q: V = core::array::from_fn(|k| oc[k] * h[f] / oc[f].abs());
                [
                    q[0] + v(center)[0],
                    q[1] + v(center)[1],
                    q[2] + v(center)[2],
                ]
            }
            _ => p,
        }
    }

    fn s_map(&self, q: V) -> ([Fx; 2], bool) {
        let Some(qv) = vec3(q) else {
            return ([Fx::ZERO; 2], false);
        };
        match self.two.surface {
            Intermediate::Box { center, half } => {
                let (oc, h) = (sub(q, v(center)), v(half));
                let mut f = 0;
                for k in 1..3 {
                    if oc[k].abs() * h[f] > oc[f].abs() * h[k] {
                        f = k;
                    }
                }
                let (a, b) = match f {
                    0 => ((oc[2], h[2]), (-oc[1], h[1])),
                    1 => ((oc[0], h[0]), (oc[2], h[2])),
                    _ => ((oc[0], h[0]), (-oc[1], h[1])),
                };
                // (a / h + 1) / 2 in I16F16.
                let t = |(x, hh): (i128, i128)| {
                    let hh = hh.max(1);
                    Fx::from_bits(((x + hh) * 32768 / hh).clamp(0, 65536) as i32)
                };
                ([t(a), t(b)], false)
            }
            _ => UvAt::at(&self.s_map, qv, Vec3::ZERO),
        }
    }
}

fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

impl UvAt for ReadyTwoStage {
    fn at(&self, p: Vec3, n: Vec3) -> ([Fx; 2], bool) {
        let (pp, nn) = (v(p), v(n));
        let q = match self.two.rule {
            OMapping::SurfaceNormal => self.normal_point(pp),
            OMapping::ObjectNormal => self.exit(pp, nn, pp),
            OMapping::Centroid(c) => {
                let c = v(c);
                self.exit(c, sub(pp, c), pp)
            }
            OMapping::ReflectedRay { eye } => {
                // r = e (n·n) − 2 (n·e) n for e = p − eye: the reflection, scaled by |n|².
                let e = direction(sub(pp, v(eye))).unwrap_or([0; 3]);
                let nd = direction(nn).unwrap_or([0; 3]);
                let (nn2, ne) = (dot(nd, nd), dot(nd, e));
                let r: V = core::array::from_fn(|k| e[k] * nn2 - 2 * ne * nd[k]);
                self.exit(pp, r, pp)
            }
        };
        self.s_map(q)
    }

    fn wraps(&self) -> bool {
        matches!(
            self.two.surface,
            Intermediate::Cylinder { .. } | Intermediate::Sphere { .. }
        )
    }
}

impl UvGenerator for TwoStage {
    type Ready = ReadyTwoStage;

    fn ready(&self) -> Result<ReadyTwoStage, Error> {
        let mapping = match self.surface {
            Intermediate::Plane { origin, s, t } => {
                if cross(v(s), v(t)) == [0; 3] {
                    return Err(Error::ZeroVector("plane (s × t)"));
                }
                UvMapping::Planar { origin, s, t }
            }
            Intermediate::Cylinder {
                center,
                axis,
                radius,
                top,
                bottom,
            } => {
                if radius <= Fx::ZERO {
                    return Err(Error::OutOfRange {
                        what: "cylinder radius (must be > 0)",
                    });
                }
                UvMapping::Cylindrical {
                    center,
                    axis,
                    top,
                    bottom,
                }
            }
            Intermediate::Sphere {
                center,
                axis,
                radius,
            } => {
                if radius <= Fx::ZERO {
                    return Err(Error::OutOfRange {
                        what: "sphere radius (must be > 0)",
                    });
                }
                UvMapping::Spherical { center, axis }
            }
            Intermediate::Box { center, half } => {
                if half.x <= Fx::ZERO || half.y <= Fx::ZERO || half.z <= Fx::ZERO {
                    return Err(Error::OutOfRange {
                        what: "box half extents (must be > 0)",
                    });
                }
                UvMapping::Spherical {
                    center,
                    axis: Axis::Y,
                }
            }
        };
        Ok(ReadyTwoStage {
            two: *self,
            s_map: mapping.ready()?,
        })
    }
}

impl TwoStage {
    /// The coordinates of one vertex (no seam or pole handling: see
    /// [`map_mesh_with`](super::map_mesh_with)).
    pub fn uv(&self, p: Vec3, n: Vec3) -> Result<[Fx; 2], Error> {
        Ok(self.ready()?.at(p, n).0)
    }
}
