//! `cargo xtask bake-displaced`: a displaced mesh baked into a Rust source file of `static`
//! arrays (the format of `bake-obj`), so firmware that shows a rocky sphere pays nothing at
//! run time: the demo UV sphere subdivided by `fixel::scene::subdivide`, welded, displaced
//! by the procedural rock height map (`fixel::demo::displaced::rock_heights`) with
//! `fixel::scene::displace`, the same functions as at run time (no f64 copy here).
//!
//! ```text
//! cargo xtask bake-displaced assets/displaced/rock_sphere.rs [--sphere coarse|fine]
//!     [--levels N] [--scale S] [--bias B] [--name NAME]
//! ```
//!
//! `coarse` is a 12 x 24 sphere (325 vertices), `fine` the 24 x 48 benchmark sphere
//! (1225); both have radius 1.5. Defaults: coarse, 1 level, scale 0.45, bias 0.5, name
//! `ROCK`.

use std::path::Path;

use fixel::demo::displaced::{rock_heights, ROCK_HEIGHT, ROCK_WIDTH};
use fixel::demo::{self, MeshData};
use fixel::math::{Fx, Vec3};
use fixel::scene::{
    count_edges, displace, subdivide, subdivide_capacity, weld, weld_table_words, Displacement,
    MeshStorage,
};
use fixel::texture::HeightMap;

use crate::bake::BakeError;
use crate::bake_obj::{source, Baked, ObjOpts, UvSource};

/// Options of one bake.
#[derive(Clone, Debug, PartialEq)]
pub struct Opts {
    pub fine: bool,
    pub levels: u32,
    pub scale: f64,
    pub bias: f64,
    pub name: String,
}

impl Default for Opts {
    fn default() -> Self {
        Opts {
            fine: false,
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
    o: &Opts,
) -> Result<Baked, String> {
    let err = |e: fixel::Error| e.to_string();
    let mesh = src.mesh().map_err(err)?;
    let mut table = vec![0u32; 2 * (8 * T + 16)];
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
    let mut heights = vec![0u8; (ROCK_WIDTH * ROCK_HEIGHT) as usize];
    rock_heights(&mut heights).map_err(err)?;
    let fxv = |v: f64, what: &str| {
        fixel::math::try_fx(v).map_err(|_| format!("{what} = {v} is outside I16F16"))
    };
    let d = Displacement {
        map: HeightMap::new(&heights, ROCK_WIDTH, ROCK_HEIGHT, 1).map_err(err)?,
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

/// The baked mesh for `o`.
pub fn bake(o: &Opts) -> Result<Baked, String> {
    if o.fine {
        displaced(&demo::sphere(), o)
    } else {
        displaced(&demo::uv_sphere::<{ 13 * 25 }, { 2 * 24 * 11 }>(12, 24), o)
    }
}

pub fn run(args: &[String]) -> Result<(), BakeError> {
    let usage = |m: &str| BakeError::Usage(m.to_string());
    let mut o = Opts::default();
    let mut output = None;
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
            "--sphere" => {
                o.fine = match val("--sphere")?.as_str() {
                    "coarse" => false,
                    "fine" => true,
                    v => return Err(usage(&format!("`--sphere {v}`: coarse or fine"))),
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
            "--scale" => o.scale = num("--scale", val("--scale")?)?,
            "--bias" => o.bias = num("--bias", val("--bias")?)?,
            "--name" => o.name = val("--name")?,
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
    let text = source(&baked, &args_line, &obj).replacen(
        &format!("`cargo xtask bake-obj {args_line}`"),
        &format!(
            "`cargo xtask bake-displaced {args_line}`: the demo {} sphere, {} level(s), \
             rock heights, scale {}, bias {}",
            if o.fine { "24 x 48" } else { "12 x 24" },
            o.levels,
            o.scale,
            o.bias
        ),
        1,
    );
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
