//! Open-stage geometry into a band renderer: the triangles of any [`ShadedDraw`], by id,
//! to a [`MeshSink`] (see
//! [`BandRenderer::render_spans`](crate::surface::BandRenderer::render_spans)).

use crate::color::TargetColor;
use crate::geometry::{ScreenTriangle, Vertex};
use crate::pipeline::{DepthStage, ProjectionStage, ShadedDraw};
use crate::shading::Shader;
use crate::surface::{Binnable, MeshSink};

/// Sends triangles `first_id..first_id + count` of an open-stage mesh to a band
/// renderer's sink: for each id the pass wants, `triangle(k, attributes)` (`k` counted from
/// 0) builds the triangle's clip-space vertices (`None` skips it), which `draw` clips,
/// projects and culls, and the sink takes as draw `draw_index` of the renderer. Triangles a
/// band does not meet are skipped before `triangle` runs, so the vertices are computed in
/// the binning pass and in the bands a triangle meets only. When `attributes` is `false`
/// (the binning pass, once the bins are full: only the rows count) the varyings may be
/// anything, zeros say, and costly per-vertex work can be skipped; the positions must be the
/// same in every pass, and a triangle skipped with `None` then must be skipped when
/// `attributes` is `true` too, or given the same positions. Returns the next free triangle
/// id (`first_id + count`).
///
/// ```
/// use fixel::prelude::*;
/// use fixel::geometry::Vertex;
/// use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
/// use fixel::scene::triangles_to_sink;
/// use fixel::shading::Gouraud;
/// use fixel::surface::{BandRange, Binned};
/// use fixel::Rgb565;
///
/// let draw = ShadedDraw::<_, Exact, NoDepth>::new(Gouraud, Viewport::new(0, 0, 32, 32)?, Cull::None)?;
/// let one = 256 << 16;
/// let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
/// let tris = [[
///     Vertex::new(p(-0.9, -0.9), [one, 0, 0]),
///     Vertex::new(p(0.9, -0.9), [0, one, 0]),
///     Vertex::new(p(0.0, 0.9), [0, 0, one]),
/// ]];
/// let mut color = [Rgb565::default(); 32 * 8];
/// let mut ranges = [BandRange::EMPTY; 1];
/// let mut bands = BandRenderer::new(&mut color, 32, 8, 32)?;
/// let stats = bands.render_spans(&[&draw], &mut [] as &mut [Binned], &mut ranges, Rgb565::default(), |sink| {
///     triangles_to_sink(&draw, 0, tris.len(), 0, |k, _| tris.get(k).copied(), sink);
/// }, |_band| Ok::<(), core::convert::Infallible>(()))?;
/// assert!(stats.reprojected && stats.pixels > 300);
/// # Ok::<(), fixel::Error>(())
/// ```
pub fn triangles_to_sink<S, P, D, C, const N: usize>(
    draw: &ShadedDraw<S, P, D>,
    draw_index: u8,
    count: usize,
    first_id: usize,
    mut triangle: impl FnMut(usize, bool) -> Option<[Vertex<N>; 3]>,
    sink: &mut MeshSink<'_, '_, '_, C>,
) -> usize
where
    S: Shader<Varyings = [i32; N]>,
    P: ProjectionStage,
    D: DepthStage,
    C: TargetColor,
    ScreenTriangle<N>: Binnable,
{
    let end = first_id.saturating_add(count);
    let (lo, hi) = sink.window();
    let stop = end.min(hi.saturating_add(1));
    let mut id = first_id.max(lo);
    while id < stop {
        id = sink.next_wanted(id, stop);
        if id >= stop {
            break;
        }
        let attributes = sink.attributes();
        if let Some(v) = triangle(id - first_id, attributes) {
            if attributes {
                draw.project(&v, &mut |s| sink.push(id, draw_index, s));
            } else {
                // Rows only: the positions projected without the varyings.
                let p = v.map(|x| Vertex::new(x.position, []));
                draw.project(&p, &mut |s| sink.push_rows::<N>(id, draw_index, s));
            }
        }
        id += 1;
    }
    end
}
