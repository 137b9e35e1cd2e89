//! `.vti` files made here: every data format, byte order, header and compressor, and the
//! malformed ones refused by name.

use base64::Engine;
use glam::Vec3;

use super::data::{read_blob, Base64, Blob, BASE64};
use super::*;

fn xml(image: &str, array: &str) -> String {
    format!(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" \
         byte_order=\"LittleEndian\" header_type=\"UInt32\">\n<ImageData {image}>\n\
         <Piece Extent=\"0 1 0 1 0 0\"><PointData Scalars=\"s\">{array}</PointData>\
         </Piece></ImageData></VTKFile>\n"
    )
}

// With a child VTK 9 writes (its text is not data).
const ASCII: &str = "<DataArray type=\"UInt8\" Name=\"s\" format=\"ascii\">1 2\n\
    <InformationKey name=\"L2_NORM_RANGE\"><Value index=\"0\">9</Value></InformationKey>\n\
    3 4</DataArray>";

#[test]
fn the_header_gives_the_grid_spacing_and_axes() {
    let file = xml(
        "WholeExtent=\"0 1 0 1 0 0\" Origin=\"5 5 5\" Spacing=\"0.5 -2 1\" \
         Direction=\"0 1 0 1 0 0 0 0 1\"",
        ASCII,
    );
    let vti = parse_xml(file.as_bytes()).unwrap();
    assert_eq!(vti.dims, [2, 2, 1]);
    assert_eq!(vti.spacing, [0.5, 2.0, 1.0]);
    assert_eq!(vti.kind, SampleType::U8);
    assert_eq!(vti.name, "s");
    // Column 0 of the row-major Direction is (0, 1, 0); axis 1 is (1, 0, 0) turned
    // around by its negative spacing.
    let axes = vti.axes.unwrap();
    assert_eq!(axes.x_axis, Vec3::Y);
    assert_eq!(axes.y_axis, -Vec3::X);
    assert_eq!(axes.z_axis, Vec3::Z);
    assert_eq!(read_samples(&vti, 4).unwrap(), [1.0, 2.0, 3.0, 4.0]);
    // No Direction, positive spacing: the axes as they are.
    let plain = xml("WholeExtent=\"0 1 0 1 0 0\"", ASCII);
    let plain = parse_xml(plain.as_bytes()).unwrap();
    assert!(plain.axes.is_none());
    assert_eq!(plain.spacing, [1.0; 3]);
}

#[test]
fn broken_headers_say_what_is_wrong() {
    let refused = |image: &str, array: &str, expected: &str| {
        let e = match parse_xml(xml(image, array).as_bytes()) {
            Ok(_) => panic!("{image} {array}: accepted"),
            Err(e) => e,
        };
        assert!(e.contains(expected), "'{e}' lacks '{expected}'");
    };
    let whole = "WholeExtent=\"0 1 0 1 0 0\"";
    refused("", ASCII, "missing WholeExtent");
    refused("WholeExtent=\"0 1 0 1\"", ASCII, "4 numbers, 6 needed");
    refused("WholeExtent=\"0 1 1 0 0 0\"", ASCII, "at or past its start");
    refused(
        &format!("{whole} Direction=\"1 0.3 0 0 1 0 0 0 1\""),
        ASCII,
        "right angles",
    );
    refused(&format!("{whole} Spacing=\"1 0 1\""), ASCII, "non-zero");
    refused(
        whole,
        &ASCII.replace("UInt8", "Int64"),
        "type Int64: 64-bit integers are not read",
    );
    refused(
        whole,
        &ASCII.replace("UInt8", "Bit"),
        "type 'Bit' is not read",
    );
    refused(
        whole,
        &ASCII.replace("format", "NumberOfComponents=\"3\" format"),
        "'s' has 3 components",
    );
    refused(
        whole,
        &ASCII.replace("\"s\"", "\"t\""),
        "Scalars 's' names no",
    );
    refused(
        whole,
        &ASCII.replace("\"ascii\"", "\"appended\" offset=\"0\""),
        "no AppendedData",
    );
    let e = parse_xml(b"<VTKFile type=\"PolyData\"><PolyData/></VTKFile>")
        .err()
        .unwrap();
    assert!(e.contains("'PolyData': a mesh"), "{e}");
    let e = parse_xml(b"<a/>").err().unwrap();
    assert!(e.contains("no VTKFile"), "{e}");
    let cells = xml(whole, "").replace(
        "<PointData Scalars=\"s\"></PointData>",
        "<CellData>\n<DataArray type=\"UInt8\" Name=\"c\" format=\"ascii\">1</DataArray>\
         </CellData>",
    );
    let e = parse_xml(cells.as_bytes()).err().unwrap();
    assert!(e.contains("CellData only"), "{e}");
    let two = xml(whole, ASCII).replace("</Piece>", "</Piece><Piece/>");
    assert!(parse_xml(two.as_bytes())
        .err()
        .unwrap()
        .contains("several Pieces"));
}

