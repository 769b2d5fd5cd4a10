//! `cargo xtask bake`: a PNG to a Rust source file of `static` RGB565 texels with their
//! mip chain, ready to live in flash.
//!
//! * Pixels: 8-bit RGB after expanding palettes and grey and stripping 16-bit samples;
//!   alpha is ignored. RGB565 by rounding to nearest, `(c * max + 127) / 255` (max 31, 63,
//!   31): the shared conversion of the benchmark textures.
//! * Chain: fixel's layout (level `k` is `max(1, w >> k) x max(1, h >> k)`, contiguous,
//!   level 0 first); every level straight from the 8-bit image at full precision, each
//!   texel the mean of the source pixels it covers, converted to RGB565 once (GL filters
//!   its levels in 8 bits per channel; box-filtering RGB565 levels compounds roundings).
//! * Sides must be powers of two up to 4096.

use std::fmt::Write as _;
use std::fs::File;
use std::io::BufReader;
use std::path::Path;

use clap::Args;

/// Options of one bake.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BakeOpts {
    /// Prefix of the generated items (`NAME_TEXELS`, ...), upper case.
    pub name: String,
    /// Number of levels (`None`: down to 1 x 1).
    pub levels: Option<u32>,
    /// Path of the RGB565 type in the generated code.
    pub rgb565: String,
}

/// Default item prefix for an input file: its stem in upper case, other characters `_`.
pub fn default_name(input: &Path) -> String {
    let stem = input
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut n: String = stem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_uppercase()
            } else {
                '_'
            }
        })
        .collect();
    if n.is_empty() || n.starts_with(|c: char| c.is_ascii_digit()) {
        n.insert_str(0, "TEX_");
    }
    n
}

/// Reads a PNG as `(width, height, RGB8 pixels)`.
pub fn read_rgb8(path: &Path) -> Result<(u32, u32, Vec<[u8; 3]>), String> {
    let file = File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut dec = png::Decoder::new(BufReader::new(file));
    dec.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = dec
        .read_info()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| format!("{}: too large", path.display()))?;
    let mut buf = vec![0; size];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let stride = match info.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        png::ColorType::Grayscale => 1,
        png::ColorType::GrayscaleAlpha => 2,
        png::ColorType::Indexed => return Err(format!("{}: unexpanded palette", path.display())),
    };
    let (w, h) = (info.width, info.height);
    let mut px = Vec::with_capacity((w * h) as usize);
    for row in buf[..info.buffer_size()]
        .chunks(info.line_size)
        .take(h as usize)
    {
        for p in row[..stride * w as usize].chunks(stride) {
            px.push(if stride >= 3 {
                [p[0], p[1], p[2]]
            } else {
                [p[0]; 3]
            });
        }
    }
    Ok((w, h, px))
}

/// 8-bit RGB to RGB565 channels `[r5, g6, b5]`, rounded to nearest.
pub fn to_565(c: [u8; 3]) -> [u8; 3] {
    let q = |v: u8, max: u32| ((u32::from(v) * max + 127) / 255) as u8;
    [q(c[0], 31), q(c[1], 63), q(c[2], 31)]
}

/// Levels of a full chain: `log2(max(w, h)) + 1`.
pub fn full_levels(w: u32, h: u32) -> u32 {
    32 - w.max(h).leading_zeros()
}

/// The mip chain of `levels` levels of an 8-bit image (`[r5, g6, b5]` texels),
/// contiguous: level 0 by [`to_565`], and every level `k` straight from the 8-bit source
/// at full precision, each texel the mean of the block of source pixels it covers
/// converted once: `round(sum * max / (255 n))` for `n` pixels (half up).
pub fn chain(src: &[[u8; 3]], w: u32, h: u32, levels: u32) -> Vec<[u8; 3]> {
    let mut out: Vec<[u8; 3]> = src.iter().map(|&c| to_565(c)).collect();
    for k in 1..levels {
        let (dw, dh) = ((w >> k).max(1), (h >> k).max(1));
        let (bw, bh) = (w / dw, h / dh);
        let n = u64::from(bw * bh);
        for j in 0..dh {
            for i in 0..dw {
                let mut sum = [0u64; 3];
                for y in j * bh..(j + 1) * bh {
                    for x in i * bw..(i + 1) * bw {
                        let t = src[(y * w + x) as usize];
                        for c in 0..3 {
                            sum[c] += u64::from(t[c]);
                        }
                    }
                }
                // round(s max / (255 n)) = floor((2 s max + 255 n) / (510 n)).
                let q = |s: u64, max: u64| ((2 * s * max + 255 * n) / (510 * n)) as u8;
                out.push([q(sum[0], 31), q(sum[1], 63), q(sum[2], 31)]);
            }
        }
    }
    out
}

