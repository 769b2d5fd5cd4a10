//! The f64 reference for two-stage mapping (Bier & Sloan, "Two-Part Texture Mappings"; the
//! cylinder S-mapping `u = atan2`, `v = height`): ray and surface intersections from the
//! formulas in f64, then the S-mappings of [`super::uv_gen`]. Shares only the conventions
//! (axes, seam, face layouts) with fixel.

use super::uv_gen::{RefAxis, RefUvMapping};

/// The intermediate surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RefSurface {
    Plane {
        origin: [f64; 3],
        s: [f64; 3],
        t: [f64; 3],
    },
    Cylinder {
        center: [f64; 3],
        axis: RefAxis,
        radius: f64,
        top: f64,
        bottom: f64,
    },
    Sphere {
        center: [f64; 3],
        axis: RefAxis,
        radius: f64,
    },
    Box {
        center: [f64; 3],
        half: [f64; 3],
    },
}

/// The O-mapping rule.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RefRule {
    Reflected { eye: [f64; 3] },
    Normal,
    Centroid([f64; 3]),
    SurfaceNormal,
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn at(o: [f64; 3], d: [f64; 3], l: f64) -> [f64; 3] {
    [o[0] + l * d[0], o[1] + l * d[1], o[2] + l * d[2]]
}

/// The far root of `a λ² + 2 b λ + c`.
fn far(a: f64, b: f64, c: f64) -> Option<f64> {
    let disc = b * b - a * c;
    (a > 0.0 && disc >= 0.0)
        .then(|| (-b + disc.sqrt()) / a)
        .filter(|l| *l >= 0.0)
}

impl RefSurface {
    fn hit(&self, o: [f64; 3], d: [f64; 3]) -> Option<[f64; 3]> {
        if d == [0.0; 3] {
            return None;
        }
        match *self {
            RefSurface::Plane { origin, s, t } => {
                let m = cross(s, t);
                let den = dot(d, m);
                let l = dot(sub(origin, o), m) / den;
                (den != 0.0 && l >= 0.0).then(|| at(o, d, l))
            }
            RefSurface::Sphere { center, radius, .. } => {
                let oc = sub(o, center);
                far(dot(d, d), dot(oc, d), dot(oc, oc) - radius * radius).map(|l| at(o, d, l))
            }
            RefSurface::Cylinder {
                center,
                axis,
                radius,
                ..
            } => {
                let oc = sub(o, center);
                let flat = |x: [f64; 3]| {
                    let (r, _, f) = axis.frame(x);
                    [r, 0.0, f]
                };
                let (o2, d2) = (flat(oc), flat(d));
                far(dot(d2, d2), dot(o2, d2), dot(o2, o2) - radius * radius).map(|l| at(o, d, l))
            }
            RefSurface::Box { center, half } => {
                let oc = sub(o, center);
                let mut best = f64::INFINITY;
                for k in 0..3 {
                    if d[k] != 0.0 {
                        let t = (half[k].copysign(d[k]) - oc[k]) / d[k];
                        if t >= 0.0 {
                            best = best.min(t);
                        }
                    }
                }
                best.is_finite().then(|| at(o, d, best))
            }
        }
    }

    fn normal_point(&self, p: [f64; 3]) -> [f64; 3] {
        match *self {
            RefSurface::Box { center, half } => {
                let oc = sub(p, center);
                let f = (0..3)
                    .max_by(|&a, &b| (oc[a].abs() / half[a]).total_cmp(&(oc[b].abs() / half[b])))
                    .unwrap_or(0);
                if oc[f] == 0.0 {
                    return p;
                }
                let s = half[f] / oc[f].abs();
                [
                    center[0] + oc[0] * s,
                    center[1] + oc[1] * s,
                    center[2] + oc[2] * s,
                ]
            }
            _ => p,
        }
    }

    /// `(uv, pole)` of surface point `q`.
    fn s_map(&self, q: [f64; 3]) -> ([f64; 2], bool) {
        match *self {
            RefSurface::Plane { origin, s, t } => RefUvMapping::Planar { origin, s, t }.uv(q),
            RefSurface::Cylinder {
                center,
                axis,
                top,
                bottom,
                ..
            } => RefUvMapping::Cylindrical {
                center,
                axis,
                top,
                bottom,
            }
            .uv(q),
            RefSurface::Sphere { center, axis, .. } => {
                RefUvMapping::Spherical { center, axis }.uv(q)
            }
            RefSurface::Box { center, half } => {
                let oc = sub(q, center);
                let f = (0..3)
                    .max_by(|&a, &b| (oc[a].abs() / half[a]).total_cmp(&(oc[b].abs() / half[b])))
                    .unwrap_or(0);
                let (a, b) = match f {
                    0 => ((oc[2], half[2]), (-oc[1], half[1])),
                    1 => ((oc[0], half[0]), (oc[2], half[2])),
                    _ => ((oc[0], half[0]), (-oc[1], half[1])),
                };
                let t = |(x, h): (f64, f64)| ((x / h + 1.0) / 2.0).clamp(0.0, 1.0);
                ([t(a), t(b)], false)
            }
        }
    }

    /// Whether `u` wraps.
    pub fn wraps(&self) -> bool {
        matches!(
            self,
            RefSurface::Cylinder { .. } | RefSurface::Sphere { .. }
        )
    }

    /// `(uv, pole)` of object point `p` with normal `n` under `rule`.
    pub fn uv(&self, rule: RefRule, p: [f64; 3], n: [f64; 3]) -> ([f64; 2], bool) {
        // Hits beyond fixel's I16F16 range are misses (grazing rays).
        let hit = |o, d| {
            self.hit(o, d)
                .filter(|q: &[f64; 3]| q.iter().all(|c| c.abs() < 32767.0))
        };
        let q = match rule {
            RefRule::SurfaceNormal => self.normal_point(p),
            RefRule::Normal => hit(p, n).unwrap_or_else(|| self.normal_point(p)),
            RefRule::Centroid(c) => hit(c, sub(p, c)).unwrap_or_else(|| self.normal_point(p)),
            RefRule::Reflected { eye } => {
                let e = sub(p, eye);
                let k = 2.0 * dot(n, e) / dot(n, n).max(1e-300);
                let r = [e[0] - k * n[0], e[1] - k * n[1], e[2] - k * n[2]];
                hit(p, r).unwrap_or_else(|| self.normal_point(p))
            }
        };
        self.s_map(q)
    }
}
