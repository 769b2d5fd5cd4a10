//! Host-side float reference, metrics and test helpers for fixel: an
//! independent f64 reference renderer ([`reference`]), the benchmark scenes
//! built in f64 ([`scenes`]), error metrics against the reference
//! ([`metrics`]), RGB565 PNG I/O ([`png_io`]) and golden-image checks
//! ([`golden`]), plus small synthetic scenes ([`synthetic`]).

pub mod adapter;
pub mod bump_fast_scene;
pub mod cost_plot;
pub mod displaced;
pub mod env_scene;
pub mod fuzz;
pub mod golden;
pub mod metrics;
pub mod noise_scenes;
pub mod plot_font;
pub mod png_io;
pub mod reference;
pub mod report_args;
pub mod report_mcu;
pub mod scenes;
pub mod shadow_scene;
pub mod surface_scene;
pub mod synthetic;
