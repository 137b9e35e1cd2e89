//! Videos of frames (`video` feature): MP4 with H.264 (openh264 encodes and decodes, the `mp4`
//! crate muxes and demuxes), as Looking Glass's players read quilt videos, and GIF (the image
//! crate), as people share turntables. [`VideoWriter`] takes frames one at a time;
//! [`VideoReader`] gives them back one at a time, so a long quilt video is never all in
//! memory.

mod gif;
mod mp4;

pub use mp4::MAX_SIDES as H264_MAX_FRAME;

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::image_io::RgbImage;
use crate::param::Param;

/// The size an H.264 quilt video gets where the quilt's own does not encode: one pixel more on
/// an odd side (a remainder Looking Glass ignores), or, over openh264's largest frame, that
/// frame in the views' orientation (Looking Glass stretches the tiles to the views' aspect).
/// `None`: the quilt encodes as it is.
pub fn h264_quilt_size(size: [u32; 2], shown: [u32; 2]) -> Option<[u32; 2]> {
    let [long, short] = H264_MAX_FRAME;
    let even = size.map(|v| v.saturating_add(v % 2));
    let fits = even[0].max(even[1]) <= long && even[0].min(even[1]) <= short;
    match fits {
        true => (even != size).then_some(even),
        false if shown[0] >= shown[1] => Some([long, short]),
        false => Some([short, long]),
    }
}

/// A video container this build writes and reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VideoFormat {
    /// MP4, H.264 (Constrained Baseline, 4:2:0): what Looking Glass Studio, Blocks and the Go's
    /// playlists play, and every browser.
    Mp4,
    /// Animated GIF (256 colours a frame).
    Gif,
}

impl VideoFormat {
    /// The format a file name's extension says (`.mp4`, `.gif`; any case), if it is a video.
    pub fn of_path(path: &Path) -> Option<Self> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "mp4" | "m4v" => Some(Self::Mp4),
            "gif" => Some(Self::Gif),
            _ => None,
        }
    }

    /// Refuses frames of `size` this format cannot hold in `path` (H.264: even sides within
    /// [`H264_MAX_FRAME`]; GIF: 65535 a side), saying what can.
    pub fn check_size(self, path: &Path, size: [u32; 2]) -> Result<()> {
        RgbImage::check_size(size[0], size[1])?;
        match self {
            Self::Mp4 => mp4::check_encodable(path, size),
            Self::Gif if size[0].max(size[1]) > u32::from(u16::MAX) => Err(video_error(
                path,
                format!(
                    "{}x{}: GIF frames are at most 65535 pixels a side",
                    size[0], size[1]
                ),
            )),
            Self::Gif => Ok(()),
        }
    }

    /// The format's name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Mp4 => "MP4 (H.264)",
            Self::Gif => "GIF",
        }
    }
}

/// How a video is encoded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VideoSettings {
    /// Frames per second.
    pub fps: f32,
    /// MP4: the target bit rate in kbit/s; `None`: about 0.15 bit per pixel and frame (8 Mbit/s
    /// for 1920×1080 at 30 fps), which keeps a quilt's fine detail.
    pub bitrate_kbps: Option<u32>,
}

impl Default for VideoSettings {
    fn default() -> Self {
        Self {
            fps: 30.0,
            bitrate_kbps: None,
        }
    }
}

impl VideoSettings {
    /// Refuses a frame rate or bit rate no video can have.
    pub fn validate(&self) -> Result<()> {
        if !(self.fps.is_finite() && self.fps > 0.0 && self.fps <= 240.0) {
            return Err(Error::invalid(
                Param::FrameRate,
                format!("{}: frames per second must be in (0, 240]", self.fps),
            ));
        }
        if self.bitrate_kbps == Some(0) {
            return Err(Error::invalid(
                Param::BitRate,
                "0 kbit/s: give a positive bit rate",
            ));
        }
        Ok(())
    }

    /// The bit rate in bit/s for frames of `size`.
    fn bits_per_second(&self, size: [u32; 2]) -> u32 {
        match self.bitrate_kbps {
            Some(kbps) => kbps.saturating_mul(1000),
            None => {
                let pixels = f64::from(size[0]) * f64::from(size[1]);
                (pixels * f64::from(self.fps) * 0.15).clamp(2e5, 2e9) as u32
            }
        }
    }
}

/// A video being written, a frame at a time; [`VideoWriter::finish`] completes the file.
pub struct VideoWriter {
    path: PathBuf,
    size: [u32; 2],
    frames: u32,
    inner: Inner,
}

enum Inner {
    Mp4(Box<mp4::Mp4Out>),
    Gif(gif::GifOut),
}

