//! Error metrics of a candidate RGB565 frame against the reference.
//!
//! Errors are per-channel absolute differences in RGB565 LSBs (r and b in
//! 1/31 steps, g in 1/63 steps) between the candidate and the reference
//! quantised to RGB565 (round to nearest), over the pixels covered by BOTH.
//! Pixels covered by only one side are counted separately and excluded.
//!
//! PSNR is over the 8-bit expansion of both RGB565 values (bit replication,
//! as stored in PNGs): `MSE = Σ (a8 - b8)² / (3 N)` over the three channels
//! of the N pixels covered by both, `PSNR = 10 log10(255² / MSE)` dB,
//! infinite when the frames agree exactly (or N = 0).

use crate::png_io::rgb565_to_rgb8;
use crate::reference::RefImage;
use std::fmt;

/// Summary of the difference between a candidate frame and the reference.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// Pixels covered by both candidate and reference.
    pub both_covered: usize,
    /// Pixels covered by the candidate only.
    pub only_candidate: usize,
    /// Pixels covered by the reference only.
    pub only_reference: usize,
    /// Largest error per channel `[r, g, b]`, in LSBs.
    pub max_per_channel: [u32; 3],
    /// Largest error over all channels, in LSBs.
    pub max: u32,
    /// Mean per-channel error (over 3 N channel values), in LSBs.
    pub mean: f64,
    /// 99th percentile (nearest rank) of the per-pixel max-channel error.
    pub p99: u32,
    /// PSNR in dB over 8-bit-expanded values (see module docs).
    pub psnr_db: f64,
    /// Share of both-covered pixels whose max-channel error exceeds 1 LSB.
    pub share_over_1: f64,
    /// Share of both-covered pixels whose max-channel error exceeds 2 LSB.
    pub share_over_2: f64,
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [r, g, b] = self.max_per_channel;
        write!(
            f,
            "covered both={} only-candidate={} only-reference={} | max={} (r{r} g{g} b{b}) \
             mean={:.4} p99={} psnr={:.2}dB >1lsb={:.3}% >2lsb={:.3}%",
            self.both_covered,
            self.only_candidate,
            self.only_reference,
            self.max,
            self.mean,
            self.p99,
            self.psnr_db,
            100.0 * self.share_over_1,
            100.0 * self.share_over_2,
        )
    }
}

/// Per-channel absolute difference in LSBs of two RGB565 values.
pub fn channel_errors(a: u16, b: u16) -> [u32; 3] {
    let ch = |p: u16| [(p >> 11) & 31, (p >> 5) & 63, p & 31];
    let (x, y) = (ch(a), ch(b));
    core::array::from_fn(|c| u32::from(x[c].abs_diff(y[c])))
}

/// Compares two RGB565 frames with coverage masks (all four slices have one
/// entry per pixel).
pub fn compare_rgb565(cand: &[u16], cand_cov: &[bool], refr: &[u16], ref_cov: &[bool]) -> Report {
    assert!(
        cand.len() == refr.len() && cand_cov.len() == cand.len() && ref_cov.len() == cand.len(),
        "frame sizes differ"
    );
    let mut r = Report {
        both_covered: 0,
        only_candidate: 0,
        only_reference: 0,
        max_per_channel: [0; 3],
        max: 0,
        mean: 0.0,
        p99: 0,
        psnr_db: f64::INFINITY,
        share_over_1: 0.0,
        share_over_2: 0.0,
    };
    let (mut sum, mut sq) = (0u64, 0u64);
    let mut pixel_max = Vec::new();
    for k in 0..cand.len() {
        match (cand_cov[k], ref_cov[k]) {
            (true, false) => r.only_candidate += 1,
            (false, true) => r.only_reference += 1,
            (false, false) => {}
            (true, true) => {
                let e = channel_errors(cand[k], refr[k]);
                for (m, &ec) in r.max_per_channel.iter_mut().zip(&e) {
                    *m = (*m).max(ec);
                    sum += u64::from(ec);
                }
                let (a8, b8) = (rgb565_to_rgb8(cand[k]), rgb565_to_rgb8(refr[k]));
                for c in 0..3 {
                    let d = u64::from(a8[c].abs_diff(b8[c]));
                    sq += d * d;
                }
                pixel_max.push(e[0].max(e[1]).max(e[2]));
            }
        }
    }
    let n = pixel_max.len();
    r.both_covered = n;
    r.max = r.max_per_channel.into_iter().max().unwrap_or(0);
    if n > 0 {
        r.mean = sum as f64 / (3 * n) as f64;
        let mse = sq as f64 / (3 * n) as f64;
        if mse > 0.0 {
            r.psnr_db = 10.0 * (255.0 * 255.0 / mse).log10();
        }
        r.share_over_1 = pixel_max.iter().filter(|&&e| e > 1).count() as f64 / n as f64;
        r.share_over_2 = pixel_max.iter().filter(|&&e| e > 2).count() as f64 / n as f64;
        pixel_max.sort_unstable();
        let rank = (0.99 * n as f64).ceil() as usize;
        r.p99 = pixel_max[rank.clamp(1, n) - 1];
    }
    r
}

