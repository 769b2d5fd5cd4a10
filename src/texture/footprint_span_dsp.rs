//! The lit span loops of [`BilinearFootprintSized`](super::BilinearFootprintSized) and
//! [`BilinearFootprint`](super::BilinearFootprint) on ARMv7E-M (Cortex-M4, M4F, M7),
//! written in assembly with the DSP extension's dual multiplies.
//!
//! What the loops compute is [`BilinearFootprintSized::sample_scaled`](super::BilinearFootprintSized::sample_scaled)
//! at every pixel of a linear piece whose intensity is in range (the loop
//! [`ModulateIntensity`](crate::shading::ModulateIntensity) runs after
//! [`Shader::piece_in_range`](crate::shading::Shader::piece_in_range)), bit for bit:
//!
//! - the footprint of `(u - REPEAT_SPLIT, v - REPEAT_SPLIT)` (I16F16 texel units; `0x7F80`), row wrapped to
//!   `2^LOG2_H`, column to `2^LOG2_W`, and its Q8 fractions `a`, `b`;
//! - the weights `w11 = (a b + 128) >> 8`, `w10 = a - w11`, `w01 = b - w11`,
//!   `w00 = 256 - a - b + w11`, packed two per word (`w00 | w10 << 16`, `w01 | w11 << 16`)
//!   to match the footprint's row words (`c00 | c10 << 16`, `c01 | c11 << 16`);
//! - per channel `S = sum w c` in two instructions (`smuad`, `smlad`: both lanes of a row
//!   word times both lanes of its weights, summed);
//! - per channel `(S i + 2^15) >> 16` for the intensity `i = (I >> 16) & 0xFF` in one
//!   (`smmulr` of `S` and `i << 16`: `(S i 2^16 + 2^31) >> 32`, the same integer).
//!
//! LLVM's code for the same loop (the generic span loop and `blend_rows_q8`) takes 53
//! instructions per pixel on Cortex-M4F: with 13 allocatable registers it rematerializes
//! nine constants and reloads four values from the stack at every pixel. [`lit_span`]
//! takes 39. It keeps its steps and footprint pointer in the stack frame it pushes and
//! reloads them with one `ldm` per pixel, and uses every register but `sp` and `pc` (`r6`
//! and `r7`, which Rust reserves, saved and restored inside the block).
//!
//! [`lit_span_depth`] tests and writes the depth in the same loop (46 instructions per
//! drawn pixel, 18 per hidden one), so the span stage hands it spans of any length
//! instead of a depth pass, a mask and a second loop (which LLVM cannot fuse on this
//! core without spilling).
//!
//! [`lit_span_runtime`] and [`lit_span_depth_runtime`] are the same loops for
//! [`BilinearFootprint`](super::BilinearFootprint), whose texture size is read at run time:
//! the footprint's row and column masked by registers instead of bit-field extracts, and
//! the row stride reloaded (40 and 48 instructions per pixel).
//!
//! On the whole-frame sphere (Cortex-M4F, the same checksum; measure with `cargo xtask
//! mcu`): against LLVM's loop, [`lit_span`] after the depth pass saves about 8 % of the
//! instructions per pixel of `whole_sphere_sized`, and [`lit_span_depth`] for every short
//! span about 4 % more (in the cycle model of `cargo xtask mcu`, where `ldm` of `n` words
//! costs `1 + n`, about 5 % and 1.5 %). On `whole_sphere_footprint`, where LLVM's loop
//! takes 60 instructions per pixel, [`lit_span_runtime`] saves about 10 % and
//! [`lit_span_depth_runtime`] about 2 % more.

use super::sample::REPEAT_SPLIT;

/// The address of a pixel's footprint in `r1`, for a size fixed at compile time: `r4`
/// (the footprints) plus `row << (LOG2_W + 3) + col << 3`, with `row` and `col` the low
/// `LOG2_H` and `LOG2_W` bits of the integer parts of `r9` = v and `r8` = u (I16F16, less
/// `0x7F80`). Operands `lh`, `lw`, `row_shift`; `r2` clobbered.
macro_rules! footprint_sized {
    () => {
        concat!(
            "ubfx r1, r9, #16, #{lh}\n",
            "ubfx r2, r8, #16, #{lw}\n",
            "add.w r1, r4, r1, lsl #{row_shift}\n",
            "add.w r1, r1, r2, lsl #3\n",
        )
    };
}

