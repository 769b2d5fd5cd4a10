//! The geometry stage for meshes, done once per vertex where it can be: a cache of
//! *prepared* vertices (transformed, outcoded and projected), culling before lighting, and
//! a triangle filter that runs before any transform (for bands).
//!
//! Per triangle, in mesh order:
//!
//! 1. `next_wanted` (a band renderer scans for the next triangle that meets the band): the
//!    others are skipped untouched;
//! 2. a triangle with a corner not prepared yet that surely faces the culled way, by its
//!    model-space positions alone ([`face_cull`](super::face_cull)), is skipped: about two
//!    in three of the benchmark sphere's vertices are then never prepared. A triangle
//!    whose corners are all prepared meets the same test after the cheaper ones of step 4
//!    kept it: the two tests can disagree on a sliver whose projection rounds to the other
//!    orientation, and the model-space one must decide whatever the cache holds;
//! 3. its three vertices from the cache, or transformed by the model-view-projection
//!    matrix, outcoded against the view volume and guard band, and projected (3 `i64`
//!    divisions), then cached;
//! 4. all three outside one plane: skip. All three inside (the common case): the screen
//!    triangle is the three cached projections; cull it by its exact sub-pixel area, and
//!    only then light its vertices (a normal transform and a dot product, once per vertex,
//!    cached). Otherwise: the full clipper (`clip_and_project`) on freshly transformed and
//!    lit vertices.
//!
//! Every screen triangle is bit-identical to what [`draw_mesh`](super::draw_mesh) draws
//! (the same model-space test, then [`mesh_triangles`](super::mesh_triangles)' transforms
//! and [`Draw::project`]'s projection and culling test), so any path drawing a mesh gives
//! the same pixels.
//!
//! The cache is caller storage of [`CachedVertex`] (32 bytes each): with one entry per mesh
//! vertex each vertex is prepared once; shorter, it is direct-mapped (`index mod 2^k`),
//! which keeps the reuse of a mesh stored in strips (the demo sphere's rings need 64
//! entries); empty, nothing is cached (each corner is prepared on its own). A band
//! renderer's sink keeps the cache across its band passes ([`TriangleOut::fresh`]), and its
//! binning pass places vertices without the depth division (completed for the triangles a
//! band draws) and hands over positions alone ([`TriangleOut::triangle_rows`]). A band
//! pass's triangles, known to pass the cull, take the same path as a whole frame's: read
//! straight out of the cache.

use crate::color::TargetColor;
use crate::geometry::clip::{complete_depth, keeps_xy, prepare, prepare_without_depth};
use crate::geometry::{Cull, ScreenTriangle, ScreenVertex, COLOR_ONE};
use crate::math::{Fx, Mat4};
use crate::pipeline::{Draw, Shading};
use crate::raster::{ATTR_SUBPIXEL_BITS, SUBPIXEL_BITS};
use crate::surface::{MeshSink, RenderTarget};

use super::face_cull::{camera_centre, Eye, FaceCull, FacingTest};
use super::face_planes::FacePlane;
use super::mesh_draw::{vertex, vertex_intensity};
use super::vertex_uv::{MeshUvs, VertexUv};
use super::{Camera, DirectionalLight, Mesh};

const EMPTY: u8 = 0;
/// Transformed and projected; colour still white.
const PLACED: u8 = 1;
/// Placed and lit.
const LIT: u8 = 2;
/// Its position or normal overflows the fixed-point range: its triangles are skipped.
const FAILED: u8 = 3;
/// Placed without the depth division (binning): `z` holds the clip-space `z`.
const NO_DEPTH: u8 = 4;
/// The outcode bit of a [`FAILED`] vertex (the clipper's planes use bits 0 to 6): a
/// triangle's one test of its corners' outcodes or-ed together then also finds failed
/// corners, which the common case (all inside, none failed) then does not test apart.
const FAILED_CODE: u8 = 0x80;

/// Bits of the attribute offset below the sub-pixel grid.
const SUB_BITS: u32 = ATTR_SUBPIXEL_BITS - SUBPIXEL_BITS;

/// One prepared vertex: its projection (uv and one colour intensity), outcode and cache
/// key; 32 bytes, so copies stay a few word moves.
#[derive(Clone, Copy, Debug, Default)]
pub struct CachedVertex {
    /// Screen x and y: the sub-pixel position times `2^(SUB_BITS + 1)` plus the attribute
    /// offset (`ScreenVertex::sub`) plus `2^(SUB_BITS - 1)`, so the entry stays 32 bytes.
    x: i32,
    y: i32,
    z: i32,
    w: i32,
    uv: [i32; 2],
    /// Colour, one channel for all three (the walker's lighting is grey).
    color: u16,
    /// Vertex index in the low 16 bits, the low 16 bits of the mesh's first triangle id
    /// (meshes sharing a cache) in the high ones: one compare finds a hit.
    key: u32,
    outcode: u8,
    state: u8,
}

