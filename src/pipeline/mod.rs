//! The pipeline: from a validated draw mode to the fused per-pixel loop.
//!
//! [`stages`] names the choices (as enums and as marker types), [`Draw`] binds a mode to
//! its texture and viewport and selects the span loop once, and the private `setup`,
//! `interp` and `span` modules hold the per-triangle set-up and the per-pixel code.

mod draw;
mod interp;
mod raster;
pub mod recip;
mod setup;
mod shaded;
mod span;
pub mod stages;

pub use draw::Draw;
pub use shaded::ShadedDraw;
pub use stages::*;
