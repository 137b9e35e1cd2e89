//! MP4 with H.264: openh264 encodes (Constrained Baseline, I420) and decodes, the `mp4` crate
//! writes and reads the container (avc1 samples: NAL units with 4-byte lengths, SPS and PPS in
//! the track's `avcC`).

use std::fs::File;
use std::io::{BufReader, BufWriter};
use std::path::Path;

use openh264::decoder::{DecodedYUV, Decoder};
use openh264::encoder::{
    BitRate, Encoder, EncoderConfig, FrameRate, FrameType, IntraFramePeriod, RateControlMode,
};
use openh264::formats::{RgbSliceU8, YUVBuffer, YUVSource};
use openh264::OpenH264API;

use super::{io_error, video_error, VideoSettings};
use crate::error::Result;
use crate::image_io::RgbImage;

/// The largest frame openh264 encodes: 3840×2160, or 2160×3840 upright.
pub const MAX_SIDES: [u32; 2] = [3840, 2160];

/// The track's time units per second: every common frame rate is a whole number of them.
const TIMESCALE: u32 = 90_000;

pub(super) struct Mp4Out {
    encoder: Encoder,
    muxer: ::mp4::Mp4Writer<BufWriter<File>>,
    size: [u32; 2],
    tick: u32,
    frame: u64,
    track: bool,
}

impl Mp4Out {
    pub(super) fn create(path: &Path, size: [u32; 2], settings: &VideoSettings) -> Result<Self> {
        let config = EncoderConfig::new()
            .bitrate(BitRate::from_bps(settings.bits_per_second(size)))
            .max_frame_rate(FrameRate::from_hz(settings.fps))
            .rate_control_mode(RateControlMode::Bitrate)
            // openh264 holds the bit rate only where it may skip frames; a skipped frame is
            // encoded again as a key frame (`push`), so every frame is in the video. A key
            // frame a second so that players can seek.
            .skip_frames(true)
            .intra_frame_period(IntraFramePeriod::from_num_frames(settings.fps.ceil() as u32));
        let encoder = Encoder::with_api_config(OpenH264API::from_source(), config)
            .map_err(|e| video_error(path, format!("the H.264 encoder did not start: {e}")))?;
        let file = File::create(path).map_err(|e| io_error(path, e))?;
        let brands = ["isom", "iso2", "avc1", "mp41"];
        let config = ::mp4::Mp4Config {
            major_brand: "isom".parse().expect("a four-letter code"),
            minor_version: 512,
            compatible_brands: brands
                .iter()
                .map(|b| b.parse().expect("a four-letter code"))
                .collect(),
            timescale: 1000,
        };
        let muxer = ::mp4::Mp4Writer::write_start(BufWriter::new(file), &config)
            .map_err(|e| video_error(path, e.to_string()))?;
        Ok(Self {
            encoder,
            muxer,
            size,
            tick: (TIMESCALE as f32 / settings.fps).round().max(1.0) as u32,
            frame: 0,
            track: false,
        })
    }

