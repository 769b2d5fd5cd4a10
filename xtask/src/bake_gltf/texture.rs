//! The base-colour texture of `bake-gltf`: the decoded image to RGB8, resampled to power-of-
//! two sides by area averaging (each target texel the mean of the source area it covers,
//! partial texels weighted by their covered fraction, in f64), then `bake`'s RGB565 rounding
//! and mip chain.

use crate::bake::{chain, full_levels};

use super::GltfOpts;

/// A baked texture chain.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BakedTexture {
    /// Index of the glTF image.
    pub image: usize,
    /// Size of the image in the file, in pixels.
    pub source_size: (u32, u32),
    /// Level 0 width, a power of two.
    pub width: u32,
    /// Level 0 height, a power of two.
    pub height: u32,
    /// Levels in `texels`.
    pub levels: u32,
    /// The chain, level 0 first, `[r5, g6, b5]`.
    pub texels: Vec<[u8; 3]>,
}

/// The decoded image as RGB8 (alpha dropped, grey expanded, 16-bit samples to their high
/// byte).
pub fn rgb8(d: &gltf::image::Data) -> Result<Vec<[u8; 3]>, String> {
    use gltf::image::Format as F;
    let (stride, wide) = match d.format {
        F::R8 => (1, false),
        F::R8G8 => (2, false),
        F::R8G8B8 => (3, false),
        F::R8G8B8A8 => (4, false),
        F::R16 => (1, true),
        F::R16G16 => (2, true),
        F::R16G16B16 => (3, true),
        F::R16G16B16A16 => (4, true),
        f => {
            return Err(format!(
                "pixel format {f:?} is not baked (8 or 16 bits per channel)"
            ))
        }
    };
    let bytes = if wide { 2 * stride } else { stride };
    let n = d.width as usize * d.height as usize;
    if d.pixels.len() < n * bytes {
        return Err(format!(
            "{} bytes of pixels for {} x {}",
            d.pixels.len(),
            d.width,
            d.height
        ));
    }
    // 16-bit samples are little-endian in the gltf crate's buffers: the high byte is second.
    let ch = |p: &[u8], c: usize| if wide { p[2 * c + 1] } else { p[c] };
    Ok(d.pixels[..n * bytes]
        .chunks_exact(bytes)
        .map(|p| {
            if stride >= 3 {
                [ch(p, 0), ch(p, 1), ch(p, 2)]
            } else {
                [ch(p, 0); 3]
            }
        })
        .collect())
}

/// `s` rounded to the nearest power of two (in log scale; at least 1).
fn nearest_pow2(s: u32) -> u32 {
    let lo = 1u32 << (31 - s.max(1).leading_zeros());
    if u64::from(s) * u64::from(s) >= 2 * u64::from(lo) * u64::from(lo) {
        lo * 2
    } else {
        lo
    }
}

/// The baked size of a `w x h` image: each side to the nearest power of two, then scaled so
/// the longer side is `size` when given (keeping the ratio of the sides, at least 1).
pub fn baked_size(w: u32, h: u32, size: Option<u32>) -> (u32, u32) {
    let (pw, ph) = (nearest_pow2(w), nearest_pow2(h));
    match size {
        None => (pw, ph),
        Some(s) => {
            let long = pw.max(ph);
            let f = |x: u32| (u64::from(x) * u64::from(s) / u64::from(long)).max(1) as u32;
            (f(pw), f(ph))
        }
    }
}

/// One axis of area resampling: for each of the `dst` cells, the source indices and weights
/// (summing to 1) of the `src` cells it covers.
fn weights(src: u32, dst: u32) -> Vec<Vec<(usize, f64)>> {
    let r = f64::from(src) / f64::from(dst);
    (0..dst)
        .map(|i| {
            let (a, b) = (f64::from(i) * r, f64::from(i + 1) * r);
            let mut v = Vec::new();
            let mut k = a.floor() as usize;
            while (k as f64) < b && k < src as usize {
                let cover = (b.min(k as f64 + 1.0) - a.max(k as f64)).max(0.0);
                if cover > 0.0 {
                    v.push((k, cover / r));
                }
                k += 1;
            }
            v
        })
        .collect()
}

