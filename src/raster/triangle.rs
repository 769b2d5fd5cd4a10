//! Triangle to spans: sorts the vertices by y, walks the long edge against the two short
//! ones with [`EdgeWalker`], and hands each non-empty row span, cropped to a clip
//! rectangle, to a [`SpanSink`].
//!
//! Rows covered are those whose centre `yc` satisfies `y_top <= yc < y_bottom` (flat top
//! edges in, flat bottom edges out); within a row the span is `[left, right)` from the two
//! edge walkers (left edges in, right edges out). Zero-area and collinear triangles emit
//! nothing. Cost: one `i64` division per edge at set-up (twice for the long edge when the
//! triangle starts above the clip rectangle), then two adds and a compare per edge per row.

use super::{EdgeWalker, SUBPIXEL_ONE};
use crate::geometry::Rect;

/// Receives the spans of covered pixels, one row at a time, top to bottom.
pub trait SpanSink {
    /// Pixels `x0..x1` (non-empty, inside the clip rectangle) of row `y` are covered.
    fn span(&mut self, y: i32, x0: i32, x1: i32);

    /// [`span`](Self::span), returning what the sink counts for the span (say, the pixels
    /// it wrote); [`rasterize`] returns the sum. By default the span is counted as 0. A
    /// count returned here is summed in a register by the row loop, where a sink's own
    /// running count is a load and a store per span.
    #[inline(always)]
    fn span_counted(&mut self, y: i32, x0: i32, x1: i32) -> u32 {
        self.span(y, x0, x1);
        0
    }
}

/// Whether the row loop sums the sink's counts ([`SpanSink::span_counted`]) or calls
/// [`SpanSink::span`], leaving a sink to count for itself: on Cortex-M4F the sum in a
/// register spares the span writer a load and a store per span (about 0.5 % of the
/// whole-frame sphere); on Cortex-M0+ (eight low registers), RV32IMC and x86-64 the one
/// more value in the row loop costs more than it saves (up to about 1.5 %; measure with
/// `cargo xtask mcu` and `cargo xtask count`). A sink that counts implements both:
/// [`rasterize`] returns 0 where the loop does not sum.
pub const COUNT_IN_LOOP: bool = cfg!(all(target_arch = "arm", target_has_atomic = "32"));

/// First pixel row whose centre is at or below `y` (sub-pixel units): `ceil((y - 8) / 16)`.
#[inline]
pub fn first_row_at_or_below(y: i32) -> i32 {
    (y - SUBPIXEL_ONE / 2 + SUBPIXEL_ONE - 1) >> super::SUBPIXEL_BITS
}

/// Rasterizes the triangle `v` (sub-pixel screen coordinates inside the guard band, any
/// winding) into spans cropped to `clip`, and returns the sum of the sink's counts
/// ([`SpanSink::span_counted`]) where the row loop sums them ([`COUNT_IN_LOOP`]), else 0.
/// Zero-area triangles emit nothing.
pub fn rasterize<S: SpanSink + ?Sized>(v: [(i32, i32); 3], clip: Rect, sink: &mut S) -> u32 {
    rasterize_rows(v, clip, sink, false)
}

/// [`rasterize`], out of line: the run-time draw's (`Draw::dynamic`) one copy for all its
/// span writers behind `dyn SpanSink`. Inlined into each of its draw types' raster
/// functions, as the typed draws' rasterizer is, its firmware grows by about 9 KB.
#[inline(never)]
pub(crate) fn rasterize_shared<S: SpanSink + ?Sized>(
    v: [(i32, i32); 3],
    clip: Rect,
    sink: &mut S,
) -> u32 {
    rasterize(v, clip, sink)
}

