//! `cargo xtask bake-palette`: an RGB565 texture (a PNG, or fixel's benchmark texture
//! `T(w, h)`) quantised to a 16- or 256-colour RGB565 palette and 4- or 8-bit indices
//! (`fixel::texture::PaletteMips`), as a Rust source file of `static` arrays, with the
//! error against the RGB565 source.
//!
//! * The source is the RGB565 chain `bake` makes (level 0 rounded to nearest, 2 x 2 box
//!   filter below), so the error printed is the palette's alone.
//! * Quantisation: median cut (the box with the largest channel range times population is
//!   split at the median of its longest channel) over the distinct colours of every level,
//!   weighted by their counts, then 8 rounds of k-means (Lloyd), the centres rounded to
//!   RGB565. Distances are squared 8-bit RGB (channels bit-replicated).
//! * One palette for every level (the format has one): the printed table also gives what a
//!   palette per level would reach, so the choice is measured.
//! * `--dither`: Floyd-Steinberg error diffusion within each level, in 8-bit RGB.
//! * Error: PSNR (dB, over the three 8-bit channels) and the largest channel error (8-bit
//!   units) against the RGB565 source, per level and over the chain.

use std::fmt::Write as _;
use std::path::Path;

use clap::Args;

use crate::bake::{chain, full_levels, read_rgb8, BakeError, Levels, DEFAULT_RGB565};

/// An RGB565 colour as its channels `[r5, g6, b5]`.
pub type C565 = [u8; 3];

/// The 8-bit channels of an RGB565 colour (bit replication, as fixel's PNG writer).
pub fn rgb8(c: C565) -> [f64; 3] {
    [
        f64::from((c[0] << 3) | (c[0] >> 2)),
        f64::from((c[1] << 2) | (c[1] >> 4)),
        f64::from((c[2] << 3) | (c[2] >> 2)),
    ]
}

/// The nearest RGB565 colour to 8-bit channels `c`.
fn to565f(c: [f64; 3]) -> C565 {
    let q = |v: f64, max: f64| (v.clamp(0.0, 255.0) * max / 255.0).round() as u8;
    [q(c[0], 31.0), q(c[1], 63.0), q(c[2], 31.0)]
}

fn dist2(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]) * (a[k] - b[k])).sum()
}

/// A palette of at most `k` colours for `px` (median cut, then 8 rounds of k-means).
pub fn quantise(px: &[C565], k: usize) -> Vec<C565> {
    let mut hist: std::collections::BTreeMap<C565, u64> = std::collections::BTreeMap::new();
    for &c in px {
        *hist.entry(c).or_default() += 1;
    }
    let colors: Vec<([f64; 3], f64)> = hist.iter().map(|(&c, &n)| (rgb8(c), n as f64)).collect();
    if colors.len() <= k {
        return hist.keys().copied().collect();
    }
    // Median cut.
    let mut boxes: Vec<Vec<usize>> = vec![(0..colors.len()).collect()];
    while boxes.len() < k {
        let score = |b: &Vec<usize>| -> (f64, usize) {
            let mut best = (0.0, 0);
            for ch in 0..3 {
                let (lo, hi) = b.iter().fold((f64::MAX, f64::MIN), |(l, h), &i| {
                    (l.min(colors[i].0[ch]), h.max(colors[i].0[ch]))
                });
                if hi - lo > best.0 {
                    best = (hi - lo, ch);
                }
            }
            let pop: f64 = b.iter().map(|&i| colors[i].1).sum();
            (best.0 * pop, best.1)
        };
        let Some((bi, ch)) = boxes
            .iter()
            .enumerate()
            .filter(|(_, b)| b.len() > 1)
            .map(|(i, b)| (i, score(b)))
            .max_by(|a, b| a.1 .0.total_cmp(&b.1 .0))
            .map(|(i, s)| (i, s.1))
        else {
            break;
        };
        let mut b = boxes.swap_remove(bi);
        b.sort_by(|&x, &y| colors[x].0[ch].total_cmp(&colors[y].0[ch]));
        let half: f64 = b.iter().map(|&i| colors[i].1).sum::<f64>() / 2.0;
        let mut acc = 0.0;
        let mut cut = 1;
        for (j, &i) in b.iter().enumerate() {
            acc += colors[i].1;
            if acc >= half {
                cut = (j + 1).clamp(1, b.len() - 1);
                break;
            }
        }
        let rest = b.split_off(cut);
        boxes.push(b);
        boxes.push(rest);
    }
    let mean = |b: &[usize]| -> [f64; 3] {
        let n: f64 = b.iter().map(|&i| colors[i].1).sum();
        core::array::from_fn(|ch| {
            b.iter()
                .map(|&i| colors[i].0[ch] * colors[i].1)
                .sum::<f64>()
                / n
        })
    };
    let mut centres: Vec<[f64; 3]> = boxes.iter().map(|b| mean(b)).collect();
    // k-means.
    for _ in 0..8 {
        let mut sum = vec![([0.0; 3], 0.0); centres.len()];
        for &(c, n) in &colors {
            let j = nearest_f(&centres, c);
            for (acc, x) in sum[j].0.iter_mut().zip(c) {
                *acc += x * n;
            }
            sum[j].1 += n;
        }
        for (c, (s, n)) in centres.iter_mut().zip(sum) {
            if n > 0.0 {
                *c = s.map(|x| x / n);
            }
        }
    }
    let mut p: Vec<C565> = centres.into_iter().map(to565f).collect();
    p.sort();
    p.dedup();
    p
}

