//! Check, not a scene: the lit span loops of `BilinearFootprintSized` and `BilinearFootprint`
//! (`Shader::shade_piece_rgb565` of `ModulateIntensity`, in assembly on ARMv7E-M) against the
//! same shader's per-pixel `shade_in_range`, over random spans (any coordinates, steps and
//! lengths 1 to 64, intensities in range) on textures of 2x2 to 256x128 texels; and, for the
//! sized sampler, each span again with the depth test in the loop
//! (`shade_piece_depth_rgb565`) against the test done per pixel. Prints `dsp_span
//! loop=asm|none spans=… depth_spans=… pixels=… mismatches=…` and fails on any mismatch. On
//! a core without the loops (`loop=none`) nothing is compared. Whole-frame memory layout.
#![no_std]
#![no_main]

use fixel::shading::{Fragment, ModulateIntensity, Shader, TexBinding, TexTriangle};
use fixel::texture::{
    write_footprints, BilinearFootprint, BilinearFootprintSized, MipTexture, Repeat, TexSampler,
    Texture,
};
use fixel::Rgb565;
use fixel_firmware::{data, outln};

/// xorshift64*: the same sequence on every core.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
}

#[derive(Default)]
struct Tally {
    asm: bool,
    spans: u32,
    depth_spans: u32,
    pixels: u32,
    mismatches: u32,
}

/// `spans` random spans through both paths of `ModulateIntensity<F>` on `chain` (`F`:
/// `BilinearFootprintSized`, with both loops, or `BilinearFootprint`, with the loop without
/// the depth test).
fn check<F: TexSampler>(
    chain: &MipTexture<'_>,
    sampler: F,
    rng: &mut Rng,
    spans: u32,
    t: &mut Tally,
) -> bool {
    let Ok(tex) = TexBinding::new(chain, sampler, Repeat, Repeat, Default::default()) else {
        return false;
    };
    let shader = ModulateIntensity { tex };
    let depth_loop = <ModulateIntensity<'_, F, Repeat, Repeat> as Shader>::PIECE_DEPTH_LOOP;
    let mut fast = [0u16; 64];
    for _ in 0..spans {
        let (r0, r1, r2) = (rng.next(), rng.next(), rng.next());
        let n = 1 + (r0 % 64) as usize;
        // Coordinates anywhere (wrapping), steps up to 4 texels either way.
        let start_uv = [r1 as i32, (r1 >> 32) as i32];
        let slope_uv = [((r2 as i32) >> 13), (((r2 >> 32) as i32) >> 13)];
        // An intensity that stays in `0..256 << 16` over the span (what `piece_in_range`
        // guarantees before the loop runs).
        let lo = (r0 >> 8) as i32 & 0xFF_FFFF;
        let hi = (r0 >> 32) as i32 & 0xFF_FFFF;
        let di = if n > 1 { (hi - lo) / (n as i32 - 1) } else { 0 };
        let start = [start_uv[0], start_uv[1], lo];
        let slope = [slope_uv[0], slope_uv[1], di];
        let out = &mut fast[..n];
        out.fill(0);
        if !shader.shade_piece_rgb565(&start, &slope, out) {
            continue;
        }
        t.asm = true;
        t.spans += 1;
        let mut v = start;
        for o in out.iter() {
            if sample(&shader, v) != Some(*o) {
                t.mismatches += 1;
            }
            t.pixels += 1;
            step(&mut v, slope);
        }
        // The same span with the depth test in the loop, against the test done per pixel:
        // stored depths and a depth ramp that pass some pixels and hide others, clamped at
        // both ends of the 16-bit range now and then.
        let r3 = rng.next();
        let mut zrow = [0u16; 64];
        for zb in zrow.iter_mut() {
            *zb = rng.next() as u16;
        }
        let z = (r3 as i32) >> ((r3 >> 40) % 4);
        let dz = ((r3 >> 32) as i32) >> (12 + (r3 >> 50) % 8);
        let zr = &mut zrow[..n];
        let mut want_z = [0u16; 64];
        want_z[..n].copy_from_slice(zr);
        let mut want = [0u16; 64];
        let mut want_shown = 0;
        let (mut v, mut zk) = (start, z);
        for k in 0..n {
            let d = (zk >> 14).clamp(0, 0xFFFF);
            if d < i32::from(want_z[k]) {
                want_z[k] = d as u16;
                want[k] = sample(&shader, v).unwrap_or(0);
                want_shown += 1;
            }
            zk = zk.wrapping_add(dz);
            step(&mut v, slope);
        }
        let out = &mut fast[..n];
        out.fill(0);
        match shader.shade_piece_depth_rgb565(&start, &slope, (z, dz), out, zr) {
            Some(shown) => {
                t.depth_spans += 1;
                t.mismatches += u32::from(shown != want_shown)
                    + out.iter().zip(&want).filter(|(a, b)| a != b).count() as u32
                    + zr.iter().zip(&want_z).filter(|(a, b)| a != b).count() as u32;
            }
            None => t.mismatches += u32::from(depth_loop),
        }
    }
    true
}