impl CachedVertex {
    /// An empty entry (all zero bits, so arrays of it can start zeroed in place).
    pub const EMPTY: CachedVertex = CachedVertex {
        x: 0,
        y: 0,
        z: 0,
        w: 0,
        uv: [0; 2],
        color: 0,
        key: 0,
        outcode: 0,
        state: EMPTY,
    };

    fn set_screen(&mut self, s: &ScreenVertex) {
        let [u, v, r, ..] = s.varyings;
        let pack = |p: i32, sub: i16| {
            p.wrapping_shl(SUB_BITS + 1)
                .wrapping_add(i32::from(sub) + (1 << (SUB_BITS - 1)))
        };
        (self.x, self.y, self.z, self.w, self.uv, self.color) = (
            pack(s.x, s.sub[0]),
            pack(s.y, s.sub[1]),
            s.z,
            s.w,
            [u, v],
            (r >> 16) as u16,
        );
    }

    /// The sub-pixel position of [`CachedVertex::screen`].
    #[inline(always)]
    fn xy(&self) -> (i32, i32) {
        (self.x >> (SUB_BITS + 1), self.y >> (SUB_BITS + 1))
    }

    /// The screen vertex with its texture coordinates; its colour varyings are left zero
    /// (the walker sets them once the vertex is lit).
    fn screen(&self) -> ScreenVertex {
        let sub = |p: i32| ((p & ((2 << SUB_BITS) - 1)) - (1 << (SUB_BITS - 1))) as i16;
        let (x, y) = self.xy();
        ScreenVertex {
            x,
            y,
            sub: [sub(self.x), sub(self.y)],
            z: self.z,
            w: self.w,
            varyings: [self.uv[0], self.uv[1], 0, 0, 0],
        }
    }
}

impl CachedVertex {
    /// [`CachedVertex::screen`] with its colour varyings: the vertex's intensity, capped at
    /// [`COLOR_ONE`], on every channel (as the walker completes them).
    #[inline(always)]
    fn screen_lit(&self) -> ScreenVertex {
        let mut s = self.screen();
        s.varyings[2..].fill(i32::from(self.color.min(COLOR_ONE)) << 16);
        s
    }
}

/// Where the walker's screen triangles go, and which triangles it should skip.
pub trait TriangleOut {
    /// True when every triangle is wanted and none is known to pass the cull
    /// ([`wants`](Self::wants) always true, [`kept`](Self::kept) always false, the window
    /// everything): a whole-frame draw. The walker then skips a run of triangles that
    /// the mesh's baked face planes cull in a loop of its own, without asking for each.
    const WANTS_EVERY: bool = false;
    /// [`WANTS_EVERY`](Self::WANTS_EVERY) known at run time: true for a pass that wants
    /// every triangle, knows none to pass the cull and has the whole window (a band
    /// renderer's binning pass), so the walker may skip runs of culled triangles there too.
    fn wants_every(&self) -> bool {
        Self::WANTS_EVERY
    }
    /// Whether triangle `id` is needed (checked before any of its vertices is touched).
    fn wants(&self, id: usize) -> bool;
    /// The first id in `id..end` that is wanted, or `end` (ids are then skipped without
    /// asking [`wants`](Self::wants) one by one). A band renderer answers from a tight scan
    /// of its band ranges: per skipped id, a loop of `wants` calls cost about 30
    /// instructions on Cortex-M0+, the scan about 8. An answer below `id` is taken as `id`
    /// (the walk always moves forward), one above `end` as `end`.
    fn next_wanted(&self, id: usize, end: usize) -> usize {
        (id..end).find(|&i| self.wants(i)).unwrap_or(end)
    }
    /// The ids that may be wanted, `lo..=hi` (the others are skipped without asking).
    fn window(&self) -> (usize, usize) {
        (0, usize::MAX)
    }
    /// Whether the cache must be emptied first (a new frame). When `false` the cache is
    /// trusted to hold this frame's vertices of this mesh (a band pass after the binning
    /// pass of the same frame).
    fn fresh(&self) -> bool {
        true
    }
    /// Whether triangle `id` is known to pass the cull test (a band pass after the binning
    /// pass pushed it, on the same screen positions): the walker then skips the test.
    fn kept(&self, _id: usize) -> bool {
        false
    }
    /// Whether pushed triangles need lighting (else their colour may stay white).
    fn attributes(&self) -> bool;
    /// One screen triangle of triangle `id`.
    fn triangle(&mut self, id: usize, tri: &ScreenTriangle);
    /// [`triangle`](Self::triangle) when [`attributes`](Self::attributes) is false: the
    /// screen triangle's positions alone (`x` and `y`; the rest zero). By default the same
    /// positions go to [`triangle`](Self::triangle) with zero depth and varyings.
    fn triangle_rows(&mut self, id: usize, tri: &ScreenTriangle<0>) {
        let at = |v: &ScreenVertex<0>| ScreenVertex {
            x: v.x,
            y: v.y,
            ..ScreenVertex::default()
        };
        self.triangle(id, &[at(&tri[0]), at(&tri[1]), at(&tri[2])]);
    }
}

