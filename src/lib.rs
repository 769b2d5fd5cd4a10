//! fixel: a `no_std`, heap-free, fixed-point texture-mapped 3D rasterizer for
//! microcontroller displays. (Crate docs are completed as the modules land.)
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs, missing_debug_implementations)]

pub mod color;
pub mod demo;
pub mod error;
pub mod geometry;
pub mod math;
pub mod pipeline;
pub mod raster;
pub mod scene;
pub mod target;
pub mod texture;

pub use error::Error;

/// The names most programs need, in one import.
pub mod prelude {
    pub use crate::geometry::{ClipVertex, Cull, Viewport};
    pub use crate::math::{Angle, Fx, Mat4, Vec3};
    pub use crate::pipeline::{DepthTest, Draw, DrawMode, Pipeline, Projection, Shading};
    pub use crate::target::{BandRenderer, Frame, RenderTarget};
    pub use crate::texture::{Filter, Texture, Wrap};
    pub use crate::Error;
}