fn nearest_f(p: &[[f64; 3]], c: [f64; 3]) -> usize {
    let mut best = (f64::MAX, 0);
    for (j, &q) in p.iter().enumerate() {
        let d = dist2(q, c);
        if d < best.0 {
            best = (d, j);
        }
    }
    best.1
}

/// Indices into `palette` for a `w x h` level `px`: nearest colour, or with Floyd-Steinberg
/// error diffusion when `dither`.
pub fn map_level(px: &[C565], w: u32, h: u32, palette: &[C565], dither: bool) -> Vec<u8> {
    let pf: Vec<[f64; 3]> = palette.iter().map(|&c| rgb8(c)).collect();
    let mut err = vec![[0.0f64; 3]; px.len()];
    let mut out = Vec::with_capacity(px.len());
    for y in 0..h as usize {
        for x in 0..w as usize {
            let i = y * w as usize + x;
            let want: [f64; 3] = core::array::from_fn(|k| rgb8(px[i])[k] + err[i][k]);
            let j = nearest_f(&pf, want);
            out.push(j as u8);
            if dither {
                let e: [f64; 3] = core::array::from_fn(|k| want[k] - pf[j][k]);
                let mut spread = |dx: isize, dy: usize, f: f64| {
                    let (nx, ny) = (x as isize + dx, y + dy);
                    if nx >= 0 && (nx as u32) < w && ny < h as usize {
                        let t = ny * w as usize + nx as usize;
                        for k in 0..3 {
                            err[t][k] += e[k] * f;
                        }
                    }
                };
                spread(1, 0, 7.0 / 16.0);
                spread(-1, 1, 3.0 / 16.0);
                spread(0, 1, 5.0 / 16.0);
                spread(1, 1, 1.0 / 16.0);
            }
        }
    }
    out
}

/// Error of `got` against `want` (RGB565 colours): (PSNR in dB over 8-bit channels, largest
/// channel error in 8-bit units). PSNR is infinite for equal colours.
pub fn error(want: &[C565], got: &[C565]) -> (f64, f64) {
    let (mut se, mut max) = (0.0, 0.0f64);
    for (&a, &b) in want.iter().zip(got) {
        let (a, b) = (rgb8(a), rgb8(b));
        for k in 0..3 {
            let d = a[k] - b[k];
            se += d * d;
            max = max.max(d.abs());
        }
    }
    let mse = se / (3.0 * want.len().max(1) as f64);
    (10.0 * (255.0 * 255.0 / mse).log10(), max)
}

/// Packs indices as fixel's `Index4` (low nibble first, a byte per odd count's last) or
/// `Index8` (one per byte), level by level.
pub fn pack(levels: &[Vec<u8>], bits: u32) -> Vec<u8> {
    let mut out = Vec::new();
    for l in levels {
        if bits == 8 {
            out.extend_from_slice(l);
        } else {
            for pair in l.chunks(2) {
                out.push(pair[0] | pair.get(1).copied().unwrap_or(0) << 4);
            }
        }
    }
    out
}

/// A quantised chain.
pub struct Quantised {
    /// Level 0 sides.
    pub width: u32,
    /// Level 0 height.
    pub height: u32,
    /// Levels.
    pub levels: u32,
    /// Bits per index.
    pub bits: u32,
    /// The palette, padded to `1 << bits` entries with black.
    pub palette: Vec<C565>,
    /// Indices per level, unpacked.
    pub indices: Vec<Vec<u8>>,
    /// (PSNR, max error) per level, shared palette.
    pub error: Vec<(f64, f64)>,
    /// (PSNR, max error) over the chain, shared palette.
    pub total: (f64, f64),
    /// PSNR per level with a palette of its own.
    pub per_level_psnr: Vec<f64>,
}