/// Compares a candidate RGB565 frame and its coverage with the reference
/// image quantised to RGB565.
pub fn compare(candidate: &[u16], candidate_covered: &[bool], reference: &RefImage) -> Report {
    compare_rgb565(
        candidate,
        candidate_covered,
        &reference.quantize_rgb565(),
        &reference.covered,
    )
}

/// Colour of one pixel in an error image: max-channel error 0 black,
/// 1 dark blue, 2 green, 3 or more red.
pub fn error_colour(max_lsb: u32) -> [u8; 3] {
    match max_lsb {
        0 => [0, 0, 0],
        1 => [0, 0, 160],
        2 => [0, 200, 0],
        _ => [255, 0, 0],
    }
}

/// Colour of a pixel covered by only one side.
pub const COVERAGE_COLOUR: [u8; 3] = [255, 0, 255];

/// Amplified RGB8 error image of two RGB565 frames with coverage masks:
/// [`error_colour`] where both cover, magenta where only one does, black
/// where neither does.
pub fn error_image_rgb565(a: &[u16], a_cov: &[bool], b: &[u16], b_cov: &[bool]) -> Vec<u8> {
    (0..a.len())
        .flat_map(|k| match (a_cov[k], b_cov[k]) {
            (true, true) => {
                let e = channel_errors(a[k], b[k]);
                error_colour(e[0].max(e[1]).max(e[2]))
            }
            (false, false) => [0, 0, 0],
            _ => COVERAGE_COLOUR,
        })
        .collect()
}

/// Amplified RGB8 error image of a candidate against the reference (same
/// size; write it with [`crate::png_io::write_png_rgb8`]).
pub fn error_image(candidate: &[u16], candidate_covered: &[bool], reference: &RefImage) -> Vec<u8> {
    error_image_rgb565(
        candidate,
        candidate_covered,
        &reference.quantize_rgb565(),
        &reference.covered,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identical_frames_have_no_error() {
        let px = [0x1234, 0xffff, 0];
        let cov = [true, true, false];
        let r = compare_rgb565(&px, &cov, &px, &cov);
        assert_eq!((r.both_covered, r.max, r.p99), (2, 0, 0));
        assert!(r.psnr_db.is_infinite());
    }

    #[test]
    fn errors_and_coverage_are_counted() {
        // Pixel 0: g off by 2; pixel 1: r off by 3; pixel 2: candidate only.
        let a = [2 << 5, 3 << 11, 0, 0];
        let b = [0, 0, 0, 0];
        let r = compare_rgb565(
            &a,
            &[true, true, true, false],
            &b,
            &[true, true, false, true],
        );
        assert_eq!((r.only_candidate, r.only_reference), (1, 1));
        assert_eq!(r.max_per_channel, [3, 2, 0]);
        assert_eq!(r.p99, 3);
        assert!((r.mean - 5.0 / 6.0).abs() < 1e-12);
        assert_eq!((r.share_over_1, r.share_over_2), (1.0, 0.5));
        // 8-bit: g 2<<2|0 = 8, r 3<<3|0 = 24: MSE = (64 + 576) / 6.
        let psnr = 10.0 * (255.0f64 * 255.0 / (640.0 / 6.0)).log10();
        assert!((r.psnr_db - psnr).abs() < 1e-9);
        let img = error_image_rgb565(
            &a,
            &[true, true, true, false],
            &b,
            &[true, true, false, true],
        );
        assert_eq!(&img[..6], &[0, 200, 0, 255, 0, 0]);
        assert_eq!(&img[6..], &[255, 0, 255, 255, 0, 255]);
        println!("{r}");
    }
}