/// [`footprint_sized`] for a size read at run time: `r6` = height - 1, `r7` = width - 1
/// (powers of two), and the row stride `8 width` in the frame at `[sp, #$stride]`; `r3`
/// clobbered too.
macro_rules! footprint_runtime {
    ($stride:literal) => {
        concat!(
            "and.w r1, r6, r9, lsr #16\n",
            "and.w r2, r7, r8, lsr #16\n",
            "ldr r3, [sp, #",
            $stride,
            "]\n",
            "mla r1, r1, r3, r4\n",
            "add.w r1, r1, r2, lsl #3\n",
        )
    };
}

/// The footprint at `r1` loaded (its two row words in `r2`, `r3`), then `r1 = a` and `r4 =
/// b << 8`, the Q8 fractions of u (`r8`) and v (`r9`).
macro_rules! load_and_fractions {
    () => {
        concat!(
            "ldrd r2, r3, [r1]\n",
            "ubfx r1, r8, #8, #8\n",
            "and r4, r9, #0xFF00\n",
        )
    };
}

/// The rest of a pixel's sample, shared by both loops, from `r5 = a b 256 + 2^15` (so
/// `w11 = r5 >> 16`): the packed weights (`r4 = w01 | w11 << 16`, `r5 = w00 | w10 << 16`:
/// `(256 - a) | a << 16` less `r4`), the three channel sums (red `r1`, green `r6`, blue
/// `r7`; masks in `lr` = `0x001F001F` and `r12` = `0x003F003F`), each scaled by the
/// intensity (`r10`, Q8.16) and rounded once, packed and stored at `r11`, which moves on.
macro_rules! weights_blend_store {
    () => {
        concat!(
            "lsr.w r5, r5, #16\n",
            "rsb.w r4, r5, r4, lsr #8\n",
            "pkhbt r4, r4, r5, lsl #16\n",
            "rsb.w r5, r1, #256\n",
            "add.w r5, r5, r1, lsl #16\n",
            "sub.w r5, r5, r4\n",
            "and.w r1, lr, r2, lsr #11\n",
            "and.w r6, lr, r3, lsr #11\n",
            "smuad r1, r1, r5\n",
            "smlad r1, r6, r4, r1\n",
            "and.w r6, r12, r2, lsr #5\n",
            "and.w r7, r12, r3, lsr #5\n",
            "smuad r6, r6, r5\n",
            "smlad r6, r7, r4, r6\n",
            "and r7, r2, #0x001F001F\n",
            "and r2, r3, #0x001F001F\n",
            "smuad r7, r7, r5\n",
            "smlad r7, r2, r4, r7\n",
            "and r2, r10, #0xFF0000\n",
            "smmulr r1, r1, r2\n",
            "smmulr r6, r6, r2\n",
            "orr.w r1, r6, r1, lsl #6\n",
            "smmulr r7, r7, r2\n",
            "orr.w r7, r7, r1, lsl #5\n",
            "strh r7, [r11], #2\n",
        )
    };
}

/// The depth test at the top of a pixel of the depth loops (the loop's label `2`): `r1 =
/// clamp(z >> 14, 0, 0xFFFF)` from `r0` = z, tested (`GL_LESS`) against the `u16` at `r11 +
/// r7` (the pixel's depth) and written there when it passes; a hidden pixel branches to
/// label `3` ([`depth_next_pixel`]). `r2` clobbered.
macro_rules! depth_test {
    () => {
        concat!(
            "usat r1, #16, r0, asr #14\n",
            "ldrh r2, [r11, r7]\n",
            "cmp r1, r2\n",
            "bhs 3f\n",
            "strh r1, [r11, r7]\n",
        )
    };
}

