//! The camera: a view matrix and a projection matrix.

use crate::math::{Angle, Fx, Mat4, Vec3};
use crate::Error;

/// A camera: `view` (world to view space) and `projection` (view to clip space).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Camera {
    /// World to view space (identity: at the origin, looking down `-z`).
    pub view: Mat4,
    /// View to OpenGL clip space.
    pub projection: Mat4,
}

impl Camera {
    /// A camera at the origin looking down `-z`, with gluPerspective's projection
    /// (`fovy` vertical field of view, `aspect` = width / height, `0 < near < far`).
    pub fn perspective(fovy: Angle, aspect: Fx, near: Fx, far: Fx) -> Result<Self, Error> {
        Ok(Camera {
            view: Mat4::IDENTITY,
            projection: Mat4::perspective(fovy, aspect, near, far)?,
        })
    }

    /// The same camera moved to `eye`, looking at `target` with `up` (gluLookAt).
    pub fn looking_at(mut self, eye: Vec3, target: Vec3, up: Vec3) -> Result<Self, Error> {
        self.view = Mat4::look_at(eye, target, up)?;
        Ok(self)
    }
}
