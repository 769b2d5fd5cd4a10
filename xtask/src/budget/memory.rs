//! Flash and RAM of a model's firmware: the baked model's arrays (their sizes in fixel's
//! formats), the firmware's code and the band storage, from the `fox` firmware's measured
//! flash and RAM (`docs/mcu.md`) less what the Fox itself takes.

use std::collections::HashMap;

use super::fit::{Counts, Measured};
use super::render::{CACHE, ROWS, SETUPS};

/// Bytes per vertex position, normal and texture coordinate (`Vec3` of I16F16, `[Fx; 2]`).
const POSITION: u64 = 12;
const NORMAL: u64 = 12;
const UV: u64 = 8;
/// Bytes per triangle (`[u16; 3]`).
const INDICES: u64 = 6;
/// Bytes per vertex colour and texel (RGB565).
const RGB565: u64 = 2;
/// Bytes of a band range, a cached prepared vertex and a kept set-up on the 32-bit parts.
const RANGE: u64 = 2;
const CACHED_VERTEX: u64 = 32;
/// (`KeptSetup` holds no pointer: the host's size is the parts'.)
const KEPT_SETUP: u64 = core::mem::size_of::<fixel::pipeline::KeptSetup>() as u64;

/// The Fox's texture as the firmware bakes it (`assets/gltf/fox.rs`): 128 x 128, 8 levels.
const FOX_TEXTURE: (u32, u32, u32) = (128, 128, 8);

/// Bytes of a mip chain of `levels` levels from `w x h`.
pub fn chain_bytes((w, h, levels): (u32, u32, u32)) -> u64 {
    (0..levels)
        .map(|k| u64::from((w >> k).max(1)) * u64::from((h >> k).max(1)) * RGB565)
        .sum()
}

/// The baked model's arrays: (what, bytes).
pub fn model_flash(c: &Counts, colors: bool, texture: (u32, u32, u32)) -> Vec<(&'static str, u64)> {
    let mut v = vec![
        ("positions", c.vertices * POSITION),
        ("normals", c.vertices * NORMAL),
        ("texture coordinates", c.vertices * UV),
        ("indices", c.triangles * INDICES),
    ];
    if colors {
        v.push(("vertex colours", c.vertices * RGB565));
    }
    v.push(("texture and mip chain", chain_bytes(texture)));
    v
}

/// Flash of the firmware besides its model (fixel's code, the harness, the vector table):
/// the `fox` firmware's flash on `target` less the Fox's arrays.
pub fn code_flash(
    measured: &HashMap<(String, String), Measured>,
    bench: &[Counts],
    target: &str,
) -> Option<u64> {
    let fox = bench.iter().find(|c| c.scene == "fox")?;
    let m = measured.get(&("fox".to_string(), target.to_string()))?;
    let data: u64 = model_flash(fox, false, FOX_TEXTURE)
        .iter()
        .map(|x| x.1)
        .sum();
    m.flash.checked_sub(data)
}

/// The band storage of a model firmware drawing `c`: (what, bytes).
pub fn band_ram(c: &Counts) -> Vec<(&'static str, u64)> {
    vec![
        (
            "colour + depth band",
            u64::from(c.size.0) * u64::from(ROWS) * 4,
        ),
        ("band ranges (one per triangle)", c.triangles * RANGE),
        ("prepared-vertex cache", CACHE as u64 * CACHED_VERTEX),
        ("kept set-ups", SETUPS as u64 * KEPT_SETUP),
    ]
}

/// RAM of the firmware besides its band storage (stack, statics): the `fox` firmware's
/// measured RAM on `target` less its band storage.
pub fn other_ram(
    measured: &HashMap<(String, String), Measured>,
    bench: &[Counts],
    target: &str,
) -> Option<u64> {
    let fox = bench.iter().find(|c| c.scene == "fox")?;
    let m = measured.get(&("fox".to_string(), target.to_string()))?;
    m.ram
        .checked_sub(band_ram(fox).iter().map(|x| x.1).sum::<u64>())
}

/// A part's memory as its common board has it: (flash, RAM) in bytes, and the board.
pub fn capacity(chip: &str) -> Option<(u64, u64, &'static str)> {
    match chip {
        "RP2040" => Some((
            2 << 20,
            264 << 10,
            "Raspberry Pi Pico: 2 MB flash, 264 KB SRAM",
        )),
        "RP2350" => Some((
            4 << 20,
            520 << 10,
            "Raspberry Pi Pico 2: 4 MB flash, 520 KB SRAM",
        )),
        "STM32F4" => Some((
            1 << 20,
            128 << 10,
            "STM32F407: 1 MB flash, 128 KB SRAM (the 64 KB CCM left out: no DMA)",
        )),
        "ESP32-C3" => Some((
            4 << 20,
            320 << 10,
            "ESP32-C3: 4 MB flash, about 320 KB of data SRAM",
        )),
        _ => None,
    }
}
