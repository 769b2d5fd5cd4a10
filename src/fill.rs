//! Filling a buffer with one value: the colour and depth clears of a frame or band.
//!
//! A clear writes every pixel of the target twice over (colour, then depth): on the
//! benchmark's whole 320x240 frame that is 300 KB, about 4.4 instructions per drawn pixel of
//! the sphere on Cortex-M4F through `memset` (16 bytes per six instructions) and 5.9 on
//! Cortex-M0+. On Arm, buffers of 2- or 4-byte elements are filled here with
//! multiple-register stores instead: 64 bytes per loop of four instructions on ARMv7-M
//! (two `stm` of eight registers), of six on ARMv6-M (four `stm` of four). Elsewhere, and
//! for the few bytes before the first word boundary and after the last whole block, it is
//! [`slice::fill`].
//!
//! The stores copy the buffer's first aligned word, which holds whole copies of the value
//! written by [`slice::fill`] first: every element ends up with the value's bytes, exactly
//! as [`slice::fill`] would leave it.

/// Bytes each pass of the store loop writes.
const BLOCK: usize = 64;

/// Buffers below this many bytes are filled by [`slice::fill`] alone.
const MIN_BYTES: usize = 2 * BLOCK;

/// How a buffer at address `addr` of `len` elements of `size` bytes is filled: `head`
/// elements by [`slice::fill`] up to the first word boundary, then `blocks` blocks of
/// [`BLOCK`] bytes by the store loop, the rest by [`slice::fill`]. `None` for buffers filled
/// by [`slice::fill`] alone (other element sizes, or too few bytes).
///
/// The blocks lie inside the buffer: `head * size + blocks * BLOCK <= len * size`, and
/// they start at a multiple of 4 (tested for every alignment and length).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Plan {
    head: usize,
    blocks: usize,
}

fn plan(addr: usize, len: usize, size: usize) -> Option<Plan> {
    if !(size == 2 || size == 4) {
        return None;
    }
    let bytes = len.checked_mul(size)?;
    if bytes < MIN_BYTES {
        return None;
    }
    let skip = addr.wrapping_neg() % 4;
    if !skip.is_multiple_of(size) {
        return None;
    }
    let blocks = (bytes - skip) / BLOCK;
    Some(Plan {
        head: skip / size,
        blocks,
    })
}

/// Fills `buf` with `v`: the same elements as [`slice::fill`], faster on Arm (see the module
/// docs). Never panics.
#[inline]
pub(crate) fn fill<T: Copy>(buf: &mut [T], v: T) {
    let size = core::mem::size_of::<T>();
    let Some(p) = plan(buf.as_ptr() as usize, buf.len(), size).filter(|_| STORE_LOOP) else {
        buf.fill(v);
        return;
    };
    let (head, body) = buf.split_at_mut(p.head);
    head.fill(v);
    // `body` starts on a word boundary and holds at least one block: its first word is
    // whole copies of `v` (4 / size of them), the pattern the loop stores.
    let per_word = 4 / size;
    let done = p.blocks * BLOCK / size;
    match body.get_mut(..done) {
        Some(blocks) if done >= per_word => {
            if let Some(first) = blocks.get_mut(..per_word) {
                first.fill(v);
            }
            store_blocks(blocks, p.blocks);
        }
        _ => {
            body.fill(v);
            return;
        }
    }
    if let Some(tail) = body.get_mut(done..) {
        tail.fill(v);
    }
}

/// Whether this target has the store loop.
const STORE_LOOP: bool = cfg!(target_arch = "arm");

