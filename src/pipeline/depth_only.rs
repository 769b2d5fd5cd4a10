//! The light pass of shadow mapping: triangles seen from the light, depth only, into a
//! [`DepthMap`].
//!
//! The same clipper, projection and edge walker as every other draw (so the same coverage
//! rules: top-left, pixel centres, 1/16-pixel snapping), with a span loop that keeps only
//! the depth plane: per texel one add, one compare and (when nearer) one store, `GL_LESS`.
//! No varyings, no set-up of anything but depth, no colour.
//!
//! Depth is the window depth of the light's clip space, `65535 (z/w + 1) / 2` truncated to
//! 16 bits (the set-up's plane carries 14 fraction bits), exactly what a colour draw's depth
//! buffer would hold.
//!
//! Culling is the caller's choice: [`Cull::Back`] keeps the faces the light sees;
//! [`Cull::Front`] keeps the back faces instead, which moves the stored depth to the far
//! side of closed objects and so removes self-shadowing acne on lit faces (at the price of
//! light leaking through where the back faces are missing, and of acne on faces turned away
//! from the light, which are dark anyway).

use crate::geometry::{clip_and_project_varyings, Cull, ScreenTriangle, Vertex, Viewport};
use crate::raster::gradient::PlaneSetup;
use crate::raster::{rasterize, Plane, SpanSink};
use crate::texture::DepthMap;
use crate::Error;

/// A depth-only draw into a shadow map of a given size.
///
/// ```
/// use fixel::prelude::*;
/// use fixel::pipeline::DepthOnlyDraw;
/// use fixel::surface::DepthMap;
///
/// // One triangle seen by the light, in the light's clip space (orthographic: w = 1).
/// let p = |x: f32, y: f32, z: f32| [Fx::from_num(x), Fx::from_num(y), Fx::from_num(z), Fx::ONE];
/// let tri = [Vertex::new(p(-0.9, -0.9, 0.0), []), Vertex::new(p(0.9, -0.9, 0.0), []),
///            Vertex::new(p(0.0, 0.9, 0.0), [])];
/// let mut texels = [0u16; 32 * 32];
/// let mut map = DepthMap::new(&mut texels, 32)?;
/// map.clear();
/// let light = DepthOnlyDraw::new(&map, Cull::Back)?;
/// let written = light.clip_triangles(&[tri], &mut map)?;
/// assert!(written > 300);
/// // z = 0 in NDC is the middle of the depth range.
/// assert_eq!(map.texels()[16 * 32 + 16], 32767);
/// // A map of another size than the pass was built for is refused, nothing drawn.
/// let mut small = [0u16; 16 * 16];
/// let mut small = DepthMap::new(&mut small, 16)?;
/// assert_eq!(light.clip_triangles(&[tri], &mut small), Err(Error::ShadowMapSizeMismatch(32)));
/// # Ok::<(), fixel::Error>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct DepthOnlyDraw {
    viewport: Viewport,
    cull: Cull,
}

impl DepthOnlyDraw {
    /// A light pass for maps of `map`'s size, culling `cull` faces (as seen from the light).
    ///
    /// # Errors
    /// None for a valid map (its size is checked where it was made); the `Result` keeps the
    /// viewport's own check.
    pub fn new(map: &DepthMap<'_>, cull: Cull) -> Result<Self, Error> {
        Ok(DepthOnlyDraw {
            viewport: Viewport::new(0, 0, map.size(), map.size())?,
            cull,
        })
    }

    /// The viewport (the whole map).
    pub fn viewport(&self) -> &Viewport {
        &self.viewport
    }

    /// Whether `map` is the size this light pass was built for.
    ///
    /// # Errors
    /// [`Error::ShadowMapSizeMismatch`] (with this pass's side) when it is not.
    pub fn check_map(&self, map: &DepthMap<'_>) -> Result<(), Error> {
        let side = self.viewport.width();
        if map.size() == side {
            Ok(())
        } else {
            Err(Error::ShadowMapSizeMismatch(side))
        }
    }

    /// Clips, projects, culls and draws triangles given in the light's clip space; returns
    /// the texels written (nearer than what was there). Any varyings are ignored.
    ///
    /// # Errors
    /// [`Error::ShadowMapSizeMismatch`] when `map` is not the size this pass was built for
    /// (nothing is drawn).
    pub fn clip_triangles<const N: usize>(
        &self,
        tris: &[[Vertex<N>; 3]],
        map: &mut DepthMap<'_>,
    ) -> Result<u32, Error> {
        self.check_map(map)?;
        Ok(self.clip_checked(tris, map))
    }

    /// [`DepthOnlyDraw::clip_triangles`] into a map already checked with
    /// [`DepthOnlyDraw::check_map`] (a mesh's light pass checks once, not per triangle).
    pub(crate) fn clip_checked<const N: usize>(
        &self,
        tris: &[[Vertex<N>; 3]],
        map: &mut DepthMap<'_>,
    ) -> u32 {
        let mut n = 0u32;
        for tri in tris {
            clip_and_project_varyings(tri, &self.viewport, self.cull, false, &mut |s| {
                n = n.wrapping_add(self.screen_triangle(s, map));
            });
        }
        n
    }

    /// Draws one screen triangle (already clipped, projected and culled) into `map`;
    /// returns the texels written.
    pub fn screen_triangle<const N: usize>(
        &self,
        tri: &ScreenTriangle<N>,
        map: &mut DepthMap<'_>,
    ) -> u32 {
        let rect = self.viewport.rect();
        let xy = [
            (tri[0].x, tri[0].y),
            (tri[1].x, tri[1].y),
            (tri[2].x, tri[2].y),
        ];
        // Coverage on the snapped grid, depth from the unsnapped positions.
        let Some(ps) = PlaneSetup::new(tri.map(|v| v.attr_position()), rect) else {
            return 0;
        };
        let mut sink = DepthSink {
            z: ps.plane([tri[0].z, tri[1].z, tri[2].z]),
            at: (ps.px_ref, ps.py_ref),
            map,
            written: 0,
        };
        rasterize(xy, rect, &mut sink);
        sink.written
    }
}

/// The depth-only span writer: one plane, one map.
struct DepthSink<'m, 'a> {
    z: Plane,
    at: (i32, i32),
    map: &'m mut DepthMap<'a>,
    written: u32,
}

impl SpanSink for DepthSink<'_, '_> {
    #[inline]
    fn span(&mut self, y: i32, x0: i32, x1: i32) {
        let z0 = self.z.at(self.at, x0, y);
        let dz = self.z.dx;
        let Some(row) = self.map.row_mut(y) else {
            return;
        };
        let (Ok(a), Ok(b)) = (usize::try_from(x0), usize::try_from(x1)) else {
            return;
        };
        let Some(texels) = row.get_mut(a..b) else {
            return;
        };
        self.written = self.written.wrapping_add(depth_span(z0, dz, texels));
    }
}

/// `GL_LESS` depth writes along one span: depth `z >> 14` saturated to 16 bits, `z` stepping
/// by `dz`. Returns the texels written.
#[inline(never)]
fn depth_span(z0: i32, dz: i32, texels: &mut [u16]) -> u32 {
    let mut z = z0;
    let mut n = 0u32;
    for t in texels.iter_mut() {
        let d = (z >> 14).clamp(0, 0xFFFF) as u16;
        if d < *t {
            *t = d;
            n += 1;
        }
        z = z.wrapping_add(dz);
    }
    n
}
