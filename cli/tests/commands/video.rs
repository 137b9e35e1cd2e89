//! Videos: a turntable as MP4 (H.264) and GIF, a quilt video interleaved frame by frame, and
//! the video flags refused where they mean nothing. The MP4's container is checked by a box
//! walk of its own (not the muxer that wrote it); its frames are decoded by openh264, the
//! GIF's by the image crate.

use std::path::{Path, PathBuf};

use autostereo::image_io::{compare, RgbImage};
use autostereo::video::VideoReader;

use crate::common::{cli, cli_refused, out};

/// The boxes of an ISO-BMFF byte range: (type, body).
fn boxes(bytes: &[u8]) -> Vec<([u8; 4], &[u8])> {
    let mut found = Vec::new();
    let mut rest = bytes;
    while rest.len() >= 8 {
        let size = u32::from_be_bytes(rest[..4].try_into().unwrap()) as usize;
        let kind: [u8; 4] = rest[4..8].try_into().unwrap();
        assert!(
            size >= 8 && size <= rest.len(),
            "a box of {size} bytes in {}",
            rest.len()
        );
        found.push((kind, &rest[8..size]));
        rest = &rest[size..];
    }
    found
}

fn child<'a>(body: &'a [u8], kind: &[u8; 4]) -> &'a [u8] {
    boxes(body)
        .into_iter()
        .find(|(k, _)| k == kind)
        .unwrap_or_else(|| panic!("no {} box", String::from_utf8_lossy(kind)))
        .1
}

/// An MP4's video track: its sample count (`stsz`) and the `avc1` entry's width and height.
fn mp4_track(path: &Path) -> (u32, [u32; 2]) {
    let bytes = std::fs::read(path).unwrap();
    let top = boxes(&bytes);
    assert_eq!(&top[0].0, b"ftyp", "an MP4 starts with its file type");
    let moov = child(&bytes, b"moov");
    let stbl = child(
        child(child(child(moov, b"trak"), b"mdia"), b"minf"),
        b"stbl",
    );
    let stsz = child(stbl, b"stsz");
    let samples = u32::from_be_bytes(stsz[8..12].try_into().unwrap());
    // stsd: version/flags, entry count, then the avc1 sample entry (6 reserved bytes, a data
    // reference index, 16 bytes of predefined/reserved, then width and height).
    let stsd = child(stbl, b"stsd");
    let entry = &stsd[8..];
    assert_eq!(&entry[4..8], b"avc1", "an H.264 sample entry");
    let body = &entry[8..];
    let w = u16::from_be_bytes(body[24..26].try_into().unwrap());
    let h = u16::from_be_bytes(body[26..28].try_into().unwrap());
    (samples, [u32::from(w), u32::from(h)])
}

fn decoded(path: &Path) -> Vec<RgbImage> {
    let mut video = VideoReader::open(path).unwrap();
    let mut frames = Vec::new();
    while let Some(frame) = video.next_frame().unwrap() {
        frames.push(frame);
    }
    assert_eq!(frames.len() as u32, video.frames(), "{path:?}");
    frames
}

fn numbered(stem: &str, k: u32) -> PathBuf {
    out(&format!("{stem}_{k:04}.png"))
}

fn run(args: &[&str]) {
    let (ok, err) = cli(args);
    assert!(ok, "{args:?}: {err}");
}

/// A 12-frame turntable as MP4 and GIF: 12 frames of the render's size, each the turntable's
/// PNG frame up to the codec's loss (PSNR stated).
#[test]
fn a_turntable_video_holds_every_frame_at_the_renders_size() {
    let base = [
        "volume",
        "--builtin-size",
        "32",
        "--size",
        "96x64",
        "--turntable",
        "12",
    ];
    let with = |out: &Path| {
        let mut args = base.to_vec();
        args.extend(["--out", out.to_str().unwrap()]);
        run(&args);
    };
    with(&out("video_frames.png"));
    let (mp4, gif) = (out("video_spin.mp4"), out("video_spin.gif"));
    with(&mp4);
    with(&gif);
    assert_eq!(mp4_track(&mp4), (12, [96, 64]));
    for (path, floor) in [(&mp4, 30.0), (&gif, 25.0)] {
        let frames = decoded(path);
        assert_eq!(frames.len(), 12, "{path:?}");
        for (k, frame) in frames.iter().enumerate() {
            assert_eq!([frame.width, frame.height], [96, 64]);
            let png = RgbImage::load_png(&numbered("video_frames", k as u32)).unwrap();
            let diff = compare(frame, &png).unwrap();
            if k == 0 {
                println!("{path:?} frame 0 vs its PNG: PSNR {:.2} dB", diff.psnr_db);
            }
            assert!(
                diff.psnr_db > floor,
                "{path:?} frame {k}: {:.2} dB",
                diff.psnr_db
            );
        }
    }
}

