//! fixel on an RP2040 (two Cortex-M0+ at 125 MHz): the benchmark cube on a 320 x 240 ST7789
//! over SPI at 62.5 MHz, sent by DMA while the next band is drawn, core 0 drawing the even
//! bands and core 1 the odd ones.
//!
//! Built for `thumbv6m-none-eabi` by `cargo xtask ci` (a build check, not run). Wiring (a
//! Pico with a Pimoroni Pico Display style panel): SPI0 SCK on GPIO18, MOSI on GPIO19, chip
//! select GPIO17 (held low), data/command GPIO16, reset GPIO20, backlight GPIO21.
//!
//! Each frame:
//! 1. core 0 bins the cube once ([`BinnedFrame::new`]) and hands core 1 a pointer to it
//!    through the SIO FIFO (which needs no atomics: ARMv6-M has no compare-and-swap);
//! 2. both cores draw their share of the bands ([`BandRenderer::render_share_to`], core 0
//!    [`BandShare`] 0 of 2, core 1 share 1 of 2), each into its own two band buffers and its
//!    own depth band, from the same bins, read only;
//! 3. the bands reach the panel in order through one DMA channel, driven by core 0: core 1
//!    passes each finished band (its address and length) through the FIFO; before core 0
//!    starts its band `k` it sends core 1's band `k - 1` and answers core 1 once that
//!    transfer is done (core 1 then draws into that buffer again). Each core draws its next
//!    band while the DMA sends.
//!
//! Core 0 waits for core 1's band transfer (0.66 ms per 320 x 8 band at 62.5 MHz) before it
//! starts its own, so a third of the link time is on core 0's clock; a DMA interrupt that
//! chains the queued bands would hide it too.
#![no_std]
#![no_main]

use core::convert::Infallible;

use embedded_hal::digital::OutputPin;
use embedded_hal::spi::{SpiBus, MODE_0};
use fixel::pipeline::{DepthLess, Exact, ModulateIntensity, Pipeline};
use fixel::prelude::*;
use fixel::scene::{mesh_triangles, DirectionalLight};
use fixel::surface::{BandDraw, BandSender, BandShare, Binned, BinnedFrame};
use fixel::texture::{Bilinear, Repeat};
use fixel_scenes as demo;
use fugit::RateExtU32;
use rp2040_hal::clocks::{init_clocks_and_plls, Clock};
use rp2040_hal::dma::{single_buffer, Channel, DMAExt, CH0};
use rp2040_hal::gpio::bank0::{Gpio16, Gpio18, Gpio19};
use rp2040_hal::gpio::{FunctionSio, FunctionSpi, Pin, PullDown, SioOutput};
use rp2040_hal::multicore::{Multicore, Stack};
use rp2040_hal::sio::SioFifo;
use rp2040_hal::spi::Enabled;
use rp2040_hal::{pac, Sio, Spi, Watchdog};

/// The second-stage bootloader (W25Q080-compatible flash, as on the Pico).
#[link_section = ".boot2"]
#[used]
pub static BOOT2: [u8; 256] = rp2040_boot2::BOOT_LOADER_W25Q080;

/// The stages this firmware links: nothing else of fixel's span loops is compiled in.
type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;

const W: u32 = 320;
const H: u32 = 240;
const ROWS: u32 = 8;
const BAND: usize = (W * ROWS) as usize;
const XTAL_HZ: u32 = 12_000_000;
/// Core 1's message after its last band of a frame (no band is at address 0).
const DONE: u32 = 0;
/// Core 0's answer to core 1: the band's transfer is over, its buffer is core 1's again.
const SENT: u32 = 1;

// The DMA sends a band's pixels as 16-bit words, most significant byte first on the wire
// (the ST7789's RGB565 order): `Rgb565` must be one `u16` in memory.
const _: () = assert!(core::mem::size_of::<Rgb565>() == 2 && core::mem::align_of::<Rgb565>() == 2);

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

/// Core 1's stack (32 KiB: two colour bands, a depth band and the renderer, 15 KiB).
static CORE1_STACK: Stack<8192> = Stack::new();

type Spi16 = Spi<
    Enabled,
    pac::SPI0,
    (
        Pin<Gpio19, FunctionSpi, PullDown>,
        Pin<Gpio18, FunctionSpi, PullDown>,
    ),
    16,
>;
type DcPin = Pin<Gpio16, FunctionSio<SioOutput>, PullDown>;

