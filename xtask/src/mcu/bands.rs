//! The bands-against-whole-frame tables of `cargo xtask mcu`: each banded scene's
//! instructions per pixel beside the same frame drawn whole, the ratio, the share spent on
//! geometry, and the firmware's RAM; the bars the one band path is held to; and the
//! regions of `README.md` and `docs/mcu.md` that `--docs` rewrites.

use std::collections::BTreeMap;
use std::fs;
use std::path::Path;

use super::{MCUS, SCENES, WHOLE_SCENES};

/// A banded technique scene may cost at most this much more than its own whole frame.
pub(super) const BAR: f64 = 1.3;

/// Scenes held to [`BAR`]: every banded scene with a whole-frame twin. (The classic cube,
/// floor, teapot and sphere in its slower mode are reported beside them.)
const HELD: [&str; 12] = [
    "sphere_sized",
    "shadow_single",
    "shadow_single_uv",
    "noise",
    "noise_flame",
    "noise_light3d",
    "env_pixel",
    "env_vertex",
    "aa_cube",
    "transparency",
    "water",
    "bump",
];

/// What one firmware run gave, by (scene, MCU label).
#[derive(Default)]
pub(super) struct Figures {
    /// Instructions per drawn pixel.
    pub per_px: BTreeMap<(String, &'static str), f64>,
    /// Share of the banded count spent up to the end of the binning pass.
    pub geometry: BTreeMap<(String, &'static str), f64>,
    /// RAM: static data + measured stack, bytes.
    pub ram: BTreeMap<(String, &'static str), u64>,
    /// The frame's counted instructions and estimated cycles (the static cycle model).
    pub frame: BTreeMap<(String, &'static str), (u64, f64)>,
}

/// Every banded scene, in table order: the band firmwares, then the banded ones built in
/// the whole layout (`sphere_sized`).
fn banded() -> impl Iterator<Item = &'static str> {
    SCENES
        .iter()
        .chain(WHOLE_SCENES.iter())
        .copied()
        .filter(|s| !s.starts_with("whole_"))
}

/// The full table (every MCU) and the bars missed.
pub(super) fn table(f: &Figures) -> (String, Vec<String>) {
    let mut t = String::from(
        "| scene | target | bands insns/px | geometry | bands - geometry | whole insns/px | \
         bands / whole | RAM B |\n|---|---|---:|---:|---:|---:|---:|---:|\n",
    );
    let mut missed = Vec::new();
    for scene in banded() {
        for m in &MCUS {
            let key = (scene.to_string(), m.label);
            let Some(b) = f.per_px.get(&key) else {
                continue;
            };
            let g = f.geometry.get(&key);
            let w = f.per_px.get(&(format!("whole_{scene}"), m.label));
            let ratio = w.map(|w| b / w);
            if let Some(r) = ratio.filter(|r| *r > BAR && HELD.contains(&scene)) {
                missed.push(format!(
                    "{scene} on {}: bands {r:.3}x the whole frame (bar {BAR})",
                    m.label
                ));
            }
            t.push_str(&format!(
                "| {scene} | {} | {b:.2} | {} | {} | {} | {} | {} |\n",
                m.label,
                g.map_or("-".into(), |g| format!("{:.1} %", 100.0 * g)),
                g.map_or("-".into(), |g| format!("{:.2}", b * (1.0 - g))),
                w.map_or("-".into(), |w| format!("{w:.2}")),
                ratio.map_or("-".into(), |r| format!("{r:.3}")),
                f.ram.get(&key).map_or("-".into(), |r| r.to_string()),
            ));
        }
    }
    (t, missed)
}

/// The README's compact form: one row per scene, the three cores side by side.
pub(super) fn compact(f: &Figures) -> String {
    let mut t = String::from(
        "| scene | instr/px in bands, M0+ / M4F / RV32 | bands / whole frame | geometry (M4F) | RAM (M4F) |\n\
         |---|---:|---:|---:|---:|\n",
    );
    // The benchmark meshes and one scene per technique (every scene: docs/mcu.md).
    let shown = [
        "cube",
        "sphere",
        "sphere_sized",
        "shadow_single",
        "noise",
        "env_pixel",
        "aa_cube",
        "transparency",
        "water",
        "bump",
    ];
    for scene in banded().filter(|s| shown.contains(s)) {
        let per = |label| f.per_px.get(&(scene.to_string(), label)).copied();
        let ratio = |label| {
            let b = per(label)?;
            let w = f.per_px.get(&(format!("whole_{scene}"), label))?;
            Some(b / w)
        };
        let three = |g: &dyn Fn(&'static str) -> Option<f64>, digits: usize| {
            ["Cortex-M0+", "Cortex-M4F", "RV32IMC"]
                .map(|l| g(l).map_or("-".into(), |v| format!("{v:.digits$}")))
                .join(" / ")
        };
        if per("Cortex-M4F").is_none() {
            continue;
        }
        let key = (scene.to_string(), "Cortex-M4F");
        t.push_str(&format!(
            "| {scene} | {} | {} | {} | {} |\n",
            three(&per, 1),
            three(&ratio, 2),
            f.geometry
                .get(&key)
                .map_or("-".into(), |g| format!("{:.1} %", 100.0 * g)),
            f.ram
                .get(&key)
                .map_or("-".into(), |r| format!("{:.1} KB", *r as f64 / 1024.0)),
        ));
    }
    t
}

/// TGX v1.1.4 (gcc 12.2 `-O2`, its own MCU configuration) on the benchmark scenes, in
/// instructions per drawn pixel, whole frames, as counted by this project under the same
/// QEMU plugin: (scene, fixel's scene name, Cortex-M4F, Cortex-M0+). TGX is measured once
/// by hand: it is C++ outside this repository.
const TGX: [(&str, &str, f64, f64); 4] = [
    (
        "cube: lit per face, bilinear from footprints, quadratic N=16",
        "cube",
        178.1,
        2098.0,
    ),
    ("floor: nearest, subdivided N=64", "floor", 42.6, 1100.0),
    (
        "floor: bilinear from footprints, subdivided N=64",
        "floor_bilinear",
        167.7,
        1997.0,
    ),
    (
        "sphere: lit, bilinear from footprints of a size fixed at compile time, adaptive",
        "sphere_sized",
        246.1,
        3899.0,
    ),
];

/// The README's table against TGX: fixel in bands (the whole frame in brackets).
pub(super) fn tgx(f: &Figures) -> String {
    let mut t = String::from(
        "| scene, fixel's mode | Cortex-M4F fixel, bands (whole) | TGX | Cortex-M0+ fixel, bands (whole) | TGX |\n\
         |---|---:|---:|---:|---:|\n",
    );
    for (what, scene, m4, m0) in TGX {
        let cell = |label| {
            let b = f.per_px.get(&(scene.to_string(), label));
            let w = f.per_px.get(&(format!("whole_{scene}"), label));
            match (b, w) {
                (Some(b), Some(w)) => format!("{b:.1} ({w:.1})"),
                (Some(b), None) => format!("{b:.1}"),
                _ => "-".into(),
            }
        };
        t.push_str(&format!(
            "| {what} | {} | {m4:.1} | {} | {m0:.0} |\n",
            cell("Cortex-M4F"),
            cell("Cortex-M0+"),
        ));
    }
    t
}

/// The glTF sample models against the only published board figures for them (a C++
/// renderer on ESP32 boards, 240 x 320): (model, fixel scene, peer's figure).
const MODELS: [(&str, &str, &str); 2] = [
    (
        "Fox (576 triangles)",
        "fox",
        "192 ms on an ESP32-C6 (RISC-V, 160 MHz, no FPU); 22.2 ms on one ESP32-S3 core, 14.9 ms on two",
    ),
    ("CesiumMan (4,672 triangles)", "cesium_man", "not published"),
];

/// The clock the RV32IMC figures are turned into milliseconds at (an ESP32-C3 / C6 class
/// core), Hz.
const RV32_CLOCK: f64 = 160e6;

/// The README's table of the glTF models: exact instructions per frame on RV32IMC, the
/// cycle model's estimate and the time it gives at 160 MHz, banded and whole, beside the
/// peer's board figures.
pub(super) fn models(f: &Figures) -> String {
    let mut t = String::from(
        "| model | fixel on RV32IMC, whole frame: instructions, est. cycles, at 160 MHz (model) | in 8-row bands (24 KB of RAM) | peer, measured on boards |\n\
         |---|---:|---:|---|\n",
    );
    for (name, scene, peer) in MODELS {
        let cell = |s: String| {
            f.frame.get(&(s, "RV32IMC")).map_or("-".into(), |(n, c)| {
                format!(
                    "{:.2} M, {:.2} M, **{:.1} ms**",
                    *n as f64 / 1e6,
                    c / 1e6,
                    c / RV32_CLOCK * 1e3
                )
            })
        };
        t.push_str(&format!(
            "| {name} | {} | {} | {peer} |\n",
            cell(format!("whole_{scene}")),
            cell(scene.to_string()),
        ));
    }
    t
}

/// The real-time modes, each a plain textured draw of the sphere after its work moved out
/// of the pixel loop, against the plain lit textured `sphere` (the same bands); and the
/// flame from baked layers against the same quad textured (`flame_plain`).
const REALTIME: [(&str, &str, &str); 6] = [
    (
        "environment map: sphere-map coordinates per vertex",
        "env_matcap",
        "sphere",
    ),
    (
        "environment map: cube-map face per triangle, its coordinates per vertex",
        "env_cube_vertex",
        "sphere",
    ),
    (
        "solid noise: marble baked into the texture (wood and granite: docs/mcu.md)",
        "noise_baked",
        "sphere",
    ),
    (
        "bump map: lighting resolved into the texture",
        "bump_fast",
        "sphere",
    ),
    (
        "solid noise: the flame from two baked layers",
        "noise_flame_baked",
        "flame_plain",
    ),
    (
        "shadow map: single tap, light coordinates from the texture coordinates",
        "shadow_single_uv",
        "shadow_none",
    ),
];

/// The plain draws the real-time modes are compared with.
const PLAIN: [(&str, &str); 3] = [
    ("plain: lit, bilinear, the sphere's own texture", "sphere"),
    ("plain: the flame's quad, bilinear, unlit", "flame_plain"),
    (
        "plain: the shadow scene's lit pass without shadows",
        "shadow_none",
    ),
];

/// The README's table of the real-time modes: instructions per pixel on each core and the
/// ratio to the plain draw they are compared with.
pub(super) fn realtime(f: &Figures) -> String {
    let mut t = String::from(
        "| mode | instr/px, M0+ / M4F / RV32 | x its plain draw, M0+ / M4F / RV32 |\n\
         |---|---:|---:|\n",
    );
    let cores = ["Cortex-M0+", "Cortex-M4F", "RV32IMC"];
    let per = |s: &str, l: &'static str| f.per_px.get(&(s.to_string(), l)).copied();
    let row = |g: &dyn Fn(&'static str) -> Option<f64>, d: usize| {
        cores
            .map(|l| g(l).map_or("-".into(), |v| format!("{v:.d$}")))
            .join(" / ")
    };
    for (what, plain) in PLAIN {
        t.push_str(&format!(
            "| {what} (`{plain}`) | {} | 1 |\n",
            row(&|l| per(plain, l), 1)
        ));
    }
    for (what, scene, plain) in REALTIME {
        let ratio = |l: &'static str| Some(per(scene, l)? / per(plain, l)?);
        t.push_str(&format!(
            "| {what} (`{scene}`) | {} | {} |\n",
            row(&|l| per(scene, l), 1),
            row(&ratio, 2),
        ));
    }
    t
}

/// Replaces the text between `<!-- generated: NAME -->` and `<!-- end: NAME -->` in `file`
/// with `body`; an error when the markers are missing.
pub(crate) fn write_region(file: &Path, name: &str, body: &str) -> Result<(), String> {
    let text = fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
    let (open, close) = (
        format!("<!-- generated: {name} -->"),
        format!("<!-- end: {name} -->"),
    );
    let (Some(a), Some(b)) = (text.find(&open), text.find(&close)) else {
        return Err(format!(
            "{}: no `{open}` ... `{close}` region to write",
            file.display()
        ));
    };
    if b < a {
        return Err(format!("{}: `{close}` before `{open}`", file.display()));
    }
    let out = format!("{}{open}\n{body}{}", &text[..a], &text[b..]);
    fs::write(file, out).map_err(|e| format!("{}: {e}", file.display()))
}

#[cfg(test)]
mod tests {
    use super::write_region;

    #[test]
    fn a_region_is_replaced_between_its_markers_and_the_rest_kept() {
        let dir = std::env::temp_dir().join(format!("fixel-region-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let f = dir.join("doc.md");
        std::fs::write(&f, "a\n<!-- generated: t -->\nold\n<!-- end: t -->\nb\n").unwrap();
        write_region(&f, "t", "new 1\nnew 2\n").unwrap();
        assert_eq!(
            std::fs::read_to_string(&f).unwrap(),
            "a\n<!-- generated: t -->\nnew 1\nnew 2\n<!-- end: t -->\nb\n"
        );
        // Twice gives the same file.
        write_region(&f, "t", "new 1\nnew 2\n").unwrap();
        assert!(std::fs::read_to_string(&f)
            .unwrap()
            .contains("new 2\n<!-- end: t -->"));
        assert!(write_region(&f, "missing", "x").is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