/// A mesh's model-view and model-view-projection matrices (two 4x4 products: about 2,500
/// instructions on Cortex-M0+) and the camera's centre in model space (exact 3x3 minors of
/// the latter, for the model-space back-face test). Build it once per mesh and frame and hand it to every band
/// pass of [`mesh_to_sink`], rather than multiplying the matrices again in each band.
///
/// `G` is where each vertex's texture coordinates come from ([`VertexUv`]): the mesh's own
/// by default, or a generator given with [`MeshTransform::with_uvs`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeshTransform<G = MeshUvs> {
    model_view: Mat4,
    mvp: Mat4,
    /// The camera's centre in homogeneous model coordinates, for the model-space cull test
    /// (see `face_cull`): exact, once per frame.
    eye: Eye,
    uvs: G,
}

impl<G: VertexUv> MeshTransform<G> {
    /// The same transform with texture coordinates from `uvs`, computed as each vertex is
    /// prepared (once per vertex while it stays in the cache).
    pub fn with_uvs<H: VertexUv>(self, uvs: H) -> MeshTransform<H> {
        MeshTransform {
            model_view: self.model_view,
            mvp: self.mvp,
            eye: self.eye,
            uvs,
        }
    }

    /// The model-view matrix (`camera.view * model`).
    pub fn model_view(&self) -> &Mat4 {
        &self.model_view
    }
}

impl MeshTransform {
    /// `camera.view * model` and `camera.projection * camera.view * model`.
    pub fn new(model: &Mat4, camera: &Camera) -> Self {
        let model_view = camera.view.mul(model);
        let mvp = camera.projection.mul(&model_view);
        MeshTransform {
            eye: camera_centre(&mvp),
            mvp,
            model_view,
            uvs: MeshUvs,
        }
    }

    /// The model-space back-face test of `mesh` under this transform for `cull` (the one the
    /// mesh walker runs before transforming a triangle's vertices), or `None` for
    /// [`Cull::None`].
    pub fn facing_test<'m>(&self, mesh: &'m Mesh<'m>, cull: Cull) -> Option<FacingTest<'m>> {
        FacingTest::new(&self.eye, mesh, cull)
    }
}

/// The matrices and options of one mesh draw.
struct Ctx<'m, 'l> {
    mesh: &'m Mesh<'m>,
    model_view: Mat4,
    mvp: Mat4,
    light: Option<&'l DirectionalLight>,
}