#[rp2040_hal::entry]
fn main() -> ! {
    let Some(mut pac) = pac::Peripherals::take() else {
        panic!()
    };
    let Some(core) = pac::CorePeripherals::take() else {
        panic!()
    };
    let mut watchdog = Watchdog::new(pac.WATCHDOG);
    let Ok(clocks) = init_clocks_and_plls(
        XTAL_HZ,
        pac.XOSC,
        pac.CLOCKS,
        pac.PLL_SYS,
        pac.PLL_USB,
        &mut pac.RESETS,
        &mut watchdog,
    ) else {
        panic!("clocks")
    };
    let mut delay = cortex_m::delay::Delay::new(core.SYST, clocks.system_clock.freq().to_Hz());
    let mut sio = Sio::new(pac.SIO);
    let pins = rp2040_hal::gpio::Pins::new(
        pac.IO_BANK0,
        pac.PADS_BANK0,
        sio.gpio_bank0,
        &mut pac.RESETS,
    );

    // --- The panel: 8-bit SPI for its set-up, then 16-bit words for the pixels. ---
    let sck = pins.gpio18.into_function::<FunctionSpi>();
    let mosi = pins.gpio19.into_function::<FunctionSpi>();
    let mut cs = pins.gpio17.into_push_pull_output();
    let mut dc = pins.gpio16.into_push_pull_output();
    let mut rst = pins.gpio20.into_push_pull_output();
    let mut backlight = pins.gpio21.into_push_pull_output();
    let peri = clocks.peripheral_clock.freq();
    let mut spi8 = Spi::<_, _, _, 8>::new(pac.SPI0, (mosi, sck)).init(
        &mut pac.RESETS,
        peri,
        62_500_000u32.Hz(),
        MODE_0,
    );
    let _ = cs.set_low();
    let _ = rst.set_low();
    delay.delay_ms(10);
    let _ = rst.set_high();
    delay.delay_ms(120);
    st7789_init(&mut spi8, &mut dc, &mut delay);
    let _ = backlight.set_high();
    let (spi0, spi_pins) = spi8.free();
    let spi16: Spi16 = Spi::<_, _, _, 16>::new(spi0, spi_pins).init(
        &mut pac.RESETS,
        peri,
        62_500_000u32.Hz(),
        MODE_0,
    );
    let dma = pac.DMA.split(&mut pac.RESETS);

    // --- Core 1: the odd bands of each frame core 0 hands it. ---
    let mut mc = Multicore::new(&mut pac.PSM, &mut pac.PPB, &mut sio.fifo);
    let cores = mc.cores();
    let Some(stack) = CORE1_STACK.take() else {
        panic!()
    };
    if cores[1].spawn(stack, core1).is_err() {
        panic!("core 1 did not start");
    }

    // --- Core 0: binning, the even bands, the link. ---
    let mut a = [Rgb565::new(0, 0, 0); BAND];
    let mut b = [Rgb565::new(0, 0, 0); BAND];
    let mut depth = [0u16; BAND];
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
    let Ok(even) = BandShare::new(0, 2) else {
        panic!()
    };
    let mut link = Link {
        dma: Some((dma.ch0, spi16)),
        running: None,
        unwaited: 0,
        dc,
        fifo: &mut sio.fifo,
    };

    let mut frame_no = 0;
    loop {
        let model = demo::cube_model(frame_no);
        let Ok(frame) = BinnedFrame::new(&draws, &mut bins, |sink| {
            mesh_triangles(&mesh, &model, &camera, Some(&light), |t| {
                draw.project(t, &mut |s| sink.push(0, s))
            })
        }) else {
            panic!("the cube's triangles fit the bins")
        };
        // SAFETY (read by core 1): `frame`, the draws and the bins it borrows stay alive and
        // unchanged until core 1 reports DONE below.
        link.fifo
            .write_blocking(&frame as *const BinnedFrame<'_, '_, Rgb565> as u32);
        link.memory_write();
        if bands
            .render_share_to(&frame, Rgb565::new(0, 0, 0), even, &mut link)
            .is_err()
        {
            panic!("the bands are set up for two cores");
        }
        // 30 bands: the last one is core 1's.
        link.send_core1_band();
        while link.fifo.read_blocking() != DONE {}
        frame_no = frame_no.wrapping_add(1);
    }
}

/// Core 1: waits for a frame, draws its odd bands into its own two buffers, hands each to
/// core 0 through the FIFO and draws on while it is sent.
fn core1() {
    // SAFETY: core 1 uses only its own side of the SIO (its FIFO ends), as rp2040-hal's
    // multicore examples do.
    let pac = unsafe { pac::Peripherals::steal() };
    let mut fifo = Sio::new(pac.SIO).fifo;
    let mut a = [Rgb565::new(0, 0, 0); BAND];
    let mut b = [Rgb565::new(0, 0, 0); BAND];
    let mut depth = [0u16; BAND];
    let mut buffers = [&mut a[..], &mut b[..]];
    let Ok(bands) = BandRenderer::with_buffers(&mut buffers, W, ROWS, H) else {
        panic!()
    };
    let Ok(mut bands) = bands.with_depth(&mut depth) else {
        panic!()
    };
    let Ok(odd) = BandShare::new(1, 2) else {
        panic!()
    };
    loop {
        let at = fifo.read_blocking() as *const BinnedFrame<'static, 'static, Rgb565>;
        // SAFETY: core 0 sent the address of a live frame and keeps it, unchanged, until
        // this core writes DONE; the frame is only read (`BinnedFrame` is shared bins and
        // draws, no interior mutability).
        let frame = unsafe { &*at };
        let mut to_core0 = ToCore0(&mut fifo);
        if bands
            .render_share_to(frame, Rgb565::new(0, 0, 0), odd, &mut to_core0)
            .is_err()
        {
            panic!("the bands are set up for two cores");
        }
        fifo.write_blocking(DONE);
    }
}