/// The end of a pixel of the depth loops: the steps (`du`, `dv`, `di`, `dz`), the
/// footprints, the end, and the depth row's offset reloaded from the frame (`ldm`: `r1` to
/// `r7`), the varyings and `z` stepped, and back to label `2` until `r11` reaches the end;
/// label `3`, a hidden pixel: the next pixel, one more hidden (the frame's word at 28).
/// Leaves the hidden count in `r1`.
macro_rules! depth_next_pixel {
    () => {
        concat!(
            "4:\n",
            "ldm sp, {{r1, r2, r3, r4, r5, r6, r7}}\n",
            "add r8, r1\n",
            "add r9, r2\n",
            "add r10, r3\n",
            "add r0, r6\n",
            "cmp r11, r5\n",
            "bne 2b\n",
            "b 5f\n",
            "3:\n",
            "add.w r11, r11, #2\n",
            "ldr r1, [sp, #28]\n",
            "add.w r1, r1, #1\n",
            "str r1, [sp, #28]\n",
            "b 4b\n",
            "5:\n",
            "ldr r1, [sp, #28]\n",
        )
    };
}

/// The piece's first texel coordinates split as the bilinear samplers split them
/// ([`REPEAT_SPLIT`]): the loops' `u` and `v` registers.
#[inline(always)]
fn split(start: &[i32; 3]) -> (i32, i32) {
    (
        start[0].wrapping_sub(REPEAT_SPLIT),
        start[1].wrapping_sub(REPEAT_SPLIT),
    )
}

/// The footprints a `2^log2_w x 2^log2_h` texture has, one per texel (the loops' own bound:
/// their loads are not checked per pixel, and they do not rely on the binding's
/// [`TexBinding::can_draw`](crate::shading::TexBinding::can_draw)); `usize::MAX` when that
/// does not fit `usize`, which no slice holds.
const fn footprints_read(log2_w: u32, log2_h: u32) -> usize {
    match 1usize.checked_shl(log2_w + log2_h) {
        Some(n) => n,
        None => usize::MAX,
    }
}

/// Whether the loops are assembled for a `2^log2_w x 2^log2_h` texture: each side from 2 to
/// 2^16 texels (the bit-field extracts take 1 to 16 bits above bit 16), at most 2^28 texels.
pub(super) const fn supported(log2_w: u32, log2_h: u32) -> bool {
    log2_w >= 1 && log2_w <= 16 && log2_h >= 1 && log2_h <= 16 && log2_w + log2_h <= 28
}

/// Writes `out[k] = sample_scaled(u0 + k du, v0 + k dv, ((i0 + k di) >> 16) & 0xFF)` for
/// every `k`, from the `2^LOG2_W x 2^LOG2_H` texture's `footprints`, with `start = [u0, v0,
/// i0]` and `slope = [du, dv, di]` (I16F16 texel units; intensity Q8.16, wrapping steps).
/// Returns false, writing nothing, when the size is not [`supported`] or `footprints` is
/// shorter than the texture.
#[inline(always)]
#[allow(unsafe_code)]
pub(super) fn lit_span<const LOG2_W: u32, const LOG2_H: u32>(
    footprints: &[u64],
    start: &[i32; 3],
    slope: &[i32; 3],
    out: &mut [u16],
) -> bool {
    if !supported(LOG2_W, LOG2_H) || footprints.len() < footprints_read(LOG2_W, LOG2_H) {
        return false;
    }
    if out.is_empty() {
        return true;
    }
    let fp = footprints.as_ptr();
    let range = out.as_mut_ptr_range();
    let (tu, tv) = split(start);
    // SAFETY:
    // - Loads: each pixel reads the 8 bytes of footprint `row << LOG2_W | col`, with `row`
    //   the low `LOG2_H` bits and `col` the low `LOG2_W` bits of the coordinates' integer
    //   parts (`ubfx`), so an index below `2^(LOG2_W + LOG2_H)`, which `footprints` holds
    //   (checked above), from its start (`u64`, so 8-byte aligned for `ldrd`).
    // - Stores: one `u16` per pixel at `out`'s start, then each next one, until the pointer
    //   equals its end; `out` is not empty, so exactly its `len` elements are written.
    // - Registers: every operand is declared; `r0`, `r12` and `lr` are clobbered; `r1` to
    //   `r5` (inputs) and `r6`, `r7` (reserved by Rust: base and frame pointer) are pushed
    //   first and popped last, and the pushed words are the loop's stack frame, released by
    //   that pop: `sp` is as it was. No calls; the flags are clobbered.
    // Tested: `cargo xtask mcu` (every Cortex-M4F firmware's frame checksum equals the
    // host's, which runs the generic loop) and the `dsp_span` firmware, which compares this
    // loop with the generic sampler pixel by pixel over random spans.
    unsafe {
        core::arch::asm!(
            // Frame: [sp] du, dv, di, footprints, end; then the saved r6, r7.
            "push {{r1, r2, r3, r4, r5, r6, r7}}",
            "mov.w r0, #0x8000",
            "mov.w r12, #0x003F003F",
            "mov.w lr, #0x001F001F",
            "2:",
            footprint_sized!(),
            load_and_fractions!(),
            // w11 = (a b + 128) >> 8, from r0 = 2^15.
            "mla r5, r1, r4, r0",
            weights_blend_store!(),
            // Steps (and the footprints and end for the next pixel) from the frame.
            "ldm sp, {{r1, r2, r3, r4, r5}}",
            "add r8, r1",
            "add r9, r2",
            "add r10, r3",
            "cmp r11, r5",
            "bne 2b",
            "pop {{r1, r2, r3, r4, r5, r6, r7}}",
            lh = const LOG2_H,
            lw = const LOG2_W,
            row_shift = const LOG2_W + 3,
            inout("r1") slope[0] => _,
            inout("r2") slope[1] => _,
            inout("r3") slope[2] => _,
            inout("r4") fp => _,
            inout("r5") range.end => _,
            inout("r8") tu => _,
            inout("r9") tv => _,
            inout("r10") start[2] => _,
            inout("r11") range.start => _,
            out("r0") _,
            out("r12") _,
            out("lr") _,
        );
    }
    true
}

