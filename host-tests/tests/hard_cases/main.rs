//! Hard-case stability suite: slivers, needles, fill-rule ties, fans and
//! strips, the near plane and w near zero, enormous and limit coordinates, extreme texture
//! coordinates and sizes, depth extremes and precision, degenerate input.
//!
//! Every case draws into a [`common::Guarded`] target (sentinel guard rows and columns around
//! the visible buffers; rows requested outside the frame are errors), so "no panic, no write
//! out of bounds" is checked everywhere. Where the f64 reference applies, the error is
//! measured with `metrics::compare` and held to a documented bound; where coverage must be
//! watertight, writes are counted per pixel.
//!
//! One test binary: a module per topic, the helpers they share in `helpers` (and the guarded
//! target in `tests/common`).

#[path = "../common/mod.rs"]
mod common;
mod helpers;

mod clipping;
mod coverage;
mod depth;
mod limits_and_degenerate;
mod textures;
