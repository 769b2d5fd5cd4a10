//! Host-side float reference, metrics and test helpers.