/// Walks the triangles of `mesh` (ids `first_id..`), preparing vertices through `cache`,
/// and hands every visible screen triangle of `draw`'s viewport and culling to `out`.
/// Lighting is skipped when `draw` does not use vertex colours (then, unlike `draw_mesh`, a
/// normal that overflows the fixed-point range does not drop its triangles: unit normals
/// under a rotation never do). Returns the id after the last triangle
/// (`first_id + mesh.triangles()`).
#[allow(clippy::too_many_arguments)]
pub fn walk_mesh<C: TargetColor, O: TriangleOut, G: VertexUv>(
    draw: &Draw<'_, C>,
    mesh: &Mesh<'_>,
    transform: &MeshTransform<G>,
    light: Option<&DirectionalLight>,
    cache: &mut [CachedVertex],
    first_id: usize,
    out: &mut O,
) -> usize {
    let MeshTransform {
        model_view,
        mvp,
        ref eye,
        uvs,
    } = *transform;
    let coloured = matches!(
        draw.mode().shading,
        Shading::Modulate | Shading::ModulateIntensity | Shading::ModulateFacet | Shading::Gouraud
    );
    let ctx = Ctx {
        mesh,
        model_view,
        mvp,
        light: light.filter(|_| coloured),
    };
    let vp = draw.viewport();
    let cull = draw.mode().cull;
    // Triangles that surely face the culled way are dropped before their vertices are
    // prepared.
    let faces = FaceCull::new(eye, mesh, cull);
    // With baked face planes the model-space test runs first for every triangle (reading
    // one plane costs less than the cache lookups), and the position-based one never.
    let planes = mesh.face_planes;
    let (baked, faces) = if planes.is_empty() {
        (None, faces)
    } else {
        (faces.map(|f| (f, f.margin_max(mesh))), None)
    };
    let n = mesh.positions.len();
    // Without caller storage, four slots of the walker's own (the corners always have one).
    let mut spare = [CachedVertex::EMPTY; 4];
    let cache: &mut [CachedVertex] = if cache.is_empty() { &mut spare } else { cache };
    // Slot of vertex i: i itself when every vertex has one, else i mod 2^k.
    let mask = if cache.len() >= n {
        usize::MAX
    } else {
        (1usize << cache.len().max(1).ilog2()) - 1
    };
    // Entries are told apart by the low 16 bits of the mesh's first id: past 65535 the
    // cache is emptied on every call (correct, only slower).
    if out.fresh() || first_id > usize::from(u16::MAX) {
        for c in cache.iter_mut() {
            c.state = EMPTY;
        }
    }
    let tag = (first_id as u32 & 0xFFFF) << 16;
    let (lo, hi) = out.window();
    let len = mesh.indices.len();
    let start = lo.saturating_sub(first_id).min(len);
    let end = match hi.checked_sub(first_id) {
        Some(h) => h.saturating_add(1).min(len),
        None => 0,
    };
    let mut next = start;
    while next < end {
        // At least `from`: an implementation answering below `id` must not stall the walk.
        let from = first_id + next;
        let t = out
            .next_wanted(from, first_id + end)
            .max(from)
            .wrapping_sub(first_id);
        if t >= end {
            break;
        }
        next = t + 1;
        let id = first_id + t;
        let known = out.kept(id);
        // With baked planes a culled triangle reads nothing else, not even its indices.
        if !known && baked.is_some_and(|(f, m)| planes.get(t).is_some_and(|p| f.culls_plane(p, m)))
        {
            if SKIP_RUNS && out.wants_every() {
                if let Some((f, m)) = baked {
                    // The rest of the run of culled triangles, out of line (half of a
                    // closed mesh faces away, in long runs).
                    next = skip_culled(&f, m, planes, next, end);
                }
            }
            continue;
        }
        let Some(idx) = mesh.indices.get(t) else {
            break;
        };
        let full = out.attributes();
        let lit = full && ctx.light.is_some();
        // A triangle not known to pass the cull: its three corners prepared in their cache
        // slots, and only what the outcode and cull tests read copied out (12 bytes per
        // corner, not 32): a culled triangle (half of a closed mesh) copies nothing more.
        let slots = idx.map(|i| usize::from(i) & mask);
        let keys = idx.map(|i| u32::from(i) | tag);
        // A triangle known to pass the cull skips both tests. Else, with corners not
        // prepared yet: unless the triangle surely faces the culled way (then they are not
        // prepared for it), prepared now.
        let faced = if known {
            None
        } else {
            let missing = (0..3).any(|k| {
                cache
                    .get(slots[k])
                    .is_some_and(|c| c.key != keys[k] || c.state == EMPTY)
            });
            // The model-space test decides whatever the cache holds (it and the
            // screen-space test can disagree on a sliver whose projection rounds to the
            // other orientation). With a corner missing it runs first, as it then saves
            // preparing corners; with all three prepared it runs once the cheaper
            // screen-space test has kept a triangle inside the guard band, or before a
            // crossing one is clipped.
            if missing && faces.is_some_and(|f| f.culls(mesh.positions, idx)) {
                continue;
            }
            faces.filter(|_| !missing)
        };
        // The corners prepared in their cache slots, and only what the outcode and cull
        // tests read copied out (12 bytes per corner, not 32): a culled triangle (half of a
        // closed mesh) copies nothing more.
        let mut cut = [(0i32, 0i32, 0u8); 3];
        for k in 0..3 {
            let i = usize::from(idx[k]);
            if let Some(c) = cache.get_mut(slots[k]) {
                if c.key != keys[k] || c.state == EMPTY {
                    place(&ctx, vp, i, c, full);
                    generate_uv(&uvs, &ctx, i, c);
                    c.key = keys[k];
                }
                cut[k] = (c.x, c.y, c.outcode);
            }
        }
        let codes = [cut[0].2, cut[1].2, cut[2].2];
        let inside = codes[0] | codes[1] | codes[2] == 0;
        let xy = |k: usize| (cut[k].0 >> (SUB_BITS + 1), cut[k].1 >> (SUB_BITS + 1));
        if !known {
            // Cull from the cached positions: a culled triangle builds no screen vertices.
            if inside && !keeps_xy([xy(0), xy(1), xy(2)], cull) {
                continue;
            }
            if faced.is_some_and(|f| f.culls_out_of_line(mesh.positions, idx)) {
                continue;
            }
        }
        if !inside {
            to_clip(draw, &ctx, &uvs, idx, lit, id, codes, out);
            continue;
        }
        if !full {
            // Without attributes only the rows count (a band renderer's binning pass once
            // its bins are full): the positions alone, straight from the cut.
            let at = |k: usize| {
                let (x, y) = xy(k);
                ScreenVertex::<0> {
                    x,
                    y,
                    ..ScreenVertex::default()
                }
            };
            out.triangle_rows(id, &[at(0), at(1), at(2)]);
            continue;
        }
        // Corners in three distinct slots (always, with a slot per vertex), placed with
        // depth: lit where they lie and read straight out of the cache, without the copies
        // of the general path below (the same triangle).
        if slots[0] != slots[1] && slots[1] != slots[2] && slots[0] != slots[2] {
            let mut ready = true;
            for k in 0..3 {
                match cache.get_mut(slots[k]) {
                    Some(c) if c.state == PLACED || c.state == LIT => {
                        if lit && c.state == PLACED {
                            light_vertex(&ctx, usize::from(idx[k]), c);
                        }
                        ready &= c.state != FAILED;
                    }
                    _ => ready = false,
                }
            }
            if let (true, Some(a), Some(b), Some(c)) = (
                ready,
                cache.get(slots[0]),
                cache.get(slots[1]),
                cache.get(slots[2]),
            ) {
                out.triangle(id, &[a.screen_lit(), b.screen_lit(), c.screen_lit()]);
                continue;
            }
        }
        // The general path (a corner the binning pass left without depth, a corner whose
        // lighting failed, or two corners of a small cache sharing a direct-mapped slot,
        // where the later one replaced the earlier: placed again): the corners copied out
        // whole.
        let mut v: [CachedVertex; 3] = core::array::from_fn(|k| match cache.get(slots[k]) {
            Some(c) if c.key == keys[k] && c.state != EMPTY => *c,
            _ => {
                let i = usize::from(idx[k]);
                let mut c = CachedVertex::EMPTY;
                place(&ctx, vp, i, &mut c, full);
                generate_uv(&uvs, &ctx, i, &mut c);
                c.key = keys[k];
                c
            }
        });
        let mut tri = [v[0].screen(), v[1].screen(), v[2].screen()];
        // Complete what binning left out (depth), then light.
        let mut failed = false;
        for k in 0..3 {
            let before = v[k].state;
            if v[k].state == NO_DEPTH {
                complete_depth(&mut tri[k], vp);
                v[k].z = tri[k].z;
                v[k].state = PLACED;
            }
            if lit && v[k].state == PLACED {
                light_vertex(&ctx, usize::from(idx[k]), &mut v[k]);
            }
            if v[k].state != before {
                if let Some(c) = cache.get_mut(slots[k]) {
                    if c.key == v[k].key {
                        *c = v[k];
                    }
                }
            }
            failed |= v[k].state == FAILED;
            let c = i32::from(v[k].color.min(COLOR_ONE)) << 16;
            tri[k].varyings[2..].fill(c);
        }
        if failed {
            continue;
        }
        out.triangle(id, &tri);
    }
    first_id + mesh.indices.len()
}

