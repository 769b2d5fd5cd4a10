//! Input and output types of the f64 reference renderer. They are deliberately
//! independent of fixel's own types (the reference must not share code with the
//! fixed-point renderer it judges); adapters from fixel's types live elsewhere.
//! Colours are `[r, g, b]` in `0.0..=1.0`; textures are RGB565 `u16` texels.

/// A texture as the reference sees it: RGB565 texels, row 0 first.
///
/// Row `j` holds the texels at `t` in `[j / height, (j + 1) / height)`, so row 0
/// is `t = 0` (OpenGL's convention for the first row uploaded).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RefTexture {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// `width * height` RGB565 texels, row-major, row 0 (t = 0) first.
    pub texels: Vec<u16>,
    /// RGB565 colour returned for `ClampToBorder` outside the texture.
    pub border: u16,
}

impl RefTexture {
    /// The texel at integer coordinates `(i, j)` (must be in range).
    pub fn texel(&self, i: u32, j: u32) -> u16 {
        self.texels[(j * self.width + i) as usize]
    }
}

/// One vertex: GL clip-space position plus attributes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefVertex {
    /// `[x, y, z, w]` in GL clip space (visible: `-w <= x, y, z <= w`).
    pub clip: [f64; 4],
    /// Normalised texture coordinates `[s, t]`: 1.0 spans the whole texture.
    pub uv: [f64; 2],
    /// Per-vertex (Gouraud) colour, each channel in `0.0..=1.0`.
    pub color: [f64; 3],
}

/// A triangle of three vertices. Counter-clockwise in NDC (y up) is the front.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefTriangle(pub [RefVertex; 3]);

/// How attributes are interpolated across a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefProjection {
    /// Screen-linear interpolation (`a = Σ λi ai`).
    Affine,
    /// Perspective-correct "hyperbolic" interpolation
    /// (`a = (Σ λi ai / wi) / (Σ λi / wi)`).
    Perspective,
}

/// Texture filter within one level (GL_NEAREST / GL_LINEAR).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefFilter {
    /// GL_NEAREST.
    Nearest,
    /// GL_LINEAR.
    Bilinear,
}

/// Filtering between mip levels (OpenGL ES 3.2, mipmapping).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefMip {
    /// No mipmapping: the minification filter samples level 0.
    None,
    /// `*_MIPMAP_NEAREST`: the nearest level.
    Nearest,
    /// `*_MIPMAP_LINEAR`: the two nearest levels blended by `frac(lambda)`.
    Linear,
}

/// Level-of-detail bias and clamps, in levels (f64):
/// `lambda' = clamp(log2(rho) + bias, min, max)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefLod {
    /// Added to `lambda`.
    pub bias: f64,
    /// Smallest `lambda'`.
    pub min: f64,
    /// Largest `lambda'`.
    pub max: f64,
}

impl Default for RefLod {
    /// No bias, no clamp.
    fn default() -> Self {
        RefLod {
            bias: 0.0,
            min: f64::NEG_INFINITY,
            max: f64::INFINITY,
        }
    }
}

/// Texture wrap mode, applied to integer texel indices (OpenGL ES 3.2, coordinate wrapping).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefWrap {
    /// GL_REPEAT.
    Repeat,
    /// GL_MIRRORED_REPEAT.
    MirroredRepeat,
    /// GL_CLAMP_TO_EDGE.
    ClampToEdge,
    /// GL_CLAMP_TO_BORDER: indices outside `[0, size)` give the border colour.
    ClampToBorder,
}

/// How a fragment's colour is made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RefShading {
    /// The texel colour.
    Replace,
    /// Texel times interpolated vertex colour, per channel.
    Modulate,
    /// The interpolated vertex colour only.
    Gouraud,
    /// One constant colour.
    Flat([f64; 3]),
}

/// Which faces are discarded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefCull {
    /// Draw both.
    None,
    /// Discard back faces (clockwise in NDC).
    Back,
    /// Discard front faces (counter-clockwise in NDC).
    Front,
}

/// The complete render state of the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefMode {
    /// Attribute interpolation.
    pub projection: RefProjection,
    /// Texture filter: the minification filter within a mip level, and the
    /// magnification filter unless `mag` says otherwise.
    pub filter: RefFilter,
    /// Magnification filter when it differs from `filter` (`None`: `filter`).
    pub mag: Option<RefFilter>,
    /// Filtering between mip levels (`RefMip::None`: level 0 only).
    pub mip: RefMip,
    /// Level-of-detail bias and clamps (mipmapped or with a separate `mag`).
    pub lod: RefLod,
    /// Wrap along s.
    pub wrap_u: RefWrap,
    /// Wrap along t.
    pub wrap_v: RefWrap,
    /// GL_LESS depth test against a buffer cleared to 1.0.
    pub depth_test: bool,
    /// Fragment colour.
    pub shading: RefShading,
    /// Face culling.
    pub cull: RefCull,
}

impl Default for RefMode {
    /// Perspective-correct, bilinear, repeat, depth test on, texture times
    /// colour, back faces culled: the benchmark scenes' state.
    fn default() -> Self {
        RefMode {
            projection: RefProjection::Perspective,
            filter: RefFilter::Bilinear,
            mag: None,
            mip: RefMip::None,
            lod: RefLod::default(),
            wrap_u: RefWrap::Repeat,
            wrap_v: RefWrap::Repeat,
            depth_test: true,
            shading: RefShading::Modulate,
            cull: RefCull::Back,
        }
    }
}

/// The reference's output: exact colours, coverage and window depth per pixel.
///
/// Row 0 is the top row of the picture (window y grows downwards, as a
/// framebuffer is stored). Index of pixel `(x, y)` is `y * width + x`.
#[derive(Clone, Debug, PartialEq)]
pub struct RefImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Exact (unquantised) colour per pixel; black where uncovered.
    pub rgb: Vec<[f64; 3]>,
    /// Whether any fragment was written to the pixel.
    pub covered: Vec<bool>,
    /// Window depth `z_w` in `[0, 1]` of the visible fragment; 1.0 where uncovered.
    pub depth: Vec<f64>,
}

impl RefImage {
    /// A black, uncovered image with depth cleared to 1.0.
    pub fn new(width: u32, height: u32) -> Self {
        let n = (width as usize) * (height as usize);
        RefImage {
            width,
            height,
            rgb: vec![[0.0; 3]; n],
            covered: vec![false; n],
            depth: vec![1.0; n],
        }
    }

    /// Number of covered pixels.
    pub fn covered_count(&self) -> usize {
        self.covered.iter().filter(|&&c| c).count()
    }

    /// Each pixel rounded to the nearest RGB565 value (`r5 = round(r * 31)`,
    /// `g6 = round(g * 63)`, `b5 = round(b * 31)`, clamped).
    pub fn quantize_rgb565(&self) -> Vec<u16> {
        self.rgb.iter().map(|&c| rgb565_from_f64(c)).collect()
    }
}

/// Rounds a `0..=1` colour to the nearest RGB565 value (channels clamped).
pub fn rgb565_from_f64(c: [f64; 3]) -> u16 {
    let q = |v: f64, max: f64| (v * max).round().clamp(0.0, max) as u16;
    (q(c[0], 31.0) << 11) | (q(c[1], 63.0) << 5) | q(c[2], 31.0)
}

/// Splits an RGB565 value into its normalised channels `r5/31, g6/63, b5/31`.
pub fn rgb565_to_f64(t: u16) -> [f64; 3] {
    [
        f64::from((t >> 11) & 31) / 31.0,
        f64::from((t >> 5) & 63) / 63.0,
        f64::from(t & 31) / 31.0,
    ]
}
