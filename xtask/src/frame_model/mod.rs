//! The frame-time model: a frame's measured work (cycles of the binning pass and of each
//! band) and a display link turned into the time from the start of the frame to the last
//! byte of its last band on the wire, three ways:
//!
//! * **serial**, one core: draw a band, send it (blocking), draw the next;
//! * **overlapped**, one core: band `k` is sent by DMA while band `k + 1` is drawn into the
//!   second of two band buffers; a band waits for its buffer only while that buffer's
//!   previous band is still on the wire;
//! * **two cores**, overlapped: the binning pass split between the cores (each bins half
//!   of the triangles), then the bands interleaved (core 0 the even ones, core 1 the odd
//!   ones), each core with two band buffers, the bands sent in order on the one link.
//!
//! One frame on its own: the next frame's binning pass does not overlap the last band's
//! transfer (which it could: a conservative figure). Everything else (wait states, bus
//! contention, the cycles per instruction) is in the cycle figures given to it.
//!
//! `cargo xtask fps` (the benchmark scenes' measured work) and `cargo xtask budget` (a
//! model's predicted work) share it, and the parts of [`chips`].

pub mod chips;

/// A display link: an SPI bus (or any serial link) to the display controller.
#[derive(Clone, Copy, Debug)]
pub struct Link {
    /// Bit clock, Hz.
    pub clock_hz: f64,
    /// Bytes per pixel on the wire (2 for RGB565).
    pub bytes_per_px: f64,
    /// Command bytes per band (a window command: CASET + RASET + RAMWR, 11 bytes).
    pub command_bytes: f64,
    /// Fixed time per band besides the bytes: chip select, data/command pin, starting the
    /// DMA, in seconds.
    pub band_overhead_s: f64,
}

impl Link {
    /// Seconds to send a band of `pixels` pixels.
    pub fn band_time(&self, pixels: u64) -> f64 {
        (pixels as f64 * self.bytes_per_px + self.command_bytes) * 8.0 / self.clock_hz
            + self.band_overhead_s
    }
}

/// A part: its clock, cores and display link, and which measured instruction set stands for
/// its cores.
#[derive(Clone, Copy, Debug)]
pub struct Chip {
    /// Its name (`RP2040`).
    pub name: &'static str,
    /// The MCU label whose counts stand for its core (`Cortex-M0+`).
    pub counts_from: &'static str,
    /// Its core (`2 x Cortex-M0+`), for the table.
    pub core: &'static str,
    /// Core clock, Hz.
    pub cpu_hz: f64,
    /// Cores that draw bands (1 or 2).
    pub cores: u32,
    /// Its display link.
    pub link: Link,
}

/// A frame's work: cycles of the binning pass (on one core, before any band) and of each
/// band, top to bottom, with each band's pixels.
#[derive(Clone, Debug)]
pub struct Work {
    /// Cycles up to the end of the binning pass.
    pub geometry: f64,
    /// Cycles of each band (clear, set-ups, spans, re-projection).
    pub bands: Vec<f64>,
    /// Pixels of each band (width x rows).
    pub band_pixels: Vec<u64>,
}

/// What the model gives for one chip and one frame.
#[derive(Clone, Copy, Debug)]
pub struct FrameTimes {
    /// Seconds of drawing alone (one core).
    pub render: f64,
    /// Seconds of the link alone (every band's bytes and overheads).
    pub link: f64,
    /// Seconds, one core, draw then send each band.
    pub serial: f64,
    /// Seconds, one core, two band buffers, each band sent while the next is drawn.
    pub overlapped: f64,
    /// Seconds, two cores with two band buffers each (`None` on a one-core part).
    pub two_cores: Option<f64>,
    /// The busier core's share of the band cycles with two cores, 0.5 to 1.
    pub balance: Option<f64>,
    /// Share of the link time the best way hides behind drawing, 0 to 1: one less the time
    /// it adds to the same cores' frame over an infinitely fast link, over the link time.
    pub hidden: f64,
}

impl FrameTimes {
    /// The best of the ways the chip has.
    pub fn best(&self) -> f64 {
        self.two_cores
            .unwrap_or(self.overlapped)
            .min(self.overlapped)
    }
}