/// Whether a whole-frame walk skips runs of culled triangles in [`skip_culled`]: on
/// Cortex-M4F that takes about 27 instructions per culled triangle where the walk's loop
/// takes 48, about 0.6 % of the whole-frame sphere; on RV32IMC it is about even (measure
/// with `cargo xtask mcu`). Not on ARMv6-M, whose plane test is four 64-bit products in
/// software (about 190 instructions either way): there the calls cost more than the loop
/// saves.
const SKIP_RUNS: bool = !crate::math::ARMV6M;

/// The first of `from..end` whose baked plane (`planes`) the test `f` (largest margin
/// `margin`) does not cull, or `end`: the rest of a run of culled triangles, in a loop that
/// keeps its few values in registers (inlined into the walk, it shared the registers of
/// the whole loop).
#[inline(never)]
fn skip_culled(f: &FaceCull, margin: u64, planes: &[FacePlane], from: usize, end: usize) -> usize {
    let end = end.min(planes.len());
    let mut t = from;
    while t < end && planes.get(t).is_some_and(|p| f.culls_plane(p, margin)) {
        t += 1;
    }
    t
}

/// A triangle with a corner outside the view volume or guard band (`codes`, its corners'
/// outcodes): clipped, unless a corner failed (overflowed) or all three are outside one
/// plane.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn to_clip<C: TargetColor, G: VertexUv>(
    draw: &Draw<'_, C>,
    ctx: &Ctx<'_, '_>,
    uvs: &G,
    idx: &[u16; 3],
    lit: bool,
    id: usize,
    codes: [u8; 3],
    out: &mut impl TriangleOut,
) {
    let any = codes[0] | codes[1] | codes[2];
    if any & FAILED_CODE == 0 && codes[0] & codes[1] & codes[2] == 0 {
        clipped(draw, ctx, uvs, idx, lit, id, out);
    }
}

