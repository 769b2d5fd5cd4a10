//! Textures (being written).
