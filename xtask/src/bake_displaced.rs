//! `cargo xtask bake-displaced`: a displaced mesh baked into a Rust source file of `static`
//! arrays (the format of `bake-obj`), so firmware that shows a rocky sphere pays nothing at
//! run time: the demo UV sphere subdivided by `fixel::scene::subdivide`, welded, displaced
//! by the procedural rock height map (`fixel_scenes::displaced::rock_heights`) with
//! `fixel::scene::displace`, the same functions as at run time (no f64 copy here).
//!
//! ```text
//! cargo xtask bake-displaced assets/displaced/rock_sphere.rs [--mesh coarse|fine|water]
//!     [--levels N] [--scale S] [--bias B] [--name NAME]
//! ```
//!
//! `coarse` is a 12 x 24 sphere (325 vertices), `fine` the 24 x 48 benchmark sphere
//! (1225), both of radius 1.5 displaced by the rock heights; `water` a 6 x 6-quad grid 4.8
//! units across displaced by the swell (`wave_heights`), which the file also holds as
//! `NAME_HEIGHTS` (64 x 64 bytes): with `--scale 0` it is the flat base of the firmware's
//! animated `water` scene. Defaults: coarse, 1 level, scale 0.45 (0 for water), bias 0.5,
//! name `ROCK` (`WATER`).

use std::fmt::Write as _;
use std::path::Path;

use fixel::math::{Fx, Vec3};
use fixel::scene::{
    count_edges, count_edges_words, displace, subdivide, subdivide_capacity, weld,
    weld_table_words, Displacement, MeshStorage,
};
use fixel::texture::HeightMap;
use fixel_scenes::displaced::{
    grid, rock_heights, wave_heights, ROCK_HEIGHT, ROCK_WIDTH, WAVE_SIDE,
};
use fixel_scenes::{self as demo, MeshData};

use clap::{Args, ValueEnum};

use crate::bake::BakeError;
use crate::bake_obj::{source, Baked, ObjOpts, UvSource};

/// The mesh and height map to bake (`--mesh`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Source {
    /// The demo 12 x 24 sphere and the rock heights.
    Coarse,
    /// The demo 24 x 48 (benchmark) sphere and the rock heights.
    Fine,
    /// A 6 x 6 grid and the swell heights.
    Water,
}

/// Options of one bake.
#[derive(Clone, Debug, PartialEq)]
pub struct Opts {
    pub mesh: Source,
    pub levels: u32,
    pub scale: f64,
    pub bias: f64,
    pub name: String,
}

impl Default for Opts {
    fn default() -> Self {
        Opts {
            mesh: Source::Coarse,
            levels: 1,
            scale: 0.45,
            bias: 0.5,
            name: "ROCK".into(),
        }
    }
}

/// Subdivides, welds and displaces `src` with fixel's run-time functions.
fn displaced<const V: usize, const T: usize>(
    src: &MeshData<V, T>,
    heights: &[u8],
    (w, h): (u32, u32),
    o: &Opts,
) -> Result<Baked, String> {
    let err = |e: fixel::Error| e.to_string();
    let mesh = src.mesh().map_err(err)?;
    let mut table = vec![0u32; count_edges_words(T)];
    let e = count_edges(&src.indices, &mut table).map_err(err)?;
    let cap = subdivide_capacity(V, T, e, o.levels);
    let (mut p, mut n, mut uv, mut ix) = (
        vec![Vec3::ZERO; cap.vertices],
        vec![Vec3::ZERO; cap.vertices],
        vec![[Fx::ZERO; 2]; cap.vertices],
        vec![[0u16; 3]; cap.triangles],
    );
    let mut table = vec![0u32; cap.edge_words.max(weld_table_words(cap.vertices))];
    let out = MeshStorage {
        positions: &mut p,
        normals: Some(&mut n),
        uvs: &mut uv,
        indices: &mut ix,
    };
    let base = subdivide(&mesh, o.levels, out, &mut table).map_err(err)?;
    let mut twins = vec![0u16; base.vertices()];
    weld(base.positions(), &mut table, &mut twins).map_err(err)?;
    let fxv = |v: f64, what: &str| {
        fixel::math::try_fx(v).map_err(|_| format!("{what} = {v} is outside I16F16"))
    };
    let d = Displacement {
        map: HeightMap::new(heights, w, h, 1).map_err(err)?,
        scale: fxv(o.scale, "--scale")?,
        bias: fxv(o.bias, "--bias")?,
        offset: [Fx::ZERO; 2],
    };
    let (mut dp, mut dn) = (
        vec![Vec3::ZERO; base.vertices()],
        vec![Vec3::ZERO; base.vertices()],
    );
    let m = displace(&d, &base, Some(&twins), &mut dp, &mut dn).map_err(err)?;
    Ok(Baked {
        positions: m.positions().to_vec(),
        normals: m.normals().unwrap_or(&[]).to_vec(),
        uvs: m.uvs().to_vec(),
        indices: m.indices().to_vec(),
        tangents: None,
        dropped: 0,
    })
}

/// The height map of `o`'s mesh: bytes and size.
pub fn heights(o: &Opts) -> (Vec<u8>, (u32, u32)) {
    if o.mesh == Source::Water {
        let mut h = vec![0u8; (WAVE_SIDE * WAVE_SIDE) as usize];
        let _ = wave_heights(&mut h);
        (h, (WAVE_SIDE, WAVE_SIDE))
    } else {
        let mut h = vec![0u8; (ROCK_WIDTH * ROCK_HEIGHT) as usize];
        let _ = rock_heights(&mut h);
        (h, (ROCK_WIDTH, ROCK_HEIGHT))
    }
}

