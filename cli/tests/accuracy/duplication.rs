//! The quilt as an output of the command line: the retired `--quilt-out` refused, every
//! method's quilt named as Looking Glass reads it. (The per-view duplication methods against the
//! N-pass, and the quilt round trip: tests/{meshes,splats,volumes}/duplication.rs.)

use crate::common;

use autostereo::image_io::RgbImage;

#[test]
fn the_quilt_is_an_output_of_every_method_named_as_looking_glass_reads_it() {
    let dir = common::out_dir().join("quilt-cli");
    std::fs::create_dir_all(&dir).unwrap();
    let quilt = dir.join("torus.png");
    let out = dir.join("spatial.png");
    let (q, o) = (quilt.to_str().unwrap(), out.to_str().unwrap());
    // --quilt-out was the tiled method's atlas only; it is retired in favour of --output.
    let (ok, stderr) = common::cli(&["mesh", "--method", "tiled", "--quilt-out", q, "--out", o]);
    assert!(!ok && stderr.contains("--output quilt --out"), "{stderr}");
    assert!(!out.exists(), "no output on a refused run");
    // hubner8 (the default display): 8 views of 96×64 in a 2×4 grid (the smallest side), the
    // same tiles from the tiled method and the N-pass.
    let mut quilts = Vec::new();
    for method in ["tiled", "n-pass"] {
        let args = [
            "mesh", "--method", method, "--size", "96x64", "--output", "quilt", "--out", q,
        ];
        let (ok, stderr) = common::cli(&args);
        assert!(ok, "{stderr}");
        let named = dir.join("torus_qs2x4a1.5.png");
        let image = RgbImage::load_png(&named).unwrap();
        assert_eq!([image.width, image.height], [192, 256]);
        quilts.push(image);
    }
    let diff = autostereo::image_io::compare(&quilts[0], &quilts[1]).unwrap();
    assert!(diff.psnr_db >= 40.0, "{diff:?}");
}
