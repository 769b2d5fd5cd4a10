//! Mipmapping in the reference renderer, written from Williams' pyramid and
//! OpenGL ES 3.2's mipmapping, in f64 (it shares no code with fixel's `texture::mip`).
//!
//! * Chain: level `k` is `max(1, w >> k) x max(1, h >> k)`, each texel the
//!   mean (f64) of the block of level-0 texels it covers, per RGB565 channel,
//!   rounded once (half up): level 0 at full precision, as GL filters its
//!   levels in 8 bits or more, not a box filter of rounded levels.
//! * Level of detail: from the exact screen-space derivatives of the texel
//!   coordinates of level 0 (`ux = du/dx` ...), Heckbert's
//!   `rho = max(sqrt(ux² + vx²), sqrt(uy² + vy²))`, `lambda = log2 rho`,
//!   `lambda' = clamp(lambda + bias, min, max)`.
//! * Selection: `lambda' <= 0` magnifies (magnification filter on level 0).
//!   Otherwise, with `q` the last level: no mipmapping samples level 0 with the
//!   minification filter; `*_MIPMAP_NEAREST` uses level
//!   `d = 0` if `lambda' <= 1/2`, else `ceil(lambda' + 1/2) - 1`, at most `q`;
//!   `*_MIPMAP_LINEAR` blends levels `floor(lambda')` and the next by
//!   `frac(lambda')`, both at most `q` (from `lambda' >= q` on, level `q` alone).
//!   Each level is sampled at the same normalised `(s, t)` (so at texel
//!   coordinates `s * w_k`, `t * h_k`) with the same wrap modes.

use super::sample;
use super::types::{RefFilter, RefLod, RefMip, RefTexture, RefWrap};

/// A mip chain: `levels[0]` is the base texture.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RefMipChain {
    /// The levels, largest first; every level has the base's border colour.
    pub levels: Vec<RefTexture>,
}

/// Number of levels of a full chain: `floor(log2(max(w, h))) + 1`.
pub fn full_levels(w: u32, h: u32) -> u32 {
    let m = w.max(h);
    let mut n = 1;
    while (m >> n) > 0 {
        n += 1;
    }
    n
}

/// Level `k` of `base`: each texel the mean of the `bw x bh` block of `base` texels it
/// covers (`bw = width / side_k`), per RGB565 channel, rounded half up once.
pub fn level_from_base(base: &RefTexture, k: u32) -> RefTexture {
    let (w, h) = ((base.width >> k).max(1), (base.height >> k).max(1));
    let (bw, bh) = (base.width / w, base.height / h);
    let n = f64::from(bw * bh);
    let mut texels = Vec::with_capacity((w * h) as usize);
    for j in 0..h {
        for i in 0..w {
            let mut sum = [0f64; 3];
            for y in j * bh..(j + 1) * bh {
                for x in i * bw..(i + 1) * bw {
                    let t = base.texel(x, y);
                    sum[0] += f64::from(t >> 11);
                    sum[1] += f64::from((t >> 5) & 63);
                    sum[2] += f64::from(t & 31);
                }
            }
            let q = |c: usize| (sum[c] / n + 0.5).floor() as u16;
            texels.push((q(0) << 11) | (q(1) << 5) | q(2));
        }
    }
    RefTexture {
        width: w,
        height: h,
        texels,
        border: base.border,
    }
}

impl RefMipChain {
    /// The chain of `levels` levels (`None`: down to 1 x 1) from `base`.
    pub fn build(base: &RefTexture, levels: Option<u32>) -> Self {
        let n = levels
            .unwrap_or_else(|| full_levels(base.width, base.height))
            .max(1);
        let levels = (0..n).map(|k| level_from_base(base, k)).collect();
        RefMipChain { levels }
    }

    /// A one-level chain (no mipmaps).
    pub fn single(base: &RefTexture) -> Self {
        RefMipChain {
            levels: vec![base.clone()],
        }
    }

    /// The chain laid out contiguously, level 0 first (fixel's layout).
    pub fn flatten(&self) -> Vec<u16> {
        self.levels
            .iter()
            .flat_map(|l| l.texels.iter().copied())
            .collect()
    }

    /// The base level.
    pub fn base(&self) -> &RefTexture {
        &self.levels[0]
    }
}

/// Heckbert's `rho` from the level-0 texel derivatives `[[ux, vx], [uy, vy]]`.
pub fn rho(d: [[f64; 2]; 2]) -> f64 {
    d[0][0].hypot(d[0][1]).max(d[1][0].hypot(d[1][1]))
}

/// `lambda' = clamp(log2(rho) + bias, min, max)` (`rho = 0` gives `-inf`
/// before the clamp).
pub fn lambda(d: [[f64; 2]; 2], lod: &RefLod) -> f64 {
    let l = rho(d).log2() + lod.bias;
    // f64::clamp panics on min > max; mirror fixel's "max wins below min".
    l.max(lod.min).min(lod.max.max(lod.min))
}

/// What GL samples for a given `lambda'`: `(level a, level b, weight of b)`,
/// and whether it is magnification.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Selection {
    /// True for `lambda' <= 0`: the magnification filter on level 0.
    pub magnify: bool,
    /// First level.
    pub a: u32,
    /// Second level (equal to `a` when only one is used).
    pub b: u32,
    /// Weight of level `b`, in `[0, 1)`.
    pub frac: f64,
}

/// Level selection for `lambda'` with a chain of `levels` levels.
pub fn select(lambda: f64, mip: RefMip, levels: u32) -> Selection {
    let q = levels.saturating_sub(1);
    let one = |k: u32| Selection {
        magnify: false,
        a: k,
        b: k,
        frac: 0.0,
    };
    if lambda.is_nan() || lambda <= 0.0 {
        return Selection {
            magnify: true,
            ..one(0)
        };
    }
    match mip {
        RefMip::None => one(0),
        RefMip::Nearest => {
            if lambda <= 0.5 {
                one(0)
            } else {
                let d = (lambda + 0.5).ceil() - 1.0;
                one((d.min(f64::from(q))) as u32)
            }
        }
        RefMip::Linear => {
            if lambda >= f64::from(q) {
                one(q)
            } else {
                let a = lambda.floor();
                Selection {
                    magnify: false,
                    a: a as u32,
                    b: a as u32 + 1,
                    frac: lambda - a,
                }
            }
        }
    }
}

/// Samples the chain at normalised `uv` with level-0 texel derivatives `d`.
#[allow(clippy::too_many_arguments)]
pub fn sample_mip(
    chain: &RefMipChain,
    uv: [f64; 2],
    d: [[f64; 2]; 2],
    filter: RefFilter,
    mag: RefFilter,
    mip: RefMip,
    lod: &RefLod,
    wrap: [RefWrap; 2],
) -> [f64; 3] {
    let sel = select(lambda(d, lod), mip, chain.levels.len() as u32);
    let at = |k: u32, f: RefFilter| {
        let t = &chain.levels[(k as usize).min(chain.levels.len() - 1)];
        sample::sample(t, uv, f, wrap[0], wrap[1])
    };
    if sel.magnify {
        return at(0, mag);
    }
    let a = at(sel.a, filter);
    if sel.b == sel.a || sel.frac == 0.0 {
        return a;
    }
    let b = at(sel.b, filter);
    core::array::from_fn(|c| (1.0 - sel.frac) * a[c] + sel.frac * b[c])
}