    pub(super) fn push(&mut self, frame: &RgbImage, path: &Path) -> Result<()> {
        let dims = (self.size[0] as usize, self.size[1] as usize);
        let yuv = YUVBuffer::from_rgb8_source(RgbSliceU8::new(&frame.data, dims));
        let frame_no = self.frame;
        let fail = |e: openh264::Error| video_error(path, format!("frame {frame_no}: {e}"));
        let mut out = Nals::of(&self.encoder.encode(&yuv).map_err(fail)?);
        if out.skipped {
            self.encoder.force_intra_frame();
            out = Nals::of(&self.encoder.encode(&yuv).map_err(fail)?);
            if out.skipped {
                return Err(video_error(
                    path,
                    format!(
                        "frame {frame_no}: the encoder skips it at this bit rate; raise --bitrate"
                    ),
                ));
            }
        }
        let Nals {
            key,
            sps,
            pps,
            sample,
            ..
        } = out;
        if !self.track {
            let (Some(seq_param_set), Some(pic_param_set)) = (sps, pps) else {
                return Err(video_error(
                    path,
                    "the encoder's first frame has no SPS and PPS",
                ));
            };
            let avc = ::mp4::AvcConfig {
                width: self.size[0] as u16,
                height: self.size[1] as u16,
                seq_param_set,
                pic_param_set,
            };
            let track = ::mp4::TrackConfig {
                track_type: ::mp4::TrackType::Video,
                timescale: TIMESCALE,
                language: "und".into(),
                media_conf: ::mp4::MediaConfig::AvcConfig(avc),
            };
            self.muxer
                .add_track(&track)
                .map_err(|e| video_error(path, e.to_string()))?;
            self.track = true;
        }
        let sample = ::mp4::Mp4Sample {
            start_time: self.frame * u64::from(self.tick),
            duration: self.tick,
            rendering_offset: 0,
            is_sync: key,
            bytes: bytes::Bytes::from(sample),
        };
        self.muxer
            .write_sample(1, &sample)
            .map_err(|e| video_error(path, format!("frame {}: {e}", self.frame)))?;
        self.frame += 1;
        Ok(())
    }

    pub(super) fn finish(mut self, path: &Path) -> Result<()> {
        if !self.track {
            return Err(video_error(path, "no frames: a video needs one at least"));
        }
        self.muxer
            .write_end()
            .map_err(|e| video_error(path, e.to_string()))?;
        use std::io::Write;
        self.muxer
            .into_writer()
            .flush()
            .map_err(|e| io_error(path, e))
    }
}

/// One encoded frame: its parameter sets and its other NAL units as an avc1 sample.
struct Nals {
    skipped: bool,
    key: bool,
    sps: Option<Vec<u8>>,
    pps: Option<Vec<u8>>,
    sample: Vec<u8>,
}

impl Nals {
    fn of(encoded: &openh264::encoder::EncodedBitStream<'_>) -> Self {
        let (mut sps, mut pps, mut sample) = (None, None, Vec::new());
        for l in 0..encoded.num_layers() {
            let layer = encoded.layer(l).expect("a layer below the count");
            for n in 0..layer.nal_count() {
                let nal = strip_start_code(layer.nal_unit(n).expect("a NAL below the count"));
                match nal.first().map(|b| b & 0x1f) {
                    Some(7) => sps = Some(nal.to_vec()),
                    Some(8) => pps = Some(nal.to_vec()),
                    Some(_) => {
                        sample.extend_from_slice(&(nal.len() as u32).to_be_bytes());
                        sample.extend_from_slice(nal);
                    }
                    None => {}
                }
            }
        }
        let frame_type = encoded.frame_type();
        Self {
            skipped: matches!(frame_type, FrameType::Skip) || sample.is_empty(),
            key: matches!(frame_type, FrameType::IDR | FrameType::I),
            sps,
            pps,
            sample,
        }
    }
}

/// Refuses a frame size H.264 (4:2:0) or openh264 cannot encode, saying what can.
pub fn check_encodable(path: &Path, size: [u32; 2]) -> Result<()> {
    let [w, h] = size;
    if w % 2 == 1 || h % 2 == 1 {
        return Err(video_error(
            path,
            format!("{w}x{h}: H.264 (4:2:0) frames need an even width and height"),
        ));
    }
    let (long, short) = (w.max(h), w.min(h));
    if long > MAX_SIDES[0] || short > MAX_SIDES[1] {
        return Err(video_error(
            path,
            format!(
                "{w}x{h}: openh264 encodes at most {}x{} (or {}x{} upright); write a smaller \
                 frame, or PNG frames (--out F.png) and encode those with ffmpeg",
                MAX_SIDES[0], MAX_SIDES[1], MAX_SIDES[1], MAX_SIDES[0]
            ),
        ));
    }
    Ok(())
}

/// A NAL unit without its Annex B start code (`00 00 01` or `00 00 00 01`).
fn strip_start_code(nal: &[u8]) -> &[u8] {
    let zeros = nal.iter().take_while(|&&b| b == 0).count();
    match nal.get(zeros) {
        Some(1) if zeros >= 2 => &nal[zeros + 1..],
        _ => nal,
    }
}