/// Quantises the RGB565 chain `src` (`levels` levels from `w x h`).
pub fn quantise_chain(
    src: &[C565],
    w: u32,
    h: u32,
    levels: u32,
    bits: u32,
    dither: bool,
) -> Quantised {
    let k = 1usize << bits;
    let mut palette = quantise(src, k);
    let (mut off, mut indices, mut error, mut per_level_psnr) = (0, vec![], vec![], vec![]);
    let mut mapped = Vec::with_capacity(src.len());
    for l in 0..levels {
        let (lw, lh) = ((w >> l).max(1), (h >> l).max(1));
        let n = (lw * lh) as usize;
        let level = &src[off..off + n];
        let ix = map_level(level, lw, lh, &palette, dither);
        let got: Vec<C565> = ix.iter().map(|&i| palette[i as usize]).collect();
        error.push(self::error(level, &got));
        mapped.extend(got);
        let own = quantise(level, k);
        let own_ix = map_level(level, lw, lh, &own, dither);
        let own_got: Vec<C565> = own_ix.iter().map(|&i| own[i as usize]).collect();
        per_level_psnr.push(self::error(level, &own_got).0);
        indices.push(ix);
        off += n;
    }
    let total = self::error(src, &mapped);
    palette.resize(k, [0, 0, 0]);
    Quantised {
        width: w,
        height: h,
        levels,
        bits,
        palette,
        indices,
        error,
        total,
        per_level_psnr,
    }
}

/// The generated Rust source.
pub fn source(q: &Quantised, input: &str, name: &str, rgb565: &str) -> String {
    let n = name;
    let packed = pack(&q.indices, q.bits);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "// Generated by `cargo xtask bake-palette {input}`. Do not edit.\n//\n\
         // {w} x {h} palette texture, {bits}-bit indices, {l} mip levels ({b} bytes of indices,\n\
         // {p} of palette), one palette for every level. Against the RGB565 source: {:.2} dB\n\
         // PSNR, largest channel error {} (8-bit units). View it with\n\
         // `fixel::texture::PaletteMips::<fixel::texture::Index{bits}>::new(&{n}_INDICES,\n\
         // &{n}_PALETTE, {n}_WIDTH, {n}_HEIGHT, {n}_LEVELS)`.\n",
        q.total.0,
        q.total.1,
        w = q.width,
        h = q.height,
        bits = q.bits,
        l = q.levels,
        b = packed.len(),
        p = 2 * q.palette.len(),
    );
    let _ = writeln!(
        s,
        "/// Width of level 0, in texels.\npub const {n}_WIDTH: u32 = {};",
        q.width
    );
    let _ = writeln!(
        s,
        "/// Height of level 0, in texels.\npub const {n}_HEIGHT: u32 = {};",
        q.height
    );
    let _ = writeln!(
        s,
        "/// Mip levels in `{n}_INDICES`.\npub const {n}_LEVELS: u32 = {};",
        q.levels
    );
    let _ = writeln!(
        s,
        "/// The palette ({} colours), RGB565.\npub static {n}_PALETTE: [{rgb565}; {}] = [",
        q.palette.len(),
        q.palette.len()
    );
    for c in &q.palette {
        let _ = writeln!(s, "    {rgb565}::new({}, {}, {}),", c[0], c[1], c[2]);
    }
    s.push_str("];\n");
    let _ = writeln!(
        s,
        "/// The indices of every level, level 0 first{}.\npub static {n}_INDICES: [u8; {}] = [",
        if q.bits == 4 {
            " (two per byte, low nibble first)"
        } else {
            ""
        },
        packed.len()
    );
    for row in packed.chunks(16) {
        let line: Vec<String> = row.iter().map(|b| format!("0x{b:02x}")).collect();
        let _ = writeln!(s, "    {},", line.join(", "));
    }
    s.push_str("];\n");
    s
}

/// Arguments of `cargo xtask bake-palette`.
#[derive(Args, Clone, Debug)]
pub struct PaletteArgs {
    /// The PNG to quantise (sides powers of two up to 4096), or `checker:WxH` for fixel's
    /// benchmark texture T(W, H)
    #[arg(value_name = "input.png|checker:WxH")]
    pub input: String,
    /// The Rust source file to write (its folder is created)
    #[arg(value_name = "output.rs")]
    pub output: String,
    /// Bits per index: 4 (16 colours) or 8 (256)
    #[arg(long, value_name = "4|8", default_value_t = 8, value_parser = parse_bits)]
    pub bits: u32,
    /// Mip levels, a number or `full` (down to 1x1)
    #[arg(long, value_name = "N|full", default_value = "1", value_parser = crate::bake::parse_levels)]
    pub levels: Levels,
    /// Floyd-Steinberg dithering
    #[arg(long)]
    pub dither: bool,
    /// Prefix of the generated items [default: the input's file stem in upper case]
    #[arg(long, value_name = "NAME", value_parser = crate::bake::parse_name)]
    pub name: Option<String>,
}

