//! Geometry on its own: instructions per transformed vertex and per set-up triangle, stage
//! by stage, for the cube (12 triangles), the benchmark sphere (2,208) and the fine sphere
//! (10,080, a compile-time flash table), frame 0 of the sphere scene's camera.
//!
//! Each stage is one counted region followed by a `bench_mark` (`cargo xtask mcu` reads the
//! per-mark counts): `transform` (model-view-projection of every vertex), `lighting` (normal
//! to view space and the light's intensity, every vertex), `project` (outcode and
//! perspective divide, every vertex), `face` (the walker's model-space back-face test,
//! `MeshTransform::facing_test`, of every triangle, before any vertex is transformed; its
//! checksum is the number it culls), `cull` (exact sub-pixel area test of every triangle
//! with its three vertices inside), `clip` (the clipper on triangles crossing a plane),
//! `setup` (the raster set-up of every kept triangle, into a one-row target no triangle
//! reaches, so no span is drawn) and `walk` (the renderer's whole geometry stage,
//! `walk_mesh` with one cached vertex per mesh vertex: lighting only for vertices of kept
//! triangles). `face_baked` and `walk_baked` are `face` and `walk` with the mesh's face
//! planes baked (`Mesh::with_face_planes`): the same results. The printed `pixels=` is the number of items of the stage (vertices or
//! triangles), so a count divided by it is the cost per item.
//!
//! Needs the whole-frame memory layout (the fine sphere is ~230 KB of flash and the
//! per-vertex arrays ~400 KB of stack).
#![no_std]
#![no_main]

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{clip_and_project, keeps, prepare, ClipVertex, ScreenTriangle, ScreenVertex};
use fixel::prelude::*;
use fixel::scene::{
    vertex_intensity, walk_mesh, write_face_planes, CachedVertex, DirectionalLight, FacePlane,
    MeshTransform, TriangleOut,
};
use fixel_firmware::{bench_end, bench_mark, bench_start, data, outln, report_begin, scenes};
use fixel_scenes::{self as demo, MeshData};

const MAXV: usize = demo::FINE_SPHERE_VERTICES;
const MAXT: usize = demo::FINE_SPHERE_TRIANGLES;

/// Per-vertex and per-triangle scratch for the stages.
struct Scratch {
    clip: [ClipVertex; MAXV],
    prepared: [(u8, ScreenVertex); MAXV],
    kept: [u16; MAXT],
    crossing: [u16; MAXT],
    cache: [CachedVertex; MAXV],
    planes: [FacePlane; MAXT],
}

/// Counts the walker's screen triangles.
struct Count(u32, u32);

impl TriangleOut for Count {
    fn wants(&self, _: usize) -> bool {
        true
    }
    fn attributes(&self) -> bool {
        true
    }
    fn triangle(&mut self, _: usize, tri: &ScreenTriangle) {
        self.0 += 1;
        self.1 = self
            .1
            .wrapping_mul(31)
            .wrapping_add(tri[0].x as u32 ^ tri[2].varyings[2] as u32);
    }
}

/// One counted stage: region, mark, result line.
fn stage(scene: &str, name: &str, f: impl FnOnce() -> (u32, u32)) {
    bench_start();
    let (items, check) = f();
    bench_end();
    bench_mark();
    outln!(
        "mode scene={} mode={} checksum=0x{:08x} pixels={}",
        scene,
        name,
        check,
        items
    );
}

