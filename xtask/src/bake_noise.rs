//! `cargo xtask bake-noise`: a solid texture baked for a sphere's own texture coordinates
//! (`fixel::shading::noise::bake_mips`), or one layer of the flame from baked layers
//! (`fixel::shading::noise::bake_flame_layer`), into a binary file of little-endian `u16`
//! (RGB565 texels with their mip chain, or Q15 partial turbulence): the format the
//! firmware's `build.rs` writes and `include_bytes!` reads, for projects that keep their
//! baked textures in the repository instead of baking them in a build script.
//!
//! ```text
//! cargo xtask bake-noise <output.bin> --pattern marble|wood|granite [--width 256]
//!     [--height 128] [--levels 1] [--octaves 6] [--radius CELLS]
//! cargo xtask bake-noise <output.bin> --pattern flame-layer0|flame-layer1 [--side 64]
//! ```

use clap::{Args, ValueEnum};
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::math::Fx;
use fixel::shading::noise::{
    bake_flame_layer, bake_mips, BandLimit, Ramps, SphereSurface, FLAME_LAYERS,
};
use fixel::texture::chain_len;

/// What to bake.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum NoisePattern {
    /// The demonstration marble (`Ramps::marble`)
    Marble,
    /// The demonstration wood (`Ramps::wood`)
    Wood,
    /// The demonstration granite (`Ramps::granite`)
    Granite,
    /// Layer 0 of `FLAME_LAYERS` (octaves 0-1, a 4-cell tile)
    FlameLayer0,
    /// Layer 1 of `FLAME_LAYERS` (octaves 2-4, a 2-cell tile)
    FlameLayer1,
}

/// Flags of `cargo xtask bake-noise`.
#[derive(Args, Clone, Debug)]
pub struct BakeNoiseArgs {
    /// The binary file to write (little-endian u16 per texel)
    #[arg(value_name = "output.bin")]
    pub output: String,
    /// The pattern or flame layer
    #[arg(long, value_enum)]
    pub pattern: NoisePattern,
    /// Texture width in texels, a power of two (patterns)
    #[arg(long, default_value_t = 256)]
    pub width: u32,
    /// Texture height in texels, a power of two (patterns)
    #[arg(long, default_value_t = 128)]
    pub height: u32,
    /// Mip levels, each baked from the pattern at its own texel size (patterns)
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=13))]
    pub levels: u32,
    /// Most octaves of the band-limited turbulence (patterns), 1..=8
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u8).range(1..=8))]
    pub octaves: u8,
    /// Sphere radius in lattice cells (patterns; default: the benchmark sphere's, 1.5 model
    /// units at the showcase scale, about 2.7 cells)
    #[arg(long, value_name = "CELLS")]
    pub radius: Option<f64>,
    /// Side of a flame layer in texels, a power of two in 2..=1024
    #[arg(long, default_value_t = 64)]
    pub side: u32,
}

/// The baked texels as little-endian bytes.
pub fn bake(args: &BakeNoiseArgs) -> Result<Vec<u8>, String> {
    let le = |v: &[u16]| v.iter().flat_map(|t| t.to_le_bytes()).collect::<Vec<u8>>();
    let layer = match args.pattern {
        NoisePattern::FlameLayer0 => Some(0),
        NoisePattern::FlameLayer1 => Some(1),
        _ => None,
    };
    if let Some(l) = layer {
        let n = args.side.checked_mul(args.side).ok_or("side too large")? as usize;
        let mut t = vec![0u16; n];
        bake_flame_layer(&FLAME_LAYERS[l], args.side, &mut t)
            .map_err(|e| format!("flame layer {l}, side {}: {e}", args.side))?;
        return Ok(le(&t));
    }
    let radius = match args.radius {
        Some(r) if r.is_finite() && r > 0.0 && r < 32_768.0 => Fx::from_num(r),
        Some(r) => return Err(format!("--radius {r}: a radius in 0..32768 cells")),
        None => fixel_scenes::noise::baked_sphere_surface().radius,
    };
    let surface = SphereSurface { radius };
    let (w, h, levels) = (args.width, args.height, args.levels);
    if !w.is_power_of_two() || !h.is_power_of_two() || w > 4096 || h > 4096 {
        return Err(format!("{w} x {h}: the sides are powers of two up to 4096"));
    }
    let mut t = vec![Rgb565::new(0, 0, 0); chain_len(w, h, levels)];
    let ramps = Ramps::new().map_err(|e| e.to_string())?;
    let o = BandLimit::new(args.octaves);
    let r = match args.pattern {
        NoisePattern::Wood => bake_mips(&ramps.wood(), &o, &surface, w, h, levels, &mut t),
        NoisePattern::Granite => bake_mips(&ramps.granite(), &o, &surface, w, h, levels, &mut t),
        _ => bake_mips(&ramps.marble(), &o, &surface, w, h, levels, &mut t),
    };
    r.map_err(|e| format!("{w} x {h}, {levels} levels: {e}"))?;
    Ok(le(&t
        .iter()
        .map(|c| c.into_storage())
        .collect::<Vec<u16>>()))
}

/// Bakes and writes the file.
pub fn run(args: &BakeNoiseArgs) -> Result<(), String> {
    let bytes = bake(args)?;
    std::fs::write(&args.output, &bytes).map_err(|e| format!("{}: {e}", args.output))?;
    println!(
        "bake-noise: wrote {} ({} bytes, {} texels)",
        args.output,
        bytes.len(),
        bytes.len() / 2
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(pattern: NoisePattern) -> BakeNoiseArgs {
        BakeNoiseArgs {
            output: String::new(),
            pattern,
            width: 16,
            height: 8,
            levels: 1,
            octaves: 6,
            radius: None,
            side: 8,
        }
    }

    /// The command's bytes are the library's bake of the benchmark sphere, as the
    /// firmware's build.rs writes them.
    #[test]
    fn the_bytes_are_the_library_bake() {
        let ramps = Ramps::new().unwrap();
        let s = fixel_scenes::noise::baked_sphere_surface();
        let mut t = vec![Rgb565::new(0, 0, 0); 16 * 8];
        fixel::shading::noise::bake(&ramps.wood(), &BandLimit::new(6), &s, 16, 8, &mut t).unwrap();
        let want: Vec<u8> = t
            .iter()
            .flat_map(|c| c.into_storage().to_le_bytes())
            .collect();
        assert_eq!(bake(&args(NoisePattern::Wood)).unwrap(), want);
        let mut l = vec![0u16; 64];
        bake_flame_layer(&FLAME_LAYERS[1], 8, &mut l).unwrap();
        let want: Vec<u8> = l.iter().flat_map(|v| v.to_le_bytes()).collect();
        assert_eq!(bake(&args(NoisePattern::FlameLayer1)).unwrap(), want);
    }

    #[test]
    fn bad_sizes_are_refused_with_a_reason() {
        let a = BakeNoiseArgs {
            width: 24,
            ..args(NoisePattern::Granite)
        };
        assert!(bake(&a).unwrap_err().contains("powers of two"));
        let a = BakeNoiseArgs {
            side: 3,
            ..args(NoisePattern::FlameLayer0)
        };
        assert!(bake(&a).unwrap_err().contains("side 3"));
        let a = BakeNoiseArgs {
            radius: Some(-1.0),
            ..args(NoisePattern::Marble)
        };
        assert!(bake(&a).unwrap_err().contains("radius"));
    }
}
