//! fixel on a real display: the benchmark cube drawn band by band into a 320 x 8 buffer and
//! streamed to an ST7789 (240 x 320, used in landscape) through `mipidsi`, one
//! `fill_contiguous` per band via [`DrawTargetFlush`].
//!
//! Built for `thumbv7em-none-eabihf` by `cargo xtask mcu` (compile check only). The SPI bus,
//! pins and delay are no-op stand-ins: replace them with your HAL's `SpiDevice`,
//! `OutputPin` and `DelayNs` (embedded-hal 1.0) and the rest stays as it is.
#![no_std]
#![no_main]

use core::convert::Infallible;

use cortex_m_rt::entry;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_hal::delay::DelayNs;
use embedded_hal::digital::{ErrorType as PinErrorType, OutputPin};
use embedded_hal::spi::{ErrorType as SpiErrorType, Operation, SpiDevice};
use fixel::pipeline::{DepthLess, Exact, ModulateIntensity, Pipeline};
use fixel::prelude::*;
use fixel::scene::{mesh_triangles, DirectionalLight};
use fixel::surface::Binned;
use fixel::surface::{BandError, DrawTargetFlush};
use fixel::texture::{Bilinear, Repeat};
use fixel_scenes as demo;
use mipidsi::interface::SpiInterface;
use mipidsi::models::ST7789;
use mipidsi::options::{Orientation, Rotation};
use mipidsi::Builder;

/// The stages this firmware links: nothing else of fixel's span loops is compiled in.
type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;

const W: u32 = 320;
const H: u32 = 240;
const ROWS: u32 = 8;
const BAND: usize = (W * ROWS) as usize;

/// A 64 x 64 checker texture made at compile time (lives in flash).
static TEXELS: [Rgb565; 64 * 64] = {
    let mut t = [Rgb565::new(0, 0, 0); 64 * 64];
    let mut i = 0;
    while i < 64 * 64 {
        let (x, y) = (i % 64, i / 64);
        let b = if (x / 16 + y / 16) % 2 == 1 { 31 } else { 0 };
        t[i] = Rgb565::new((x / 2) as u8, y as u8, b);
        i += 1;
    }
    t
};
static TEXTURE: Texture<'static> = Texture::from_static(&TEXELS, 64, 64);

#[entry]
fn main() -> ! {
    // --- Board specifics: replace with your HAL. ---
    let (spi, dc, rst, mut delay) = (NoSpi, NoPin, NoPin, NoDelay);

    // --- Display: mipidsi over SPI, landscape 320 x 240. ---
    let mut spi_buf = [0u8; 512];
    let di = SpiInterface::new(spi, dc, &mut spi_buf);
    let Ok(mut display) = Builder::new(ST7789, di)
        .display_size(240, 320)
        .orientation(Orientation::new().rotate(Rotation::Deg90))
        .reset_pin(rst)
        .init(&mut delay)
    else {
        panic!("display init failed");
    };

    // --- fixel: a band buffer (colour + depth, 10 KiB), a few bins, one typed draw. ---
    let mut color = [Rgb565::new(0, 0, 0); BAND];
    let mut depth = [0u16; BAND];
    let mut bins = [Binned::default(); 16];
    let cube = demo::cube();
    let Ok(mesh) = cube.mesh() else { panic!() };
    let camera = demo::camera(20);
    let light = DirectionalLight::default();
    let Ok(vp) = Viewport::new(0, 0, W, H) else {
        panic!()
    };
    let Ok(draw) = Draw::new::<Lit>(Some(TEXTURE), vp, Cull::Back) else {
        panic!()
    };
    let Ok(bands) = BandRenderer::new(&mut color, W, ROWS, H) else {
        panic!()
    };
    let Ok(mut bands) = bands.with_depth(&mut depth) else {
        panic!()
    };

    let mut frame = 0;
    loop {
        let model = demo::cube_model(frame);
        let mut out = DrawTargetFlush(&mut display);
        // Geometry runs once (binned); each band is drawn, then streamed to the panel.
        let drawn = bands.render(
            &[&draw],
            &mut bins,
            Rgb565::new(0, 0, 0),
            |sink| {
                mesh_triangles(&mesh, &model, &camera, Some(&light), |t| {
                    draw.project(t, &mut |s| sink.push(0, s))
                })
            },
            |band| out.flush(band),
        );
        match drawn {
            Ok(_stats) => {}
            // Input errors are bugs in this program (a draw index, a missing depth band).
            Err(BandError::Input(e)) => panic!("{e}"),
            // A failed bus transfer: the next frame redraws every band.
            Err(BandError::Flush(_)) => {}
        }
        frame = frame.wrapping_add(1);
    }
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    #[allow(clippy::empty_loop)]
    loop {}
}

/// Stand-in SPI device (embedded-hal 1.0): accepts every transaction.
struct NoSpi;
impl SpiErrorType for NoSpi {
    type Error = Infallible;
}
impl SpiDevice for NoSpi {
    fn transaction(&mut self, _ops: &mut [Operation<'_, u8>]) -> Result<(), Infallible> {
        Ok(())
    }
}

/// Stand-in GPIO pin (data/command select, reset).
struct NoPin;
impl PinErrorType for NoPin {
    type Error = Infallible;
}
impl OutputPin for NoPin {
    fn set_low(&mut self) -> Result<(), Infallible> {
        Ok(())
    }
    fn set_high(&mut self) -> Result<(), Infallible> {
        Ok(())
    }
}

/// Stand-in delay.
struct NoDelay;
impl DelayNs for NoDelay {
    fn delay_ns(&mut self, _ns: u32) {}
}
