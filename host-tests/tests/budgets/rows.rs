//! The measured rows: each scene in every fixel projection against the reference, and the
//! summary table of the worst case over the scenes.

use std::fmt::Write as _;

use fixel::pipeline::Projection;
use host_tests::adapter;
use host_tests::metrics::{self, Report};
use host_tests::reference::{self, RefFilter, RefImage, RefMode, RefProjection};

use crate::cases::Scene;
use crate::detail::{detail, render_uv, uv_geometry, Detail};

const PROJECTIONS: [(&str, Projection); 8] = [
    ("Exact", Projection::Exact),
    ("Subdivided N=4", Projection::Subdivided { log2_n: 2 }),
    ("Subdivided N=8", Projection::Subdivided { log2_n: 3 }),
    ("Subdivided N=16", Projection::Subdivided { log2_n: 4 }),
    ("Subdivided N=32", Projection::Subdivided { log2_n: 5 }),
    ("Quadratic N=16", Projection::Quadratic { log2_n: 4 }),
    ("Quadratic N=32", Projection::Quadratic { log2_n: 5 }),
    ("Affine", Projection::Affine),
];

fn render_ref(sc: &Scene, filter: RefFilter, proj: RefProjection) -> RefImage {
    let mode = RefMode {
        filter,
        projection: proj,
        ..sc.mode
    };
    reference::render(&sc.tris, sc.tex.as_ref(), &mode, sc.width, sc.height)
}

pub struct Row {
    pub order: usize,
    pub scene: String,
    pub shading: &'static str,
    pub filter: &'static str,
    pub projection: &'static str,
    /// Interpolation of the reference: the same as fixel's (implementation
    /// error) or perspective for Affine (the cost of choosing the mode).
    pub same: bool,
    pub rep: Report,
    /// Per-pixel detail (textured scenes only).
    pub detail: Option<Detail>,
}

/// A reference image quantised once, with its uv geometry when textured.
pub struct Ref {
    pub q: Vec<u16>,
    pub covered: Vec<bool>,
    pub geo: Option<Vec<(f64, f64)>>,
}

pub fn reference_for(sc: &Scene, filter: RefFilter, proj: RefProjection) -> Ref {
    let r = render_ref(sc, filter, proj);
    Ref {
        q: r.quantize_rgb565(),
        covered: r.covered,
        geo: sc
            .tex
            .as_ref()
            .filter(|_| sc.textured())
            .map(|t| uv_geometry(&render_uv(sc, proj), t)),
    }
}

pub fn measure(sc: &Scene, si: usize, filter: RefFilter) -> Vec<Row> {
    let clip = adapter::clip_triangles(&sc.tris);
    let ref_p = reference_for(sc, filter, RefProjection::Perspective);
    let ref_a = reference_for(sc, filter, RefProjection::Affine);
    let filter_name = match (sc.textured(), filter) {
        (false, _) => "-",
        (true, RefFilter::Nearest) => "Nearest",
        (true, RefFilter::Bilinear) => "Bilinear",
    };
    let mut rows = Vec::new();
    for &(pname, proj) in &PROJECTIONS {
        let mode = adapter::draw_mode(&RefMode { filter, ..sc.mode }, Some(proj), sc.intensity);
        let f = adapter::render(&clip, sc.tex.as_ref(), mode, sc.width, sc.height);
        let mut push = |same: bool, r: &Ref| {
            rows.push(Row {
                order: si * 2 + usize::from(filter == RefFilter::Nearest),
                scene: sc.name.clone(),
                shading: sc.shading_name(),
                filter: filter_name,
                projection: pname,
                same,
                rep: metrics::compare_rgb565(&f.pixels, &f.covered, &r.q, &r.covered),
                detail: r
                    .geo
                    .as_ref()
                    .filter(|_| same)
                    .map(|g| detail(&f.pixels, &f.covered, &r.q, &r.covered, g)),
            })
        };
        if proj == Projection::Affine {
            push(true, &ref_a);
            push(false, &ref_p);
        } else {
            push(true, &ref_p);
        }
    }
    rows
}

/// One line per (reference, filter, projection): the worst case over the
/// scenes (Flat excluded: it is exact everywhere).
pub fn summary(rows: &[Row]) -> String {
    let mut s = String::from(
        "### Summary (worst case over the scenes)\n\n\
         | projection | filter | reference | max LSB | p99 | >1 LSB | >2 LSB | min PSNR dB | cov diff |\n\
         |---|---|---|---:|---:|---:|---:|---:|---:|\n",
    );
    for same in [true, false] {
        for filter in ["Bilinear", "Nearest", "-"] {
            for &(p, _) in &PROJECTIONS {
                if !same && p != "Affine" {
                    continue;
                }
                let sel: Vec<&Row> = rows
                    .iter()
                    .filter(|r| {
                        r.projection == p
                            && r.filter == filter
                            && r.same == same
                            && r.shading != "Flat"
                            && !(r.scene == "floor" && p == "Affine" && same)
                    })
                    .collect();
                if sel.is_empty() {
                    continue;
                }
                let max = sel.iter().map(|r| r.rep.max).max().unwrap_or(0);
                let p99 = sel.iter().map(|r| r.rep.p99).max().unwrap_or(0);
                let o1 = sel.iter().map(|r| r.rep.share_over_1).fold(0.0, f64::max);
                let o2 = sel.iter().map(|r| r.rep.share_over_2).fold(0.0, f64::max);
                let psnr = sel
                    .iter()
                    .map(|r| r.rep.psnr_db)
                    .fold(f64::INFINITY, f64::min);
                let cov: usize = sel
                    .iter()
                    .map(|r| r.rep.only_candidate + r.rep.only_reference)
                    .sum();
                writeln!(
                    s,
                    "| {p} | {filter} | {} | {max} | {p99} | {:.3}% | {:.3}% | {psnr:.1} | {cov} |",
                    if same && p == "Affine" {
                        "affine"
                    } else {
                        "perspective"
                    },
                    100.0 * o1,
                    100.0 * o2,
                )
                .unwrap();
            }
        }
    }
    s
}