/// [`lit_span`] with the depth test in the loop, for a span of a shader that keeps every
/// pixel: pixel `k` has the 16-bit depth `d = clamp(z_k >> 14, 0, 0xFFFF)` with `z_k = z +
/// k dz` (wrapping, Q14 above the depth); where `d < zrow[k]` (`GL_LESS`) it writes `d` to
/// `zrow[k]` and the sample to `out[k]`, elsewhere neither. Returns the pixels that passed,
/// or `None`, writing nothing, when the size is not [`supported`], `footprints` is shorter
/// than the texture or `zrow` shorter than `out`. The loop of the span stage's
/// `shade_depth_inline`, bit for bit, without the depth pass and mask of longer spans.
#[inline(always)]
#[allow(unsafe_code, clippy::too_many_arguments)]
pub(super) fn lit_span_depth<const LOG2_W: u32, const LOG2_H: u32>(
    footprints: &[u64],
    start: &[i32; 3],
    slope: &[i32; 3],
    z: i32,
    dz: i32,
    out: &mut [u16],
    zrow: &mut [u16],
) -> Option<u32> {
    if !supported(LOG2_W, LOG2_H)
        || footprints.len() < footprints_read(LOG2_W, LOG2_H)
        || zrow.len() < out.len()
    {
        return None;
    }
    if out.is_empty() {
        return Some(0);
    }
    let n = out.len() as u32;
    let fp = footprints.as_ptr();
    let range = out.as_mut_ptr_range();
    // `zrow[k]` is `out[k]`'s address plus this (bytes, wrapping).
    let zoff = (zrow.as_mut_ptr() as usize).wrapping_sub(range.start as usize);
    let (tu, tv) = split(start);
    let hidden: u32;
    // SAFETY: as `lit_span` for the footprints and `out`. Depth: pixel `k` reads and may
    // write the `u16` at `out`'s `k`-th element plus `zoff`, which is `zrow[k]`'s address;
    // `zrow` holds at least `out.len()` elements (checked above) and is a distinct
    // exclusive borrow. Frame: `r6`, `r7` pushed first, then the hidden-pixel counter, then
    // the loop's steps and constants (`r1` to `r5`, `r12`, `lr`: inputs); all of it
    // released before `r6`, `r7` are popped, so `sp` is as it was. `r0` to `r5`, `r12` and
    // `lr` are declared as clobbered or outputs; no calls; the flags are clobbered.
    // Tested by the `dsp_span` firmware (against a per-pixel loop with the same depth test)
    // and every Cortex-M4F checksum of `cargo xtask mcu`.
    unsafe {
        core::arch::asm!(
            // Frame: [sp] du, dv, di, footprints, end, dz, zoff, hidden; the saved r6, r7.
            "push {{r6, r7}}",
            "mov.w r6, #0",
            "str r6, [sp, #-4]!",
            "push {{r1, r2, r3, r4, r5, r12, lr}}",
            "mov.w r12, #0x003F003F",
            "mov.w lr, #0x001F001F",
            "ldr r7, [sp, #24]",
            "2:",
            depth_test!(),
            // The sample, as in `lit_span` (w11 from a multiply and an add: r0 holds z).
            footprint_sized!(),
            load_and_fractions!(),
            "mul r5, r1, r4",
            "add.w r5, r5, #0x8000",
            weights_blend_store!(),
            depth_next_pixel!(),
            "add sp, #32",
            "pop {{r6, r7}}",
            lh = const LOG2_H,
            lw = const LOG2_W,
            row_shift = const LOG2_W + 3,
            inout("r1") slope[0] => hidden,
            inout("r2") slope[1] => _,
            inout("r3") slope[2] => _,
            inout("r4") fp => _,
            inout("r5") range.end => _,
            inout("r12") dz => _,
            inout("lr") zoff => _,
            inout("r0") z => _,
            inout("r8") tu => _,
            inout("r9") tv => _,
            inout("r10") start[2] => _,
            inout("r11") range.start => _,
        );
    }
    Some(n.wrapping_sub(hidden))
}

