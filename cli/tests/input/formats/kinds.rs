//! A file of another kind, or of an unknown format, is refused naming what reads it.

use super::*;

#[test]
fn a_file_of_another_kind_names_the_command_that_reads_it() {
    let nrrd = write(
        "head.nrrd",
        b"NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n\0\0\0\0\0\0\0\0",
    );
    let stl = write(
        "part.stl",
        b"solid part\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n\
          endloop\nendfacet\nendsolid part\n",
    );
    let obj = write("bunny.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let cloud = write(
        "cloud.ply",
        b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
    );
    let jpeg = write(
        "photo.jpg",
        &[0xff, 0xd8, 0xff, 0xe0, 0, 0x10, b'J', b'F', b'I', b'F'],
    );
    let png = write("spatial.png", b"\x89PNG\r\n\x1a\n");
    let laz = write("scan.laz", b"LASF\0\0\0\0");
    let mut dicom = vec![0u8; 132];
    dicom[128..].copy_from_slice(b"DICM");
    let dicom = write("slice.dcm", &dicom);
    let polydata = write(
        "mesh.vtk",
        b"# vtk DataFile Version 3.0\nmesh\nASCII\nDATASET POLYDATA\nPOINTS 0 float\n",
    );
    let notes = write("notes.txt", b"hello");
    let target = s(&out("never.png")).to_string();
    let cases: Vec<(Vec<&str>, String)> = vec![
        (
            vec!["mesh", s(&nrrd)],
            format!(
                "a volume (NRRD), not a mesh: `autostereo volume {}` reads it",
                s(&nrrd)
            ),
        ),
        (
            vec!["points", s(&stl)],
            format!(
                "a mesh (STL), not a point cloud: `autostereo mesh {}` reads it",
                s(&stl)
            ),
        ),
        (
            vec!["volume", s(&obj)],
            format!(
                "a mesh (OBJ), not a volume: `autostereo mesh {}` reads it",
                s(&obj)
            ),
        ),
        (
            vec!["mesh", s(&cloud)],
            format!(
                "this is a point cloud (PLY: no faces with three or more corners, 1 vertices), not \
                 a mesh: `autostereo points {}` reads it",
                s(&cloud)
            ),
        ),
        (
            vec!["volume", s(&jpeg)],
            "an image (JPEG), not a volume".into(),
        ),
        (vec!["mesh", s(&png)], "an image (PNG), not a mesh".into()),
        (
            vec!["interleave", s(&obj), "--out", &target],
            "a mesh (OBJ), not an image".into(),
        ),
        (vec!["points", s(&laz)], "malformed LAS header".into()),
        (vec!["volume", s(&dicom)], "malformed DICOM".into()),
        (
            vec!["volume", s(&polydata)],
            "DATASET POLYDATA: a mesh/polydata, not image data".into(),
        ),
        (
            vec!["volume", s(&notes)],
            "unknown format; read here: meshes .obj .ply .stl .gltf .glb".into(),
        ),
    ];
    for (args, expected) in cases {
        let (ok, err) = common::cli(&common::measuring(&args));
        assert!(!ok, "{args:?} succeeded");
        assert!(
            err.contains(&expected),
            "{args:?}: '{err}' lacks '{expected}'"
        );
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    assert!(!Path::new(&target).exists());
}
