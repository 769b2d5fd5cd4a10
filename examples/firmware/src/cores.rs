//! Two cores drawing one frame (`cores_*` firmwares, `cargo xtask cores`): the scene's
//! frame 0 binned once, each hart walking half of the triangles into bins of its own
//! ([`BinnedFrame::join`]), then hart 0 draws the even bands and
//! hart 1 the odd ones ([`BandShare`]), at the same time on QEMU RISC-V `virt -smp 2`, each
//! with its own two band buffers and depth band, from the same bins. Before that, the same
//! frame on hart 0 alone (every band), for the one-core count and checksum.
//!
//! Each finished band is copied into a whole frame (outside the counted regions, as the
//! harness's checksum of a band is), whose checksum, once both harts are done, must equal
//! the one-core frame's and the host's. Counted per hart (QEMU plugin `icount_smp.c`): the
//! binning pass and the even bands on hart 0, the odd bands on hart 1; `bench_mark` after
//! each part. Waiting for the other hart is outside the counted regions.
//!
//! On Arm (one core) the odd bands run after the even ones on the same core: the build
//! compiles, `cargo xtask cores` runs the RISC-V build only.

use core::convert::Infallible;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::ScreenTriangle;
use fixel::prelude::*;
use fixel::scene::{
    walk_mesh, CachedVertex, DirectionalLight, FacePlane, Mesh, MeshTransform, TriangleOut,
};
use fixel::surface::{BandDraw, BandShare, Binned, BinnedFrame, Blocking, TriangleSink};
use fixel::texture::MipTexture;
use fixel_scenes as demo;

use crate::scenes::{viewport, Fnv1a, LitFootprint, LitSphere, BAND_PIXELS, H, ROWS, W};
use crate::{bench_end, bench_mark, bench_start, data, outln};

/// Screen triangles a frame may bin: the teapot's and the sphere's visible ones fit.
const BINS: usize = 1200;

static mut BIN_STORE: [Binned; BINS] = [Binned::EMPTY; BINS];
/// Prepared vertices, one walker cache per hart (a slot per mesh vertex).
static mut CACHES: [[CachedVertex; 2048]; 2] = [[CachedVertex::EMPTY; 2048]; 2];

/// Hart `h`'s vertex cache, a slot for each of `n` vertices.
fn cache(h: usize, n: usize) -> &'static mut [CachedVertex] {
    // SAFETY: each hart takes its own cache, once per binning pass.
    unsafe {
        let all = &mut *core::ptr::addr_of_mut!(CACHES);
        let c = &mut all[h.min(1)];
        &mut c[..n.min(2048)]
    }
}
static mut FRAME: [Rgb565; (W * H) as usize] = [Rgb565::new(0, 0, 0); (W * H) as usize];

/// Copies `band` into the whole frame at its rows (raw pointer: the two harts write
/// disjoint rows of it).
fn keep(band: &Frame<'_, Rgb565>) {
    let at = band.first_row().max(0) as usize * W as usize;
    let px = band.pixels();
    // SAFETY: FRAME is only written here, each band's rows by one hart, and read after
    // both harts are done.
    unsafe {
        let frame = &mut *core::ptr::addr_of_mut!(FRAME);
        if let Some(dst) = frame.get_mut(at..at + px.len()) {
            dst.copy_from_slice(px);
        }
    }
}

/// The whole frame's checksum (FNV-1a over the pixels, as the band harness).
fn checksum() -> u32 {
    let mut sum = Fnv1a::default();
    // SAFETY: both harts are done with FRAME.
    unsafe { sum.pixels(&*core::ptr::addr_of!(FRAME)) };
    sum.0
}

