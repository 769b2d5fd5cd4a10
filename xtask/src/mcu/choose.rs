//! The README's choice of a mode per technique and chip: of each technique's firmware
//! scenes, the most accurate one whose frame reaches 20 frames per second on a 320 x 240
//! screen with a third of it covered, or none, by the cycle model of `cargo xtask mcu`.
//!
//! Frame time = estimated cycles per drawn pixel (the scene's exact instruction count
//! times its cycles per instruction from `xtask/mcu/cycles.py`) x 25,600 pixels / the
//! chip's clock: one core, drawing only (the display link overlapped with the drawing, as
//! `docs/fps.md` models it, and zero-wait-state memory). Modes are listed most accurate
//! first, as the technique reports (`docs/report/`) measure them against their f64
//! references.

use super::bands::Figures;

/// Pixels drawn per frame: a third of 320 x 240.
const PIXELS: f64 = 320.0 * 240.0 / 3.0;

/// Frames per second a mode must reach.
const FPS: f64 = 20.0;

/// The chips of the table: name, the MCU label its figures are measured as, clock (Hz).
const CHIPS: [(&str, &str, f64); 3] = [
    ("RP2040 (Cortex-M0+, 133 MHz)", "Cortex-M0+", 133e6),
    ("STM32F4 (Cortex-M4F, 168 MHz)", "Cortex-M4F", 168e6),
    ("ESP32-C3 (RV32IMC, 160 MHz)", "RV32IMC", 160e6),
];

/// Each technique's modes, most accurate first: what the mode is, its firmware scene.
const TECHNIQUES: [(&str, &[(&str, &str)]); 7] = [
    (
        "plain textured sphere (for scale)",
        &[
            ("lit, bilinear", "sphere"),
            (
                "lit, bilinear from footprints sized at compile time",
                "sphere_sized",
            ),
        ],
    ),
    (
        "environment map",
        &[
            ("reflection per pixel", "env_pixel"),
            ("reflection per vertex", "env_vertex"),
            ("cube-map directions per vertex", "env_cube_vertex"),
            ("sphere-map coordinates per vertex", "env_matcap"),
        ],
    ),
    (
        "solid noise",
        &[
            ("marble per pixel, 6 octaves", "noise"),
            ("marble baked into the texture", "noise_baked"),
        ],
    ),
    (
        "animated flame",
        &[
            ("5 octaves per pixel", "noise_flame"),
            ("two baked layers of octaves", "noise_flame_baked"),
        ],
    ),
    (
        "bump map",
        &[
            ("lit per pixel", "bump"),
            ("lighting resolved into the texture", "bump_fast"),
        ],
    ),
    (
        "anti-aliasing (the cube)",
        &[
            ("rotated-grid 4x", "aa_cube"),
            ("silhouette edges from depth", "aa_edge"),
        ],
    ),
    (
        "shadow map",
        &[
            ("PCF 3 x 3", "shadow_pcf3x3"),
            ("PCF 2 x 2", "shadow_pcf2x2"),
            ("single tap", "shadow_single"),
            (
                "single tap, light from texture coordinates",
                "shadow_single_uv",
            ),
        ],
    ),
];

/// Frames per second of `scene` on the chip measured as `label` at `clock`, by the model.
fn fps(f: &Figures, scene: &str, label: &'static str, clock: f64) -> Option<f64> {
    let key = (scene.to_string(), label);
    let per_px = f.per_px.get(&key)?;
    let (insns, cycles) = f.frame.get(&key)?;
    if *insns == 0 {
        return None;
    }
    let cycles_per_px = per_px * cycles / *insns as f64;
    Some(clock / (cycles_per_px * PIXELS))
}

/// The README's table: per technique and chip, the mode chosen and its frame rate, or
/// none (with the fastest mode's rate).
pub(super) fn table(f: &Figures) -> String {
    let mut t = String::from("| technique |");
    for (chip, _, _) in CHIPS {
        t.push_str(&format!(" {chip} |"));
    }
    t.push_str("\n|---|");
    t.push_str(&"---|".repeat(CHIPS.len()));
    t.push('\n');
    for (technique, modes) in TECHNIQUES {
        t.push_str(&format!("| {technique} |"));
        for (_, label, clock) in CHIPS {
            let rated: Vec<(&str, &str, f64)> = modes
                .iter()
                .filter_map(|(what, scene)| Some((*what, *scene, fps(f, scene, label, clock)?)))
                .collect();
            let cell = match rated.iter().find(|m| m.2 >= FPS) {
                Some((what, scene, r)) => format!("{what} (`{scene}`): **{r:.0} fps**"),
                None => match rated.iter().max_by(|a, b| a.2.total_cmp(&b.2)) {
                    Some((_, scene, r)) => format!("none (fastest, `{scene}`: {r:.0} fps)"),
                    None => "-".into(),
                },
            };
            t.push_str(&format!(" {cell} |"));
        }
        t.push('\n');
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_most_accurate_mode_reaching_the_rate_is_chosen() {
        let mut f = Figures::default();
        // 100 instructions per pixel at 1 cycle each on every chip: 133e6 / 2.56e6 = 52 fps
        // on the slowest; 1,000: 5.2 fps.
        for (scene, per_px) in [("bump", 1000.0), ("bump_fast", 100.0), ("aa_cube", 3000.0)] {
            for (_, label, _) in CHIPS {
                f.per_px.insert((scene.to_string(), label), per_px);
                f.frame.insert((scene.to_string(), label), (1000, 1000.0));
            }
        }
        let t = table(&f);
        let bump = t.lines().find(|l| l.starts_with("| bump map")).unwrap();
        assert!(
            bump.contains("lighting resolved into the texture (`bump_fast`): **52 fps**"),
            "{bump}"
        );
        let aa = t
            .lines()
            .find(|l| l.starts_with("| anti-aliasing"))
            .unwrap();
        assert!(aa.contains("none (fastest, `aa_cube`: 2 fps)"), "{aa}");
        let env = t.lines().find(|l| l.starts_with("| environment")).unwrap();
        assert!(env.contains("| - |"), "{env}");
    }
}