/// Transforms, outcodes and projects vertex `i` into `c` (white, not lit yet; without
/// the depth division unless `depth`).
fn place(
    ctx: &Ctx<'_, '_>,
    vp: &crate::geometry::Viewport,
    i: usize,
    c: &mut CachedVertex,
    depth: bool,
) {
    match vertex(ctx.mesh, i as u16, &ctx.model_view, &ctx.mvp, None) {
        Some(v) => {
            let (outcode, screen) = if depth {
                prepare(&v, vp)
            } else {
                prepare_without_depth(&v, vp)
            };
            c.outcode = outcode;
            c.set_screen(&screen);
            c.state = if depth { PLACED } else { NO_DEPTH };
        }
        None => {
            c.state = FAILED;
            c.outcode = FAILED_CODE;
        }
    }
}

/// Replaces the texture coordinates of placed vertex `i` with those of the walk's source
/// (nothing at all for the mesh's own, [`VertexUv::GENERATES`] false); a vertex whose
/// source fails is marked failed, as an overflowing position is.
#[inline(always)]
fn generate_uv<G: VertexUv>(uvs: &G, ctx: &Ctx<'_, '_>, i: usize, c: &mut CachedVertex) {
    if !G::GENERATES || c.state == FAILED {
        return;
    }
    let was = [Fx::from_bits(c.uv[0]), Fx::from_bits(c.uv[1])];
    match uvs.uv(ctx.mesh, i, &ctx.model_view, was) {
        Some(uv) => c.uv = [uv[0].to_bits(), uv[1].to_bits()],
        None => {
            c.state = FAILED;
            c.outcode = FAILED_CODE;
        }
    }
}

/// Lights a placed vertex (its colour becomes the light's intensity on all channels).
/// Inlined on ARMv7-M, where the walk calls it at two places: that saves a fraction of an
/// instruction per pixel of the Cortex-M4F whole-frame sphere for 56 bytes of flash.
#[cfg_attr(all(target_arch = "arm", target_has_atomic = "32"), inline(always))]
fn light_vertex(ctx: &Ctx<'_, '_>, i: usize, c: &mut CachedVertex) {
    let Some(l) = ctx.light else {
        return;
    };
    match vertex_intensity(ctx.mesh, i, &ctx.model_view, l) {
        Some(q) => {
            c.color = q;
            c.state = LIT;
        }
        None => {
            c.state = FAILED;
            c.outcode |= FAILED_CODE;
        }
    }
}

/// A triangle that crosses a clip plane: the full clipper on fresh vertices. Out of line:
/// its polygon buffers (over a kilobyte of stack) would otherwise sit in the walker's
/// frame, where on Cortex-M0+ every store beyond 1 KB of the stack pointer costs four
/// instructions instead of one.
#[inline(never)]
fn clipped<C: TargetColor, G: VertexUv>(
    draw: &Draw<'_, C>,
    ctx: &Ctx<'_, '_>,
    uvs: &G,
    idx: &[u16; 3],
    lit: bool,
    id: usize,
    out: &mut impl TriangleOut,
) {
    let light = if lit { ctx.light } else { None };
    let v = |k: usize| {
        let mut v = vertex(ctx.mesh, idx[k], &ctx.model_view, &ctx.mvp, light)?;
        if G::GENERATES {
            let i = usize::from(idx[k]);
            v.uv = uvs.uv(ctx.mesh, i, &ctx.model_view, v.uv)?;
        }
        Some(v)
    };
    if let (Some(a), Some(b), Some(c)) = (v(0), v(1), v(2)) {
        draw.project(&[a, b, c], &mut |s| out.triangle(id, s));
    }
}

/// Sends a mesh's triangles to a band renderer's sink (see
/// [`BandRenderer::render_spans`](crate::surface::BandRenderer::render_spans)): triangles
/// the band does not need are skipped before their vertices are transformed. `draw` must be
/// `draws[draw_index]` of the renderer; `transform` is built once per frame, outside the
/// band closure. Returns the next free triangle id.
#[allow(clippy::too_many_arguments)]
pub fn mesh_to_sink<C: TargetColor, G: VertexUv>(
    draw: &Draw<'_, C>,
    draw_index: u8,
    mesh: &Mesh<'_>,
    transform: &MeshTransform<G>,
    light: Option<&DirectionalLight>,
    cache: &mut [CachedVertex],
    first_id: usize,
    sink: &mut MeshSink<'_, '_, '_, C>,
) -> usize {
    struct ToSink<'x, 's, 'f, 'a, C: TargetColor> {
        sink: &'x mut MeshSink<'s, 'f, 'a, C>,
        draw: u8,
    }
    impl<C: TargetColor> TriangleOut for ToSink<'_, '_, '_, '_, C> {
        fn wants(&self, id: usize) -> bool {
            self.sink.wants(id)
        }
        fn next_wanted(&self, id: usize, end: usize) -> usize {
            self.sink.next_wanted(id, end)
        }
        fn window(&self) -> (usize, usize) {
            self.sink.window()
        }
        fn fresh(&self) -> bool {
            self.sink.fresh()
        }
        fn wants_every(&self) -> bool {
            // The binning pass: every id wanted, none known to pass the cull.
            self.sink.fresh()
        }
        fn kept(&self, id: usize) -> bool {
            self.sink.binned(id)
        }
        fn attributes(&self) -> bool {
            self.sink.attributes()
        }
        fn triangle(&mut self, id: usize, tri: &ScreenTriangle) {
            self.sink.push(id, self.draw, tri);
        }
        fn triangle_rows(&mut self, id: usize, tri: &ScreenTriangle<0>) {
            self.sink
                .push_rows::<{ crate::geometry::CLASSIC_VARYINGS }>(id, self.draw, tri);
        }
    }
    let mut out = ToSink {
        sink,
        draw: draw_index,
    };
    walk_mesh(draw, mesh, transform, light, cache, first_id, &mut out)
}

