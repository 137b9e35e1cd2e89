//! The reference views a warp starts from: where their cameras sit, the images they are
//! rendered into, and the trait a primitive's renderer implements to render them.

use crate::camera::MultiViewCamera;
use crate::display::{Display, DisplayKind};
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::param::Param;
use crate::render::ViewLayers;
use crate::target::SPATIAL_FORMAT;

/// Format of the nearness layers: the bits of the f32 `fd / d` for eye depth d (1 on the focal
/// plane, larger in front of it), 0 where nothing was hit. Bits in R32Uint rather than
/// R32Float: GL can neither render to nor store into R32Float, and R32Uint does both
/// everywhere (docs/DESIGN.md §7).
pub const REFERENCE_NEARNESS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;

/// The frame of `references` reference views of `frame`: the same camera with R views spread
/// evenly over the same span, so the outermost references are the outermost views (R = 1: the
/// centre view). Its display is a plain `lenticular:R` (references are never interleaved).
pub fn reference_frame(frame: &Frame, references: u32) -> Result<Frame> {
    let views = frame.camera.views;
    if references == 0 || references > views {
        return Err(Error::invalid(
            Param::References,
            format!("{references}: between 1 and the display's {views} views"),
        ));
    }
    let separation = if references > 1 {
        frame.camera.separation * (views - 1) as f32 / (references - 1) as f32
    } else {
        0.0
    };
    let camera = MultiViewCamera {
        views: references,
        separation,
        ..frame.camera.clone()
    };
    Ok(Frame {
        camera,
        display: Display::new(DisplayKind::Lenticular { views: references })?,
        ..frame.clone()
    })
}

/// R reference views of one size: colour ([`SPATIAL_FORMAT`]) and nearness
/// ([`REFERENCE_NEARNESS_FORMAT`]) layers, layer j = reference j, each renderable, bindable and storable.
pub struct ReferenceImages {
    /// Colour layers (with the depth buffer the rasterising renderers share).
    pub color: ViewLayers,
    /// Nearness layers.
    pub nearness: ViewLayers,
}

impl ReferenceImages {
    /// Allocate `references` layers of `size` of each, after checking the limits.
    pub fn new(device: &wgpu::Device, size: [u32; 2], references: u32) -> Result<Self> {
        let usage = wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC;
        Ok(Self {
            color: ViewLayers::with_format(
                device,
                ("reference views", Param::References),
                size,
                references,
                SPATIAL_FORMAT,
                usage,
            )?,
            nearness: ViewLayers::with_format(
                device,
                ("reference nearness", Param::References),
                size,
                references,
                REFERENCE_NEARNESS_FORMAT,
                usage,
            )?,
        })
    }

    /// Number of references R.
    pub fn references(&self) -> u32 {
        self.color.layers()
    }

    /// Size of each layer.
    pub fn size(&self) -> [u32; 2] {
        self.color.size()
    }
}

/// A renderer that can render a frame's views with their nearness into [`ReferenceImages`]:
/// the first half of a warp. `frame` is a [`reference_frame`]: its camera's views are the
/// references. The colour of each reference equals that view of the renderer's N-pass.
pub trait ReferenceRenderer<S: ?Sized>: Send {
    /// Get ready (pipelines, scratch) for references like `frame` of `scene`.
    fn prepare_references(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &S,
        frame: &Frame,
    ) -> Result<()>;

    /// Record the rendering of `frame`'s views into `images` (layer j = view j).
    fn encode_references(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &S,
        frame: &Frame,
        images: &ReferenceImages,
    ) -> Result<()>;

    /// What the representative depth of a pixel is (docs, `describe`).
    fn depth_meaning(&self) -> &'static str;
}

/// The error of a primitive's reference renderer used to render frames.
pub(crate) fn not_a_frame_renderer(renderer: &str) -> Error {
    Error::invalid(
        Param::Method,
        format!(
            "warp: this {renderer} renders a warp's reference views; render warped frames \
             with warp::SceneWarp"
        ),
    )
}

/// `Ok` when a renderer built for `method` renders references (built for `Method::Warp`).
pub(crate) fn check_reference_method(renderer: &str, method: crate::render::Method) -> Result<()> {
    if method == crate::render::Method::Warp {
        return Ok(());
    }
    Err(Error::invalid(
        Param::Method,
        format!("{renderer} built for {method} renders no reference views: build it for warp"),
    ))
}