/// The generated Rust source for a `w x h` 8-bit image.
pub fn source(base: &[[u8; 3]], w: u32, h: u32, input: &str, o: &BakeOpts) -> String {
    let levels = o.levels.unwrap_or_else(|| full_levels(w, h));
    let texels = chain(base, w, h, levels);
    let n = &o.name;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "// Generated by `cargo xtask bake {input}`. Do not edit.\n\
         //\n\
         // {w} x {h} RGB565 texture with {levels} mip levels ({} texels), contiguous, level 0\n\
         // first; level k is max(1, w >> k) x max(1, h >> k), each texel the mean of the\n\
         // source pixels it covers, filtered from the 8-bit image and rounded once.\n\
         // View it with `fixel::texture::MipTexture::new(&{n}_TEXELS, {n}_WIDTH, {n}_HEIGHT,\n\
         // {n}_LEVELS)`.\n",
        texels.len()
    );
    s.push_str(&texel_items(&texels, w, h, levels, input, o));
    s
}

/// The items of a baked chain (`texels`: `levels` levels from a `w x h` level 0, as
/// [`chain`] makes them): `NAME_WIDTH`, `NAME_HEIGHT`, `NAME_LEVELS` and `NAME_TEXELS`,
/// without a file header (`bake-gltf` writes them after its mesh).
pub fn texel_items(
    texels: &[[u8; 3]],
    w: u32,
    h: u32,
    levels: u32,
    input: &str,
    o: &BakeOpts,
) -> String {
    let n = &o.name;
    let mut s = String::new();
    let _ = writeln!(s, "/// Width of level 0 of `{n}_TEXELS`, in texels.");
    let _ = writeln!(s, "pub const {n}_WIDTH: u32 = {w};");
    let _ = writeln!(s, "/// Height of level 0 of `{n}_TEXELS`, in texels.");
    let _ = writeln!(s, "pub const {n}_HEIGHT: u32 = {h};");
    let _ = writeln!(s, "/// Number of mip levels in `{n}_TEXELS`.");
    let _ = writeln!(s, "pub const {n}_LEVELS: u32 = {levels};");
    let _ = writeln!(
        s,
        "/// The texels of `{input}` and its mip chain ({w} x {h}, {levels} levels), RGB565."
    );
    let _ = writeln!(
        s,
        "pub static {n}_TEXELS: [{t}; {len}] = [",
        t = o.rgb565,
        len = texels.len()
    );
    for t in texels {
        let _ = writeln!(s, "    {}::new({}, {}, {}),", o.rgb565, t[0], t[1], t[2]);
    }
    s.push_str("];\n");
    s
}

/// Why `bake` failed: bad arguments (exit status 2, as the help says) or a failure while
/// baking (exit status 1).
pub enum BakeError {
    /// The command line is wrong.
    Usage(String),
    /// Reading, converting or writing failed.
    Failed(String),
}

impl From<String> for BakeError {
    fn from(e: String) -> Self {
        BakeError::Failed(e)
    }
}

/// Path of the RGB565 type in generated code unless `--rgb565` says otherwise.
pub const DEFAULT_RGB565: &str = "embedded_graphics_core::pixelcolor::Rgb565";

/// Arguments of `cargo xtask bake`.
#[derive(Args, Clone, Debug)]
pub struct BakeArgs {
    /// The PNG to bake (sides powers of two up to 4096)
    #[arg(value_name = "input.png")]
    pub input: String,
    /// The Rust source file to write (its folder is created)
    #[arg(value_name = "output.rs")]
    pub output: String,
    /// Prefix of the generated items, letters, digits and `_` [default: the input's file stem in upper case]
    #[arg(long, value_name = "NAME", value_parser = parse_name)]
    pub name: Option<String>,
    /// Mip levels, a number or `full` (down to 1x1)
    #[arg(long, value_name = "N|full", default_value = "full", value_parser = parse_levels)]
    pub levels: Levels,
    /// Path of the colour type in the output
    #[arg(long, value_name = "PATH", default_value = DEFAULT_RGB565)]
    pub rgb565: String,
}

/// `--levels`: a number of levels or the full chain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Levels {
    /// Down to 1 x 1.
    Full,
    /// This many levels, from level 0.
    Count(u32),
}

pub(crate) fn parse_levels(s: &str) -> Result<Levels, String> {
    match s {
        "full" => Ok(Levels::Full),
        n => match n.parse::<u32>() {
            Ok(l) if l > 0 => Ok(Levels::Count(l)),
            _ => Err(format!("`{n}` is not a positive number or `full`")),
        },
    }
}

pub(crate) fn parse_name(s: &str) -> Result<String, String> {
    if s.is_empty() || !s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        Err("use letters, digits and `_`".into())
    } else {
        Ok(s.to_string())
    }
}

