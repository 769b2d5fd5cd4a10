//! Golden images: fixel's output for each benchmark scene and each feature,
//! compared bit for bit with `host-tests/golden/*.png`. After an intended
//! change, `FIXEL_BLESS=1 cargo test -p host-tests --test goldens` (or
//! `cargo xtask bless`) rewrites them; review the images before committing.
//! The error budgets against the reference live in `budgets/`; goldens
//! only catch unintended changes.

use fixel::pipeline::{DrawMode, Projection, Shading};
use fixel::texture::{Filter, Wrap};
use host_tests::golden::assert_golden;
use host_tests::reference::{RefCull, RefMode, RefShading, RefTexture, RefTriangle};
use host_tests::{adapter, scenes, synthetic};

fn render(
    tris: &[RefTriangle],
    tex: Option<&RefTexture>,
    mode: DrawMode,
    w: u32,
    h: u32,
) -> Vec<u16> {
    adapter::render(&adapter::clip_triangles(tris), tex, mode, w, h).pixels
}

fn scene(name: &str, s: &scenes::SceneDesc, filter: Filter) {
    let mode = DrawMode {
        filter,
        ..adapter::draw_mode(&s.mode, None, true)
    };
    let px = render(
        &scenes::to_ref_triangles(s),
        Some(&s.texture),
        mode,
        s.width,
        s.height,
    );
    assert_golden(name, s.width, s.height, &px);
}

#[test]
fn cube_frame_0() {
    scene("scene-cube-0", &scenes::cube(0), Filter::Bilinear);
}

#[test]
fn sphere_frame_0() {
    scene("scene-sphere-0", &scenes::sphere(0), Filter::Bilinear);
}

#[test]
fn floor_nearest() {
    scene("scene-floor-nearest", &scenes::floor(), Filter::Nearest);
}

#[test]
fn floor_bilinear() {
    scene("scene-floor-bilinear", &scenes::floor(), Filter::Bilinear);
}

/// The perspective quad's mode: Exact, Bilinear, Repeat, Replace, no depth
/// test, no culling.
fn quad_mode() -> DrawMode {
    let m = RefMode {
        shading: RefShading::Replace,
        depth_test: false,
        cull: RefCull::None,
        ..RefMode::default()
    };
    adapter::draw_mode(&m, None, false)
}

fn quad(name: &str, tris: &[RefTriangle], textured: bool, mode: DrawMode) {
    let tex = synthetic::quad_texture();
    let px = render(
        tris,
        textured.then_some(&tex),
        mode,
        synthetic::WIDTH,
        synthetic::HEIGHT,
    );
    assert_golden(name, synthetic::WIDTH, synthetic::HEIGHT, &px);
}

#[test]
fn wrap_modes() {
    for (name, w) in [
        ("repeat", Wrap::Repeat),
        ("mirrored-repeat", Wrap::MirroredRepeat),
        ("clamp-to-edge", Wrap::ClampToEdge),
        ("clamp-to-border", Wrap::ClampToBorder),
    ] {
        for (fname, filter) in [("nearest", Filter::Nearest), ("bilinear", Filter::Bilinear)] {
            let mode = DrawMode {
                wrap: [w; 2],
                filter,
                ..quad_mode()
            };
            quad(
                &format!("wrap-{name}-{fname}"),
                &synthetic::wrap_quad(),
                true,
                mode,
            );
        }
    }
}

#[test]
fn filters() {
    for (name, filter) in [("nearest", Filter::Nearest), ("bilinear", Filter::Bilinear)] {
        let tris = synthetic::quad([0.0, 0.0], [1.0, 1.0], [[1.0; 3]; 4]);
        quad(
            &format!("filter-{name}"),
            &tris,
            true,
            DrawMode {
                filter,
                ..quad_mode()
            },
        );
    }
}

#[test]
fn shadings() {
    let grey = synthetic::quad(
        [0.0, 0.0],
        [2.0, 2.0],
        [[1.0; 3], [0.6; 3], [0.3; 3], [0.8; 3]],
    );
    let cases: [(&str, Vec<RefTriangle>, Shading); 5] = [
        ("replace", synthetic::colored_quad(), Shading::Replace),
        ("modulate", synthetic::colored_quad(), Shading::Modulate),
        ("modulate-intensity", grey, Shading::ModulateIntensity),
        ("gouraud", synthetic::gouraud_triangle(), Shading::Gouraud),
        ("flat", synthetic::colored_quad(), Shading::Flat),
    ];
    for (name, tris, shading) in cases {
        let mode = DrawMode {
            shading,
            ..quad_mode()
        };
        quad(&format!("shading-{name}"), &tris, shading.textured(), mode);
    }
}

#[test]
fn projections() {
    for (name, projection) in [
        ("exact", Projection::Exact),
        ("subdivided-4", Projection::Subdivided { log2_n: 2 }),
        ("subdivided-8", Projection::Subdivided { log2_n: 3 }),
        ("subdivided-16", Projection::Subdivided { log2_n: 4 }),
        ("subdivided-32", Projection::Subdivided { log2_n: 5 }),
        ("quadratic-16", Projection::Quadratic { log2_n: 4 }),
        ("quadratic-32", Projection::Quadratic { log2_n: 5 }),
        ("affine", Projection::Affine),
    ] {
        let mode = DrawMode {
            projection,
            ..quad_mode()
        };
        quad(
            &format!("projection-{name}"),
            &synthetic::wrap_quad(),
            true,
            mode,
        );
    }
}
