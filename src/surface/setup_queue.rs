//! Which raster set-ups a band renderer keeps for the next band: a queue in triangle order.
//!
//! A band pass meets its triangles in the order the geometry pushes them (ascending ids,
//! and a clipped triangle's pieces in order), the same order in every band. The set-ups of
//! the triangles that go on below a band are appended to a ring of
//! [`KeptSetup`] entries while there is room; the next band meets those triangles again in
//! the same order, so the one it needs is always at the head: a hit is one comparison, and
//! a head older than the current triangle (a triangle the band did not draw) is dropped.
//! Entries appended by the current band wait behind the previous band's, so each band
//! reads only what the band above it kept.
//!
//! With `n` entries the first `n` triangles crossing each band boundary (in id order) skip
//! their second set-up; the ring costs 100 bytes per entry and nothing when empty.
//!
//! An entry that also holds the rest of its triangle's raster
//! ([`KeptSetup::resumable`]) need not even be met again: the next band draws it from the
//! queue ([`SetupQueue::resume_before`]) when the geometry pushes a later triangle, or at
//! the end of the band, so in the same order as the walk would, and the band renderer ends
//! the triangle's band range so the geometry skips it.

use crate::pipeline::{KeptSetup, SetupSlot};

/// The ring's state between bands (the entries themselves are lent per band).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct QueueState {
    head: usize,
    len: usize,
}

/// Keys fit 24 bits of id and 8 of piece index.
const MAX_ID: usize = (1 << 24) - 1;

/// A screen triangle's key: `id` times 256 plus its piece index (saturated), or `None`
/// for ids past 2^24 (never kept).
pub(super) fn key(id: usize, piece: u32) -> Option<u32> {
    (id <= MAX_ID).then(|| ((id as u32) << 8) | piece.min(255))
}

/// The ring of kept set-ups, for one band pass.
#[derive(Debug)]
pub(super) struct SetupQueue<'s> {
    slots: &'s mut [KeptSetup],
    state: QueueState,
    /// This band's index modulo 256.
    band: u8,
}

impl<'s> SetupQueue<'s> {
    /// The ring over `slots` in state `state`, for band `band` (modulo 256).
    pub(super) fn new(slots: &'s mut [KeptSetup], state: QueueState, band: u8) -> Self {
        SetupQueue { slots, state, band }
    }

    /// The state to hand to the next band.
    pub(super) fn state(&self) -> QueueState {
        self.state
    }

    /// Index `k` places after the head (`k <= len`), without a division.
    fn at(&self, k: usize) -> usize {
        let i = self.state.head + k;
        if i >= self.slots.len() {
            i - self.slots.len()
        } else {
            i
        }
    }

    fn pop(&mut self) {
        self.state.head = self.at(1);
        self.state.len -= 1;
    }

    /// What to do with the set-up of screen triangle `key` of draw `draw` in this band;
    /// `goes_on` when it has rows below the band (its set-up is worth keeping). Inlined
    /// into the band passes, which ask once per triangle a band draws.
    #[inline(always)]
    pub(super) fn slot(&mut self, key: u32, draw: u8, goes_on: bool) -> SetupSlot<'_> {
        let above = self.band.wrapping_sub(1);
        // Drop what the band above kept for triangles before this one (and anything older).
        let mut hit = false;
        while self.state.len > 0 {
            let h = &self.slots[self.state.head];
            if h.band == self.band {
                break; // kept by this band, for the next one
            }
            if h.band == above && h.key >= key {
                hit = h.key == key && h.draw == draw;
                break;
            }
            self.pop();
        }
        let cap = self.slots.len();
        if hit {
            let from = self.state.head;
            self.pop();
            if !goes_on {
                return Some(&mut self.slots[from]);
            }
            // Moved to the tail for the next band (the same place when the ring is full).
            let to = self.at(self.state.len);
            if to != from {
                self.slots[to] = self.slots[from];
            }
            self.state.len += 1;
            let entry = &mut self.slots[to];
            entry.band = self.band;
            return Some(entry);
        }
        if goes_on && self.state.len < cap {
            let to = self.at(self.state.len);
            self.state.len += 1;
            let entry = &mut self.slots[to];
            // Empty: the raster stage builds the set-up and keeps it here.
            entry.clear();
            (entry.key, entry.draw, entry.band) = (key, draw, self.band);
            return Some(entry);
        }
        None
    }
}

