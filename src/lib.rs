//! fixel: a `no_std`, heap-free, fixed-point texture-mapped 3D rasterizer for
//! microcontroller displays. (Crate docs are completed as the modules land.)
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs, missing_debug_implementations)]

pub mod color;
pub mod error;
pub mod geometry;
pub mod math;
pub mod pipeline;
pub mod raster;
pub mod target;
pub mod texture;

pub use error::Error;
