//! `cargo xtask bake-displaced`: a displaced mesh baked into a Rust source file of `static`
//! arrays (the format of `bake-obj`), so firmware that shows a rocky sphere pays nothing at
//! run time: the demo UV sphere subdivided by `fixel::scene::subdivide`, welded, displaced
//! by the procedural rock height map (`fixel::demo::displaced::rock_heights`) with
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

use fixel::demo::displaced::{
    grid, rock_heights, wave_heights, ROCK_HEIGHT, ROCK_WIDTH, WAVE_SIDE,
};
use fixel::demo::{self, MeshData};
use fixel::math::{Fx, Vec3};
use fixel::scene::{
    count_edges, count_edges_words, displace, subdivide, subdivide_capacity, weld,
    weld_table_words, Displacement, MeshStorage,
};
use fixel::texture::HeightMap;

use crate::bake::BakeError;
use crate::bake_obj::{source, Baked, ObjOpts, UvSource};

/// The mesh and height map to bake.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    Coarse,
    Fine,
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

pub fn run(args: &[String]) -> Result<(), BakeError> {
    let usage = |m: &str| BakeError::Usage(m.to_string());
    let mut o = Opts::default();
    let mut output = None;
    let (mut scaled, mut named) = (false, false);
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut val = |flag: &str| {
            it.next()
                .cloned()
                .ok_or_else(|| usage(&format!("`{flag}` needs a value")))
        };
        let num = |flag: &str, v: String| {
            v.parse::<f64>()
                .map_err(|_| usage(&format!("`{flag} {v}`: not a number")))
        };
        match a.as_str() {
            "--mesh" => {
                o.mesh = match val("--mesh")?.as_str() {
                    "coarse" => Source::Coarse,
                    "fine" => Source::Fine,
                    "water" => {
                        if !scaled {
                            o.scale = 0.0;
                        }
                        if !named {
                            o.name = "WATER".into();
                        }
                        Source::Water
                    }
                    v => return Err(usage(&format!("`--mesh {v}`: coarse, fine or water"))),
                }
            }
            "--levels" => {
                let v = val("--levels")?;
                o.levels = v
                    .parse()
                    .ok()
                    .filter(|&l| l <= 4)
                    .ok_or_else(|| usage(&format!("`--levels {v}`: 0 to 4")))?;
            }
            "--scale" => {
                o.scale = num("--scale", val("--scale")?)?;
                scaled = true;
            }
            "--bias" => o.bias = num("--bias", val("--bias")?)?,
            "--name" => {
                o.name = val("--name")?;
                named = true;
            }
            f if f.starts_with("--") => return Err(usage(&format!("unknown flag `{f}`"))),
            p if output.is_none() => output = Some(p.to_string()),
            p => return Err(usage(&format!("unexpected argument `{p}`"))),
        }
    }
    let output = output.ok_or_else(|| usage("missing <output.rs>"))?;
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
    let args_line = args.join(" ");
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
            "/// The swell (`fixel::demo::displaced::wave_heights`), {w} x {hh} heights.\n\
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
    let path = Path::new(&output);
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