fn parse_bits(v: &str) -> Result<u32, String> {
    match v {
        "4" => Ok(4),
        "8" => Ok(8),
        _ => Err("4 or 8".into()),
    }
}

/// The 8-bit image of `input`: a PNG, or `checker:WxH` (RGB565 widened to 8 bits).
fn read_source(input: &str) -> Result<(u32, u32, Vec<[u8; 3]>), String> {
    if let Some(size) = input.strip_prefix("checker:") {
        let (w, h) = size
            .split_once('x')
            .and_then(|(a, b)| Some((a.parse::<u32>().ok()?, b.parse::<u32>().ok()?)))
            .ok_or_else(|| format!("{input}: expected checker:WxH"))?;
        let mut t = vec![fixel::Rgb565::new(0, 0, 0); (w * h) as usize];
        fixel_scenes::checker_texture(w, h, &mut t).map_err(|e| format!("{input}: {e}"))?;
        // Bit-replicated to 8 bits: `chain` rounds them back to exactly these texels.
        return Ok((w, h, t.iter().map(|c| widen(channels(*c))).collect()));
    }
    read_rgb8(Path::new(input))
}

/// RGB565 channels widened to 8 bits by bit replication (`to_565` inverts it exactly).
fn widen(c: C565) -> [u8; 3] {
    [
        (c[0] << 3) | (c[0] >> 2),
        (c[1] << 2) | (c[1] >> 4),
        (c[2] << 3) | (c[2] >> 2),
    ]
}

/// The channels of an `Rgb565`.
pub fn channels(c: fixel::Rgb565) -> C565 {
    use embedded_graphics_core::pixelcolor::IntoStorage;
    let raw = c.into_storage();
    [(raw >> 11) as u8, ((raw >> 5) & 63) as u8, (raw & 31) as u8]
}

/// Bakes `args.input` into `args.output`.
pub fn run(args: &PaletteArgs) -> Result<(), BakeError> {
    let (w, h, base) = read_source(&args.input)?;
    let pow2 = |s: u32| s.is_power_of_two() && s <= 4096;
    if !pow2(w) || !pow2(h) {
        return Err(format!(
            "{}: {w} x {h}: sides must be powers of two up to 4096",
            args.input
        )
        .into());
    }
    let full = full_levels(w, h);
    let levels = match args.levels {
        Levels::Full => full,
        Levels::Count(l) if l <= full => l,
        Levels::Count(l) => {
            return Err(BakeError::Usage(format!(
                "--levels {l}: a {w} x {h} chain has 1..={full}"
            )))
        }
    };
    let src = chain(&base, w, h, levels);
    let q = quantise_chain(&src, w, h, levels, args.bits, args.dither);
    let name = args
        .name
        .clone()
        .unwrap_or_else(|| crate::bake::default_name(Path::new(&args.input.replace(':', "_"))));
    let mut cmd = format!("--bits {} ", args.bits);
    if levels != 1 {
        let _ = write!(
            cmd,
            "--levels {} ",
            if levels == full {
                "full".to_string()
            } else {
                levels.to_string()
            }
        );
    }
    if args.dither {
        cmd.push_str("--dither ");
    }
    if let Some(n) = &args.name {
        let _ = write!(cmd, "--name {n} ");
    }
    let _ = write!(cmd, "{} {}", args.input, args.output);
    let outp = Path::new(&args.output);
    if let Some(dir) = outp.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    std::fs::write(outp, source(&q, &cmd, &name, DEFAULT_RGB565))
        .map_err(|e| format!("{}: {e}", args.output))?;
    let packed = pack(&q.indices, q.bits).len();
    println!(
        "bake-palette: {} -> {}: {w} x {h}, {levels} levels, {}-bit: {} B of indices + {} B of \
         palette = {} B (RGB565: {} B); {:.2} dB PSNR, largest channel error {} against RGB565",
        args.input,
        args.output,
        args.bits,
        packed,
        2 * q.palette.len(),
        packed + 2 * q.palette.len(),
        2 * src.len(),
        q.total.0,
        q.total.1
    );
    println!("| level | PSNR, one palette | PSNR, a palette per level | largest error |\n|---:|---:|---:|---:|");
    for (l, (e, own)) in q.error.iter().zip(&q.per_level_psnr).enumerate() {
        println!("| {l} | {:.2} | {:.2} | {} |", e.0, own, e.1);
    }
    Ok(())
}

#[cfg(test)]
mod tests;
