//! The scene level: meshes with model matrices, a camera and a directional light, turned
//! into clip-space triangles for a [`Draw`](crate::pipeline::Draw).
//!
//! Conventions: right-handed, column vectors (`p' = M p`), camera looking down `-z` with `+y`
//! up (OpenGL), angles as [`Angle`](crate::math::Angle) (65536 = one turn), lighting in view
//! space. Normals are transformed by the model-view matrix and renormalised, which is exact
//! for rotations, translations and uniform scales (the scenes fixel targets); a non-uniform
//! scale would need the inverse transpose, which is out of scope.
//!
//! Mesh draws cull in two steps: a triangle that surely faces the culled way is dropped by
//! its model-space positions before any of its vertices is transformed (exact in its
//! decisions: see `face_cull`), and the rest by the winding of their projected sub-pixel
//! positions (OpenGL's rule). On a closed mesh the first step spares the vertices of the far
//! side: the benchmark sphere prepares about 440 of its 1,225 vertices per frame.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::scene::{draw_mesh, Camera, DirectionalLight, Mesh};
//!
//! // One white-lit triangle, untextured Gouraud, into a 32 x 24 frame.
//! let positions = [Vec3::from_num(-1, -1, -3), Vec3::from_num(1, -1, -3), Vec3::from_num(0, 1, -3)];
//! let normals = [Vec3::from_num(0, 0, 1); 3];
//! let uvs = [[Fx::ZERO; 2]; 3];
//! let indices = [[0u16, 1, 2]];
//! let mesh = Mesh::new(&positions, Some(&normals), &uvs, &indices)?;
//! let camera = Camera::perspective(Angle::from_degrees(fx(45)), fx(4) / 3, fx(0.5), fx(20))?;
//! let light = DirectionalLight::default();
//! let mode = DrawMode { shading: Shading::Gouraud, ..DrawMode::default() };
//! let draw = Draw::dynamic(mode, None, Viewport::new(0, 0, 32, 24)?)?;
//! let mut pixels = [Rgb565::BLACK; 32 * 24];
//! let mut frame = Frame::new(&mut pixels, 32, 24)?;
//! let written = draw_mesh(&draw, &mesh, &Mat4::IDENTITY, &camera, Some(&light), &mut frame)?;
//! assert!(written > 50);
//! # Ok::<(), fixel::Error>(())
//! ```

mod face_cull;
mod face_planes;
#[cfg(test)]
mod face_tests;
mod lit_mesh;
mod matcap;
mod mesh;
mod mesh_draw;
mod open_sink;
mod tangent;
mod vertex_uv;
mod walk;

pub use crate::geometry::Camera;
pub use crate::shading::DirectionalLight;
pub use face_cull::FacingTest;
pub use face_planes::{face_planes, write_face_planes, FacePlane};
pub use lit_mesh::{LitMesh, PixelLight};
pub use matcap::SphereMapUvs;
pub use mesh::Mesh;
pub use mesh_draw::{
    draw_mesh, draw_mesh_cached, mesh_triangles, mesh_triangles_cached, vertex_intensity,
};
pub use open_sink::triangles_to_sink;
pub use tangent::{tangents, Tangent};
pub use vertex_uv::{MeshUvs, VertexUv};
pub use walk::{
    draw_mesh_walked, mesh_to_sink, walk_mesh, CachedVertex, MeshTransform, TriangleOut,
};
mod depth_sort;
mod jitter;
pub use depth_sort::sort_back_to_front;
mod quad;
pub use jitter::{jittered, SamplePattern};
mod displace;
mod shadow;
mod subdivide;
mod two_stage;
mod uv_gen;
pub use crate::shading::uv_mapping::{Axis, ReadyMapping, UvAt, UvGenerator, UvMapping};
pub use displace::{displace, displace_positions, recompute_normals, Displacement};
pub use quad::{draw_quad, quad_triangles, QuadTriangles, QUAD_TRIANGLES_MAX};
pub use shadow::{light_pass_mesh, shadowed_mesh_triangles};
pub use subdivide::{
    count_edges, count_edges_words, subdivide, subdivide_capacity, weld, weld_table_words,
    SubdivideCapacity,
};
pub use two_stage::{Intermediate, OMapping, ReadyTwoStage, TwoStage};
pub use uv_gen::{map_mesh, map_mesh_capacity, map_mesh_capacity_with, map_mesh_with, MeshStorage};
