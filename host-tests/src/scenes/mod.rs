//! The three benchmark scenes of docs/scenes.md (`cube`, `sphere`, `floor`) built
//! in f64 as neutral descriptions ([`SceneDesc`]), and their conversion to
//! reference triangles ([`to_ref_triangles`]): model, view (identity) and GL
//! perspective projection, plus per-vertex lighting in view space
//! `i = 0.3 + 0.7 max(0, n . l)`, `l = normalize(-0.4, 0.6, 1.0)`.
//!
//! Interpretation: "model matrix = Rx * Ry" rotates the object about its own
//! centre, so the meshes are built centred at the origin and the model
//! matrix is `T(centre) * Rx * Ry` (the floor is built in place, model = I).

pub mod math;
pub mod mesh;

pub use mesh::{
    cube_mesh, floor_mesh, procedural_texture, rgb888_to_rgb565, sphere_mesh, MeshDesc,
};

use crate::reference::{RefFilter, RefMode, RefShading, RefTexture, RefTriangle, RefVertex};
use math::Mat4;

/// Framebuffer width of every benchmark scene.
pub const WIDTH: u32 = 320;
/// Framebuffer height of every benchmark scene.
pub const HEIGHT: u32 = 240;

/// Light direction in view space before normalisation.
pub const LIGHT_DIR: [f64; 3] = [-0.4, 0.6, 1.0];

/// A benchmark scene, independent of any renderer's types.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneDesc {
    /// Scene name as in docs/scenes.md.
    pub name: &'static str,
    /// Object-space mesh.
    pub mesh: MeshDesc,
    /// Model matrix for this frame (row-major, column vectors); view = I.
    pub model: Mat4,
    /// Vertical field of view in degrees.
    pub fovy_deg: f64,
    /// Near plane distance.
    pub near: f64,
    /// Far plane distance.
    pub far: f64,
    /// Framebuffer width (320).
    pub width: u32,
    /// Framebuffer height (240).
    pub height: u32,
    /// The scene's texture.
    pub texture: RefTexture,
    /// Whether per-vertex lighting applies (colour = intensity, else white).
    pub lit: bool,
    /// Number of frames N the benchmark runs.
    pub frames: u32,
    /// Suggested render state (filter, wrap, shading, culling, depth test).
    pub mode: RefMode,
}

impl SceneDesc {
    /// The GL perspective matrix of the scene (aspect = width / height).
    pub fn projection(&self) -> Mat4 {
        math::perspective(
            self.fovy_deg,
            f64::from(self.width) / f64::from(self.height),
            self.near,
            self.far,
        )
    }
}

/// The cube scene, frame `frame` (N = 100): side 2 at (0, 0, -4), rotated
/// about y by `0.7 + 0.05 i`, then about x by `0.3 + 0.031 i`; `T(128, 128)`,
/// lit, bilinear, perspective-correct, repeat.
pub fn cube(frame: u32) -> SceneDesc {
    let i = f64::from(frame);
    let rot = math::mul(
        &math::rotation_x(0.3 + 0.031 * i),
        &math::rotation_y(0.7 + 0.05 * i),
    );
    SceneDesc {
        name: "cube",
        mesh: cube_mesh(),
        model: math::mul(&math::translation([0.0, 0.0, -4.0]), &rot),
        fovy_deg: 45.0,
        near: 0.5,
        far: 20.0,
        width: WIDTH,
        height: HEIGHT,
        texture: procedural_texture(128, 128),
        lit: true,
        frames: 100,
        mode: RefMode::default(),
    }
}

/// The sphere scene, frame `frame` (N = 100): radius 1.5 at (0, 0, -5),
/// 24 x 48, rotated about y by `0.02 i`; `T(256, 128)`, lit, bilinear,
/// perspective-correct, repeat.
pub fn sphere(frame: u32) -> SceneDesc {
    let rot = math::rotation_y(0.02 * f64::from(frame));
    SceneDesc {
        name: "sphere",
        mesh: sphere_mesh(1.5, 24, 48),
        model: math::mul(&math::translation([0.0, 0.0, -5.0]), &rot),
        fovy_deg: 45.0,
        near: 0.5,
        far: 20.0,
        width: WIDTH,
        height: HEIGHT,
        texture: procedural_texture(256, 128),
        lit: true,
        frames: 100,
        mode: RefMode::default(),
    }
}