/// [`lit_span`] for a texture whose size is read at run time
/// ([`BilinearFootprint`](super::BilinearFootprint)): `2^log2_w x 2^log2_h` texels, exactly
/// one footprint per texel. The same pixels as `gather_footprint` with the texture's width
/// and the footprints' count (its index masked by `len - 1` is `row width + col` when `len`
/// is the texel count). 40 instructions per pixel (one more than the sized loop: the row
/// stride reloaded). Returns false, writing nothing, for other sizes or counts.
#[inline(always)]
#[allow(unsafe_code)]
pub(super) fn lit_span_runtime(
    footprints: &[u64],
    (log2_w, log2_h): (u32, u32),
    start: &[i32; 3],
    slope: &[i32; 3],
    out: &mut [u16],
) -> bool {
    // Any side works here (masks, not bit fields); the count bounds every index.
    if footprints.len() != footprints_read(log2_w, log2_h) {
        return false;
    }
    if out.is_empty() {
        return true;
    }
    let hmask = 1u32.wrapping_shl(log2_h).wrapping_sub(1);
    let wmask = 1u32.wrapping_shl(log2_w).wrapping_sub(1);
    let stride = 8u32.wrapping_shl(log2_w);
    let fp = footprints.as_ptr();
    let range = out.as_mut_ptr_range();
    let (tu, tv) = split(start);
    // SAFETY: as `lit_span`, with the footprint index `row 2^log2_w + col`, `row <=
    // 2^log2_h - 1` and `col <= 2^log2_w - 1` (masked), below `footprints.len()` =
    // `2^(log2_w + log2_h)` (checked above). Frame: `r6`, `r7` pushed first, then the stride
    // (from `r0`), then `r1` to `r5`, `r12`, `lr` (inputs); all released before `r6`, `r7`
    // are popped. Tested by the `dsp_span` firmware and the Cortex-M4F checksums of
    // `cargo xtask mcu` (`whole_sphere_footprint` and the report firmwares).
    unsafe {
        core::arch::asm!(
            // Frame: [sp] du, dv, di, footprints, end, height - 1, width - 1, stride;
            // the saved r6, r7.
            "push {{r6, r7}}",
            "str r0, [sp, #-4]!",
            "push {{r1, r2, r3, r4, r5, r12, lr}}",
            "mov.w r0, #0x8000",
            "mov.w r12, #0x003F003F",
            "mov.w lr, #0x001F001F",
            "ldrd r6, r7, [sp, #20]",
            "2:",
            footprint_runtime!("28"),
            load_and_fractions!(),
            "mla r5, r1, r4, r0",
            weights_blend_store!(),
            // Steps, footprints, end and the masks for the next pixel from the frame.
            "ldm sp, {{r1, r2, r3, r4, r5, r6, r7}}",
            "add r8, r1",
            "add r9, r2",
            "add r10, r3",
            "cmp r11, r5",
            "bne 2b",
            "add sp, #32",
            "pop {{r6, r7}}",
            inout("r1") slope[0] => _,
            inout("r2") slope[1] => _,
            inout("r3") slope[2] => _,
            inout("r4") fp => _,
            inout("r5") range.end => _,
            inout("r12") hmask => _,
            inout("lr") wmask => _,
            inout("r0") stride => _,
            inout("r8") tu => _,
            inout("r9") tv => _,
            inout("r10") start[2] => _,
            inout("r11") range.start => _,
        );
    }
    true
}

