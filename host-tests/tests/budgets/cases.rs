//! The scenes under test: the benchmark scenes and the synthetic quads and triangle, each
//! with the reference state its fixel mode mirrors.

use host_tests::reference::{RefCull, RefMode, RefShading, RefTexture, RefTriangle, RefWrap};
use host_tests::{scenes, synthetic};

/// One scene under test, with the reference state its fixel mode mirrors.
pub struct Scene {
    pub name: String,
    pub tris: Vec<RefTriangle>,
    pub tex: Option<RefTexture>,
    pub mode: RefMode,
    /// Use `ModulateIntensity` for `Modulate` (grey vertex colours).
    pub intensity: bool,
    pub width: u32,
    pub height: u32,
}

impl Scene {
    pub fn textured(&self) -> bool {
        !matches!(self.mode.shading, RefShading::Gouraud | RefShading::Flat(_))
    }

    pub fn shading_name(&self) -> &'static str {
        match self.mode.shading {
            RefShading::Replace => "Replace",
            RefShading::Modulate if self.intensity => "ModulateIntensity",
            RefShading::Modulate => "Modulate",
            RefShading::Gouraud => "Gouraud",
            RefShading::Flat(_) => "Flat",
        }
    }
}

pub fn bench_scene(name: String, s: &scenes::SceneDesc, mode: RefMode, intensity: bool) -> Scene {
    Scene {
        name,
        tris: scenes::to_ref_triangles(s),
        tex: Some(s.texture.clone()),
        mode,
        intensity,
        width: s.width,
        height: s.height,
    }
}

fn synthetic_scene(
    name: &str,
    tris: Vec<RefTriangle>,
    shading: RefShading,
    wrap: RefWrap,
) -> Scene {
    Scene {
        name: name.into(),
        tris,
        tex: Some(synthetic::quad_texture()),
        mode: RefMode {
            wrap_u: wrap,
            wrap_v: wrap,
            shading,
            depth_test: false,
            cull: RefCull::None,
            ..RefMode::default()
        },
        intensity: false,
        width: synthetic::WIDTH,
        height: synthetic::HEIGHT,
    }
}

pub fn all_scenes() -> Vec<Scene> {
    let mut v = Vec::new();
    for f in [0, 33, 66] {
        let s = scenes::cube(f);
        v.push(bench_scene(format!("cube {f}"), &s, s.mode, true));
    }
    let s = scenes::cube(0);
    v.push(bench_scene("cube 0".into(), &s, s.mode, false));
    v.push(bench_scene(
        "cube 0".into(),
        &s,
        RefMode {
            shading: RefShading::Flat([1.0; 3]),
            ..s.mode
        },
        false,
    ));
    let s = scenes::sphere(0);
    v.push(bench_scene("sphere 0".into(), &s, s.mode, true));
    let s = scenes::floor();
    v.push(bench_scene("floor".into(), &s, s.mode, false));
    let mut narrow = s.clone();
    for p in &mut narrow.mesh.positions {
        p[0] *= 8.0 / 50.0;
    }
    v.push(bench_scene("floor narrow".into(), &narrow, s.mode, false));
    for (name, w) in [
        ("quad Repeat", RefWrap::Repeat),
        ("quad MirroredRepeat", RefWrap::MirroredRepeat),
        ("quad ClampToEdge", RefWrap::ClampToEdge),
        ("quad ClampToBorder", RefWrap::ClampToBorder),
    ] {
        v.push(synthetic_scene(
            name,
            synthetic::wrap_quad(),
            RefShading::Replace,
            w,
        ));
    }
    v.push(synthetic_scene(
        "quad coloured",
        synthetic::colored_quad(),
        RefShading::Modulate,
        RefWrap::Repeat,
    ));
    let mut g = synthetic_scene(
        "triangle",
        synthetic::gouraud_triangle(),
        RefShading::Gouraud,
        RefWrap::Repeat,
    );
    g.tex = None;
    v.push(g);
    v
}
