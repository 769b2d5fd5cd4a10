//! Textures: a borrowed power-of-two RGB565 [`Texture`], wrap modes and filters.
//!
//! Units and conventions (OpenGL ES 3.2, texture minification and magnification): texels
//! are row-major with row 0
//! first (`v = 0` at row 0), texel centres at `i + 0.5`, sampling coordinates are raw I16F16
//! texel units (`i32`, 65536 = one texel). Sides are powers of two, 1..=4096. Wrap modes and
//! filters are zero-sized markers ([`Repeat`], [`MirroredRepeat`], [`ClampToEdge`],
//! [`ClampToBorder`]; [`Nearest`], [`Bilinear`], [`BilinearFootprint`],
//! [`BilinearFootprintSized`]) so the per-pixel path is monomorphised;
//! [`DynWrap`], [`Filter`] and [`Texture::sample_dyn`] select at run time. All results are
//! raw RGB565 `u16`. See each submodule for the exact formulas. Palette textures
//! ([`PaletteTexture`], [`PaletteMips`]: 8- or 4-bit indices into an RGB565 palette) sample
//! through the same filters and wraps.

pub(crate) mod depth_map;
mod footprint;
mod footprint_sized;
#[cfg(fixel_dsp)]
mod footprint_span_dsp;
mod footprint_words;
mod height;
pub(crate) mod mip;
mod palette;
pub(crate) mod sample;
#[allow(clippy::module_inception)]
mod texture;
mod wrap;

pub use depth_map::{DepthMap, ShadowMap, MAX_MAP_SIZE, MIN_MAP_SIZE};
pub use footprint::BilinearFootprint;
pub(crate) use footprint_sized::check_level0_size;
pub use footprint_sized::BilinearFootprintSized;
pub use footprint_words::{footprint_texels, write_footprints};
pub use height::{generate_height_mips, HeightMap};
pub use mip::{
    chain_len, direction_lambda, full_levels, generate_mips, lambda_q8, lerp565, level_side,
    log2_q8, DynMip, LinearMipmapNearest, Lod, LodGranularity, MipFilter, MipTexture, Mipmapped,
    NearestMipmapLinear, NearestMipmapNearest, TexSampler, Trilinear, MAX_LEVELS,
};
pub use palette::{
    palette_chain_bytes, Index4, Index8, IndexFormat, PaletteFilter, PaletteMips, PaletteTexture,
};
pub use sample::{Bilinear, BilinearFast, Filter, Nearest, Sampler};
pub use texture::{Texture, MAX_LOG2_SIZE};
pub use wrap::{ClampToBorder, ClampToEdge, DynWrap, MirroredRepeat, Repeat, Wrap, WrapMode};