/// The floor scene (N = 20, camera fixed): the quad on y = -1, `T(64, 64)`,
/// not lit, far 200. The mode hint is nearest/repeat/replace; the benchmark
/// also runs it bilinear (set `mode.filter`) and trilinear (which the
/// reference does not model).
pub fn floor() -> SceneDesc {
    SceneDesc {
        name: "floor",
        mesh: floor_mesh(),
        model: math::IDENTITY,
        fovy_deg: 45.0,
        near: 0.5,
        far: 200.0,
        width: WIDTH,
        height: HEIGHT,
        texture: procedural_texture(64, 64),
        lit: false,
        frames: 20,
        mode: RefMode {
            filter: RefFilter::Nearest,
            shading: RefShading::Replace,
            ..RefMode::default()
        },
    }
}

/// Per-vertex light intensity for a view-space unit normal.
pub fn light_intensity(n_view: [f64; 3]) -> f64 {
    let l = math::normalize(LIGHT_DIR);
    0.3 + 0.7 * math::dot(n_view, l).max(0.0)
}

/// Transforms the scene's mesh to clip space (`P * V * M`, V = I) and
/// lights it (colour `[i, i, i]` if lit, else white), one triangle per index
/// triple, winding preserved.
pub fn to_ref_triangles(scene: &SceneDesc) -> Vec<RefTriangle> {
    let mvp = math::mul(&scene.projection(), &scene.model);
    let m = &scene.mesh;
    let vertex = |k: u16| {
        let k = usize::from(k);
        let [x, y, z] = m.positions[k];
        let color = if scene.lit {
            // The model's 3x3 part is a rotation, so it transforms normals too.
            let n = math::normalize(math::transform_dir(&scene.model, m.normals[k]));
            [light_intensity(n); 3]
        } else {
            [1.0; 3]
        };
        RefVertex {
            clip: math::transform(&mvp, [x, y, z, 1.0]),
            uv: m.uvs[k],
            color,
        }
    };
    m.indices
        .iter()
        .map(|t| RefTriangle(t.map(vertex)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Geometric normal of each triangle points away from the mesh centre.
    fn assert_outward(m: &MeshDesc) {
        for t in &m.indices {
            let p = t.map(|k| m.positions[usize::from(k)]);
            let e1 = core::array::from_fn(|c| p[1][c] - p[0][c]);
            let e2 = core::array::from_fn(|c| p[2][c] - p[0][c]);
            let centroid = core::array::from_fn(|c| (p[0][c] + p[1][c] + p[2][c]) / 3.0);
            assert!(math::dot(math::cross(e1, e2), centroid) > 0.0, "{t:?}");
        }
    }

    #[test]
    fn meshes_are_counter_clockwise_from_outside() {
        assert_outward(&cube_mesh());
        assert_outward(&sphere_mesh(1.5, 24, 48));
    }

    #[test]
    fn mesh_sizes_match_scenes_md() {
        assert_eq!(cube_mesh().indices.len(), 12);
        let s = sphere_mesh(1.5, 24, 48);
        assert_eq!(s.indices.len(), 2208);
        assert_eq!(s.positions.len(), 25 * 49);
        let f = floor_mesh();
        let n = math::cross([100.0, 0.0, 0.0], [100.0, 0.0, -99.0]);
        assert!(n[1] > 0.0);
        assert_eq!(f.uvs[2], [50.0, 49.5]);
    }

    #[test]
    fn texture_formula() {
        let t = procedural_texture(128, 128);
        // x = 127: r8 = 254 -> r5 = (254*31+127)/255 = 31; y = 0: g = 0; b odd block.
        assert_eq!(t.texel(127, 0), (31 << 11) | 31);
        assert_eq!(t.texel(0, 0), 0);
        // x = 16: r8 = 32 -> r5 = 4; b = 255 -> 31.
        assert_eq!(t.texel(16, 0), (4 << 11) | 31);
        assert_eq!(rgb888_to_rgb565(255, 255, 255), 0xffff);
    }
}