/// `px` (`w x h`, RGB8) resampled to `tw x th` by area averaging, rounded to 8 bits.
pub fn resample(px: &[[u8; 3]], w: u32, h: u32, tw: u32, th: u32) -> Vec<[u8; 3]> {
    let (wx, wy) = (weights(w, tw), weights(h, th));
    // Rows first: h x tw.
    let mut rows = vec![[0.0f64; 3]; h as usize * tw as usize];
    for y in 0..h as usize {
        for (x, ws) in wx.iter().enumerate() {
            let mut acc = [0.0; 3];
            for &(k, wt) in ws {
                let p = px[y * w as usize + k];
                for c in 0..3 {
                    acc[c] += wt * f64::from(p[c]);
                }
            }
            rows[y * tw as usize + x] = acc;
        }
    }
    let mut out = Vec::with_capacity(tw as usize * th as usize);
    for ws in &wy {
        for x in 0..tw as usize {
            let mut acc = [0.0; 3];
            for &(k, wt) in ws {
                let p = rows[k * tw as usize + x];
                for c in 0..3 {
                    acc[c] += wt * p[c];
                }
            }
            out.push(acc.map(|v| v.round().clamp(0.0, 255.0) as u8));
        }
    }
    out
}

/// Flash of a chain of `levels` levels from `w x h`, in bytes (RGB565).
fn chain_bytes(w: u32, h: u32, levels: u32) -> u64 {
    (0..levels)
        .map(|k| u64::from((w >> k).max(1)) * u64::from((h >> k).max(1)) * 2)
        .sum()
}

/// Bakes image `image` (`w x h` RGB8 `px`) with the options `o`: refused when the chain
/// would take more than `o.max_texture_kib`, or `o.levels` exceeds the full chain.
pub fn bake_texture(
    image: usize,
    w: u32,
    h: u32,
    px: &[[u8; 3]],
    o: &GltfOpts,
) -> Result<BakedTexture, String> {
    if w == 0 || h == 0 {
        return Err(format!("image {image}: empty ({w} x {h})"));
    }
    let (tw, th) = baked_size(w, h, o.texture_size);
    let what = format!("image {image} ({w} x {h})");
    if tw > 4096 || th > 4096 {
        return Err(format!(
            "{what}: {tw} x {th} is larger than fixel's textures (sides up to 4096); pass \
             --texture-size"
        ));
    }
    let full = full_levels(tw, th);
    let levels = o.levels.unwrap_or(full);
    if levels > full {
        return Err(format!(
            "{what}: --levels {levels}, but a {tw} x {th} chain has 1..={full}"
        ));
    }
    let bytes = chain_bytes(tw, th, levels);
    let max = u64::from(o.max_texture_kib) * 1024;
    if bytes > max {
        let mut fit = tw.max(th);
        while fit > 1 && {
            let (a, b) = baked_size(w, h, Some(fit));
            chain_bytes(a, b, levels.min(full_levels(a, b))) > max
        } {
            fit /= 2;
        }
        return Err(format!(
            "{what}: its base-colour texture baked at {tw} x {th} with {levels} levels takes \
             {bytes} bytes of flash, more than --max-texture-kib {} ({max} bytes); \
             --texture-size {fit} fits",
            o.max_texture_kib
        ));
    }
    let base: Vec<[u8; 3]> = if (tw, th) == (w, h) {
        px.to_vec()
    } else {
        resample(px, w, h, tw, th)
    };
    // `chain` takes the 8-bit image: level 0 rounded to RGB565 once, the others filtered
    // from the 8-bit texels at full precision.
    Ok(BakedTexture {
        image,
        source_size: (w, h),
        width: tw,
        height: th,
        levels,
        texels: chain(&base, tw, th, levels),
    })
}
