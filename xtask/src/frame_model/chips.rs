//! The parts `cargo xtask fps` and `cargo xtask budget` model: clock, cores, display link,
//! and which measured instruction set stands for their cores.

use super::{Chip, Link};

/// An ST7789-class display over SPI at `mhz`: RGB565, a window command per band.
const fn spi(mhz: f64) -> Link {
    Link {
        clock_hz: mhz * 1e6,
        bytes_per_px: 2.0,
        command_bytes: 11.0,
        band_overhead_s: 2e-6,
    }
}

/// The parts modelled.
pub const CHIPS: [Chip; 4] = [
    Chip {
        name: "RP2040",
        counts_from: "Cortex-M0+",
        core: "2 x Cortex-M0+, 133 MHz",
        cpu_hz: 133e6,
        cores: 2,
        link: spi(62.5),
    },
    Chip {
        name: "RP2350",
        counts_from: "Cortex-M4F",
        core: "2 x Cortex-M33, 150 MHz",
        cpu_hz: 150e6,
        cores: 2,
        link: spi(62.5),
    },
    Chip {
        name: "STM32F4",
        counts_from: "Cortex-M4F",
        core: "1 x Cortex-M4F, 168 MHz",
        cpu_hz: 168e6,
        cores: 1,
        link: spi(42.0),
    },
    Chip {
        name: "ESP32-C3",
        counts_from: "RV32IMC",
        core: "1 x RV32IMC, 160 MHz",
        cpu_hz: 160e6,
        cores: 1,
        link: spi(40.0),
    },
];
