//! Scene `env_matcap`: the benchmark sphere (frame `i`) as a mirror of the sky through a
//! 128 x 128 sphere map with its coordinates computed per vertex
//! (`fixel::scene::SphereMapUvs`), then a plain unlit textured draw: bilinear,
//! clamp-to-edge, exact every 64 pixels, in the `sphere` scene's 320 x 8 bands with the same
//! vertex cache, kept set-ups and baked face planes, so the two figures compare directly.
//! Shared word for word by the firmware and the host test `mcu_checksums`.

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::pipeline::{DepthLess, Pipeline, Replace, SubdividedBy};
use fixel::prelude::*;
use fixel::scene::{Mesh, MeshTransform, SphereMapUvs};
use fixel::texture::{Bilinear, ClampToEdge, MipTexture};
use fixel_scenes as demo;

use crate::scenes::{render_walk, viewport, FrameResult, Target};

/// The sphere-map draw: the `sphere` scene's projection and filter, unlit (the map holds
/// the lighting), clamp-to-edge (coordinates stay in `[0, 1]`).
pub type Matcap = Pipeline<SubdividedBy<6>, Bilinear, ClampToEdge, ClampToEdge, Replace, DepthLess>;

/// One frame of the sphere `mesh` (with normals) through the sphere map `texture`.
pub fn env_matcap<const R: usize, const V: usize, const B: usize, const S: usize>(
    buf: Target<'_, R, V, B, S>,
    texture: Texture<'_>,
    mesh: &Mesh<'_>,
    i: u32,
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<FrameResult, Error> {
    let draw = Draw::<Rgb565>::new_mip::<Matcap>(
        Some(MipTexture::single(texture)),
        viewport()?,
        Cull::Back,
    )?;
    let transform =
        MeshTransform::new(&demo::sphere_model(i), &demo::camera(20)).with_uvs(SphereMapUvs);
    render_walk(buf, &draw, mesh, &transform, false, pause, resume)
}
