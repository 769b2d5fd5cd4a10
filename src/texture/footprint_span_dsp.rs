//! The lit span loop of [`BilinearFootprintSized`](super::BilinearFootprintSized) on
//! ARMv7E-M (Cortex-M4, M4F, M7), written in assembly with the DSP extension's dual
//! multiplies.
//!
//! What it computes is [`BilinearFootprintSized::sample_scaled`](super::BilinearFootprintSized::sample_scaled)
//! at every pixel of a linear piece whose intensity is in range (the loop
//! [`ModulateIntensity`](crate::shading::ModulateIntensity) runs after
//! [`Shader::piece_in_range`](crate::shading::Shader::piece_in_range)), bit for bit:
//!
//! - the footprint of `(u - 0x7F80, v - 0x7F80)` (I16F16 texel units), row wrapped to
//!   `2^LOG2_H`, column to `2^LOG2_W`, and its Q8 fractions `a`, `b`;
//! - the weights `w11 = (a b + 128) >> 8`, `w10 = a - w11`, `w01 = b - w11`,
//!   `w00 = 256 - a - b + w11`, packed two per word (`w00 | w10 << 16`, `w01 | w11 << 16`)
//!   to match the footprint's row words (`c00 | c10 << 16`, `c01 | c11 << 16`);
//! - per channel `S = sum w c` in two instructions (`smuad`, `smlad`: both lanes of a row
//!   word times both lanes of its weights, summed);
//! - per channel `(S i + 2^15) >> 16` for the intensity `i = (I >> 16) & 0xFF` in one
//!   (`smmulr` of `S` and `i << 16`: `(S i 2^16 + 2^31) >> 32`, the same integer).
//!
//! LLVM's code for the same loop (the generic span loop and `blend_rows_q8`) took 53
//! instructions per pixel on Cortex-M4F: with 13 allocatable registers it rematerialized
//! nine constants and reloaded four values from the stack at every pixel. [`lit_span`]
//! takes 39. It keeps its steps and footprint pointer in the stack frame it pushes and
//! reloads them with one `ldm` per pixel, and uses every register but `sp` and `pc` (`r6`
//! and `r7`, which Rust reserves, saved and restored inside the block).
//!
//! [`lit_span_depth`] tests and writes the depth in the same loop (46 instructions per
//! drawn pixel, about 15 per hidden one), so the span stage hands it spans of any length
//! instead of a depth pass, a mask and a second loop (which LLVM could not fuse on this
//! core without spilling).
//!
//! Measured on the whole-frame sphere (`whole_sphere_sized`, Cortex-M4F, instructions per
//! pixel, the same checksum): 157.56 -> 144.68 with [`lit_span`] after the depth pass,
//! -> 138.33 with [`lit_span_depth`] for every short span. The cycle model of `cargo xtask
//! mcu` (where `ldm` of `n` words costs `1 + n`): 214.0 -> 204.2 for the first.

/// The start of a pixel's sample, shared by both loops: the footprint's two row words
/// loaded into `r2`, `r3` (from `r4`, the footprints, plus `row << (LOG2_W + 3) + col <<
/// 3`), then `r1 = a` and `r4 = b << 8`, the Q8 fractions. Registers: `r8` = u, `r9` = v
/// (I16F16, already less `0x7F80`); operands `lh`, `lw`, `row_shift`.
macro_rules! footprint_and_fractions {
    () => {
        concat!(
            "ubfx r1, r9, #16, #{lh}\n",
            "ubfx r2, r8, #16, #{lw}\n",
            "add.w r1, r4, r1, lsl #{row_shift}\n",
            "add.w r1, r1, r2, lsl #3\n",
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

/// The loop's own bound on the footprints (its loads are not checked per pixel): the
/// caller's binding holds at least this many ([`TexBinding::can_draw`](crate::shading::TexBinding::can_draw)),
/// but the loop does not rely on that.
const fn footprints_read(log2_w: u32, log2_h: u32) -> usize {
    1usize << (log2_w + log2_h)
}

/// Whether the loop is assembled for a `2^log2_w x 2^log2_h` texture: each side from 2 to
/// 2^16 texels (the bit-field extracts take 1 to 16 bits above bit 16).
pub(super) const fn supported(log2_w: u32, log2_h: u32) -> bool {
    log2_w >= 1 && log2_w <= 16 && log2_h >= 1 && log2_h <= 16
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
    // Bilinear's split of the coordinates (`t = u - 1/2 + 1/512`, see `gather_footprint`).
    let tu = start[0].wrapping_sub(0x7F80);
    let tv = start[1].wrapping_sub(0x7F80);
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
            footprint_and_fractions!(),
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
    let tu = start[0].wrapping_sub(0x7F80);
    let tv = start[1].wrapping_sub(0x7F80);
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
            // Depth: r1 = d, tested against and written to [r11 + r7].
            "usat r1, #16, r0, asr #14",
            "ldrh r2, [r11, r7]",
            "cmp r1, r2",
            "bhs 3f",
            "strh r1, [r11, r7]",
            // The sample, as in `lit_span` (w11 from a multiply and an add: r0 holds z).
            footprint_and_fractions!(),
            "mul r5, r1, r4",
            "add.w r5, r5, #0x8000",
            weights_blend_store!(),
            // Next pixel: steps, footprints, end, dz and zoff from the frame.
            "4:",
            "ldm sp, {{r1, r2, r3, r4, r5, r6, r7}}",
            "add r8, r1",
            "add r9, r2",
            "add r10, r3",
            "add r0, r6",
            "cmp r11, r5",
            "bne 2b",
            "b 5f",
            // Hidden: the next pixel, one more hidden.
            "3:",
            "add.w r11, r11, #2",
            "ldr r1, [sp, #28]",
            "add.w r1, r1, #1",
            "str r1, [sp, #28]",
            "b 4b",
            "5:",
            "ldr r1, [sp, #28]",
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