/// Draws `mesh` into `target` through the vertex cache (`cache`: one entry per vertex for
/// a single pass per vertex; any length works); returns the pixels written. Same pixels as
/// [`draw_mesh`](super::draw_mesh), and the same [`Error::NoDepthBuffer`](crate::Error).
pub fn draw_mesh_walked<C: TargetColor, T: RenderTarget<Color = C>, G: VertexUv>(
    draw: &Draw<'_, C>,
    mesh: &Mesh<'_>,
    transform: &MeshTransform<G>,
    light: Option<&DirectionalLight>,
    cache: &mut [CachedVertex],
    target: &mut T,
) -> Result<u32, crate::Error> {
    draw.check_target(target)?;
    struct ToTarget<'x, 'd, 'a, C: TargetColor, T> {
        draw: &'d Draw<'a, C>,
        target: &'x mut T,
        pixels: u32,
    }
    impl<C: TargetColor, T: RenderTarget<Color = C>> TriangleOut for ToTarget<'_, '_, '_, C, T> {
        const WANTS_EVERY: bool = true;
        fn wants(&self, _: usize) -> bool {
            true
        }
        fn attributes(&self) -> bool {
            true
        }
        fn triangle(&mut self, _: usize, tri: &ScreenTriangle) {
            let p = self.draw.screen_triangle_checked(tri, self.target);
            self.pixels = self.pixels.wrapping_add(p);
        }
    }
    let mut out = ToTarget {
        draw,
        target,
        pixels: 0,
    };
    walk_mesh(draw, mesh, transform, light, cache, 0, &mut out);
    Ok(out.pixels)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::{walk_mesh, CachedVertex, MeshTransform, TriangleOut};
    use crate::geometry::{Cull, ScreenTriangle, Viewport};
    use crate::pipeline::{Draw, DrawMode, Shading};
    use crate::test_scenes as demo;
    use embedded_graphics_core::pixelcolor::Rgb565;
    use std::vec::Vec;

    /// Records the triangles it is given; `next_wanted` answers with `answer(id, end)`.
    struct Recorder<F: Fn(usize, usize) -> usize> {
        answer: F,
        seen: Vec<usize>,
    }

    impl<F: Fn(usize, usize) -> usize> TriangleOut for Recorder<F> {
        fn wants(&self, _: usize) -> bool {
            true
        }
        fn next_wanted(&self, id: usize, end: usize) -> usize {
            (self.answer)(id, end)
        }
        fn attributes(&self) -> bool {
            true
        }
        fn triangle(&mut self, id: usize, _: &ScreenTriangle) {
            self.seen.push(id);
        }
    }

    fn walk(answer: impl Fn(usize, usize) -> usize) -> Vec<usize> {
        let cube = demo::cube();
        let mesh = cube.mesh().expect("the demo cube");
        let vp = Viewport::new(0, 0, 320, 240).expect("a viewport");
        let mode = DrawMode {
            shading: Shading::Gouraud,
            cull: Cull::None,
            ..DrawMode::default()
        };
        let draw = Draw::<Rgb565>::dynamic(mode, None, vp).expect("an untextured draw");
        let transform = MeshTransform::new(&demo::cube_model(10), &demo::camera(20));
        let mut cache = [CachedVertex::default(); 8];
        let mut out = Recorder {
            answer,
            seen: Vec::new(),
        };
        walk_mesh(&draw, &mesh, &transform, None, &mut cache, 5, &mut out);
        out.seen
    }

    /// Records each triangle's id and corner positions; asks for attributes when `full`.
    struct Positions {
        full: bool,
        seen: Vec<(usize, [(i32, i32); 3])>,
    }

    impl TriangleOut for Positions {
        fn wants(&self, _: usize) -> bool {
            true
        }
        fn attributes(&self) -> bool {
            self.full
        }
        fn triangle(&mut self, id: usize, tri: &ScreenTriangle) {
            if !self.full {
                // Through the default `triangle_rows`: positions alone.
                assert!(tri
                    .iter()
                    .all(|v| v.z == 0 && v.w == 0 && v.varyings == [0; 5]));
            }
            self.seen.push((id, tri.map(|v| (v.x, v.y))));
        }
    }

    /// Without attributes the walker hands over the very positions it hands over with them
    /// (the rows a band renderer's binning pass counts), for the same triangles, whatever
    /// the cache: a slot per vertex, direct-mapped, or so short that corners of one
    /// triangle share a slot (16 entries: the sphere's rings are 49 vertices apart).
    #[test]
    fn rows_alone_are_the_positions_of_the_full_walk() {
        let sphere = demo::sphere();
        let mesh = sphere.mesh().expect("the demo sphere");
        let vp = Viewport::new(0, 0, 320, 240).expect("a viewport");
        let mode = DrawMode {
            shading: Shading::Gouraud,
            cull: Cull::Back,
            ..DrawMode::default()
        };
        let draw = Draw::<Rgb565>::dynamic(mode, None, vp).expect("an untextured draw");
        let transform = MeshTransform::new(&demo::sphere_model(3), &demo::camera(20));
        for len in [mesh.vertices(), 64, 16, 0] {
            let run = |full: bool| {
                let mut cache = std::vec![CachedVertex::default(); len];
                let mut out = Positions {
                    full,
                    seen: Vec::new(),
                };
                walk_mesh(&draw, &mesh, &transform, None, &mut cache, 0, &mut out);
                out.seen
            };
            let full = run(true);
            assert!(full.len() > 500, "{} triangles", full.len());
            assert_eq!(run(false), full, "cache of {len}");
        }
    }

    /// The model-space back-face test spares the far side's vertices: with back faces
    /// culled, the demo sphere prepares well under half of its vertices, and draws exactly
    /// the triangles it draws without the test (every triangle it drops faces away).
    #[test]
    fn back_faces_are_dropped_before_their_vertices_are_prepared() {
        let sphere = demo::sphere();
        let mesh = sphere.mesh().expect("the demo sphere");
        let vp = Viewport::new(0, 0, 320, 240).expect("a viewport");
        let transform = MeshTransform::new(&demo::sphere_model(0), &demo::camera(20));
        let run = |cull: Cull| {
            let mode = DrawMode {
                shading: Shading::Gouraud,
                cull,
                ..DrawMode::default()
            };
            let draw = Draw::<Rgb565>::dynamic(mode, None, vp).expect("an untextured draw");
            let mut cache = std::vec![CachedVertex::default(); mesh.vertices()];
            let mut out = Recorder {
                answer: |id: usize, _: usize| id,
                seen: Vec::new(),
            };
            walk_mesh(&draw, &mesh, &transform, None, &mut cache, 0, &mut out);
            let prepared = cache.iter().filter(|c| c.state != super::EMPTY).count();
            (out.seen, prepared)
        };
        let (none, all_prepared) = run(Cull::None);
        let (back, prepared) = run(Cull::Back);
        let (front, _) = run(Cull::Front);
        // Without culling every referenced vertex is prepared (two of the 1,225 are not).
        assert!(all_prepared + 2 >= mesh.vertices());
        assert!(
            prepared * 2 < all_prepared,
            "{prepared} of {all_prepared} vertices prepared"
        );
        // Back and front culling split the drawn triangles between them (none is edge-on
        // here), as the screen-space test alone would.
        let mut both: Vec<usize> = back.iter().chain(front.iter()).copied().collect();
        both.sort_unstable();
        assert_eq!(both, none);
    }

    /// Whatever `next_wanted` answers, the walk moves forward and ends: an answer below
    /// `id` is `id`, one past `end` ends the walk, and a faithful answer visits every
    /// triangle once, in order.
    #[test]
    fn the_walk_moves_forward_whatever_next_wanted_answers() {
        let all = walk(|id, _| id);
        assert!(!all.is_empty(), "the cube draws something");
        assert!(all.windows(2).all(|w| w[0] < w[1]), "{all:?}");
        assert_eq!(walk(|_, _| 0), all, "an answer below id");
        assert_eq!(
            walk(|_, _| usize::MAX),
            Vec::<usize>::new(),
            "an answer past end"
        );
        let odd = walk(|id, end| (id..end).find(|i| i % 2 == 1).unwrap_or(end));
        let want: Vec<usize> = all.iter().copied().filter(|i| i % 2 == 1).collect();
        assert_eq!(odd, want, "every other id");
    }
}
