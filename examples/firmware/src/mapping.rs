//! Texture-coordinate generation on microcontrollers (`report_mapping`, shared with the
//! host report): each generator over a mesh's vertices, and a triplanar frame. The same
//! code runs on the host, so checksums compare bit for bit.

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Viewport};
use fixel::math::{Fx, Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::scene::{
    Axis, Camera, DirectionalLight, Intermediate, OMapping, TwoStage, UvAt, UvGenerator, UvMapping,
};
use fixel::shading::triplanar::{Triplanar, TriplanarMesh};
use fixel::shading::uv_per_pixel::{PerPixelMesh, PerPixelUv};
use fixel::surface::Frame;
use fixel::texture::{Bilinear, Texture};
use fixel::Error;

/// Triplanar frame size.
pub const W: u32 = 240;
/// Triplanar frame height.
pub const H: u32 = 180;

/// The per-vertex generators measured, by report name.
pub const GENERATORS: [&str; 5] = [
    "uv-planar",
    "uv-cylindrical",
    "uv-spherical",
    "two-stage-cylinder-normal",
    "two-stage-sphere-reflected",
];

/// FNV-1a over the coordinates' bits.
pub fn checksum(uvs: &[[Fx; 2]]) -> u32 {
    let mut h = 0x811C_9DC5u32;
    for uv in uvs {
        for c in uv {
            for b in c.to_bits().to_le_bytes() {
                h = (h ^ u32::from(b)).wrapping_mul(0x0100_0193);
            }
        }
    }
    h
}

fn each<G: UvGenerator>(g: &G, p: &[Vec3], n: &[Vec3], out: &mut [[Fx; 2]]) -> Result<(), Error> {
    let r = g.ready()?;
    for ((o, &pp), &nn) in out.iter_mut().zip(p).zip(n) {
        *o = r.at(pp, nn).0;
    }
    Ok(())
}

/// Coordinates of every vertex under generator `k` of [`GENERATORS`] into `out` (per
/// vertex, no seam handling: the per-vertex cost).
#[inline(never)]
pub fn generate(k: usize, p: &[Vec3], n: &[Vec3], out: &mut [[Fx; 2]]) -> Result<(), Error> {
    let axis = Axis::Y;
    let center = Vec3::ZERO;
    match k {
        0 => each(
            &UvMapping::Planar {
                origin: Vec3::from_num(-3, 1.75, 0),
                s: Vec3::from_num(1.0 / 6.5, 0, 0),
                t: Vec3::from_num(0, -1.0 / 3.5, 0),
            },
            p,
            n,
            out,
        ),
        1 => each(
            &UvMapping::Cylindrical {
                center,
                axis,
                top: Fx::from_num(1.6),
                bottom: Fx::from_num(-1.6),
            },
            p,
            n,
            out,
        ),
        2 => each(&UvMapping::Spherical { center, axis }, p, n, out),
        3 => each(
            &TwoStage {
                surface: Intermediate::Cylinder {
                    center,
                    axis,
                    radius: Fx::from_num(4),
                    top: Fx::from_num(2),
                    bottom: Fx::from_num(-2),
                },
                rule: OMapping::ObjectNormal,
            },
            p,
            n,
            out,
        ),
        _ => each(
            &TwoStage {
                surface: Intermediate::Sphere {
                    center,
                    axis,
                    radius: Fx::from_num(4),
                },
                rule: OMapping::ReflectedRay {
                    eye: Vec3::from_num(0, 3, 10),
                },
            },
            p,
            n,
            out,
        ),
    }
}

/// Which per-pixel frame [`frame`] draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PerPixel {
    /// Triplanar mapping (`fixel::shading::triplanar`).
    Triplanar,
    /// Cylindrical coordinates computed per pixel (`fixel::shading::uv_per_pixel`).
    Cylindrical,
}

/// The triplanar teapot frame: model and camera of the report.
pub fn triplanar_model() -> Mat4 {
    Mat4::translation(Vec3::from_num(0.2, -0.1, -6.5))
        * Mat4::rotation_x(fixel::math::Angle::from_degrees(Fx::from_num(20)))
        * Mat4::rotation_y(fixel::math::Angle::from_degrees(Fx::from_num(-30)))
}

/// Draws the triplanar teapot (`p`, `n`, `ix`) into `color`/`depth` (`W x H`), the
/// triangles one at a time (no storage), and returns `(checksum, pixels)`; `pause` and
/// `resume` bracket the checksum.
#[allow(clippy::too_many_arguments)]
pub fn triplanar_frame(
    kind: PerPixel,
    tex: Texture<'_>,
    p: &[Vec3],
    n: &[Vec3],
    ix: &[[u16; 3]],
    color: &mut [Rgb565],
    depth: &mut [u16],
    pause: &mut dyn FnMut(),
    resume: &mut dyn FnMut(),
) -> Result<(u32, u32), Error> {
    let mut frame = Frame::new(color, W, H)?.with_depth(depth)?;
    frame.clear(Rgb565::new(26, 54, 28));
    let camera = Camera::perspective(
        fixel::math::Angle::from_degrees(Fx::from_num(40)),
        Fx::from_num(4) / 3,
        Fx::from_num(0.5),
        Fx::from_num(30),
    )?;
    let light = DirectionalLight::default();
    let vp = Viewport::new(0, 0, W, H)?;
    let mut pixels = 0u32;
    let mut err = Ok(());
    match kind {
        PerPixel::Triplanar => {
            let draw = ShadedDraw::<_, Exact, DepthLess>::new(
                Triplanar::new(tex, Bilinear),
                vp,
                Cull::Back,
            )?;
            let mesh = TriplanarMesh {
                positions: p,
                normals: n,
                indices: ix,
                texels_per_unit: Fx::from_num(40),
            };
            mesh.triangles(&triplanar_model(), &camera, Some(&light), |t| {
                match draw.clip_triangles(core::slice::from_ref(t), &mut frame) {
                    Ok(n) => pixels += n,
                    Err(e) => err = Err(e),
                }
            });
        }
        PerPixel::Cylindrical => {
            let mapping = UvMapping::Cylindrical {
                center: Vec3::ZERO,
                axis: Axis::Y,
                top: Fx::from_num(1.6),
                bottom: Fx::from_num(-1.6),
            };
            let draw = ShadedDraw::<_, Exact, DepthLess>::new(
                PerPixelUv::new(tex, &mapping, Bilinear)?,
                vp,
                Cull::Back,
            )?;
            let mesh = PerPixelMesh {
                positions: p,
                normals: Some(n),
                indices: ix,
            };
            mesh.triangles(&triplanar_model(), &camera, Some(&light), |t| {
                match draw.clip_triangles(core::slice::from_ref(t), &mut frame) {
                    Ok(n) => pixels += n,
                    Err(e) => err = Err(e),
                }
            });
        }
    }
    err?;
    pause();
    let mut f = crate::scenes::Fnv1a::default();
    f.pixels(frame.pixels());
    resume();
    Ok((f.0, pixels))
}