pub(super) struct Mp4In {
    reader: ::mp4::Mp4Reader<BufReader<File>>,
    decoder: Decoder,
    track: u32,
    next: u32,
    /// SPS and PPS in Annex B, sent before the first sample.
    headers: Option<Vec<u8>>,
    pub(super) size: [u32; 2],
    pub(super) frames: u32,
    pub(super) fps: f32,
}

impl Mp4In {
    pub(super) fn open(path: &Path) -> Result<Self> {
        let file = File::open(path).map_err(|e| io_error(path, e))?;
        let bytes = file.metadata().map_err(|e| io_error(path, e))?.len();
        let reader = ::mp4::Mp4Reader::read_header(BufReader::new(file), bytes)
            .map_err(|e| video_error(path, format!("not a readable MP4: {e}")))?;
        let (track, info) = reader
            .tracks()
            .iter()
            .find(|(_, t)| matches!(t.media_type(), Ok(::mp4::MediaType::H264)))
            .ok_or_else(|| video_error(path, "no H.264 video track (only H.264 is read)"))?;
        let size = [u32::from(info.width()), u32::from(info.height())];
        RgbImage::check_size(size[0], size[1])?;
        let mut headers = Vec::new();
        for set in [info.sequence_parameter_set(), info.picture_parameter_set()] {
            let set = set.map_err(|e| video_error(path, format!("no avcC: {e}")))?;
            headers.extend_from_slice(&[0, 0, 0, 1]);
            headers.extend_from_slice(set);
        }
        let frames = info.sample_count();
        let seconds = info.duration().as_secs_f64();
        let fps = if seconds > 0.0 {
            (f64::from(frames) / seconds) as f32
        } else {
            0.0
        };
        let track = *track;
        let decoder = Decoder::new()
            .map_err(|e| video_error(path, format!("the H.264 decoder did not start: {e}")))?;
        Ok(Self {
            reader,
            decoder,
            track,
            next: 1,
            headers: Some(headers),
            size,
            frames,
            fps,
        })
    }

    pub(super) fn next_frame(&mut self, path: &Path) -> Result<Option<RgbImage>> {
        while self.next <= self.frames {
            let id = self.next;
            self.next += 1;
            let sample = self
                .reader
                .read_sample(self.track, id)
                .map_err(|e| video_error(path, format!("frame {}: {e}", id - 1)))?;
            let Some(sample) = sample else { continue };
            let mut annex_b = self.headers.take().unwrap_or_default();
            let mut rest: &[u8] = &sample.bytes;
            while rest.len() >= 4 {
                let len = u32::from_be_bytes([rest[0], rest[1], rest[2], rest[3]]) as usize;
                let Some(nal) = rest.get(4..4 + len) else {
                    return Err(video_error(
                        path,
                        format!("frame {}: a NAL unit past the sample's end", id - 1),
                    ));
                };
                annex_b.extend_from_slice(&[0, 0, 0, 1]);
                annex_b.extend_from_slice(nal);
                rest = &rest[4 + len..];
            }
            let decoded = self
                .decoder
                .decode(&annex_b)
                .map_err(|e| video_error(path, format!("frame {}: {e}", id - 1)))?;
            if let Some(yuv) = decoded {
                return Ok(Some(to_rgb(&yuv, self.size, path)?));
            }
        }
        Ok(None)
    }
}

fn to_rgb(yuv: &DecodedYUV<'_>, size: [u32; 2], path: &Path) -> Result<RgbImage> {
    let (w, h) = yuv.dimensions();
    if [w as u32, h as u32] != size {
        return Err(video_error(
            path,
            format!("a frame of {w}x{h} in a video of {}x{}", size[0], size[1]),
        ));
    }
    let mut image = RgbImage::new(size[0], size[1]);
    // openh264's own YUV → RGB, the inverse of its encoder's (BT.601, limited range).
    yuv.write_rgb8(&mut image.data);
    Ok(image)
}
