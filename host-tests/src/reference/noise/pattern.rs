//! The solid-texture patterns in f64: the colour ramp, marble, wood, granite, composition
//! by selection, and the flame.

use super::{noise, turbulence, RefOctaves};

/// The colour of a piecewise-linear ramp (`(position 0..=255, 0xRRGGBB)` keys) at position
/// `x` (`0..=255`, clamped), channels `0..=1`.
pub fn ramp(keys: &[(u8, u32)], x: f64) -> [f64; 3] {
    let ch = |c: u32, s: u32| f64::from((c >> s) & 255) / 255.0;
    let rgb = |c: u32| [ch(c, 16), ch(c, 8), ch(c, 0)];
    let x = x.clamp(0.0, 255.0);
    let first = keys[0];
    if x <= f64::from(first.0) {
        return rgb(first.1);
    }
    for w in keys.windows(2) {
        let (a, b) = (w[0], w[1]);
        if x <= f64::from(b.0) {
            let t = (x - f64::from(a.0)) / (f64::from(b.0) - f64::from(a.0));
            let (ca, cb) = (rgb(a.1), rgb(b.1));
            return core::array::from_fn(|i| ca[i] + t * (cb[i] - ca[i]));
        }
    }
    rgb(keys[keys.len() - 1].1)
}

/// A solid texture in f64: colour at a point (cells), given the turbulence there.
#[derive(Clone, Copy, Debug)]
pub enum RefPattern {
    /// `ramp((1 + sin(2π (f x + a t))) / 2 · 255)`: `f` turns per cell, `a` turns.
    Marble {
        /// Ramp keys.
        keys: &'static [(u8, u32)],
        /// Turns per cell.
        freq: f64,
        /// Turns per unit turbulence.
        amp: f64,
    },
    /// `ramp(frac(rings · sqrt(x² + z²) + a t) · 256)`.
    Wood {
        /// Ramp keys.
        keys: &'static [(u8, u32)],
        /// Rings per cell.
        rings: f64,
        /// Rings per unit turbulence.
        amp: f64,
    },
    /// `ramp(turbulence(2^s p) · 256)`.
    Granite {
        /// Ramp keys.
        keys: &'static [(u8, u32)],
        /// Grain scale `s`.
        shift: u32,
    },
    /// `a` or `b` by a third noise with a smooth threshold: see [`select_color`].
    Select {
        /// Below the threshold.
        a: &'static RefPattern,
        /// Above it.
        b: &'static RefPattern,
        /// Threshold, noise units.
        threshold: f64,
        /// Blend width, noise units.
        width: f64,
        /// Selector scale `2^shift`.
        shift: u32,
        /// Selector offset, cells.
        offset: [f64; 3],
    },
}

impl RefPattern {
    /// The demonstration patterns, from fixel's preset constants (data).
    pub fn presets() -> [RefPattern; 3] {
        use fixel::shading::noise::presets::*;
        [
            RefPattern::Marble {
                keys: &MARBLE_KEYS,
                freq: f64::from(MARBLE_FREQ) / 65536.0,
                amp: f64::from(MARBLE_AMP) / 256.0,
            },
            RefPattern::Wood {
                keys: &WOOD_KEYS,
                rings: f64::from(WOOD_RINGS) / 256.0,
                amp: f64::from(WOOD_AMP) / 256.0,
            },
            RefPattern::Granite {
                keys: &GRANITE_KEYS,
                shift: u32::from(GRANITE_SHIFT),
            },
        ]
    }

    /// The colour at `p` (cells) for a pixel of level of detail `lambda`.
    pub fn color(&self, p: [f64; 3], octaves: RefOctaves, lambda: f64) -> [f64; 3] {
        match *self {
            RefPattern::Marble { keys, freq, amp } => {
                let t = turbulence(p, octaves, lambda);
                let phase = freq * p[0] + amp * t;
                let s = (2.0 * std::f64::consts::PI * phase).sin();
                ramp(keys, (1.0 + s) / 2.0 * 255.0)
            }
            RefPattern::Wood { keys, rings, amp } => {
                let t = turbulence(p, octaves, lambda);
                let r = (p[0] * p[0] + p[2] * p[2]).sqrt();
                let ring = rings * r + amp * t;
                ramp(keys, (ring - ring.floor()) * 256.0)
            }
            RefPattern::Granite { keys, shift } => {
                let s = f64::from(1u32 << shift);
                let t = turbulence(p.map(|c| c * s), octaves, lambda + f64::from(shift));
                ramp(keys, t * 256.0)
            }
            RefPattern::Select {
                a,
                b,
                threshold,
                width,
                shift,
                offset,
            } => select_color(*a, *b, threshold, width, shift, offset, p, octaves, lambda),
        }
    }
}

/// The flame as fixel defines it (`fixel::shading::noise::flame`), in
/// f64: turbulence at `(2x, 2y − rise·t, churn·t)`, bend `= gain · (turbulence − mid)`,
/// colour `ramp(|x| + y/2 + bend)` times the fade `1 − y + bend / 2`. `x`, `y` in flame
/// units, `t` in seconds; constants from fixel's (data).
pub fn flame(x: f64, y: f64, t: f64, octaves: u32) -> [f64; 3] {
    use fixel::shading::noise::{FLAME_CHURN, FLAME_RISE};
    let rise = f64::from(FLAME_RISE) / 65536.0;
    let churn = f64::from(FLAME_CHURN) / 65536.0;
    let p = [2.0 * x, 2.0 * y - rise * t, churn * t];
    flame_color(x, y, turbulence(p, RefOctaves::Fixed(octaves), 0.0))
}

/// The flame's colour at `(x, y)` (flame units) for the turbulence `turb` there: the
/// colour of [`flame`] and of the flame from baked layers.
pub fn flame_color(x: f64, y: f64, turb: f64) -> [f64; 3] {
    use fixel::shading::noise::{FLAME_GAIN, FLAME_KEYS, FLAME_TURB_MID};
    let bend = f64::from(FLAME_GAIN) / 256.0 * (turb - f64::from(FLAME_TURB_MID) / 32768.0);
    let arg = x.abs().min(2.0) + y.clamp(0.0, 2.0) / 2.0 + bend;
    let c = ramp(&FLAME_KEYS, (arg * 256.0).clamp(0.0, 255.0));
    let fade = (1.0 - y + bend / 2.0).clamp(0.0, 1.0);
    c.map(|v| v * fade)
}

/// Composition by selection (fixel's `Select`), in f64: the selector `n = noise(2^shift ·
/// p + offset)`, `t = clamp((n − (threshold − width/2)) / width, 0, 1)`, the weight of `b`
/// `w = 3t² − 2t³`, and the colour `a · (1 − w) + b · w`. Threshold and width in noise
/// units (`-1..1`), offset in cells.
#[allow(clippy::too_many_arguments)]
pub fn select_color(
    a: RefPattern,
    b: RefPattern,
    threshold: f64,
    width: f64,
    shift: u32,
    offset: [f64; 3],
    p: [f64; 3],
    octaves: RefOctaves,
    lambda: f64,
) -> [f64; 3] {
    let s = f64::from(1u32 << shift);
    let n = noise(
        p[0] * s + offset[0],
        p[1] * s + offset[1],
        p[2] * s + offset[2],
    );
    let t = ((n - (threshold - width / 2.0)) / width).clamp(0.0, 1.0);
    let w = t * t * (3.0 - 2.0 * t);
    let (ca, cb) = (a.color(p, octaves, lambda), b.color(p, octaves, lambda));
    core::array::from_fn(|i| ca[i] * (1.0 - w) + cb[i] * w)
}
