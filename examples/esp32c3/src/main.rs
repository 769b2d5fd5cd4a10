//! fixel on an ESP32-C3 (one RV32IMC core at 160 MHz, `esp-hal`, stable Rust): the
//! benchmark cube on a 320 x 240 ST7789 over SPI2 at 40 MHz with DMA, each band sent while
//! the next is drawn.
//!
//! Built for `riscv32imc-unknown-none-elf` by `cargo xtask ci` (a build check, not run).
//! Wiring: SCK on GPIO6 and MOSI on GPIO7 (SPI2's IO MUX pins), chip select GPIO10,
//! data/command GPIO2, reset GPIO3, backlight GPIO1.
//!
//! The frame is fixel's `async` one ([`BandRenderer::render_async`]) with
//! [`SpiSender`] over an `embedded-hal-async` `SpiDevice`: esp-hal's SPI with a DMA channel
//! in async mode (`Spi::with_dma(..).into_async()`, behind esp-hal's `unstable` feature in
//! 1.2) under `embedded-hal-bus`'s `ExclusiveDevice`. The sender's first poll converts band
//! `k` to big-endian bytes in its scratch buffer and starts the DMA from there (one transfer
//! of 5,120 bytes); band `k + 1` is drawn meanwhile, then the transfer is awaited. One band
//! takes 1.0 ms on the wire at 40 MHz; `embassy-futures`' `block_on` runs the frame (no
//! executor, no interrupts of the firmware's own).
#![no_std]
#![no_main]

use embassy_futures::block_on;
use embedded_hal::spi::SpiDevice;
use embedded_hal_bus::spi::ExclusiveDevice;
use esp_hal::clock::CpuClock;
use esp_hal::delay::Delay;
use esp_hal::gpio::{Level, Output, OutputConfig};
use esp_hal::spi::master::{Config as SpiConfig, Spi};
use esp_hal::spi::Mode;
use esp_hal::time::Rate;
use fixel::pipeline::{DepthLess, Exact, ModulateIntensity, Pipeline};
use fixel::prelude::*;
use fixel::scene::{mesh_triangles, DirectionalLight};
use fixel::surface::{BandDraw, BandError, Binned, SpiSender};
use fixel::texture::{Bilinear, Repeat};
use fixel_scenes as demo;

esp_bootloader_esp_idf::esp_app_desc!();

/// The stages this firmware links: nothing else of fixel's span loops is compiled in.
type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;

const W: u32 = 320;
const H: u32 = 240;
const ROWS: u32 = 8;
const BAND: usize = (W * ROWS) as usize;

/// A 64 x 64 checker texture made at compile time (lives in flash): the one of the
/// `examples/display` firmware.
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

#[esp_hal::main]
fn main() -> ! {
    let p = esp_hal::init(esp_hal::Config::default().with_cpu_clock(CpuClock::max()));
    let delay = Delay::new();

    // --- The panel: SPI2 with a DMA channel, async; chip select by embedded-hal-bus. ---
    let config = SpiConfig::default()
        .with_frequency(Rate::from_mhz(40))
        .with_mode(Mode::_0);
    let Ok(spi) = Spi::new(p.SPI2, config) else {
        panic!("SPI configuration")
    };
    let bus = spi
        .with_sck(p.GPIO6)
        .with_mosi(p.GPIO7)
        .with_dma(p.DMA_CH0)
        .into_async();
    let cs = Output::new(p.GPIO10, Level::High, OutputConfig::default());
    let mut dc = Output::new(p.GPIO2, Level::Low, OutputConfig::default());
    let mut rst = Output::new(p.GPIO3, Level::Low, OutputConfig::default());
    let mut backlight = Output::new(p.GPIO1, Level::Low, OutputConfig::default());
    // Its error type is `Infallible` for esp-hal's pins.
    let Ok(mut spi) = ExclusiveDevice::new_no_delay(bus, cs);
    delay.delay_millis(10);
    rst.set_high();
    delay.delay_millis(120);
    st7789_init(&mut spi, &mut dc, &delay);
    backlight.set_high();

    // --- fixel: two band buffers (one drawn while the other is sent), a depth band, the
    // sender's byte buffer (a whole band: one DMA transfer per band). 20 KiB. ---
    let mut a = [Rgb565::new(0, 0, 0); BAND];
    let mut b = [Rgb565::new(0, 0, 0); BAND];
    let mut depth = [0u16; BAND];
    let mut scratch = [0u8; 2 * BAND];
    let mut buffers = [&mut a[..], &mut b[..]];
    let Ok(bands) = BandRenderer::with_buffers(&mut buffers, W, ROWS, H) else {
        panic!()
    };
    let Ok(mut bands) = bands.with_depth(&mut depth) else {
        panic!()
    };
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
    let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];

    let mut frame = 0;
    loop {
        let model = demo::cube_model(frame);
        // The window is the whole panel (set once): RAMWR, then the bands as data.
        dc.set_low();
        let _ = spi.write(&[0x2C]);
        dc.set_high();
        let Ok(mut link) = SpiSender::new(&mut spi, &mut scratch) else {
            panic!()
        };
        let drawn = block_on(bands.render_async(
            &draws,
            &mut bins,
            Rgb565::new(0, 0, 0),
            |sink| {
                mesh_triangles(&mesh, &model, &camera, Some(&light), |t| {
                    draw.project(t, &mut |s| sink.push(0, s))
                })
            },
            &mut link,
        ));
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

/// The ST7789's set-up for a 320 x 240 landscape RGB565 frame.
fn st7789_init<S: SpiDevice>(spi: &mut S, dc: &mut Output<'_>, delay: &Delay) {
    let mut cmd = |c: u8, args: &[u8]| {
        dc.set_low();
        let _ = spi.write(&[c]);
        dc.set_high();
        if !args.is_empty() {
            let _ = spi.write(args);
        }
    };
    cmd(0x01, &[]); // SWRESET
    delay.delay_millis(150);
    cmd(0x11, &[]); // SLPOUT
    delay.delay_millis(120);
    cmd(0x3A, &[0x55]); // COLMOD: 16 bits per pixel
    cmd(0x36, &[0x60]); // MADCTL: rows and columns exchanged (landscape)
    cmd(0x21, &[]); // INVON (IPS panels)
    cmd(0x2A, &[0, 0, ((W - 1) >> 8) as u8, (W - 1) as u8]); // CASET 0..=319
    cmd(0x2B, &[0, 0, ((H - 1) >> 8) as u8, (H - 1) as u8]); // RASET 0..=239
    cmd(0x13, &[]); // NORON
    cmd(0x29, &[]); // DISPON
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    #[allow(clippy::empty_loop)]
    loop {}
}