/// Core 1's sender: each finished band goes to core 0 through the FIFO (address, then
/// length in pixels); `wait` returns when core 0 answers that the oldest one is sent.
struct ToCore0<'f>(&'f mut SioFifo);

impl BandSender<Rgb565> for ToCore0<'_> {
    type Error = Infallible;

    fn start(&mut self, band: &Frame<'_, Rgb565>) -> Result<(), Infallible> {
        self.0.write_blocking(band.pixels().as_ptr() as u32);
        self.0.write_blocking(band.pixels().len() as u32);
        Ok(())
    }

    fn wait(&mut self) -> Result<(), Infallible> {
        while self.0.read_blocking() != SENT {}
        Ok(())
    }
}

/// The display link, driven by core 0: one DMA channel into SPI0 (16-bit words), core 1's
/// bands interleaved with core 0's in band order.
struct Link<'f> {
    /// The channel and the bus while no transfer runs.
    dma: Option<(Channel<CH0>, Spi16)>,
    running: Option<single_buffer::Transfer<Channel<CH0>, &'static [u16], Spi16>>,
    /// Core 0's bands started and not yet waited for.
    unwaited: u32,
    dc: DcPin,
    fifo: &'f mut SioFifo,
}

impl Link<'_> {
    /// Waits for the running transfer, if any (the channel and the bus are back).
    fn finish(&mut self) {
        if let Some(t) = self.running.take() {
            let (ch, _, spi) = t.wait();
            self.dma = Some((ch, spi));
        }
    }

    /// Starts a transfer of `len` pixels at `at` (after the running one).
    ///
    /// SAFETY: the pixels stay in place, unwritten, until [`finish`](Self::finish) returned
    /// for this transfer (fixel's `BandSender` contract for core 0's bands; core 1 draws
    /// into a band's buffer again only after `SENT`).
    unsafe fn start_raw(&mut self, at: *const u16, len: usize) {
        self.finish();
        let Some((ch, spi)) = self.dma.take() else {
            return;
        };
        let words: &'static [u16] = unsafe { core::slice::from_raw_parts(at, len) };
        self.running = Some(single_buffer::Config::new(ch, words, spi).start());
    }

    /// Receives core 1's next band and sends it; answers SENT once it is on the wire.
    fn send_core1_band(&mut self) {
        let at = self.fifo.read_blocking();
        let len = self.fifo.read_blocking();
        // SAFETY: core 1 draws into this buffer again only after SENT, written below once
        // the transfer is over.
        unsafe { self.start_raw(at as *const u16, len as usize) };
        self.finish();
        self.fifo.write_blocking(SENT);
    }

    /// Starts the frame's pixel stream: RAMWR (the window is the whole panel), as one 16-bit
    /// word after a NOP byte; then data.
    fn memory_write(&mut self) {
        self.finish();
        if let Some((_, spi)) = self.dma.as_mut() {
            // The last frame's final words may still be shifting out of the FIFO.
            let _ = spi.flush();
            let _ = self.dc.set_low();
            let _ = spi.write(&[0x002C]);
            let _ = spi.flush();
            let _ = self.dc.set_high();
        }
    }
}

impl BandSender<Rgb565> for Link<'_> {
    type Error = Infallible;

    fn start(&mut self, band: &Frame<'_, Rgb565>) -> Result<(), Infallible> {
        // Core 0 draws the even bands: the odd one before this goes first.
        if band.first_row() > 0 {
            self.send_core1_band();
        }
        let px = band.pixels();
        // SAFETY: fixel neither writes this band's buffer nor returns from the frame before
        // `wait` returned for it, and `wait` finishes the transfer.
        unsafe { self.start_raw(px.as_ptr().cast::<u16>(), px.len()) };
        self.unwaited += 1;
        Ok(())
    }

    fn wait(&mut self) -> Result<(), Infallible> {
        // Transfers run one at a time: only the newest band may still be on the wire.
        self.unwaited = self.unwaited.saturating_sub(1);
        if self.unwaited == 0 {
            self.finish();
        }
        Ok(())
    }
}

/// The ST7789's set-up for a 320 x 240 landscape RGB565 frame (8-bit commands).
fn st7789_init<S: SpiBus<u8>, P: OutputPin>(
    spi: &mut S,
    dc: &mut P,
    delay: &mut cortex_m::delay::Delay,
) {
    let mut cmd = |c: u8, args: &[u8]| {
        let _ = dc.set_low();
        let _ = spi.write(&[c]);
        let _ = spi.flush();
        let _ = dc.set_high();
        let _ = spi.write(args);
        let _ = spi.flush();
    };
    cmd(0x01, &[]); // SWRESET
    delay.delay_ms(150);
    cmd(0x11, &[]); // SLPOUT
    delay.delay_ms(120);
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