/// [`rasterize`], with `unclamped_rows`: a triangle within the columns of `clip`
/// ([`within_columns`]) then takes row loops that do not clamp its spans to them (the same
/// spans). A constant where it is inlined: the draws of meshes of small triangles pass
/// `true` and link two more copies of the row loop (about 0.3 KB on Cortex-M4F; the minimal
/// firmwares, which pass `false`, do not). That saves about 0.3 % of the whole-frame
/// sphere on Cortex-M4F and RV32IMC (measure with `cargo xtask mcu`); not on ARMv6-M (see
/// the caller).
#[inline(always)]
pub(crate) fn rasterize_rows<S: SpanSink + ?Sized>(
    v: [(i32, i32); 3],
    clip: Rect,
    sink: &mut S,
    unclamped_rows: bool,
) -> u32 {
    let mut p = v;
    // Sort by y (a stable 3-element network).
    if p[1].1 < p[0].1 {
        p.swap(0, 1);
    }
    if p[2].1 < p[1].1 {
        p.swap(1, 2);
    }
    if p[1].1 < p[0].1 {
        p.swap(0, 1);
    }
    let [top, mid, bot] = p;
    // Side of the middle vertex relative to the long edge; zero means collinear.
    let d = |a: i32, b: i32| i64::from(a) - i64::from(b);
    let cross = crate::math::wide::det2(
        d(mid.0, top.0),
        d(mid.1, top.1),
        d(bot.0, top.0),
        d(bot.1, top.1),
    );
    if cross == 0 {
        return 0;
    }
    let mid_right = cross > 0;

    let row_top = first_row_at_or_below(top.1).max(clip.y0);
    let row_mid = first_row_at_or_below(mid.1).clamp(row_top, clip.y1.max(row_top));
    let row_bot = first_row_at_or_below(bot.1).min(clip.y1);
    if row_top >= row_bot {
        return 0;
    }
    let mut count = 0u32;
    let mut long = EdgeWalker::new(top, bot, row_top);
    // Upper half: rows with centre in [top.y, mid.y); lower half: [mid.y, bot.y). One
    // loop over the two, so the row loop and the short edge's set-up are one copy each.
    let start = row_mid.max(row_top);
    let halves = [
        (top, mid, row_top, row_mid.min(row_bot)),
        (mid, bot, start, row_bot),
    ];
    let inside = unclamped_rows && within_columns([top.0, mid.0, bot.0], clip);
    for (a, b, y0, y1) in halves {
        if y0 < y1 {
            let mut short = EdgeWalker::new(a, b, y0);
            let (long, short) = (&mut long, &mut short);
            count = count.wrapping_add(match (inside, mid_right) {
                (true, true) => walk::<S, false, true>(long, short, y0, y1, clip, sink),
                (true, false) => walk::<S, false, false>(long, short, y0, y1, clip, sink),
                (false, true) => walk::<S, true, true>(long, short, y0, y1, clip, sink),
                (false, false) => walk::<S, true, false>(long, short, y0, y1, clip, sink),
            });
        }
    }
    count
}

/// Whether every span of a triangle whose corners have the sub-pixel columns `x` lies
/// within the columns of `clip`: its edges' crossings of the rows it covers lie between
/// its corners' columns, and a corner at or right of `16 clip.x0` (at or left of `16
/// clip.x1`) puts a span's first pixel (its end) at or right of `clip.x0` (at or left of
/// `clip.x1`), pixel centres being half a pixel in. Then the row loop need not clamp its
/// spans (two compares and two moves per row).
#[inline(always)]
fn within_columns(x: [i32; 3], clip: Rect) -> bool {
    let (lo, hi) = (x[0].min(x[1]).min(x[2]), x[0].max(x[1]).max(x[2]));
    match (
        clip.x0.checked_mul(SUBPIXEL_ONE),
        clip.x1.checked_mul(SUBPIXEL_ONE),
    ) {
        (Some(x0), Some(x1)) => lo >= x0 && hi <= x1,
        _ => false,
    }
}