/// The shader's pixel at varyings `v`, one pixel at a time.
fn sample<S: Shader<Varyings = [i32; 3], Triangle = TexTriangle>>(
    shader: &S,
    v: [i32; 3],
) -> Option<u16> {
    let f = Fragment {
        varyings: v,
        x: 0,
        y: 0,
        depth: 0,
        lambda: 0,
        triangle: TexTriangle::default(),
    };
    shader.shade_in_range(&f)
}

fn step(v: &mut [i32; 3], slope: [i32; 3]) {
    for (a, d) in v.iter_mut().zip(slope) {
        *a = a.wrapping_add(d);
    }
}

/// A `w x h` texture of random texels with its footprints, checked as `check` does.
fn check_small<const LW: u32, const LH: u32>(rng: &mut Rng, t: &mut Tally) -> bool {
    let (w, h) = (1u32 << LW, 1u32 << LH);
    let mut texels = [Rgb565::new(0, 0, 0); 256];
    let mut fp = [0u64; 256];
    let n = (w * h) as usize;
    let (Some(texels), Some(fp)) = (texels.get_mut(..n), fp.get_mut(..n)) else {
        return false;
    };
    for c in texels.iter_mut() {
        let r = rng.next();
        *c = Rgb565::new(
            (r & 31) as u8,
            ((r >> 8) & 63) as u8,
            ((r >> 16) & 31) as u8,
        );
    }
    let Ok(tex) = Texture::new(texels, w, h) else {
        return false;
    };
    if write_footprints(&tex, fp).is_err() {
        return false;
    }
    let Ok(chain) = MipTexture::single(tex).with_footprints(fp) else {
        return false;
    };
    check(&chain, BilinearFootprintSized::<LW, LH>, rng, 400, t)
        && check(&chain, BilinearFootprint, rng, 400, t)
}

fn run() -> bool {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut t = Tally::default();
    let ok = check(
        &data::T256X128_FP,
        BilinearFootprintSized::<8, 7>,
        &mut rng,
        3000,
        &mut t,
    ) && check(
        &data::T256X128_FP,
        BilinearFootprint,
        &mut rng,
        3000,
        &mut t,
    ) && check(
        &data::T64_FP,
        BilinearFootprintSized::<6, 6>,
        &mut rng,
        1000,
        &mut t,
    ) && check(&data::T64_FP, BilinearFootprint, &mut rng, 1000, &mut t)
        && check(
            &data::T128_FP,
            BilinearFootprintSized::<7, 7>,
            &mut rng,
            1000,
            &mut t,
        )
        && check(&data::T128_FP, BilinearFootprint, &mut rng, 1000, &mut t)
        && check_small::<1, 1>(&mut rng, &mut t)
        && check_small::<2, 1>(&mut rng, &mut t)
        && check_small::<3, 5>(&mut rng, &mut t)
        && check_small::<4, 4>(&mut rng, &mut t);
    outln!(
        "dsp_span loop={} spans={} depth_spans={} pixels={} mismatches={}",
        if t.asm { "asm" } else { "none" },
        t.spans,
        t.depth_spans,
        t.pixels,
        t.mismatches
    );
    ok && t.mismatches == 0
}

fixel_firmware::entry!(run);
