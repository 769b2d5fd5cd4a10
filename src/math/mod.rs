//! Fixed-point math (being written).