/// A quilt video interleaved frame by frame equals `interleave` of each of its frames.
#[test]
fn a_quilt_video_interleaves_frame_by_frame() {
    run(&[
        "volume",
        "--builtin-size",
        "32",
        "--size",
        "48x32",
        "--turntable",
        "12",
        "--output",
        "quilt",
        "--out",
        out("video_quilt.mp4").to_str().unwrap(),
    ]);
    let quilt = out("video_quilt_qs2x4a1.5.mp4");
    assert_eq!(mp4_track(&quilt), (12, [96, 128]));
    run(&[
        "interleave",
        quilt.to_str().unwrap(),
        "--display",
        "hubner8",
        "--out",
        out("video_spatial.png").to_str().unwrap(),
    ]);
    for (k, frame) in decoded(&quilt).iter().enumerate() {
        let one = out(&format!("video_quilt_{k:02}_qs2x4a1.5.png"));
        frame.save_png(&one).unwrap();
        let alone = out(&format!("video_alone_{k:02}.png"));
        run(&[
            "interleave",
            one.to_str().unwrap(),
            "--display",
            "hubner8",
            "--out",
            alone.to_str().unwrap(),
        ]);
        let a = RgbImage::load_png(&alone).unwrap();
        let b = RgbImage::load_png(&numbered("video_spatial", k as u32)).unwrap();
        assert_eq!(a.data, b.data, "frame {k}");
    }
    // And to a spatial video: the same frames, encoded.
    let spatial = out("video_spatial.mp4");
    run(&[
        "interleave",
        quilt.to_str().unwrap(),
        "--display",
        "hubner8",
        "--out",
        spatial.to_str().unwrap(),
    ]);
    assert_eq!(mp4_track(&spatial), (12, [48, 32]));
}

#[test]
fn video_flags_are_refused_where_they_mean_nothing() {
    let mp4 = out("video_refused.mp4");
    let m = mp4.to_str().unwrap();
    fn volume<'a>(more: &[&'a str]) -> Vec<&'a str> {
        let mut args = vec!["volume", "--builtin-size", "16", "--size", "48x32"];
        args.extend_from_slice(more);
        args
    }
    cli_refused(
        &volume(&["--out", m]),
        &["a video is a turntable's frames", "--turntable"],
    );
    cli_refused(
        &volume(&["--turntable", "2", "--output", "views", "--out", m]),
        &["--output views writes a file per view"],
    );
    let png = out("video_refused.png");
    cli_refused(
        &volume(&[
            "--turntable",
            "2",
            "--fps",
            "12",
            "--out",
            png.to_str().unwrap(),
        ]),
        &["--fps encodes a video"],
    );
    let gif = out("video_refused.gif");
    cli_refused(
        &volume(&[
            "--turntable",
            "2",
            "--bitrate",
            "800",
            "--out",
            gif.to_str().unwrap(),
        ]),
        &["--bitrate sets an MP4's"],
    );
    cli_refused(
        &volume(&["--turntable", "2", "--fps", "0", "--out", m]),
        &["--fps", "frames per second"],
    );
    let mut odd = volume(&["--turntable", "2", "--out", m]);
    odd[4] = "47x32";
    cli_refused(&odd, &["47x32", "even width and height"]);
    let mut huge = volume(&["--turntable", "2", "--out", m]);
    huge[4] = "4000x2000";
    cli_refused(&huge, &["openh264 encodes at most 3840x2160"]);
    cli_refused(
        &["volume", "--turntable", "2", "--out", "x.avi"],
        &["PNG, MP4 or GIF"],
    );
    assert!(!mp4.exists(), "nothing written");
}
