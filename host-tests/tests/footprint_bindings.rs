//! The footprint filters as the draws and bindings take them: a chain without footprint words
//! refused with an error that says so, one of another size refused by a sized filter, and the
//! accepted bindings drawing `Bilinear`'s pixels.

use embedded_graphics_core::pixelcolor::raw::RawU16;
use fixel::geometry::{Cull, Viewport};
use fixel::pipeline::{
    Affine, DepthLess, Draw, Exact, ModulateIntensity, NoDepth, Pipeline, Replace,
};
use fixel::shading::{TexBinding, TexTriangle};
use fixel::texture::{
    write_footprints, Bilinear, BilinearFootprint, BilinearFootprintSized, Lod, MipTexture, Repeat,
    Texture,
};
use fixel::{Error, Rgb565};

/// Draws and bindings refuse the footprint filter on a chain without footprints, with an
/// error that says so; with footprints they accept it, and draw `Bilinear`'s pixels.
#[test]
fn bindings_refuse_missing_footprints() {
    type Fp = Pipeline<Affine, BilinearFootprint, Repeat, Repeat, Replace, NoDepth>;
    let t = [1u16, 2, 3, 4].map(|r| Rgb565::from(RawU16::new(r)));
    let plain = Texture::new(&t, 2, 2).unwrap();
    let vp = Viewport::new(0, 0, 8, 8).unwrap();
    let needs = Error::BadMode(
        "BilinearFootprint needs a texture with footprints (MipTexture::with_footprints)",
    );
    assert_eq!(
        Draw::<Rgb565>::new::<Fp>(Some(plain), vp, Cull::None).unwrap_err(),
        needs
    );
    let chain = MipTexture::single(plain);
    assert_eq!(
        Draw::<Rgb565>::new_mip::<Fp>(Some(chain), vp, Cull::None).unwrap_err(),
        needs
    );
    assert_eq!(
        TexBinding::new(&chain, BilinearFootprint, Repeat, Repeat, Lod::default()).unwrap_err(),
        needs
    );
    let mut fp = [0u64; 4];
    write_footprints(&plain, &mut fp).unwrap();
    let chain = chain.with_footprints(&fp).unwrap();
    assert!(Draw::<Rgb565>::new_mip::<Fp>(Some(chain), vp, Cull::None).is_ok());
    let b = TexBinding::new(&chain, BilinearFootprint, Repeat, Repeat, Lod::default()).unwrap();
    let plain_b = TexBinding::new(&chain, Bilinear, Repeat, Repeat, Lod::default()).unwrap();
    let tri = TexTriangle::default();
    for (u, v) in [(0x8000, 0x8000), (0x1_4000, 0x9000), (-0x2_0000, 0x7_FFFF)] {
        assert_eq!(b.sample(tri, u, v, 0), plain_b.sample(tri, u, v, 0));
        assert_eq!(
            b.sample_scaled(tri, u, v, 0, 200),
            plain_b.sample_scaled(tri, u, v, 0, 200)
        );
    }
}

/// A typed draw checks the texture's size as a binding does.
#[test]
fn a_sized_footprint_draw_refuses_a_chain_of_another_size() {
    static T: [Rgb565; 8] = [Rgb565::new(0, 0, 0); 8];
    static F: [u64; 8] = [0; 8];
    let chain = MipTexture::single(Texture::from_static(&T, 4, 2)).with_footprints_static(&F);
    type Lit<F> = Pipeline<Exact, F, Repeat, Repeat, ModulateIntensity, DepthLess>;
    let vp = Viewport::new(0, 0, 8, 8).unwrap();
    let ok =
        Draw::<Rgb565>::new_mip::<Lit<BilinearFootprintSized<2, 1>>>(Some(chain), vp, Cull::None);
    assert!(ok.is_ok());
    let wrong =
        Draw::<Rgb565>::new_mip::<Lit<BilinearFootprintSized<1, 2>>>(Some(chain), vp, Cull::None);
    assert_eq!(
        wrong.err(),
        Some(Error::TextureSizeMismatch {
            width: 2,
            height: 4
        })
    );
}
