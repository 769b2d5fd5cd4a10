//! Measuring one mode: host timing of the whole scene, frame 0 through the firmware's band
//! code (the checksum the MCU must print), and the error frames drawn against the f64
//! references.

use std::time::Instant;

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{ClipVertex, Cull, Viewport};
use fixel::pipeline::{DepthTest, DrawMode, Shading};
use fixel::scene::{draw_mesh, DirectionalLight};
use fixel::surface::Frame;
use fixel_scenes as demo;
use host_tests::adapter;
use host_tests::reference::{self, RefFilter, RefMip, RefMode, RefProjection, RefShading};
use host_tests::scenes as refscenes;

use crate::bench_scenes::{Meshes, Scene, Tex};
use crate::modes::{Filt, Mode};
use crate::scenes;
use crate::{H, SS, W};

/// Host timing of one mode: ns per drawn pixel of each run, and drawn pixels per run.
pub fn time_mode(scene: Scene, m: &Mode, tex: &Tex, meshes: &Meshes, runs: u32) -> (Vec<f64>, u64) {
    let vp = Viewport::new(0, 0, W, H).expect("viewport");
    let draw = m.draw(tex.for_mode(m), vp).expect("draw");
    let mesh = meshes.mesh(scene);
    let camera = demo::camera(scene.far());
    let light = DirectionalLight::default();
    let light = m.lit.then_some(&light);
    let n = (W * H) as usize;
    let mut color = vec![Rgb565::new(0, 0, 0); n];
    let mut depth = vec![0u16; n];
    let mut run = || {
        let mut px = 0u64;
        for i in 0..scene.frames() {
            let model = scene.model(i);
            let mut frame = Frame::new(&mut color, W, H)
                .expect("frame")
                .with_depth(&mut depth)
                .expect("depth");
            frame.clear(Rgb565::new(0, 0, 0));
            px += u64::from(draw_mesh(&draw, &mesh, &model, &camera, light, &mut frame).unwrap());
        }
        std::hint::black_box(px)
    };
    let pixels = run();
    let mut ns = Vec::new();
    for _ in 0..runs {
        let t0 = Instant::now();
        let px = run();
        ns.push(t0.elapsed().as_nanos() as f64 / px.max(1) as f64);
    }
    (ns, pixels)
}

/// Frame 0 through the firmware's band code: (checksum, pixels), as the MCU prints them.
pub fn band_checksum(scene: Scene, m: &Mode, tex: &Tex, meshes: &Meshes) -> (String, u64) {
    let mut buf = Box::new(scenes::Buffers::new());
    let (mut a, mut b) = (|| {}, || {});
    let vp = scenes::viewport().expect("viewport");
    let draw = m.draw(tex.for_mode(m), vp).expect("draw");
    let r = match scene {
        Scene::Cube => scenes::cube_with(
            scenes::Target::Bands(&mut buf),
            &draw,
            m.lit,
            0,
            &mut a,
            &mut b,
        ),
        Scene::Sphere => {
            let mesh = meshes.mesh(scene);
            scenes::sphere_with(
                scenes::Target::Bands(&mut buf),
                &draw,
                &mesh,
                m.lit,
                0,
                &mut a,
                &mut b,
            )
        }
        Scene::Floor => scenes::floor_with(scenes::Target::Bands(&mut buf), &draw, &mut a, &mut b),
    }
    .expect("band frame");
    (format!("0x{:08x}", r.checksum), u64::from(r.stats.pixels))
}

/// The reference state a mode's filter corresponds to.
fn ref_filter(f: Filt) -> (RefFilter, RefMip) {
    match f {
        Filt::Nearest => (RefFilter::Nearest, RefMip::None),
        Filt::Bilinear | Filt::BilinearFootprint => (RefFilter::Bilinear, RefMip::None),
        Filt::NearestMip => (RefFilter::Nearest, RefMip::Nearest),
        Filt::Trilinear | Filt::TrilinearSpan => (RefFilter::Bilinear, RefMip::Linear),
    }
}

/// One error frame of a scene: the reference's triangles (lit and unlit), fixel's clip
/// triangles, and fixel's coverage.
pub struct ErrFrame {
    desc: [refscenes::SceneDesc; 2],
    ref_tris: [Vec<reference::RefTriangle>; 2],
    clip: [Vec<[ClipVertex; 3]>; 2],
    pub covered: Vec<bool>,
}

impl ErrFrame {
    pub fn new(scene: Scene, i: u32) -> Self {
        let lit = scene.desc(i);
        let unlit = refscenes::SceneDesc {
            lit: false,
            ..lit.clone()
        };
        let ref_tris = [
            refscenes::to_ref_triangles(&unlit),
            refscenes::to_ref_triangles(&lit),
        ];
        let clip = [
            adapter::clip_triangles(&ref_tris[0]),
            adapter::clip_triangles(&ref_tris[1]),
        ];
        let cov_mode = DrawMode {
            shading: Shading::Flat,
            depth: DepthTest::Less,
            cull: Cull::Back,
            ..DrawMode::default()
        };
        let covered = adapter::render(&clip[0], None, cov_mode, W, H).covered;
        ErrFrame {
            desc: [unlit, lit],
            ref_tris,
            clip,
            covered,
        }
    }

    fn ref_mode(&self, lit: bool, f: Filt) -> RefMode {
        let (filter, mip) = ref_filter(f);
        RefMode {
            projection: RefProjection::Perspective,
            filter,
            mip,
            shading: if lit {
                RefShading::Modulate
            } else {
                RefShading::Replace
            },
            ..self.desc[usize::from(lit)].mode
        }
    }

    /// The f64 reference (RGB565-quantised pixels, coverage).
    pub fn reference(&self, lit: bool, f: Filt) -> (Vec<u16>, Vec<bool>) {
        let l = usize::from(lit);
        let r = reference::render(
            &self.ref_tris[l],
            Some(&self.desc[l].texture),
            &self.ref_mode(lit, f),
            W,
            H,
        );
        (r.quantize_rgb565(), r.covered)
    }

    /// The supersampled reference (bilinear on level 0, box filtered), unlit.
    pub fn supersampled(&self) -> (Vec<u16>, Vec<bool>) {
        let r = reference::render_supersampled(
            &self.ref_tris[0],
            Some(&self.desc[0].texture),
            &self.ref_mode(false, Filt::Bilinear),
            W,
            H,
            SS,
        );
        (r.quantize_rgb565(), r.covered)
    }

    /// fixel's frame with the typed draw of `m`.
    pub fn fixel(&self, m: &Mode, tex: &Tex) -> Vec<u16> {
        let vp = Viewport::new(0, 0, W, H).expect("viewport");
        let draw = m.draw(tex.for_mode(m), vp).expect("draw");
        let n = (W * H) as usize;
        let mut color = vec![Rgb565::new(0, 0, 0); n];
        let mut depth = vec![0u16; n];
        let mut frame = Frame::new(&mut color, W, H)
            .expect("frame")
            .with_depth(&mut depth)
            .expect("depth");
        frame.clear(Rgb565::new(0, 0, 0));
        draw.clip_triangles(&self.clip[usize::from(m.lit)], &mut frame)
            .unwrap();
        color
            .iter()
            .map(|&c| RawU16::from(c).into_inner())
            .collect()
    }
}