#[test]
fn appended_data_is_split_from_the_xml() {
    let mut file = b"<VTKFile type=\"ImageData\"><ImageData WholeExtent=\"0 0 0 0 0 1\">\
        <Piece><PointData><DataArray type=\"Int16\" Name=\"a\" format=\"appended\" \
        offset=\"6\"/></PointData></Piece></ImageData>\n<AppendedData encoding=\"raw\">\n  _"
        .to_vec();
    // Another array first (count 2: 2 bytes), then ours: count 4, values 7 and −2.
    file.extend_from_slice(&[2, 0, 0, 0, 9, 9, 4, 0, 0, 0, 7, 0, 0xfe, 0xff]);
    file.extend_from_slice(b"\n</AppendedData></VTKFile>");
    let vti = parse_xml(&file).unwrap();
    assert!(matches!(vti.data, Stored::Appended { offset: 6, .. }));
    assert_eq!(read_samples(&vti, 4).unwrap(), [7.0, -2.0]);
}

#[test]
fn base64_of_a_header_and_its_data_encoded_apart_or_together() {
    let header = 4u32.to_le_bytes();
    let data = [1u8, 2, 3, 4];
    let apart = format!("{}{}", BASE64.encode(header), BASE64.encode(data));
    let together = BASE64.encode([header, data].concat());
    assert!(apart.contains("==") && apart != together);
    for text in [apart, together] {
        let mut blob = Blob::Base64(Base64::new(text.as_bytes()));
        let bytes = read_blob(&mut blob, Layout::default(), 4).unwrap();
        assert_eq!(&*bytes, &data, "{text}");
    }
}

#[test]
fn zlib_blocks_are_inflated_no_further_than_needed() {
    use std::io::Write;
    let zlib = |b: &[u8]| {
        let mut e = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::fast());
        e.write_all(b).unwrap();
        e.finish().unwrap()
    };
    let data: Vec<u8> = (0..10).collect();
    let (a, b) = (zlib(&data[..6]), zlib(&data[6..]));
    let layout = Layout {
        header64: true,
        zlib: true,
        ..Layout::default()
    };
    let mut bytes = Vec::new();
    for w in [2u64, 6, 4, a.len() as u64, b.len() as u64] {
        bytes.extend_from_slice(&w.to_le_bytes());
    }
    bytes.extend_from_slice(&a);
    bytes.extend_from_slice(&b);
    let mut blob = Blob::Raw(&bytes);
    let got = read_blob(&mut blob, layout, 10).unwrap();
    assert_eq!(&*got, &data);
    // A block count past the file, and a cut block, are errors.
    let mut huge = bytes.clone();
    huge[..8].copy_from_slice(&u64::MAX.to_le_bytes());
    let e = read_blob(&mut Blob::Raw(&huge), layout, 10).unwrap_err();
    assert!(e.contains("more than the file holds"), "{e}");
    let cut = &bytes[..bytes.len() - 3];
    let e = read_blob(&mut Blob::Raw(cut), layout, 10).unwrap_err();
    assert!(e.contains("truncated"), "{e}");
}