/// Copies the first word of `blocks` (which starts on a word boundary, and is `n * BLOCK`
/// bytes long, `n >= 1`) over all of it, with multiple-register stores.
#[cfg(target_arch = "arm")]
#[inline(always)]
#[allow(unsafe_code)]
fn store_blocks<T: Copy>(blocks: &mut [T], n: usize) {
    debug_assert_eq!(core::mem::size_of_val(blocks), n * BLOCK);
    let ptr = blocks.as_mut_ptr();
    // ARMv6-M: `stm` takes low registers only (r6 and r7 are reserved): four per store.
    #[cfg(not(target_has_atomic = "32"))]
    // SAFETY: `ptr` is `blocks`' start, on a word boundary (`plan`), and `blocks` is
    // exclusively borrowed and exactly `n * 64` bytes long with `n >= 1` (the caller), so the
    // loop's `n` passes of 64 bytes each write only inside it, with aligned word stores. The
    // word read and copied is the buffer's own first word: whole copies of one `T` value
    // (the caller fills it first), so every element written holds that value's bytes, a
    // valid `T` (`T: Copy`, as `slice::fill` copies it). No stack access; the flags are
    // clobbered (no `preserves_flags`). Tested by the checksums of every `cargo xtask mcu`
    // firmware, which clears each frame and band through here, and `plan_keeps_blocks_inside`.
    unsafe {
        core::arch::asm!(
            "ldr r2, [r0]",
            "mov r3, r2",
            "mov r4, r2",
            "mov r5, r2",
            "2:",
            "stm r0!, {{r2, r3, r4, r5}}",
            "stm r0!, {{r2, r3, r4, r5}}",
            "stm r0!, {{r2, r3, r4, r5}}",
            "stm r0!, {{r2, r3, r4, r5}}",
            "subs r1, r1, #1",
            "bne 2b",
            inout("r0") ptr => _,
            inout("r1") n => _,
            out("r2") _,
            out("r3") _,
            out("r4") _,
            out("r5") _,
            options(nostack),
        );
    }
    // ARMv7-M and later: eight registers per store.
    #[cfg(target_has_atomic = "32")]
    // SAFETY: as above (two stores of 32 bytes per 64-byte pass).
    unsafe {
        core::arch::asm!(
            "ldr r2, [r0]",
            "mov r3, r2",
            "mov r4, r2",
            "mov r5, r2",
            "mov r8, r2",
            "mov r10, r2",
            "mov r12, r2",
            "mov lr, r2",
            "2:",
            "stm r0!, {{r2, r3, r4, r5, r8, r10, r12, lr}}",
            "stm r0!, {{r2, r3, r4, r5, r8, r10, r12, lr}}",
            "subs r1, r1, #1",
            "bne 2b",
            inout("r0") ptr => _,
            inout("r1") n => _,
            out("r2") _,
            out("r3") _,
            out("r4") _,
            out("r5") _,
            out("r8") _,
            out("r10") _,
            out("r12") _,
            out("lr") _,
            options(nostack),
        );
    }
}

/// Elsewhere: never called ([`STORE_LOOP`] is off); the safe fill.
#[cfg(not(target_arch = "arm"))]
#[inline(always)]
fn store_blocks<T: Copy>(blocks: &mut [T], _n: usize) {
    if let Some(&v) = blocks.first() {
        blocks.fill(v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plan_keeps_blocks_inside() {
        for size in [1usize, 2, 3, 4, 8] {
            for addr in 0..8usize {
                for len in 0..400usize {
                    let Some(p) = plan(addr, len, size) else {
                        let skip = (4 - addr % 4) % 4;
                        assert!(
                            !(size == 2 || size == 4) || len * size < MIN_BYTES || skip % size != 0
                        );
                        continue;
                    };
                    assert!(size == 2 || size == 4);
                    let start = addr + p.head * size;
                    assert_eq!(start % 4, 0, "blocks start on a word");
                    assert!(p.head * size < 4);
                    assert!(p.blocks >= 1);
                    assert!(p.head * size + p.blocks * BLOCK <= len * size);
                    // Less than a block is left over.
                    assert!(len * size - p.head * size - p.blocks * BLOCK < BLOCK);
                }
            }
        }
    }

    #[test]
    fn fill_equals_slice_fill() {
        for len in [0usize, 1, 5, 63, 64, 65, 127, 128, 300, 1000] {
            for off in 0..3 {
                let mut a = [7u16; 1100];
                let mut b = [7u16; 1100];
                fill(&mut a[off..off + len], 0xBEEF);
                b[off..off + len].fill(0xBEEF);
                assert_eq!(a, b);
                let mut c = [7u32; 1100];
                let mut d = [7u32; 1100];
                fill(&mut c[off..off + len], 0xDEAD_BEEF);
                d[off..off + len].fill(0xDEAD_BEEF);
                assert_eq!(c, d);
            }
        }
    }
}
