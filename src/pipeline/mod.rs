//! The pipeline: from a draw (a shader, a projection, a depth stage) to the per-pixel loop.
//!
//! [`ShadedDraw`] draws any [`Shader`](crate::shading::Shader); [`DrawMode`] and [`Pipeline`] name
//! the classic choices (as enums and as marker types) and [`Draw`] binds them to built-in
//! shaders, selecting the span loop once. The private `raster` module runs one triangle
//! (shader hook, set-up, edge walk), `setup` builds its planes, `interp` and
//! `quadratic` interpolate the varyings and `span` is the chunked per-pixel loop (depth mask, varyings, shading).

mod depth_only;
mod draw;
mod dyn_interp;
mod in_range;
mod interp;
mod quadratic;
mod raster;

mod setup;
mod setup_cache;
mod shaded;
mod span;
pub(crate) mod stages;
mod target;
mod tri_setup;

pub use depth_only::DepthOnlyDraw;
pub use draw::Draw;
pub(crate) use setup_cache::SetupSlot;
pub use setup_cache::{KeptSetup, KEPT_VARYINGS};
pub use shaded::ShadedDraw;
pub use stages::{
    Adaptive, Affine, DepthLess, DepthStage, DepthTest, DrawMode, DynProjection, Exact, Flat,
    FromMode, FromWrap, Gouraud, Modulate, ModulateFacet, ModulateIntensity, NoDepth, Pipeline,
    ProjKind, Projection, ProjectionStage, Quadratic, QuadraticBy, Replace, Shading, ShadingStage,
    Stages, Subdivided, SubdividedBy,
};
pub use target::{Lent, RenderTarget, Row, Rows};
