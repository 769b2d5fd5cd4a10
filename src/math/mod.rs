//! Fixed-point math (being written).
pub type Fx = fixed::types::I16F16;
