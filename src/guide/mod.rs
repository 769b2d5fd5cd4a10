//! The guide, one chapter per topic: from `Cargo.toml` to a first frame, then to a display
//! in bands, then the choices a program makes (projection, filter, mipmaps), each technique
//! built on the open fragment stage, what each chip spends, how close the pixels are to an
//! f64 reference, and what the errors mean. Every code block of every chapter is a doctest,
//! compiled and run by `cargo test`.
//!
//! Start here:
//!
//! 1. [`first_frame`]: the dependency, a mesh, a camera, a light, a texture, a draw, and a
//!    whole frame written as a PNG on the desktop.
//! 2. [`bands`]: the same frame on a display through a buffer of a few rows; meshes larger
//!    than the bins; techniques in bands.
//! 3. [`projection_and_filter`]: perspective-correct, subdivided, quadratic, adaptive or
//!    affine; nearest, bilinear or bilinear from footprints: speed against error.
//! 4. [`mipmaps`]: minified textures, GL's mipmapped filters and where the level of detail
//!    is taken.
//!
//! The techniques, each a shader (or a wrapper of one) on the open fragment stage; a draw
//! that does not use one links none of its code:
//!
//! - [`environment_maps`]: cube, sphere and lat-long maps; seamless filtering and mip chains;
//!   diffuse and glossy maps, and baking them.
//! - [`shadow_maps`]: a depth pass from the light and a wrapper over any shader, with PCF.
//! - [`solid_textures`]: Perlin noise, turbulence, marble, wood, granite, flames, 4D noise and
//!   3D light maps.
//! - [`texture_coordinates`]: planar, cylindrical and spherical coordinates, two-stage
//!   mapping, triplanar mapping, projective quads and models baked from OBJ.
//! - [`anti_aliasing`]: supersampling and accumulation in bands, and edge smoothing.
//! - [`transparency`]: alpha test, blending and back-to-front sorting.
//! - [`lighting`]: per-pixel lighting, bump maps and normal maps.
//! - [`displacement`]: subdivision and displacement of meshes into caller storage.
//!
//! Then:
//!
//! - [`performance`]: what a frame costs on Cortex-M0+, Cortex-M4F and RV32IMC, in flash,
//!   RAM and instructions, and the commands that measure it.
//! - [`accuracy`]: the f64 reference renderer, the error budgets and what they mean.
//! - [`troubleshooting`]: the errors a program meets, what they mean and what to do.
//!
//! The figures quoted in the repository's `docs/` (instruction counts, flash, RAM, error) are
//! written there by the commands that measure them, never copied by hand; each chapter says
//! which command.

#[doc = include_str!("first_frame.md")]
pub mod first_frame {}

#[doc = include_str!("bands.md")]
pub mod bands {}

#[doc = include_str!("projection_and_filter.md")]
pub mod projection_and_filter {}

#[doc = include_str!("mipmaps.md")]
pub mod mipmaps {}

#[doc = include_str!("environment_maps.md")]
pub mod environment_maps {}

#[doc = include_str!("shadow_maps.md")]
pub mod shadow_maps {}

#[doc = include_str!("solid_textures.md")]
pub mod solid_textures {}

#[doc = include_str!("texture_coordinates.md")]
pub mod texture_coordinates {}

#[doc = include_str!("anti_aliasing.md")]
pub mod anti_aliasing {}

#[doc = include_str!("transparency.md")]
pub mod transparency {}

#[doc = include_str!("lighting.md")]
pub mod lighting {}

#[doc = include_str!("displacement.md")]
pub mod displacement {}

#[doc = include_str!("performance.md")]
pub mod performance {}

#[doc = include_str!("accuracy.md")]
pub mod accuracy {}

#[doc = include_str!("troubleshooting.md")]
pub mod troubleshooting {}

#[cfg(test)]
mod tests {
    /// Every chapter, as the crate docs include it.
    const CHAPTERS: [(&str, &str); 16] = [
        ("mod.rs", include_str!("mod.rs")),
        ("first_frame.md", include_str!("first_frame.md")),
        ("bands.md", include_str!("bands.md")),
        (
            "projection_and_filter.md",
            include_str!("projection_and_filter.md"),
        ),
        ("mipmaps.md", include_str!("mipmaps.md")),
        ("environment_maps.md", include_str!("environment_maps.md")),
        ("shadow_maps.md", include_str!("shadow_maps.md")),
        ("solid_textures.md", include_str!("solid_textures.md")),
        (
            "texture_coordinates.md",
            include_str!("texture_coordinates.md"),
        ),
        ("anti_aliasing.md", include_str!("anti_aliasing.md")),
        ("transparency.md", include_str!("transparency.md")),
        ("lighting.md", include_str!("lighting.md")),
        ("displacement.md", include_str!("displacement.md")),
        ("performance.md", include_str!("performance.md")),
        ("accuracy.md", include_str!("accuracy.md")),
        ("troubleshooting.md", include_str!("troubleshooting.md")),
    ];

    /// The first place where `text` names a work session, an issue or a seed section by
    /// number (a word from `WORDS`, any case, followed by a digit).
    fn history_at(text: &str) -> Option<usize> {
        const WORDS: [&[u8]; 3] = [b"session ", b"issue ", b"seed 00"];
        let b = text.as_bytes();
        (0..b.len()).find(|&i| {
            WORDS.iter().any(|w| {
                b.get(i..i + w.len())
                    .is_some_and(|s| s.eq_ignore_ascii_case(w))
                    && b.get(i + w.len()).is_some_and(u8::is_ascii_digit)
            })
        })
    }

    #[test]
    fn history_check_finds_numbered_sessions_issues_and_seed_sections() {
        assert_eq!(history_at("Measured in Session\x2012."), Some(12));
        assert_eq!(history_at("see issue\x2060"), Some(4));
        assert_eq!(history_at("seed\x20000, section 3.4"), Some(0));
        assert_eq!(history_at("a fixed seed; the issue is"), None);
    }

    #[test]
    fn chapters_speak_in_the_present_tense() {
        for (name, text) in CHAPTERS {
            assert_eq!(
                history_at(text),
                None,
                "{name} names a session, issue or seed section"
            );
        }
    }
}
