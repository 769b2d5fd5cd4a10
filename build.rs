//! Tells the core which instruction set extensions its target has, where `cfg` alone cannot:
//! stable Rust exposes no `target_feature` for Arm's DSP extension.
//!
//! `fixel_dsp`: ARMv7E-M (`thumbv7em-*`: Cortex-M4, M4F, M7), whose DSP extension has the
//! dual 16-bit multiplies (`smuad`, `smlad`), the rounding high multiply (`smmulr`) and the
//! halfword packing (`pkhbt`) that the span loops of the footprint samplers
//! (`BilinearFootprintSized`, `BilinearFootprint`; `src/texture/footprint_span_dsp.rs`) are
//! written with.
//! Cortex-M3 (`thumbv7m-*`) has none of them.

fn main() {
    println!("cargo::rustc-check-cfg=cfg(fixel_dsp)");
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-env-changed=TARGET");
    let target = std::env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumbv7em") {
        println!("cargo::rustc-cfg=fixel_dsp");
    }
}
