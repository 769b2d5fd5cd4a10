//! The real-time row of the environment-mapping report: the sphere through per-vertex
//! sphere-map (matcap) coordinates and a 128 x 128 sphere map baked from the sky cube map,
//! drawn as a plain
//! textured mesh (`examples/firmware/src/matcap_scene.rs`, the `env_matcap` scene).

use std::time::Instant;

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::prelude::*;
use fixel::scene::{draw_mesh_walked, CachedVertex, MeshTransform, SphereMapUvs};
use fixel::surface::DEPTH_CLEAR;
use host_tests::reference::matcap::render_matcap;
use host_tests::reference::RefTexture;

use crate::matcap_scene::{env_matcap, Matcap};
use crate::measure::Image;
use crate::scenes::{SphereBuffers, Target};
use crate::{H, W};

/// Side of the sphere map.
pub const SIDE: u32 = 128;

/// What the row needs: fixel's frame, its median ns per pixel, the firmware's band
/// checksum and pixels, and the f64 reference of the same per-vertex definition.
pub struct MatcapRow {
    /// fixel's whole frame.
    pub image: Image,
    /// Median ns per pixel.
    pub ns: f64,
    /// The band frame's checksum and pixel count (what the MCU must print).
    pub want: (String, u64),
    /// The reference with the same per-vertex coordinates.
    pub own: Image,
}

/// Draws, times and references the matcap sphere (`runs` timed frames).
pub fn matcap_row(runs: u32) -> MatcapRow {
    let map = host_tests::env_scene::sky_sphere_map(SIDE);
    let tex = Texture::new(&map, SIDE, SIDE).expect("texture");
    let s = Box::new(fixel_scenes::sphere());
    let mesh = s.mesh().expect("mesh");
    let cam = fixel_scenes::camera(20);
    let model = fixel_scenes::sphere_model(0);
    let draw = Draw::new::<Matcap>(
        Some(tex),
        Viewport::new(0, 0, W, H).expect("vp"),
        Cull::Back,
    )
    .expect("draw");
    let t = MeshTransform::new(&model, &cam).with_uvs(SphereMapUvs);
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
    let mut cache = vec![CachedVertex::EMPTY; s.positions.len()];
    let mut ns = Vec::new();
    for _ in 0..runs.max(1) {
        let t0 = Instant::now();
        let mut f = Frame::new(&mut color, W, H)
            .expect("frame")
            .with_depth(&mut depth)
            .expect("depth");
        f.clear(Rgb565::new(0, 0, 0));
        let px = draw_mesh_walked(&draw, &mesh, &t, None, &mut cache, &mut f).expect("drawn");
        ns.push(t0.elapsed().as_nanos() as f64 / f64::from(px.max(1)));
    }
    ns.sort_by(f64::total_cmp);
    let image = (
        color.iter().map(|c| c.into_storage()).collect(),
        depth.iter().map(|&z| z != DEPTH_CLEAR).collect(),
    );
    let planes = fixel::scene::face_planes(&s.positions, &s.indices);
    let banded = s
        .mesh()
        .and_then(|m| m.with_face_planes(&planes))
        .expect("mesh");
    let mut buf = Box::new(SphereBuffers::with_storage());
    let (mut a, mut b) = (|| {}, || {});
    let r =
        env_matcap(Target::Bands(&mut *buf), tex, &banded, 0, &mut a, &mut b).expect("band frame");
    let mv = cam.view.mul(&model);
    let rt = RefTexture {
        width: SIDE,
        height: SIDE,
        texels: map.iter().map(|c| c.into_storage()).collect(),
        border: 0,
    };
    let own = render_matcap(
        &s.positions,
        &s.normals,
        &s.indices,
        &mv,
        &cam.projection.mul(&mv),
        &rt,
        W,
        H,
    );
    MatcapRow {
        image,
        ns: ns[ns.len() / 2],
        want: (format!("0x{:08x}", r.checksum), u64::from(r.stats.pixels)),
        own,
    }
}