/// [`lit_span_depth`] for a texture whose size is read at run time, as [`lit_span_runtime`]:
/// 48 instructions per drawn pixel. `None`, writing nothing, for other sizes or counts, or
/// `zrow` shorter than `out`.
#[inline(always)]
#[allow(unsafe_code, clippy::too_many_arguments)]
pub(super) fn lit_span_depth_runtime(
    footprints: &[u64],
    (log2_w, log2_h): (u32, u32),
    start: &[i32; 3],
    slope: &[i32; 3],
    z: i32,
    dz: i32,
    out: &mut [u16],
    zrow: &mut [u16],
) -> Option<u32> {
    if footprints.len() != footprints_read(log2_w, log2_h) || zrow.len() < out.len() {
        return None;
    }
    if out.is_empty() {
        return Some(0);
    }
    let n = out.len() as u32;
    let range = out.as_mut_ptr_range();
    let zoff = (zrow.as_mut_ptr() as usize).wrapping_sub(range.start as usize);
    // Copied into the loop's frame by its prologue (no register is left to pass them).
    let extra: [u32; 4] = [
        range.end as u32,
        1u32.wrapping_shl(log2_h).wrapping_sub(1),
        1u32.wrapping_shl(log2_w).wrapping_sub(1),
        8u32.wrapping_shl(log2_w),
    ];
    let (tu, tv) = split(start);
    let hidden: u32;
    // SAFETY: as `lit_span_depth` for `out` and `zrow`, and as `lit_span_runtime` for the
    // footprints. `r5` points at `extra` (four words, read before the frame is built). Frame:
    // `r6`, `r7` pushed first, then 44 bytes (du, dv, di, footprints, end, dz, zoff, hidden,
    // height - 1, width - 1, stride), all released before `r6`, `r7` are popped. Tested by
    // the `dsp_span` firmware and the Cortex-M4F checksums of `cargo xtask mcu`.
    unsafe {
        core::arch::asm!(
            "push {{r6, r7}}",
            "sub sp, #44",
            "stm sp, {{r1, r2, r3, r4}}",
            "ldm r5, {{r1, r2, r3, r4}}",
            "str r1, [sp, #16]",
            "strd r12, lr, [sp, #20]",
            "mov.w r1, #0",
            "str r1, [sp, #28]",
            "strd r2, r3, [sp, #32]",
            "str r4, [sp, #40]",
            "ldr r4, [sp, #12]",
            "mov.w r12, #0x003F003F",
            "mov.w lr, #0x001F001F",
            "ldr r7, [sp, #24]",
            "2:",
            depth_test!(),
            "ldrd r6, r7, [sp, #32]",
            footprint_runtime!("40"),
            load_and_fractions!(),
            "mul r5, r1, r4",
            "add.w r5, r5, #0x8000",
            weights_blend_store!(),
            depth_next_pixel!(),
            "add sp, #44",
            "pop {{r6, r7}}",
            inout("r1") slope[0] => hidden,
            inout("r2") slope[1] => _,
            inout("r3") slope[2] => _,
            inout("r4") footprints.as_ptr() => _,
            inout("r5") extra.as_ptr() => _,
            inout("r12") dz => _,
            inout("lr") zoff => _,
            inout("r0") z => _,
            inout("r8") tu => _,
            inout("r9") tv => _,
            inout("r10") start[2] => _,
            inout("r11") range.start => _,
        );
    }
    Some(n.wrapping_sub(hidden))
}