/// The baked mesh for `o`.
pub fn bake(o: &Opts) -> Result<Baked, String> {
    let (h, size) = heights(o);
    match o.mesh {
        Source::Fine => displaced(&demo::sphere(), &h, size, o),
        Source::Coarse => displaced(
            &demo::uv_sphere::<{ 13 * 25 }, { 2 * 24 * 11 }>(12, 24),
            &h,
            size,
            o,
        ),
        Source::Water => displaced(&grid::<49, 72>(6, Fx::from_num(2.4)), &h, size, o),
    }
}

/// Arguments of `cargo xtask bake-displaced`.
#[derive(Args, Clone, Debug)]
pub struct DisplacedArgs {
    /// The Rust source file to write (its folder is created)
    #[arg(value_name = "output.rs")]
    pub output: String,
    /// The mesh and height map: the demo sphere (coarse 12 x 24, fine 24 x 48) and the rock heights, or a 6 x 6 grid and the swell
    #[arg(long, value_name = "coarse|fine|water", default_value = "coarse")]
    pub mesh: Source,
    /// Subdivision levels, 0 to 4
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(0..=4))]
    pub levels: u32,
    /// Displacement scale, model units per 256 height steps (negative pushes inwards) [default: 0.45, 0 for water]
    #[arg(long, value_name = "S", allow_negative_numbers = true)]
    pub scale: Option<f64>,
    /// Displacement bias (the height that stays in place)
    #[arg(
        long,
        value_name = "B",
        default_value_t = 0.5,
        allow_negative_numbers = true
    )]
    pub bias: f64,
    /// Prefix of the generated items [default: ROCK, WATER for water]
    #[arg(long, value_name = "NAME")]
    pub name: Option<String>,
}

impl DisplacedArgs {
    /// The bake options: the defaults of `--scale` and `--name` depend on the mesh.
    pub fn opts(&self) -> Opts {
        let water = self.mesh == Source::Water;
        Opts {
            mesh: self.mesh,
            levels: self.levels,
            scale: self
                .scale
                .unwrap_or(if water { 0.0 } else { Opts::default().scale }),
            bias: self.bias,
            name: self.name.clone().unwrap_or_else(|| {
                if water {
                    "WATER".into()
                } else {
                    Opts::default().name
                }
            }),
        }
    }

    /// The arguments as a command line for the generated file's header: the output, then
    /// each option given or not at its default.
    pub fn command_line(&self) -> String {
        let mut s = self.output.clone();
        let d = Opts::default();
        if self.mesh != d.mesh {
            let m = self
                .mesh
                .to_possible_value()
                .map(|v| v.get_name().to_string());
            let _ = write!(s, " --mesh {}", m.unwrap_or_default());
        }
        if self.levels != d.levels {
            let _ = write!(s, " --levels {}", self.levels);
        }
        if let Some(scale) = self.scale {
            let _ = write!(s, " --scale {scale}");
        }
        if self.bias != d.bias {
            let _ = write!(s, " --bias {}", self.bias);
        }
        if let Some(name) = &self.name {
            let _ = write!(s, " --name {name}");
        }
        s
    }
}

/// Bakes the displaced mesh of `args` into `args.output`.
pub fn run(args: &DisplacedArgs) -> Result<(), BakeError> {
    let o = args.opts();
    let output = &args.output;
    let baked = bake(&o).map_err(BakeError::Failed)?;
    let obj = ObjOpts {
        name: o.name.clone(),
        uv: UvSource::Keep,
        axis: fixel::scene::Axis::Y,
        smooth_normals: false,
        tangents: false,
        scale: 1.0,
        krate: "fixel".into(),
    };
    let args_line = args.command_line();
    let what = match o.mesh {
        Source::Coarse => "the demo 12 x 24 sphere and the rock heights",
        Source::Fine => "the demo 24 x 48 sphere and the rock heights",
        Source::Water => "a 6 x 6 grid and the swell heights",
    };
    let mut text = source(&baked, &args_line, &obj).replacen(
        &format!("`cargo xtask bake-obj {args_line}`"),
        &format!(
            "`cargo xtask bake-displaced {args_line}`:\n// {what}, {} level(s), scale {}, \
             bias {}",
            o.levels, o.scale, o.bias
        ),
        1,
    );
    if o.mesh == Source::Water {
        let (h, (w, hh)) = heights(&o);
        let _ = writeln!(
            text,
            "/// The swell (`fixel_scenes::displaced::wave_heights`), {w} x {hh} heights.\n\
             pub static {}_HEIGHTS: [u8; {}] = [",
            o.name,
            h.len()
        );
        for row in h.chunks(w as usize) {
            let row: Vec<String> = row.iter().map(u8::to_string).collect();
            let _ = writeln!(text, "    {},", row.join(", "));
        }
        text.push_str("];\n");
    }
    let path = Path::new(output);
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| BakeError::Failed(format!("{output}: {e}")))?;
    }
    std::fs::write(path, text).map_err(|e| BakeError::Failed(format!("{output}: {e}")))?;
    let bytes = baked.positions.len() * 32 + baked.indices.len() * 6;
    println!(
        "bake-displaced: {} vertices, {} triangles, {bytes} bytes of flash -> {output}",
        baked.positions.len(),
        baked.indices.len()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coarse_sphere_bakes() {
        let b = bake(&Opts::default()).unwrap();
        assert_eq!(b.indices.len(), 4 * 2 * 24 * 11);
        assert_eq!(b.positions.len(), b.normals.len());
    }
}