impl SetupQueue<'_> {
    /// Whether [`resume_before`](Self::resume_before) with `key` has anything to do: its
    /// first test of the head, inline, so that the band pass calls it (out of line, with
    /// its closure) only when the head waits to be resumed or dropped.
    #[inline(always)]
    pub(super) fn waits_before(&self, key: Option<u32>) -> bool {
        if self.state.len == 0 {
            return false;
        }
        let Some(h) = self.slots.get(self.state.head) else {
            return false;
        };
        let above = self.band.wrapping_sub(1);
        !(h.band == self.band || key.is_some_and(|k| h.band == above && h.key >= k))
    }

    /// Draws what the band above kept resumable for the screen triangles before `key`
    /// (every one with `None`), in key order, through `draw`; returns the pixels `draw`
    /// counted. An entry whose triangle goes on below row `end` (this band's end,
    /// excluded) moves to the tail for the next band; the others are freed, as is what
    /// the band above kept without the rest of its triangle (that triangle was not drawn in
    /// this band before `key`, so its set-up is not wanted any more).
    ///
    /// Resuming draws a triangle exactly as its screen triangle would in this band: the
    /// entry holds its set-up and the rest of its raster, and a triangle the band above
    /// kept goes on into this band (its rows end below the band above's).
    pub(super) fn resume_before(
        &mut self,
        key: Option<u32>,
        end: i32,
        mut draw: impl FnMut(&mut KeptSetup) -> u32,
    ) -> u32 {
        let above = self.band.wrapping_sub(1);
        let mut pixels = 0u32;
        while self.state.len > 0 {
            let from = self.state.head;
            let h = &self.slots[from];
            if h.band == self.band || key.is_some_and(|k| h.band == above && h.key >= k) {
                break;
            }
            let resume = h.band == above && h.resumable();
            let goes_on = resume && h.rows().1 > end;
            self.pop();
            if !resume {
                continue;
            }
            let entry = if goes_on {
                // Moved to the tail (the same place when the ring is full).
                let to = self.at(self.state.len);
                if to != from {
                    self.slots[to] = self.slots[from];
                }
                self.state.len += 1;
                let entry = &mut self.slots[to];
                entry.band = self.band;
                entry
            } else {
                &mut self.slots[from]
            };
            pixels = pixels.saturating_add(draw(entry));
        }
        pixels
    }
}

/// Empties every entry (a new frame: its triangles are not the last frame's).
pub(super) fn clear(slots: &mut [KeptSetup]) {
    for s in slots {
        s.clear();
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec;

    /// What `slot` answered, without the entry.
    #[derive(Debug, PartialEq, Eq)]
    enum Said {
        Build,
        Take(u32),
        Keep,
    }

    fn ask(q: &mut SetupQueue<'_>, key: u32, goes_on: bool) -> Said {
        match q.slot(key, 0, goes_on) {
            None => Said::Build,
            Some(e) if e.is_empty() => {
                // As the raster stage does: builds the set-up and keeps it.
                e.fill_for_test();
                Said::Keep
            }
            Some(e) => Said::Take(e.key),
        }
    }

    /// Runs bands over triangles given as (key, first band, last band): each band asks
    /// about the triangles that meet it, in key order. Returns, per band, the answers.
    fn run(slots: &mut [KeptSetup], tris: &[(u32, u8, u8)], bands: u8) -> Vec<Vec<Said>> {
        clear(slots);
        let mut state = QueueState::default();
        let mut out = Vec::new();
        for b in 0..bands {
            let mut q = SetupQueue::new(slots, state, b);
            let said = tris
                .iter()
                .filter(|t| t.1 <= b && b <= t.2)
                .map(|t| ask(&mut q, t.0, b < t.2))
                .collect();
            state = q.state();
            out.push(said);
        }
        out
    }

    #[test]
    fn the_band_below_takes_what_the_band_above_kept() {
        use Said::*;
        let mut slots = [KeptSetup::default(); 2];
        // Triangle 1 spans bands 0-2, 2 only band 0, 3 bands 0-1, 4 bands 1-2.
        let tris = [(1, 0, 2), (2, 0, 0), (3, 0, 1), (4, 1, 2)];
        let said = run(&mut slots, &tris, 3);
        assert_eq!(said[0], [Keep, Build, Keep]);
        // 1 is taken and kept again (the ring is full: in place); 3 taken; 4 kept.
        assert_eq!(said[1], [Take(1), Take(3), Keep]);
        assert_eq!(said[2], [Take(1), Take(4)]);
    }

    #[test]
    fn a_full_ring_builds_what_it_cannot_keep() {
        use Said::*;
        let mut slots = [KeptSetup::default(); 1];
        let tris = [(1, 0, 1), (2, 0, 1), (5, 1, 2)];
        let said = run(&mut slots, &tris, 3);
        assert_eq!(said[0], [Keep, Build]);
        assert_eq!(said[1], [Take(1), Build, Keep]);
        assert_eq!(said[2], [Take(5)]);
    }

    #[test]
    fn a_kept_set_up_the_next_band_does_not_ask_for_is_dropped() {
        use Said::*;
        let mut slots = [KeptSetup::default(); 2];
        clear(&mut slots);
        let mut q = SetupQueue::new(&mut slots, QueueState::default(), 0);
        assert_eq!(ask(&mut q, 1, true), Keep);
        let state = q.state();
        let mut q = SetupQueue::new(&mut slots, state, 1);
        // 1 is not asked for: dropped when 2 comes.
        assert_eq!(ask(&mut q, 2, true), Keep);
        assert_eq!(q.state().len, 1);
        let state = q.state();
        let mut q = SetupQueue::new(&mut slots, state, 2);
        assert_eq!(ask(&mut q, 1, false), Build);
        assert_eq!(ask(&mut q, 2, false), Take(2));
        assert_eq!(q.state().len, 0);
    }

    #[test]
    fn an_empty_ring_always_builds() {
        let mut slots: [KeptSetup; 0] = [];
        let said = run(&mut slots, &[(1, 0, 3), (2, 1, 2)], 4);
        assert!(said.iter().flatten().all(|s| *s == Said::Build));
    }

    #[test]
    fn keys_order_ids_then_pieces() {
        assert!(key(3, 255).unwrap() < key(4, 0).unwrap());
        assert_eq!(key(3, 300), key(3, 255));
        assert_eq!(key(MAX_ID + 1, 0), None);
    }
}
