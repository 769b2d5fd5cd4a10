//! Geometry stage: clip-space triangles in, screen-space triangles out.
//!
//! * [`Vertex`], [`ClipVertex`], [`ScreenVertex`]: the clip-space vertex (the low-level entry point's input) and the screen
//!   vertex (the rasterizer's input).
//! * [`clip_and_project`]: homogeneous clipping against the near and far planes, a minimum `w`, and the
//!   guard band, so nothing behind the camera or absurdly far off screen reaches the
//!   raster math.
//! * [`Viewport`]: the viewport, perspective divide and mapping to sub-pixel coordinates,
//!   back-face culling.
//!
//! Clip space follows OpenGL: a point is visible when `-w <= x, y, z <= w`; NDC z in
//! `[-1, 1]` maps to depth `[0, 1]`; NDC y up maps to screen y down.

mod camera;
pub(crate) mod clip;
pub(crate) mod homography;
pub(crate) mod mesh_checks;
mod project_recip;
pub(crate) mod screen;
pub(crate) mod vertex;
pub(crate) mod viewport;

pub use camera::Camera;
pub use clip::{
    clip_and_project, clip_and_project_varyings, complete_depth, keeps, prepare,
    prepare_without_depth, project_unclipped, project_unclipped_varyings, W_MIN_BITS,
};
pub use homography::{Homography, CORNER_TOLERANCE};
pub use screen::{
    Rect, ATTR_SUBPIXEL_BITS, DEPTH_CLEAR, GUARD_BAND_PX, MAX_VIEWPORT_PX, SUBPIXEL_BITS,
    SUBPIXEL_ONE,
};
pub use vertex::{ClipVertex, ScreenTriangle, ScreenVertex, Vertex, CLASSIC_VARYINGS, COLOR_ONE};
pub use viewport::{Cull, Viewport};