/// Frame time of the bands drawn by `cores` cores, band `k` by core `k mod cores`, each
/// core with `buffers` band buffers, starting at `start` seconds; bands sent in order, one
/// at a time, as soon as drawn. `serial`: the core waits for each band's transfer before
/// drawing on (blocking send).
fn pipeline(
    start: f64,
    draw: &[f64],
    send: &[f64],
    cores: usize,
    buffers: usize,
    serial: bool,
) -> f64 {
    let cores = cores.max(1);
    let mut core_free = vec![start; cores];
    // When each band's transfer ends.
    let mut sent = vec![0.0f64; draw.len()];
    let mut link_free = start;
    for k in 0..draw.len() {
        let c = k % cores;
        // The core's buffer for band k held band k - cores * buffers before.
        let reuse = k.checked_sub(cores * buffers).map_or(start, |j| sent[j]);
        let begin = core_free[c].max(reuse);
        let drawn = begin + draw[k];
        let on_wire = drawn.max(link_free);
        sent[k] = on_wire + send[k];
        link_free = sent[k];
        core_free[c] = if serial { sent[k] } else { drawn };
    }
    link_free.max(core_free.iter().copied().fold(start, f64::max))
}

/// The frame times of `work` (cycles) on `chip`.
pub fn frame_times(chip: &Chip, work: &Work) -> FrameTimes {
    let hz = chip.cpu_hz;
    let geometry = work.geometry / hz;
    let draw: Vec<f64> = work.bands.iter().map(|c| c / hz).collect();
    let send: Vec<f64> = work
        .band_pixels
        .iter()
        .map(|&p| chip.link.band_time(p))
        .collect();
    let render = geometry + draw.iter().sum::<f64>();
    let link = send.iter().sum();
    let serial = pipeline(geometry, &draw, &send, 1, 1, true);
    let overlapped = pipeline(geometry, &draw, &send, 1, 2, false);
    let instant = vec![0.0; send.len()];
    let (two_cores, balance, hidden) = if chip.cores >= 2 {
        let even: f64 = draw.iter().step_by(2).sum();
        let odd: f64 = draw.iter().skip(1).step_by(2).sum();
        let share = even.max(odd) / (even + odd).max(f64::MIN_POSITIVE);
        let start = geometry / 2.0;
        let two = pipeline(start, &draw, &send, 2, 2, false);
        let exposed = two - pipeline(start, &draw, &instant, 2, 2, false);
        (Some(two), Some(share), exposed)
    } else {
        (None, None, overlapped - render)
    };
    FrameTimes {
        render,
        link,
        serial,
        overlapped,
        two_cores,
        balance,
        hidden: (1.0 - hidden / link.max(f64::MIN_POSITIVE)).clamp(0.0, 1.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chip(cores: u32) -> Chip {
        Chip {
            name: "test",
            counts_from: "Cortex-M0+",
            core: "test",
            cpu_hz: 1.0,
            cores,
            link: Link {
                clock_hz: 8.0,
                bytes_per_px: 1.0,
                command_bytes: 0.0,
                band_overhead_s: 0.0,
            },
        }
    }

    /// Bands of 2 units of drawing and 1 of sending: serial is their sum, overlapped hides
    /// every transfer but the last, two cores draw two bands at a time.
    #[test]
    fn draw_bound_frames() {
        let w = Work {
            geometry: 1.0,
            bands: vec![2.0; 4],
            band_pixels: vec![1; 4],
        };
        let t = frame_times(&chip(2), &w);
        assert_eq!(t.serial, 1.0 + 4.0 * 3.0);
        assert_eq!(t.overlapped, 1.0 + 4.0 * 2.0 + 1.0);
        // Half the binning pass each, then the last two bands wait for the link.
        assert_eq!(t.two_cores, Some(6.5));
        assert_eq!(t.balance, Some(0.5));
        assert!((t.hidden - 0.5).abs() < 1e-12);
        assert!((frame_times(&chip(1), &w).hidden - 0.75).abs() < 1e-12);
    }

    /// A link slower than drawing bounds every way but serial by the link's time.
    #[test]
    fn link_bound_frames() {
        let w = Work {
            geometry: 0.0,
            bands: vec![1.0; 6],
            band_pixels: vec![3; 6],
        };
        let t = frame_times(&chip(2), &w);
        assert_eq!(t.link, 18.0);
        assert_eq!(t.serial, 24.0);
        assert_eq!(t.overlapped, 19.0);
        assert_eq!(t.two_cores, Some(19.0));
        assert_eq!(frame_times(&chip(1), &w).two_cores, None);
    }
}
