//! JPEG images are read wherever PNGs are; a volume renders alike from NRRD and MetaImage.

use super::*;

/// JPEG wherever a PNG is read: a JPEG colour image and a JPEG quilt give what the same pixels
/// (the JPEG decoded, saved as PNG) give.
#[test]
fn jpeg_images_are_read_where_pngs_are() {
    let (w, h) = (48u32, 32u32);
    let mut colour = image::RgbImage::new(w, h);
    for (x, y, p) in colour.enumerate_pixels_mut() {
        *p = image::Rgb([(x * 5) as u8, (y * 7) as u8, ((x + y) * 3) as u8]);
    }
    let jpeg = out("colour.jpg");
    colour.save(&jpeg).unwrap();
    let decoded = out("colour_decoded.png");
    image::open(&jpeg)
        .unwrap()
        .to_rgb8()
        .save(&decoded)
        .unwrap();
    let mut depth = image::GrayImage::new(w, h);
    for (x, _, p) in depth.enumerate_pixels_mut() {
        *p = image::Luma([(x * 5) as u8]);
    }
    let depth_path = out("depth.png");
    depth.save(&depth_path).unwrap();
    let spatial = |colour: &Path, name: &str| {
        let image = out(name);
        let (ok, err) = common::cli(&[
            "rgbd",
            s(colour),
            s(&depth_path),
            "--display",
            "lenticular:8",
            "--out",
            s(&image),
        ]);
        assert!(ok, "{name}: {err}");
        RgbImage::load_png(&image).unwrap()
    };
    let from_jpeg = spatial(&jpeg, "rgbd_jpeg.png");
    let from_png = spatial(&decoded, "rgbd_png.png");
    assert_eq!(compare(&from_jpeg, &from_png).unwrap().max_abs_err, 0);
    // A 4×2 quilt of 8 views as JPEG, against the same pixels as PNG.
    let quilt = out("views_qs4x2a1.5.jpg");
    image::RgbImage::from_fn(4 * w, 2 * h, |x, y| {
        image::Rgb([(x % 251) as u8, (y * 3) as u8, 77])
    })
    .save(&quilt)
    .unwrap();
    let quilt_png = out("views_png_qs4x2a1.5.png");
    image::open(&quilt)
        .unwrap()
        .to_rgb8()
        .save(&quilt_png)
        .unwrap();
    let interleaved = |quilt: &Path, name: &str| {
        let image = out(name);
        let (ok, err) = common::cli(&[
            "interleave",
            s(quilt),
            "--display",
            "lenticular:8",
            "--out",
            s(&image),
        ]);
        assert!(ok, "{name}: {err}");
        RgbImage::load_png(&image).unwrap()
    };
    let a = interleaved(&quilt, "interleave_jpeg.png");
    let b = interleaved(&quilt_png, "interleave_png.png");
    assert_eq!(compare(&a, &b).unwrap().max_abs_err, 0);
}

/// `autostereo volume` reads a MetaImage as the same scan in NRRD (LPS geometry as a
/// TransformMatrix against RAS space directions), and a VTK `.vti` whose Direction points the
/// voxel axes where the NRRD's land on screen: the same image; and the geometry is used: the
/// NRRD's axes flipped render another picture.
#[test]
fn a_volume_renders_alike_from_nrrd_and_metaimage() {
    let n = 16usize;
    let voxels: Vec<u8> = (0..n * n * n)
        .map(|i| {
            let (x, y, z) = (i % n, i / n % n, i / (n * n));
            let d = (x as f32 - 5.0).powi(2) + (y as f32 - 8.0).powi(2) + (z as f32 - 10.0).powi(2);
            if d < 20.0 {
                200
            } else if x < 3 {
                120
            } else {
                0
            }
        })
        .collect();
    // Voxel axes in RAS+: i posterior, j right, k superior.
    let nrrd = |directions: &str| {
        let mut b = format!(
            "NRRD0004\ntype: uchar\ndimension: 3\nspace: RAS\nsizes: {n} {n} {n}\n\
             space directions: {directions}\nencoding: raw\n\n"
        )
        .into_bytes();
        b.extend(&voxels);
        b
    };
    let mut mha = format!(
        "ObjectType = Image\nNDims = 3\nTransformMatrix = 0 1 0 -1 0 0 0 0 1\n\
         ElementSpacing = 1 1 1\nDimSize = {n} {n} {n}\nElementType = MET_UCHAR\n\
         ElementDataFile = LOCAL\n"
    )
    .into_bytes();
    mha.extend(&voxels);
    let render = |file: &Path, name: &str| {
        let image = out(&format!("{name}.png"));
        let (ok, err) = common::cli(&[
            "volume",
            s(file),
            "--size",
            "48x48",
            "--tf",
            "ct-bone",
            "--out",
            s(&image),
        ]);
        assert!(ok, "{name}: {err}");
        RgbImage::load_png(&image).unwrap()
    };
    let from_nrrd = render(
        &write("scan.nrrd", &nrrd("(0,-1,0) (1,0,0) (0,0,1)")),
        "nrrd",
    );
    let from_mha = render(&write("scan.mha", &mha), "mha");
    assert_eq!(compare(&from_mha, &from_nrrd).unwrap().max_abs_err, 0);
    // VTK's world is the screen's (x right, y up, z toward the viewer): the NRRD's axes on
    // screen are i → −z, j → −x, k → +y, the columns of this row-major Direction.
    let values: Vec<String> = voxels.iter().map(u8::to_string).collect();
    let vti = format!(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" byte_order=\"LittleEndian\">\n\
         <ImageData WholeExtent=\"0 {m} 0 {m} 0 {m}\" Spacing=\"1 1 1\" \
         Direction=\"0 -1 0 0 0 1 -1 0 0\">\n<Piece Extent=\"0 {m} 0 {m} 0 {m}\">\n\
         <PointData Scalars=\"ct\"><DataArray type=\"UInt8\" Name=\"ct\" format=\"ascii\">\n\
         {}\n</DataArray></PointData></Piece></ImageData></VTKFile>\n",
        values.join(" "),
        m = n - 1
    );
    let from_vti = render(&write("scan.vti", vti.as_bytes()), "vti");
    assert_eq!(compare(&from_vti, &from_nrrd).unwrap().max_abs_err, 0);
    let flipped = render(
        &write("flipped.nrrd", &nrrd("(0,1,0) (-1,0,0) (0,0,1)")),
        "flipped",
    );
    assert!(compare(&flipped, &from_nrrd).unwrap().frac_off_2 > 0.01);
}
