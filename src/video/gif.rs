//! Animated GIF through the image crate: frames quantised to 256 colours each (NeuQuant),
//! looping forever, as turntables are shared.

use std::cell::RefCell;
use std::fs::File;
use std::io::{BufReader, BufWriter, Write};
use std::path::Path;
use std::rc::Rc;

use image::codecs::gif::{GifDecoder, GifEncoder, Repeat};
use image::{AnimationDecoder, Delay, Frame, Frames, RgbaImage};

use super::{io_error, video_error, VideoSettings};
use crate::error::Result;
use crate::image_io::RgbImage;

pub(super) struct GifOut {
    encoder: GifEncoder<BufWriter<Recorded>>,
    /// The first write error, kept where the encoder's drop (which writes the trailer and
    /// flushes) would lose it.
    failed: Rc<RefCell<Option<std::io::Error>>>,
    delay: Delay,
    frames: u32,
}

impl GifOut {
    pub(super) fn create(path: &Path, _size: [u32; 2], settings: &VideoSettings) -> Result<Self> {
        let file = File::create(path).map_err(|e| io_error(path, e))?;
        let failed = Rc::new(RefCell::new(None));
        let recorded = Recorded {
            file,
            failed: failed.clone(),
        };
        // Speed 10 of 1–30: NeuQuant's default trade of palette quality for time.
        let mut encoder = GifEncoder::new_with_speed(BufWriter::new(recorded), 10);
        encoder
            .set_repeat(Repeat::Infinite)
            .map_err(|e| video_error(path, e.to_string()))?;
        // GIF counts delays in hundredths of a second: 30 fps plays at 1/0.03 s ≈ 33 fps.
        let ms = (1000.0 / settings.fps).round().max(10.0) as u32;
        Ok(Self {
            encoder,
            failed,
            delay: Delay::from_numer_denom_ms(ms, 1),
            frames: 0,
        })
    }

    pub(super) fn push(&mut self, frame: &RgbImage, path: &Path) -> Result<()> {
        let rgba: Vec<u8> = frame
            .data
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect();
        let image = RgbaImage::from_raw(frame.width, frame.height, rgba)
            .expect("4 bytes per pixel of the frame's size");
        self.encoder
            .encode_frame(Frame::from_parts(image, 0, 0, self.delay))
            .map_err(|e| video_error(path, format!("frame {}: {e}", self.frames)))?;
        self.frames += 1;
        Ok(())
    }

    pub(super) fn finish(self, path: &Path) -> Result<()> {
        if self.frames == 0 {
            return Err(video_error(path, "no frames: a video needs one at least"));
        }
        // Dropping the encoder writes the trailer and flushes the buffer into `Recorded`.
        drop(self.encoder);
        match self.failed.borrow_mut().take() {
            Some(error) => Err(io_error(path, error)),
            None => Ok(()),
        }
    }
}

/// The file, with the first error any write or flush met recorded.
struct Recorded {
    file: File,
    failed: Rc<RefCell<Option<std::io::Error>>>,
}

impl Write for Recorded {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.file.write(buf).inspect_err(|e| self.record(e))
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.file.flush().inspect_err(|e| self.record(e))
    }
}

impl Recorded {
    fn record(&self, error: &std::io::Error) {
        let mut failed = self.failed.borrow_mut();
        if failed.is_none() {
            *failed = Some(std::io::Error::new(error.kind(), error.to_string()));
        }
    }
}

pub(super) struct GifIn {
    frames_left: Frames<'static>,
    pub(super) size: [u32; 2],
    pub(super) frames: u32,
    pub(super) fps: f32,
}

impl GifIn {
    pub(super) fn open(path: &Path) -> Result<Self> {
        let decoder = |path: &Path| -> Result<GifDecoder<BufReader<File>>> {
            let file = File::open(path).map_err(|e| io_error(path, e))?;
            GifDecoder::new(BufReader::new(file))
                .map_err(|e| video_error(path, format!("not a readable GIF: {e}")))
        };
        let first = decoder(path)?;
        let (w, h) = image::ImageDecoder::dimensions(&first);
        RgbImage::check_size(w, h)?;
        // One pass to count the frames and read the first delay (GIF headers hold neither).
        let mut frames = 0u32;
        let mut fps = 0.0f32;
        for frame in first.into_frames() {
            let frame = frame.map_err(|e| video_error(path, format!("frame {frames}: {e}")))?;
            if frames == 0 {
                let (numer, denom) = frame.delay().numer_denom_ms();
                fps = if numer > 0 {
                    1000.0 * denom as f32 / numer as f32
                } else {
                    0.0
                };
            }
            frames += 1;
        }
        Ok(Self {
            frames_left: decoder(path)?.into_frames(),
            size: [w, h],
            frames,
            fps,
        })
    }

    pub(super) fn next_frame(&mut self, path: &Path) -> Result<Option<RgbImage>> {
        let Some(frame) = self.frames_left.next() else {
            return Ok(None);
        };
        let frame = frame.map_err(|e| video_error(path, e.to_string()))?;
        let buffer = frame.into_buffer();
        let mut image = RgbImage::new(buffer.width(), buffer.height());
        for (out, p) in image.data.chunks_exact_mut(3).zip(buffer.pixels()) {
            out.copy_from_slice(&p.0[..3]);
        }
        Ok(Some(image))
    }
}