/// Draws `share`'s bands of `frame` through two band buffers, each band kept in the whole
/// frame outside the counted region; the pixels written.
fn draw_share(frame: &BinnedFrame<'_, '_, Rgb565>, share: BandShare) -> Result<u32, Error> {
    let (mut a, mut b) = (
        [Rgb565::new(0, 0, 0); BAND_PIXELS],
        [Rgb565::new(0, 0, 0); BAND_PIXELS],
    );
    let mut depth = [0u16; BAND_PIXELS];
    let mut buffers = [&mut a[..], &mut b[..]];
    let mut bands = BandRenderer::with_buffers(&mut buffers, W, ROWS, H)?.with_depth(&mut depth)?;
    let mut send = Blocking(|band: &Frame<'_, Rgb565>| {
        bench_end();
        keep(band);
        bench_start();
        Ok::<(), Infallible>(())
    });
    let stats = bands.render_share_to(frame, Rgb565::new(0, 0, 0), share, &mut send)?;
    Ok(stats.pixels)
}

/// Screen triangles of the walker pushed as draw 0 into a binning sink.
struct ToBins<'a, 's, 'f, 'd>(&'a mut TriangleSink<'s, 'f, 'd, Rgb565>);

impl TriangleOut for ToBins<'_, '_, '_, '_> {
    fn wants(&self, _: usize) -> bool {
        true
    }
    fn attributes(&self) -> bool {
        true
    }
    fn triangle(&mut self, _: usize, tri: &ScreenTriangle) {
        self.0.push(0, tri);
    }
}

/// A mesh's arrays, to walk a part of its triangles.
pub struct Parts<'m> {
    pub positions: &'m [Vec3],
    pub normals: &'m [Vec3],
    pub uvs: &'m [[Fx; 2]],
    pub indices: &'m [[u16; 3]],
    pub faces: &'m [FacePlane],
}

impl<'m> Parts<'m> {
    /// Triangles `range` as a mesh (with their baked face planes, if any).
    fn mesh(&self, range: core::ops::Range<usize>) -> Result<Mesh<'m>, Error> {
        let indices = self.indices.get(range.clone()).ok_or(Error::BadSize(0))?;
        let m = Mesh::new(self.positions, Some(self.normals), self.uvs, indices)?;
        match self.faces.get(range) {
            Some(f) if !self.faces.is_empty() => m.with_face_planes(f),
            _ => Ok(m),
        }
    }
}

/// Bins the triangles of `mesh` (walked with a vertex cache) into `bins`.
fn bin<'f, 'd>(
    draws: &'f [&'d dyn BandDraw<Rgb565>],
    draw: &Draw<'_, Rgb565>,
    mesh: &Mesh<'_>,
    transform: &MeshTransform,
    bins: &'f mut [Binned],
    cache: &mut [CachedVertex],
) -> Result<BinnedFrame<'f, 'd, Rgb565>, Error> {
    let light = DirectionalLight::default();
    BinnedFrame::new(draws, bins, |sink| {
        walk_mesh(
            draw,
            mesh,
            transform,
            Some(&light),
            cache,
            0,
            &mut ToBins(sink),
        );
    })
}

