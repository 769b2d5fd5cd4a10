//! The colour keys and parameters of fixel's demonstration solid textures, shared (as data)
//! by the showcase, the firmware scenes, the report and the f64 reference.

use super::patterns::{Granite, Marble, Ramp, Wood};
use crate::Error;

/// White Carrara-like marble through a sine: dark grey-green veins at the troughs.
pub const MARBLE_KEYS: [(u8, u32); 5] = [
    (0, 0x40_48_50),
    (10, 0x8A_92_96),
    (40, 0xD4_D2_CC),
    (150, 0xEE_EB_E4),
    (255, 0xF8_F6_F1),
];

/// One ring of a light wood: early wood, then the dark late-wood line.
pub const WOOD_KEYS: [(u8, u32); 5] = [
    (0, 0xD2_A0_62),
    (150, 0xE0_B4_78),
    (200, 0xB0_78_40),
    (228, 0x86_52_26),
    (255, 0xD2_A0_62),
];

/// Pink granite: dark biotite, grey quartz, pink feldspar, by turbulence.
pub const GRANITE_KEYS: [(u8, u32); 6] = [
    (0, 0x1C_1A_1A),
    (40, 0x4A_44_44),
    (70, 0x9C_94_92),
    (100, 0xC8_A0_96),
    (140, 0xE6_C4_B8),
    (255, 0xF6_EE_EA),
];

/// Marble stripe frequency: turns per lattice cell along x (I16F16 bits): 0.75.
pub const MARBLE_FREQ: i32 = 0xC000;
/// Marble turbulence amplitude, turns (Q8): 1.0.
pub const MARBLE_AMP: i32 = 256;
/// Wood rings per lattice cell of radius (Q8): 4.
pub const WOOD_RINGS: i32 = 1024;
/// Wood rings per unit of turbulence (Q8): 0.3.
pub const WOOD_AMP: i32 = 77;
/// Granite grain: 2^2 times the lattice frequency.
pub const GRANITE_SHIFT: u8 = 2;

/// The three demonstration ramps.
#[derive(Clone, Debug)]
pub struct Ramps {
    /// [`MARBLE_KEYS`] through a sine.
    pub marble: Ramp,
    /// [`WOOD_KEYS`].
    pub wood: Ramp,
    /// [`GRANITE_KEYS`].
    pub granite: Ramp,
}

impl Ramps {
    /// Builds the tables (1.5 KB).
    ///
    /// # Errors
    /// None with these keys; [`Ramp`]'s checks otherwise.
    pub fn new() -> Result<Ramps, Error> {
        Ok(Ramps {
            marble: Ramp::sine(&MARBLE_KEYS)?,
            wood: Ramp::from_keys(&WOOD_KEYS)?,
            granite: Ramp::from_keys(&GRANITE_KEYS)?,
        })
    }

    /// The demonstration marble.
    pub fn marble(&self) -> Marble<'_> {
        Marble {
            ramp: &self.marble,
            freq: MARBLE_FREQ,
            amp: MARBLE_AMP,
        }
    }

    /// The demonstration wood.
    pub fn wood(&self) -> Wood<'_> {
        Wood {
            ramp: &self.wood,
            rings: WOOD_RINGS,
            amp: WOOD_AMP,
        }
    }

    /// The demonstration granite.
    pub fn granite(&self) -> Granite<'_> {
        Granite {
            ramp: &self.granite,
            shift: GRANITE_SHIFT,
        }
    }
}