#[inline(always)]
fn walk<S: SpanSink + ?Sized, const CLIP: bool, const SHORT_IS_RIGHT: bool>(
    long: &mut EdgeWalker,
    short: &mut EdgeWalker,
    y0: i32,
    y1: i32,
    clip: Rect,
    sink: &mut S,
) -> u32 {
    let mut count = 0u32;
    for y in y0..y1 {
        let (l, r) = if SHORT_IS_RIGHT {
            (long.x(), short.x())
        } else {
            (short.x(), long.x())
        };
        let (l, r) = if CLIP {
            (l.max(clip.x0), r.min(clip.x1))
        } else {
            (l, r)
        };
        if l < r {
            if COUNT_IN_LOOP {
                count = count.wrapping_add(sink.span_counted(y, l, r));
            } else {
                sink.span(y, l, r);
            }
        }
        long.step();
        short.step();
    }
    count
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec;

    /// Counts writes per pixel into a small grid and fails on out-of-bounds spans.
    struct Grid {
        w: i32,
        h: i32,
        hits: Vec<u8>,
    }
    impl Grid {
        fn new(w: i32, h: i32) -> Self {
            Grid {
                w,
                h,
                hits: std::vec![0; (w * h) as usize],
            }
        }
        fn ascii(&self) -> std::string::String {
            let mut s = std::string::String::new();
            for y in 0..self.h {
                for x in 0..self.w {
                    let c = self.hits[(y * self.w + x) as usize];
                    s.push(match c {
                        0 => '.',
                        1 => '#',
                        _ => '2',
                    });
                }
                s.push('\n');
            }
            s
        }
    }
    impl SpanSink for Grid {
        fn span(&mut self, y: i32, x0: i32, x1: i32) {
            assert!(
                x0 < x1 && x0 >= 0 && x1 <= self.w && y >= 0 && y < self.h,
                "bad span"
            );
            for x in x0..x1 {
                self.hits[(y * self.w + x) as usize] += 1;
            }
        }
    }

    fn px(x: i32, y: i32) -> (i32, i32) {
        (x * 16, y * 16)
    }

    /// The row loop sums what `span_counted` returns where it calls it, and a sink that
    /// counts in `span` sees the same spans.
    #[test]
    fn rasterize_sums_the_sinks_counts() {
        struct Counting(u32);
        impl SpanSink for Counting {
            fn span(&mut self, _: i32, x0: i32, x1: i32) {
                self.0 += (x1 - x0) as u32;
            }
            fn span_counted(&mut self, _: i32, x0: i32, x1: i32) -> u32 {
                (x1 - x0) as u32
            }
        }
        let mut g = Grid::new(40, 40);
        let tri = [(5, 7), (600, 90), (130, 620)];
        rasterize(tri, Rect::of_size(40, 40), &mut g);
        let covered = g.hits.iter().map(|&c| u32::from(c)).sum::<u32>();
        let mut c = Counting(0);
        let summed = rasterize(tri, Rect::of_size(40, 40), &mut c);
        assert!(covered > 100);
        assert_eq!(summed + c.0, covered);
        assert_eq!(summed, if COUNT_IN_LOOP { covered } else { 0 });
        // A sink without its own count: the loop sums zeros.
        assert_eq!(rasterize(tri, Rect::of_size(40, 40), &mut g), 0);
    }

    #[test]
    fn square_of_two_triangles_covers_each_pixel_once() {
        let mut g = Grid::new(6, 4);
        let clip = Rect::of_size(6, 4);
        rasterize([px(1, 0), px(5, 0), px(5, 3)], clip, &mut g);
        rasterize([px(1, 0), px(5, 3), px(1, 3)], clip, &mut g);
        assert_eq!(g.ascii(), ".####.\n.####.\n.####.\n......\n");
    }

    #[test]
    fn fill_rule_ties_on_pixel_centres() {
        // Vertices exactly on pixel centres: left/top edges through centres are in,
        // right/bottom ones out.
        let c = |x: i32, y: i32| (x * 16 + 8, y * 16 + 8);
        let mut g = Grid::new(5, 5);
        rasterize([c(0, 0), c(4, 0), c(0, 4)], Rect::of_size(5, 5), &mut g);
        assert_eq!(g.ascii(), "####.\n###..\n##...\n#....\n.....\n");
    }

    #[test]
    fn fan_around_a_vertex_is_watertight() {
        let (w, h) = (40, 40);
        let mut g = Grid::new(w, h);
        let centre = (20 * 16 + 5, 19 * 16 + 11);
        let ring: Vec<(i32, i32)> = [
            (0, 0),
            (13, 0),
            (40, 0),
            (40, 17),
            (40, 40),
            (22, 40),
            (0, 40),
            (0, 9),
        ]
        .iter()
        .map(|&(x, y)| (x * 16, y * 16))
        .collect();
        for i in 0..ring.len() {
            rasterize(
                [centre, ring[i], ring[(i + 1) % ring.len()]],
                Rect::of_size(40, 40),
                &mut g,
            );
        }
        assert!(g.hits.iter().all(|&c| c == 1), "\n{}", g.ascii());
    }

    #[test]
    fn degenerate_triangles_emit_nothing() {
        let mut g = Grid::new(8, 8);
        let clip = Rect::of_size(8, 8);
        rasterize([px(1, 1), px(5, 5), px(3, 3)], clip, &mut g); // collinear
        rasterize([px(2, 2), px(2, 2), px(2, 2)], clip, &mut g); // a point
        rasterize([px(1, 1), px(7, 1), px(4, 1)], clip, &mut g); // flat
        assert!(g.hits.iter().all(|&c| c == 0));
    }

    /// The unclamped row loops emit the spans the clamped ones do: random triangles near
    /// and across the clip's columns (corners on, just inside and just outside them).
    #[test]
    fn unclamped_rows_emit_the_clamped_spans() {
        struct Spans(Vec<(i32, i32, i32)>);
        impl SpanSink for Spans {
            fn span(&mut self, y: i32, x0: i32, x1: i32) {
                self.0.push((y, x0, x1));
            }
        }
        let mut rng = crate::test_rng::Rng(0xC0_1A_B5);
        let clip = Rect {
            x0: 5,
            y0: 0,
            x1: 29,
            y1: 40,
        };
        let mut inside = 0;
        for _ in 0..20_000 {
            let mut corner = || {
                let r = rng.next();
                let x = match r % 4 {
                    0 => clip.x0 * 16 + (r >> 8) as i32 % 3 - 1,
                    1 => clip.x1 * 16 + (r >> 8) as i32 % 3 - 1,
                    _ => (r >> 8) as i32 % (40 * 16),
                };
                (x, (r >> 32) as i32 % (40 * 16))
            };
            let tri = [corner(), corner(), corner()];
            inside += usize::from(within_columns([tri[0].0, tri[1].0, tri[2].0], clip));
            let (mut a, mut b) = (Spans(Vec::new()), Spans(Vec::new()));
            rasterize_rows(tri, clip, &mut a, false);
            rasterize_rows(tri, clip, &mut b, true);
            assert_eq!(a.0, b.0, "{tri:?}");
        }
        assert!(inside > 1_000, "{inside}");
    }

    #[test]
    fn clipping_to_rows_and_columns_equals_cropping() {
        let tri = [(-300, -50), (900, 200), (100, 1000)];
        let mut whole = Grid::new(40, 40);
        rasterize(tri, Rect::of_size(40, 40), &mut whole);
        let mut parts = Grid::new(40, 40);
        for band in 0..5 {
            rasterize(
                tri,
                Rect::of_size(40, 40).rows(band * 8, band * 8 + 8),
                &mut parts,
            );
        }
        assert_eq!(whole.hits, parts.hits);
        assert!(whole.hits.contains(&1));
    }
}
