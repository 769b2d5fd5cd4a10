//! The one error type of fixel: returned by constructors that validate input.
//!
//! Drawing never fails: degenerate or clipped-away triangles are skipped. Everything that can
//! be wrong with *input* (a texture whose side is not a power of two, a slice of the wrong
//! length, a band taller than its buffer, a mesh index out of range) is refused where it
//! enters, with a variant that says what is wrong.

use core::fmt;

/// What is wrong with an input handed to a fixel constructor.
///
/// `Copy + Debug + Display`, and `#[non_exhaustive]` so that new checks can be added without
/// a breaking change.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    /// A texture or buffer side is not a power of two (the value is the offending side).
    NotPowerOfTwo(u32),
    /// A side is zero or larger than the largest supported (the value is the offending side).
    BadSize(u32),
    /// A slice does not have the length its declared size needs.
    WrongLength {
        /// Length the declared size needs.
        expected: usize,
        /// Length that was given.
        actual: usize,
    },
    /// A band is taller than the buffer that should hold it, or has zero height.
    BandTooTall {
        /// Rows asked for.
        rows: u16,
        /// Rows the buffer can hold.
        capacity: u16,
    },
    /// A mesh index points past the end of the vertex list.
    IndexOutOfRange {
        /// Position of the bad index in the index list.
        at: usize,
        /// The bad index.
        index: u16,
        /// Number of vertices.
        vertices: usize,
    },
    /// A viewport side is zero or larger than the raster supports (2048 pixels, see
    /// `geometry::viewport`).
    BadViewport {
        /// Requested width in pixels.
        width: u32,
        /// Requested height in pixels.
        height: u32,
    },
    /// A viewport whose sides are valid reaches past the raster's limit on one axis:
    /// `offset + size` is above `limit` (see `geometry::viewport`).
    ViewportOutOfBounds {
        /// The axis, `"x"` or `"y"`.
        axis: &'static str,
        /// The requested offset (`x0` or `y0`) in pixels.
        offset: u32,
        /// The requested side (width or height) in pixels.
        size: u32,
        /// The largest `offset + size`, pixels.
        limit: u32,
    },
    /// A camera or projection parameter is out of its documented range.
    BadProjection(&'static str),
    /// A draw mode is inconsistent (for example textured shading without a texture).
    BadMode(&'static str),
    /// A mesh has more elements than its index type can address.
    MeshTooLarge {
        /// What there are too many of ("vertices").
        what: &'static str,
        /// How many were given.
        count: usize,
        /// The most the index type can address.
        limit: usize,
    },
    /// A texture's footprints do not match its texels (see `MipTexture::with_footprints`).
    FootprintMismatch {
        /// The first word that is not texel `index` and its right neighbour.
        index: usize,
    },
    /// A mesh's face planes were not baked from its positions and indices (see
    /// `Mesh::with_face_planes`).
    FacePlaneMismatch {
        /// The first triangle whose plane differs (or the count, when the lengths differ).
        triangle: usize,
    },
    /// A texture is not the size a sampler was built for (see
    /// `texture::BilinearFootprintSized`); the fields are the sampler's. (Two fields, not
    /// four: every firmware that formats an error links this variant's `Debug`, which with
    /// four fields cost up to 0.8 KB of flash.)
    TextureSizeMismatch {
        /// Width the sampler is built for, texels.
        width: u32,
        /// Height the sampler is built for, texels.
        height: u32,
    },
    /// A shadow map is not the size its light pass was built for (see
    /// `pipeline::DepthOnlyDraw`); the field is the light pass's side, in texels.
    ShadowMapSizeMismatch(u32),
    /// A fixed-capacity store is full.
    CapacityExceeded {
        /// Its capacity.
        capacity: usize,
    },
    /// A depth-testing draw was given a target without a depth buffer (attach one with
    /// `Frame::with_depth` or `BandRenderer::with_depth`, or draw with `DepthTest::Off`).
    NoDepthBuffer,
    /// A triangle was pushed with a draw index past the end of the draws given to the band
    /// renderer.
    BadDrawIndex {
        /// The index pushed.
        index: u8,
        /// How many draws there are.
        draws: usize,
    },
    /// A triangle was pushed to the band renderer with a varying count other than its
    /// draw's (each draw's screen triangles carry the varyings its shader declares).
    WrongVaryings {
        /// The index of the draw.
        draw: u8,
        /// The draw's varyings per vertex.
        expected: u8,
        /// The triangle's.
        actual: u8,
    },
    /// A vector that must have a direction is zero (for example a light direction).
    ZeroVector(&'static str),
    /// A number converted into fixed point is NaN or outside the format's range.
    OutOfRange {
        /// What was converted.
        what: &'static str,
    },
    /// Four corners that no projective map of a square reaches: the reason ("three corners
    /// are collinear", "the corners cross (a bow-tie)", "the quad is concave").
    BadQuad(&'static str),
    /// A cube-map face is not square or not the size of face 0.
    BadCubeMap {
        /// The face (0..=5: +X, -X, +Y, -Y, +Z, -Z).
        face: u8,
        /// Its width.
        width: u32,
        /// Its height.
        height: u32,
    },
    /// A band renderer that sends a band while drawing the next needs at least two band
    /// buffers (`BandRenderer::with_buffers`).
    TooFewBandBuffers {
        /// How many were given.
        given: usize,
    },
    /// The band buffers of `BandRenderer::with_buffers` are not all of one length.
    BandBuffersDiffer {
        /// The first buffer whose length differs from buffer 0's.
        index: usize,
        /// Its length, pixels.
        len: usize,
        /// Buffer 0's length, pixels.
        first: usize,
    },
    /// A share of a frame's bands names no core of its cores (`BandShare::new`: `core`
    /// must be below `cores`, `cores` from 1 to 255).
    BadBandShare {
        /// The core asked for.
        core: u32,
        /// The cores sharing the frame.
        cores: u32,
    },
    /// A frame has fewer bands than the cores it is split between: some core would draw
    /// nothing (use fewer cores or lower bands).
    TooFewBands {
        /// Bands in the frame.
        bands: u32,
        /// Cores sharing it.
        cores: u32,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::NotPowerOfTwo(n) => write!(f, "size {n} is not a power of two"),
            Error::BadSize(n) => write!(f, "size {n} is zero or larger than supported"),
            Error::WrongLength { expected, actual } => {
                write!(
                    f,
                    "slice has {actual} elements, the declared size needs {expected}"
                )
            }
            Error::BandTooTall { rows, capacity } => {
                write!(
                    f,
                    "band of {rows} rows does not fit a buffer of {capacity} rows"
                )
            }
            Error::IndexOutOfRange {
                at,
                index,
                vertices,
            } => write!(
                f,
                "index {index} at position {at} is out of range for {vertices} vertices"
            ),
            Error::BadViewport { width, height } => write!(
                f,
                "viewport {width}x{height} has a side outside 1..={}",
                crate::raster::MAX_VIEWPORT_PX
            ),
            Error::ViewportOutOfBounds {
                axis,
                offset,
                size,
                limit,
            } => write!(
                f,
                "viewport {axis} offset {offset} plus size {size} is past the limit: {axis} offset + size must be at most {limit}"
            ),
            Error::BadProjection(what) => write!(f, "bad projection: {what}"),
            Error::BadMode(what) => write!(f, "bad draw mode: {what}"),
            Error::MeshTooLarge { what, count, limit } => write!(
                f,
                "mesh has {count} {what}, more than the {limit} its u16 indices can address"
            ),
            Error::FootprintMismatch { index } => write!(
                f,
                "footprint {index} is not the four texels around texel {index} (build footprints with footprint_texels or write_footprints)"
            ),
            Error::FacePlaneMismatch { triangle } => write!(
                f,
                "face plane {triangle} is not triangle {triangle}'s (bake face planes with face_planes or write_face_planes from the mesh's own positions and indices)"
            ),
            Error::TextureSizeMismatch { width, height } => write!(
                f,
                "texture is not the {width}x{height} texels the sampler is built for"
            ),
            Error::ShadowMapSizeMismatch(side) => write!(
                f,
                "shadow map is not the {side}x{side} texels its light pass is built for"
            ),
            Error::CapacityExceeded { capacity } => {
                write!(f, "fixed capacity of {capacity} exceeded")
            }
            Error::NoDepthBuffer => {
                write!(f, "the draw tests depth but the target has no depth buffer")
            }
            Error::BadDrawIndex { index, draws } => write!(
                f,
                "draw index {index} is past the {draws} draws given to the renderer"
            ),
            Error::WrongVaryings {
                draw,
                expected,
                actual,
            } => write!(
                f,
                "a triangle of draw {draw} carries {actual} varyings, the draw's shader takes {expected}"
            ),
            Error::ZeroVector(what) => write!(f, "{what} is a zero vector"),
            Error::OutOfRange { what } => {
                write!(f, "{what} is NaN or outside the fixed-point range")
            }
            Error::BadQuad(why) => write!(f, "quad refused: {why}"),
            Error::BadCubeMap {
                face,
                width,
                height,
            } => write!(
                f,
                "cube-map face {face} is {width}x{height}: faces must be square and the size of face 0"
            ),
            Error::TooFewBandBuffers { given } => write!(
                f,
                "{given} band buffer(s) given: sending one band while drawing the next needs at least two"
            ),
            Error::BandBuffersDiffer { index, len, first } => write!(
                f,
                "band buffer {index} holds {len} pixels, buffer 0 {first}: the band buffers must all be of one length"
            ),
            Error::BadBandShare { core, cores } => write!(
                f,
                "band share of core {core} of {cores} cores: the core must be below the cores, the cores from 1 to 255"
            ),
            Error::TooFewBands { bands, cores } => write!(
                f,
                "a frame of {bands} band(s) cannot be split between {cores} cores: each core needs a band"
            ),
        }
    }
}

impl core::error::Error for Error {}

/// `Result<_, Infallible>` (for example a band flush into an in-memory display) converts
/// into any `Result<_, Error>` with `?`.
impl From<core::convert::Infallible> for Error {
    fn from(never: core::convert::Infallible) -> Self {
        match never {}
    }
}
