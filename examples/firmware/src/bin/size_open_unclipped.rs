//! `cargo xtask size`: `size_open` without the clipper (`ShadedDraw::project_unclipped`:
//! the geometry stays in view).
#![no_std]
#![no_main]

fn run() -> bool {
    fixel_firmware::size::open::<false>()
}

fixel_firmware::entry!(run);
