//! `--out F.mp4` / `--out F.gif`: a video of a turntable's frames (render commands) or of a
//! quilt video's frames interleaved (`interleave`), and the flags that encode it.

use std::path::Path;

use anyhow::{bail, Result};
use autostereo::video::{VideoFormat, VideoSettings};

/// How a video `--out` is encoded.
#[derive(clap::Args, Clone, Debug, Default)]
#[command(next_help_heading = "Output")]
pub struct VideoArgs {
    /// With --out F.mp4 or F.gif: frames per second (default 30; a quilt video interleaved:
    /// the input's).
    #[arg(long, value_name = "FPS")]
    pub fps: Option<f32>,
    /// With --out F.mp4: the H.264 bit rate in kbit/s (default: about 0.15 bit per pixel and
    /// frame, 9.3 Mbit/s for 1920x1080 at 30 fps).
    #[arg(long, value_name = "KBPS")]
    pub bitrate: Option<u32>,
}

impl VideoArgs {
    /// The encoder's settings; `fps` where `--fps` is not given.
    pub fn settings(&self, fps: f32) -> VideoSettings {
        VideoSettings {
            fps: self.fps.unwrap_or(fps),
            bitrate_kbps: self.bitrate,
        }
    }

    /// Refuse video flags for an `out` that is not a video (and a bit rate for a GIF).
    pub fn check(&self, out: Option<&Path>) -> Result<()> {
        let format = out.and_then(VideoFormat::of_path);
        let flag = match (self.fps.is_some(), self.bitrate.is_some()) {
            (_, true) => "--bitrate",
            (true, false) => "--fps",
            (false, false) => return Ok(()),
        };
        match format {
            None => bail!("{flag} encodes a video: --out must name one (F.mp4 or F.gif)"),
            Some(VideoFormat::Gif) if self.bitrate.is_some() => {
                bail!("--bitrate sets an MP4's H.264 rate; a GIF has none (its size follows its colours)")
            }
            Some(_) => Ok(self.settings(30.0).validate()?),
        }
    }
}

/// Whether `path` names a video.
pub fn is_video(path: &Path) -> bool {
    VideoFormat::of_path(path).is_some()
}
