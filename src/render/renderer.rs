//! The interface every renderer shares: one frame of a scene into a spatial target. A renderer
//! per primitive (meshes: `Renderer<MeshBuffers>`, volumes: `Renderer<VolumeScene>`) and per
//! method (single pass, N-pass, single view), all behind one camera + display + output.

use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::param::Param;
use crate::target::SpatialTarget;

/// Renders scenes of type `S` (single pass, N-pass, single view…).
///
/// Prepare, then record: [`Renderer::prepare`] does everything that compiles, sizes or
/// uploads (pipelines for the frame's display, scratch for its size, tables derived from the
/// scene); [`Renderer::encode`] records into the caller's encoder and never waits. Encode
/// writes nothing through the queue: the frame's constants (camera, mask, per-pass uniforms, a
/// few hundred bytes) go into small buffers of the frame's own, created with their contents,
/// so several frames, even with different cameras, can be encoded before one submit.
///
/// Renderers are `Send` (their GPU objects are on native backends): a binding may render on
/// another thread than the one that built it (the Python module releases the GIL).
pub trait Renderer<S: ?Sized>: Send {
    /// Get ready for frames like `frame` of `scene`: call it once, and again when the display,
    /// the size or the scene changes. Cheap when nothing changed.
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &S,
        frame: &Frame,
    ) -> Result<()>;

    /// Record one frame into the caller's `encoder`. Fails with [`Error::NotPrepared`] when
    /// [`Renderer::prepare`] was not called for this frame's display, size and scene.
    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &S,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()>;

    /// The per-view images of the last frame as a quilt atlas, where the method renders one
    /// (the tiled methods); `None` for the others.
    fn atlas(&self) -> Option<&crate::render::atlas::Atlas> {
        None
    }

    /// One line on how an approximating renderer makes its frames, for reports (the warp: its
    /// references and what their depth means); `None` for the others.
    fn describe(&self) -> Option<String> {
        None
    }

    /// Prepare, encode one frame, submit it and wait for the GPU.
    fn render(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &S,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        self.prepare(device, queue, scene, frame)?;
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("frame"),
        });
        self.encode(device, &mut encoder, scene, frame, target)?;
        queue.submit([encoder.finish()]);
        crate::readback::wait_idle(device)
    }

    /// One frame into a target of its own, read back: for tools and tests that want the
    /// image (a live viewer renders into its own target and never reads back).
    fn render_image(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &S,
        frame: &Frame,
    ) -> Result<crate::image_io::RgbImage> {
        let target = SpatialTarget::new(device, frame.size)?;
        self.render(device, queue, scene, frame, &target)?;
        target.read(device, queue)
    }
}

/// The start of every `prepare`: forget what was prepared (so that a failure half-way leaves
/// nothing `encode` would take as ready), then check the frame and its size against the
/// device limits before anything is allocated for it.
pub(crate) fn begin_prepare<K>(
    device: &wgpu::Device,
    frame: &Frame,
    prepared: &mut Option<K>,
) -> Result<()> {
    *prepared = None;
    frame.validate()?;
    crate::gpu::check_size_2d(device, frame.size[0], frame.size[1])
}

/// `Err(NotPrepared)` unless `prepared` (what [`Renderer::prepare`] last got ready) equals
/// `wanted` (what this frame needs).
pub(crate) fn check_prepared<K: PartialEq + std::fmt::Debug>(
    renderer: &'static str,
    prepared: &Option<K>,
    wanted: &K,
) -> Result<()> {
    if prepared.as_ref() == Some(wanted) {
        return Ok(());
    }
    Err(Error::NotPrepared {
        renderer,
        frame: format!("{wanted:?}"),
        prepared: prepared
            .as_ref()
            .map_or_else(|| "nothing".to_string(), |p| format!("{p:?}")),
    })
}

/// Everything a renderer's `prepare` made for one frame, with the key of what it was made for.
pub(crate) trait PreparedState {
    /// What a frame needs (size, views, display specialisation…).
    type Key: PartialEq + std::fmt::Debug;
    /// What this state was made for.
    fn key(&self) -> &Self::Key;
}

/// What `prepare` made for one frame (`made`: an atlas, a depth array…) with that frame's key.
pub(crate) struct Prepared<K, R> {
    pub key: K,
    pub made: R,
}

impl<K: PartialEq + std::fmt::Debug, R> PreparedState for Prepared<K, R> {
    type Key = K;

    fn key(&self) -> &K {
        &self.key
    }
}

/// The state [`Renderer::prepare`] made, if it was made for `wanted`; else `Err(NotPrepared)`.
/// `encode` reads what `prepare` allocated from here, never through an `expect`.
pub(crate) fn prepared_state<'a, P: PreparedState>(
    renderer: &'static str,
    prepared: &'a Option<P>,
    wanted: &P::Key,
) -> Result<&'a P> {
    match prepared {
        Some(state) if state.key() == wanted => Ok(state),
        _ => Err(Error::NotPrepared {
            renderer,
            frame: format!("{wanted:?}"),
            prepared: prepared
                .as_ref()
                .map_or_else(|| "nothing".to_string(), |p| format!("{:?}", p.key())),
        }),
    }
}

/// What `prepare` made and a renderer keeps in an `Option`, read back by `encode` (or a
/// helper of it): missing is `Err(NotPrepared)` naming `what`, never a panic.
pub(crate) trait Made<T> {
    fn made(&self, what: &'static str) -> Result<&T>;
}

impl<T> Made<T> for Option<T> {
    fn made(&self, what: &'static str) -> Result<&T> {
        self.as_ref().ok_or_else(|| Error::NotPrepared {
            renderer: what,
            frame: "this frame".to_string(),
            prepared: "nothing".to_string(),
        })
    }
}

/// The start of every `encode`: a valid frame, and a target of its size.
pub(crate) fn check_target(frame: &Frame, target: &SpatialTarget) -> Result<()> {
    frame.validate()?;
    if target.size() != frame.size {
        return Err(Error::invalid(
            Param::Target,
            format!(
                "size {:?} differs from the frame's {:?}",
                target.size(),
                frame.size
            ),
        ));
    }
    Ok(())
}