#[inline(never)]
fn stages<const V: usize, const T: usize>(
    scene: &str,
    m: &MeshData<V, T>,
    model: &Mat4,
    s: &mut Scratch,
) -> bool {
    let Ok(mesh) = m.mesh() else {
        return false;
    };
    let Ok(vp) = scenes::viewport() else {
        return false;
    };
    let Ok(draw) = Draw::new::<scenes::LitSub4>(Some(data::T256X128), vp, Cull::Back) else {
        return false;
    };
    let camera = demo::camera(20);
    let light = DirectionalLight::default();
    let mv = camera.view.mul(model);
    let mvp = camera.projection.mul(&mv);
    let n = V.min(MAXV);
    let t = T.min(MAXT);
    let (mut nk, mut nc) = (0usize, 0usize);

    stage(scene, "transform", || {
        let mut bad = 0;
        for i in 0..n {
            match mvp.transform_point(m.positions[i]) {
                Some(p) => s.clip[i] = ClipVertex::new([p.x, p.y, p.z, p.w], m.uvs[i]),
                None => bad += 1,
            }
        }
        (n as u32, bad)
    });
    stage(scene, "lighting", || {
        let mut sum = 0u32;
        for i in 0..n {
            let q = vertex_intensity(&mesh, i, &mv, &light).unwrap_or(0);
            s.clip[i].color = [q; 3];
            sum = sum.wrapping_add(u32::from(q));
        }
        (n as u32, sum)
    });
    stage(scene, "project", || {
        let mut sum = 0u32;
        for i in 0..n {
            s.prepared[i] = prepare(&s.clip[i], &vp);
            sum = sum.wrapping_add(s.prepared[i].1.x as u32);
        }
        (n as u32, sum)
    });
    // Built outside the region: the walk's row below counts the transform's per-frame set-up
    // (the camera centre among it), this one the test per triangle.
    let transform = MeshTransform::new(model, &camera);
    stage(scene, "face", || {
        let Some(test) = transform.facing_test(&mesh, Cull::Back) else {
            return (t as u32, 0);
        };
        let culled = (0..t).filter(|&k| test.culls(k)).count();
        (t as u32, culled as u32)
    });
    stage(scene, "cull", || {
        for (k, idx) in m.indices[..t].iter().enumerate() {
            let v = idx.map(|i| s.prepared[usize::from(i)]);
            if v[0].0 & v[1].0 & v[2].0 != 0 {
                continue;
            }
            if v[0].0 | v[1].0 | v[2].0 != 0 {
                s.crossing[nc] = k as u16;
                nc += 1;
                continue;
            }
            if keeps(&[v[0].1, v[1].1, v[2].1], Cull::Back) {
                s.kept[nk] = k as u16;
                nk += 1;
            }
        }
        (t as u32, nk as u32)
    });
    stage(scene, "clip", || {
        let mut out = 0u32;
        for &k in &s.crossing[..nc] {
            let idx = m.indices[usize::from(k)];
            let tri = idx.map(|i| s.clip[usize::from(i)]);
            clip_and_project(&tri, &vp, Cull::Back, false, &mut |_| out += 1);
        }
        (nc as u32, out)
    });
    let mut color = [Rgb565::new(0, 0, 0); scenes::W as usize];
    let mut depth = [0u16; scenes::W as usize];
    let Ok(row) = Frame::new(&mut color, scenes::W, 1) else {
        return false;
    };
    let Ok(mut row) = row.with_depth(&mut depth) else {
        return false;
    };
    if draw.check_target(&row).is_err() {
        return false;
    }
    stage(scene, "setup", || {
        let mut px = 0u32;
        for &k in &s.kept[..nk] {
            let idx = m.indices[usize::from(k)];
            let tri = idx.map(|i| s.prepared[usize::from(i)].1);
            px += draw.screen_triangle(&tri, &mut row).unwrap_or(0); // target checked above
        }
        (nk as u32, px)
    });
    stage(scene, "walk", || {
        let mut c = Count(0, 0);
        walk_mesh(
            &draw,
            &mesh,
            &MeshTransform::new(model, &camera),
            Some(&light),
            &mut s.cache,
            0,
            &mut c,
        );
        (t as u32, c.1 ^ c.0)
    });
    // The same two stages with the mesh's face planes baked (here at run time, outside the
    // regions; a firmware bakes them into flash with `face_planes`): the same culls and
    // triangles (the same checksums), from one plane per triangle.
    let planes = &mut s.planes[..t];
    if write_face_planes(&m.positions, &m.indices, planes).is_err() {
        return false;
    }
    let Ok(baked) = mesh.with_face_planes(planes) else {
        return false;
    };
    stage(scene, "face_baked", || {
        let Some(test) = transform.facing_test(&baked, Cull::Back) else {
            return (t as u32, 0);
        };
        let culled = (0..t).filter(|&k| test.culls(k)).count();
        (t as u32, culled as u32)
    });
    stage(scene, "walk_baked", || {
        let mut c = Count(0, 0);
        walk_mesh(
            &draw,
            &baked,
            &MeshTransform::new(model, &camera),
            Some(&light),
            &mut s.cache,
            0,
            &mut c,
        );
        (t as u32, c.1 ^ c.0)
    });
    true
}

fn run() -> bool {
    let mut s = Scratch {
        clip: [ClipVertex::default(); MAXV],
        prepared: [(0, ScreenVertex::default()); MAXV],
        kept: [0; MAXT],
        crossing: [0; MAXT],
        cache: [CachedVertex::default(); MAXV],
        planes: [FacePlane::ZERO; MAXT],
    };
    let model = demo::sphere_model(0);
    report_begin();
    let mut ok = stages("cube", &demo::cube(), &demo::cube_model(0), &mut s);
    ok &= stages(
        "sphere",
        core::hint::black_box(&data::SPHERE),
        &model,
        &mut s,
    );
    ok &= stages(
        "fine_sphere",
        core::hint::black_box(&data::FINE_SPHERE),
        &model,
        &mut s,
    );
    ok
}

fixel_firmware::entry!(run);
