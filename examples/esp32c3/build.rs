//! esp-hal's linker script (memory map, the boot sections, the vector table).
fn main() {
    println!("cargo:rustc-link-arg=-Tlinkall.x");
}