/// The frame on one hart, then on two; prints the checksums and pixels.
fn frame(scene: &str, draw: &Draw<'_, Rgb565>, parts: &Parts<'_>, model: &Mat4) -> bool {
    let transform = MeshTransform::new(model, &demo::camera(20));
    let draws: [&dyn BandDraw<Rgb565>; 1] = [draw];
    let n = parts.indices.len();
    let (Ok(whole), Ok(first), Ok(later)) =
        (parts.mesh(0..n), parts.mesh(0..n / 2), parts.mesh(n / 2..n))
    else {
        return false;
    };
    // SAFETY: each hart bins into its own half; the bins are read only after both are done.
    let bins = unsafe { &mut *core::ptr::addr_of_mut!(BIN_STORE) };
    // Pair 0 (empty): the marker overhead.
    bench_start();
    bench_end();

    // One core: bin, every band.
    bench_start();
    let nv = parts.positions.len();
    let one = bin(
        &draws,
        draw,
        &whole,
        &transform,
        &mut bins[..],
        cache(0, nv),
    )
    .and_then(|f| draw_share(&f, BandShare::ALL));
    bench_end();
    bench_mark();
    let one_sum = checksum();

    // Two cores: each bins half of the triangles (hart 0 the first), then draws its share
    // of the bands (hart 0 the even ones) from the joined bins.
    let (Ok(s0), Ok(s1)) = (BandShare::new(0, 2), BandShare::new(1, 2)) else {
        return false;
    };
    let (bins0, bins1) = bins.split_at_mut(BINS / 2);
    let (mut bins0, mut bins1) = (Some(bins0), Some(bins1));
    let (mut part0, mut part1) = (Err(Error::BadSize(0)), Err(Error::BadSize(0)));
    crate::smp::both(
        &mut || {
            bench_start();
            if let Some(b) = bins0.take() {
                part0 = bin(&draws, draw, &first, &transform, b, cache(0, nv));
            }
            bench_end();
            bench_mark();
        },
        &mut || {
            // Hart 1's pair 0: its marker overhead.
            bench_start();
            bench_end();
            bench_start();
            if let Some(b) = bins1.take() {
                part1 = bin(&draws, draw, &later, &transform, b, cache(1, nv));
            }
            bench_end();
            bench_mark();
        },
    );
    let Ok(binned) = part0.and_then(|a| a.join(part1?)) else {
        outln!("scene={} error=binning", scene);
        return false;
    };
    let (mut even, mut odd) = (Ok(0), Ok(0));
    crate::smp::both(
        &mut || {
            bench_start();
            even = draw_share(&binned, s0);
            bench_end();
            bench_mark();
        },
        &mut || {
            bench_start();
            odd = draw_share(&binned, s1);
            bench_end();
            bench_mark();
        },
    );
    let two_sum = checksum();
    match (one, even, odd) {
        (Ok(p1), Ok(p0), Ok(p2)) => {
            outln!(
                "scene={} checksum=0x{:08x} pixels={} two_checksum=0x{:08x} two_pixels={} triangles={}",
                scene,
                one_sum,
                p1,
                two_sum,
                p0 + p2,
                binned.triangles()
            );
            true
        }
        (a, b, c) => {
            outln!(
                "scene={} error={:?} {:?} {:?}",
                scene,
                a.err(),
                b.err(),
                c.err()
            );
            false
        }
    }
}

/// Frame 0 of scene `scene` (`cube`, `sphere` or `teapot`) on one core, then on two.
pub fn run(scene: &str) -> bool {
    let Ok(vp) = viewport() else {
        return false;
    };
    let sphere_texture = MipTexture::single(data::T256X128);
    let (draw, parts, model) = match scene {
        "cube" => {
            let m = demo::cube();
            let Ok(draw) = Draw::new_mip::<LitFootprint>(Some(data::T128_FP), vp, Cull::Back)
            else {
                return false;
            };
            // The cube's arrays live in this frame: drawn here.
            let parts = Parts {
                positions: &m.positions,
                normals: &m.normals,
                uvs: &m.uvs,
                indices: &m.indices,
                faces: &[],
            };
            return frame(scene, &draw, &parts, &demo::cube_model(0));
        }
        "sphere" => (
            Draw::new_mip::<LitSphere>(Some(sphere_texture), vp, Cull::Back),
            Parts {
                positions: &data::SPHERE.positions,
                normals: &data::SPHERE.normals,
                uvs: &data::SPHERE.uvs,
                indices: &data::SPHERE.indices,
                faces: &data::SPHERE_FACES,
            },
            demo::sphere_model(0),
        ),
        "teapot" => {
            use crate::data::teapot;
            (
                Draw::new_mip::<LitSphere>(Some(sphere_texture), vp, Cull::Back),
                Parts {
                    positions: &teapot::TEAPOT_POSITIONS,
                    normals: &teapot::TEAPOT_NORMALS,
                    uvs: &teapot::TEAPOT_UVS,
                    indices: &teapot::TEAPOT_INDICES,
                    faces: &[],
                },
                crate::scenes::teapot_model(0),
            )
        }
        _ => return false,
    };
    match draw {
        Ok(draw) => frame(scene, &draw, &parts, &model),
        Err(_) => false,
    }
}