/// Bakes `args.input` into `args.output`.
pub fn run(args: &BakeArgs) -> Result<(), BakeError> {
    use BakeError::Usage;
    let (input, output) = (&args.input, &args.output);
    let levels = match args.levels {
        Levels::Full => None,
        Levels::Count(l) => Some(l),
    };
    let (inp, outp) = (Path::new(input), Path::new(output));
    let (w, h, px) = read_rgb8(inp)?;
    let pow2 = |s: u32| s.is_power_of_two() && s <= 4096;
    if !pow2(w) || !pow2(h) {
        return Err(format!("{input}: {w} x {h}: sides must be powers of two up to 4096").into());
    }
    let full = full_levels(w, h);
    if let Some(l) = levels {
        if l > full {
            return Err(Usage(format!(
                "--levels {l}: a {w} x {h} chain has 1..={full}"
            )));
        }
    }
    let o = BakeOpts {
        name: args.name.clone().unwrap_or_else(|| default_name(inp)),
        levels,
        rgb565: args.rgb565.clone(),
    };
    let shown = inp
        .file_name()
        .map_or(input.clone(), |f| f.to_string_lossy().into_owned());
    let src = source(&px, w, h, &shown, &o);
    if let Some(dir) = outp.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    std::fs::write(outp, src).map_err(|e| format!("{output}: {e}"))?;
    let levels = o.levels.unwrap_or(full);
    println!(
        "baked {input} ({w} x {h}, {levels} levels) into {output} as {}_TEXELS",
        o.name
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_and_box_filter() {
        assert_eq!(to_565([255, 255, 255]), [31, 63, 31]);
        assert_eq!(to_565([0, 0, 0]), [0, 0, 0]);
        assert_eq!(to_565([128, 128, 128]), [16, 32, 16]); // 128*31+127 = 4095 -> 16
        assert_eq!(full_levels(64, 64), 7);
        assert_eq!(full_levels(256, 128), 9);
        assert_eq!(full_levels(1, 8), 4);
        // 4 x 2 -> 2 x 1 -> 1 x 1 from 8-bit pixels: level 1 red of the left block is
        // (10 + 20 + 10 + 20) / 4 = 15 -> round(15 * 31 / 255) = 2; level 2 over all eight.
        let base = [
            [10, 0, 0],
            [20, 0, 0],
            [0, 0, 255],
            [0, 0, 255],
            [10, 0, 0],
            [20, 0, 0],
            [0, 0, 255],
            [0, 0, 0],
        ];
        let c = chain(&base, 4, 2, 3);
        assert_eq!(&c[..2], &[to_565(base[0]), to_565(base[1])]);
        // Blue of the right block: 765 / 4 = 191.25 -> round(23.25) = 23; level 2: 765 / 8
        // = 95.6 -> round(11.6) = 12; red: 60 / 8 = 7.5 -> round(0.91) = 1.
        assert_eq!(&c[8..], &[[2, 0, 0], [0, 0, 23], [1, 0, 12]]);
        assert_eq!(default_name(Path::new("a/brick-wall.png")), "BRICK_WALL");
        assert_eq!(default_name(Path::new("8x8.png")), "TEX_8X8");
    }

    /// The committed example bake is what `bake` produces today.
    #[test]
    fn committed_bake_is_current() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../host-tests/tests/baked");
        let (w, h, base) = read_rgb8(&root.join("checker.png")).unwrap();
        let o = BakeOpts {
            name: "CHECKER".into(),
            levels: None,
            rgb565: DEFAULT_RGB565.into(),
        };
        let want = source(&base, w, h, "checker.png", &o);
        let got = std::fs::read_to_string(root.join("checker.rs")).unwrap();
        assert!(
            got == want,
            "host-tests/tests/baked/checker.rs is stale: run `cargo xtask bake \
             host-tests/tests/baked/checker.png host-tests/tests/baked/checker.rs --name CHECKER`"
        );
    }
}

#[cfg(test)]
mod usage_tests {
    use super::*;
    use crate::{parse, Command};

    #[test]
    fn usage_errors_are_usage_errors() {
        use clap::CommandFactory;
        crate::Cli::command().debug_assert();
        for bad in [
            &["bake"][..],
            &["bake", "in.png"],
            &["bake", "a.png", "b.rs", "--bogus"],
            &["bake", "a.png", "b.rs", "--levels", "x"],
            &["bake", "a.png", "b.rs", "--levels", "0"],
            &["bake", "a.png", "b.rs", "--name", "a-b"],
        ] {
            let e = parse(bad).expect_err(&format!("{bad:?}"));
            assert_eq!(e.exit_code(), 2, "{bad:?}");
        }
        let Ok(Command::Bake(a)) = parse(&["bake", "/nonexistent/in.png", "/tmp/out.rs"]) else {
            panic!("bake with two paths does not parse");
        };
        assert_eq!(
            (a.levels, a.rgb565.as_str()),
            (Levels::Full, DEFAULT_RGB565)
        );
        assert!(matches!(run(&a), Err(BakeError::Failed(_))));
    }
}