impl VideoWriter {
    /// A video of frames of `size` at `path`, its format from the extension.
    pub fn create(path: &Path, size: [u32; 2], settings: &VideoSettings) -> Result<Self> {
        settings.validate()?;
        RgbImage::check_size(size[0], size[1])?;
        let format = VideoFormat::of_path(path).ok_or_else(|| not_a_video(path))?;
        format.check_size(path, size)?;
        let inner = match format {
            VideoFormat::Mp4 => Inner::Mp4(Box::new(mp4::Mp4Out::create(path, size, settings)?)),
            VideoFormat::Gif => Inner::Gif(gif::GifOut::create(path, size, settings)?),
        };
        Ok(Self {
            path: path.to_path_buf(),
            size,
            frames: 0,
            inner,
        })
    }

    /// Append one frame (of the video's size).
    pub fn push(&mut self, frame: &RgbImage) -> Result<()> {
        if [frame.width, frame.height] != self.size {
            return Err(video_error(
                &self.path,
                format!(
                    "frame {} is {}x{}, the video {}x{}",
                    self.frames, frame.width, frame.height, self.size[0], self.size[1]
                ),
            ));
        }
        match &mut self.inner {
            Inner::Mp4(out) => out.push(frame, &self.path)?,
            Inner::Gif(out) => out.push(frame, &self.path)?,
        }
        self.frames += 1;
        Ok(())
    }

    /// Complete the file; returns the frames written.
    pub fn finish(self) -> Result<u32> {
        match self.inner {
            Inner::Mp4(out) => out.finish(&self.path)?,
            Inner::Gif(out) => out.finish(&self.path)?,
        }
        Ok(self.frames)
    }
}

/// A video being read, a frame at a time.
pub struct VideoReader {
    path: PathBuf,
    size: [u32; 2],
    frames: u32,
    fps: f32,
    inner: Source,
}

enum Source {
    Mp4(Box<mp4::Mp4In>),
    Gif(gif::GifIn),
}

impl VideoReader {
    /// The video at `path`, its format from the extension.
    pub fn open(path: &Path) -> Result<Self> {
        let (inner, size, frames, fps) = match VideoFormat::of_path(path) {
            Some(VideoFormat::Mp4) => {
                let input = mp4::Mp4In::open(path)?;
                let (size, frames, fps) = (input.size, input.frames, input.fps);
                (Source::Mp4(Box::new(input)), size, frames, fps)
            }
            Some(VideoFormat::Gif) => {
                let input = gif::GifIn::open(path)?;
                let (size, frames, fps) = (input.size, input.frames, input.fps);
                (Source::Gif(input), size, frames, fps)
            }
            None => return Err(not_a_video(path)),
        };
        Ok(Self {
            path: path.to_path_buf(),
            size,
            frames,
            fps,
            inner,
        })
    }

    /// The frames' size in pixels.
    pub fn size(&self) -> [u32; 2] {
        self.size
    }

    /// The frames the file holds.
    pub fn frames(&self) -> u32 {
        self.frames
    }

    /// Frames per second (of the first frame's duration for GIF).
    pub fn fps(&self) -> f32 {
        self.fps
    }

    /// The next frame, `None` after the last.
    pub fn next_frame(&mut self) -> Result<Option<RgbImage>> {
        match &mut self.inner {
            Source::Mp4(input) => input.next_frame(&self.path),
            Source::Gif(input) => input.next_frame(&self.path),
        }
    }
}

fn video_error(path: &Path, reason: impl Into<String>) -> Error {
    Error::Video {
        path: path.to_path_buf(),
        reason: reason.into(),
    }
}

fn not_a_video(path: &Path) -> Error {
    video_error(
        path,
        "not a video name: .mp4 (H.264) and .gif are written and read",
    )
}

fn io_error(path: &Path, error: std::io::Error) -> Error {
    Error::Io {
        path: path.to_path_buf(),
        error,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quilt_videos_get_a_size_h264_encodes() {
        // The 16" Spatial Display's 5999² quilt: over the encoder's largest, so 3840×2160 for
        // landscape views, 2160×3840 for upright ones.
        assert_eq!(
            h264_quilt_size([5999, 5999], [3840, 2160]),
            Some([3840, 2160])
        );
        assert_eq!(
            h264_quilt_size([4092, 4092], [1440, 2560]),
            Some([2160, 3840])
        );
        // An odd side grows by the pixel Looking Glass ignores; an encodable quilt stays.
        assert_eq!(h264_quilt_size([145, 96], [48, 32]), Some([146, 96]));
        assert_eq!(h264_quilt_size([144, 96], [48, 32]), None);
        let path = Path::new("x.mp4");
        assert!(VideoFormat::Mp4.check_size(path, [3840, 2160]).is_ok());
        assert!(VideoFormat::Mp4.check_size(path, [2160, 3840]).is_ok());
        assert!(VideoFormat::Mp4.check_size(path, [3841, 2160]).is_err());
        assert!(VideoFormat::Mp4.check_size(path, [4096, 2160]).is_err());
        assert!(VideoFormat::Gif.check_size(path, [70000, 10]).is_err());
        assert_eq!(
            VideoFormat::of_path(Path::new("a/B.MP4")),
            Some(VideoFormat::Mp4)
        );
        assert_eq!(VideoFormat::of_path(Path::new("a.png")), None);
    }
}
