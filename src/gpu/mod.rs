//! The GPU below the renderers: the headless context (adapter selection, any backend,
//! overridable by environment; one device), the adapter's limits and features, and the
//! crate-internal helpers every pass builds on: `gpu_buffer` (the one resizable GPU buffer type
//! and the storage-binding limit check), `dispatch` (the one compute dispatch splitter),
//! `pipeline`, `texture`, `pass_params` (uniforms and constants) and `storage_fence`. Nothing
//! here imports [`crate::render`].

pub(crate) mod dispatch;
pub(crate) mod gpu_buffer;
pub(crate) mod pass_params;
pub(crate) mod pipeline;
pub(crate) mod storage_fence;
pub(crate) mod texture;

use crate::error::{Error, Result};
use crate::param::Param;

/// How to choose the adapter. Both fields default to the environment:
/// `WGPU_BACKEND` (e.g. `vulkan`, `gl`) and `WGPU_ADAPTER_NAME` (case-insensitive substring).
#[derive(Clone, Debug, Default)]
pub struct GpuOptions {
    /// Backends to search; `None` = `WGPU_BACKEND` or all.
    pub backends: Option<wgpu::Backends>,
    /// Adapter name substring; `None` = `WGPU_ADAPTER_NAME` or the first adapter.
    pub adapter_name: Option<String>,
}

/// Optional features the renderers use when the adapter has them; never required up front.
/// Renderers that need one check [`require_features`] and fail with a typed error.
const OPTIONAL_FEATURES: wgpu::Features = wgpu::Features::TIMESTAMP_QUERY
    .union(wgpu::Features::TIMESTAMP_QUERY_INSIDE_ENCODERS)
    .union(wgpu::Features::DUAL_SOURCE_BLENDING)
    .union(wgpu::Features::SHADER_INT64)
    .union(wgpu::Features::SHADER_INT64_ATOMIC_MIN_MAX)
    .union(wgpu::Features::SHADER_INT64_ATOMIC_ALL_OPS)
    .union(wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES)
    .union(wgpu::Features::FLOAT32_FILTERABLE)
    .union(wgpu::Features::MULTIVIEW)
    .union(wgpu::Features::CLIP_DISTANCES);

/// An adapter, its device and queue. Owns them; renderers borrow the device.
///
/// Keep one per adapter per process: on GL, a second device from the same adapter silently
/// breaks the first (docs/DESIGN.md §7).
pub struct GpuContext {
    /// The chosen adapter.
    pub adapter: wgpu::Adapter,
    /// The device created on it.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
}

impl GpuOptions {
    /// The backends to search: the option, else `WGPU_BACKEND`, else all.
    pub fn backends(&self) -> wgpu::Backends {
        self.backends
            .unwrap_or_else(|| wgpu::Backends::all().with_env())
    }
}

impl GpuContext {
    /// Pick an adapter per `options` (and the environment) and create a device with all of its
    /// limits and the optional features it offers.
    pub fn new(options: &GpuOptions) -> Result<Self> {
        pollster::block_on(Self::new_async(options))
    }

    async fn new_async(options: &GpuOptions) -> Result<Self> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = options.backends();
        let instance = wgpu::Instance::new(desc);
        Self::from_instance(&instance, None, options).await
    }

    /// Like [`GpuContext::new`], on `instance` and among the adapters that can present to
    /// `surface` (a window's, made by `instance`): what a viewer needs. The instance should
    /// carry the window system's display handle (`InstanceDescriptor::display`: GL needs it to
    /// present).
    pub fn for_surface(
        instance: &wgpu::Instance,
        surface: &wgpu::Surface<'_>,
        options: &GpuOptions,
    ) -> Result<Self> {
        pollster::block_on(Self::from_instance(instance, Some(surface), options))
    }

    async fn from_instance(
        instance: &wgpu::Instance,
        surface: Option<&wgpu::Surface<'_>>,
        options: &GpuOptions,
    ) -> Result<Self> {
        let backends = options.backends();
        let name = options
            .adapter_name
            .clone()
            .or_else(|| std::env::var("WGPU_ADAPTER_NAME").ok())
            .filter(|n| !n.is_empty());
        let mut adapters = instance.enumerate_adapters(backends).await;
        adapters.retain(|a| surface.is_none_or(|s| a.is_surface_supported(s)));
        // Prefer real GPUs, then integrated, then CPU (lavapipe/llvmpipe): stable across runs.
        adapters.sort_by_key(|a| device_rank(a.get_info().device_type));
        let adapter = adapters
            .into_iter()
            .find(|a| match &name {
                Some(n) => a.get_info().name.to_lowercase().contains(&n.to_lowercase()),
                None => true,
            })
            .ok_or_else(|| Error::NoAdapter {
                backends: backend_names(backends),
                name: name
                    .as_ref()
                    .map(|n| format!(", name contains '{n}'"))
                    .unwrap_or_default()
                    + if surface.is_some() {
                        ", that can present to the window"
                    } else {
                        ""
                    },
                available: available_adapters(),
            })?;
        let info = adapter.get_info();
        log::info!(
            "adapter: {} ({:?}, {:?}, driver {} {})",
            info.name,
            info.backend,
            info.device_type,
            info.driver,
            info.driver_info
        );
        let features = adapter.features() & OPTIONAL_FEATURES;
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("autostereo device"),
                required_features: features,
                required_limits: adapter.limits(),
                ..Default::default()
            })
            .await
            .map_err(|source| Error::RequestDevice {
                adapter: info.name.clone(),
                source,
            })?;
        Ok(Self {
            adapter,
            device,
            queue,
            info,
        })
    }

    /// Adapter name and backend, e.g. `llvmpipe (LLVM 15.0.6, 256 bits) (Vulkan)`.
    pub fn adapter_label(&self) -> String {
        format!("{} ({:?})", self.info.name, self.info.backend)
    }

    /// The adapter's info.
    pub fn info(&self) -> &wgpu::AdapterInfo {
        &self.info
    }

    /// Check a 2D render size against the device limits.
    pub fn check_size_2d(&self, width: u32, height: u32) -> Result<()> {
        check_size_2d(&self.device, width, height)
    }
}

/// Fail with [`Error::MissingFeature`] unless `device` has every feature in `needed`. The
/// error names the adapter, says what is missing in words and what to use `instead`.
pub fn require_features(
    device: &wgpu::Device,
    needed: wgpu::Features,
    purpose: &str,
    instead: crate::advice::Advice,
) -> Result<()> {
    let missing = needed - device.features();
    if missing.is_empty() {
        return Ok(());
    }
    let info = device.adapter_info();
    Err(Error::MissingFeature {
        adapter: format!("{} ({:?})", info.name, info.backend),
        missing: describe_features(missing),
        purpose: purpose.to_string(),
        instead,
    })
}

/// `features` in words, each with wgpu's name, e.g. "64-bit integers (SHADER_INT64)".
pub fn describe_features(features: wgpu::Features) -> String {
    const WORDS: &[(wgpu::Features, &str)] = &[
        (wgpu::Features::SHADER_INT64, "64-bit integers in shaders"),
        (
            wgpu::Features::SHADER_INT64_ATOMIC_MIN_MAX,
            "64-bit atomic min/max",
        ),
        (
            wgpu::Features::SHADER_INT64_ATOMIC_ALL_OPS,
            "all 64-bit atomic operations",
        ),
        (
            wgpu::Features::DUAL_SOURCE_BLENDING,
            "dual-source blending (a blend factor per colour channel)",
        ),
        (wgpu::Features::TIMESTAMP_QUERY, "GPU timestamp queries"),
        (wgpu::Features::CLIP_DISTANCES, "clip distances"),
        (wgpu::Features::MULTIVIEW, "multiview render passes"),
        (
            wgpu::Features::FLOAT32_FILTERABLE,
            "filterable 32-bit float textures",
        ),
    ];
    let mut parts = Vec::new();
    let mut rest = features;
    for (feature, words) in WORDS {
        if features.contains(*feature) {
            parts.push(format!("{words} ({})", feature_names(*feature)));
            rest = rest - *feature;
        }
    }
    if !rest.is_empty() {
        parts.push(feature_names(rest));
    }
    parts.join(" and ")
}

/// wgpu's names of `features`, e.g. `SHADER_INT64 | SHADER_INT64_ATOMIC_MIN_MAX`.
fn feature_names(features: wgpu::Features) -> String {
    features
        .iter_names()
        .map(|(name, _)| name)
        .collect::<Vec<_>>()
        .join(" | ")
}

/// Check a 2D render size: non-zero and within `max_texture_dimension_2d`.
pub fn check_size_2d(device: &wgpu::Device, width: u32, height: u32) -> Result<()> {
    if width == 0 || height == 0 {
        return Err(Error::invalid(
            Param::Size,
            format!("{width}x{height}: width and height must be at least 1"),
        ));
    }
    let limit = device.limits().max_texture_dimension_2d;
    for (what, value) in [("image width", width), ("image height", height)] {
        if value > limit {
            return Err(Error::LimitExceeded {
                what: what.into(),
                value: value.into(),
                limit: limit.into(),
                param: Some(Param::ImageSize),
                advice: None,
            });
        }
    }
    Ok(())
}

/// `backends` as `WGPU_BACKEND` spells them (`vulkan, gl`); where none is left, what
/// `WGPU_BACKEND` said (a name wgpu does not know selects nothing).
fn backend_names(backends: wgpu::Backends) -> String {
    let names: Vec<&str> = BACKENDS
        .iter()
        .filter(|(b, _)| backends.contains(*b))
        .map(|(_, name)| *name)
        .collect();
    if !names.is_empty() {
        return names.join(", ");
    }
    match std::env::var("WGPU_BACKEND") {
        Ok(env) => format!(
            "none: WGPU_BACKEND='{}' names no backend ({})",
            env.escape_debug(),
            BACKENDS.map(|(_, n)| n).join(", ")
        ),
        Err(_) => "none".into(),
    }
}

/// The backends a user picks from, with `WGPU_BACKEND`'s names for them.
const BACKENDS: [(wgpu::Backends, &str); 4] = [
    (wgpu::Backends::VULKAN, "vulkan"),
    (wgpu::Backends::GL, "gl"),
    (wgpu::Backends::METAL, "metal"),
    (wgpu::Backends::DX12, "dx12"),
];

/// For [`Error::NoAdapter`]: every adapter on any backend (name and backend) and how to pick
/// one, or, where there is none, how to get one. Enumerated on an instance of its own, so that
/// adapters the search's backends left out are listed too.
fn available_adapters() -> String {
    let backends = BACKENDS
        .iter()
        .fold(wgpu::Backends::empty(), |all, (b, _)| all | *b);
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = backends;
    let adapters = pollster::block_on(wgpu::Instance::new(desc).enumerate_adapters(backends));
    if adapters.is_empty() {
        return "there is no adapter on any backend; on a machine without a GPU install Mesa's \
                lavapipe: apt-get install mesa-vulkan-drivers libvulkan1"
            .into();
    }
    let listed: Vec<String> = adapters
        .iter()
        .map(|a| {
            let info = a.get_info();
            let backend = BACKENDS
                .iter()
                .find(|(b, _)| *b == info.backend.into())
                .map_or_else(|| format!("{:?}", info.backend), |(_, n)| n.to_string());
            format!("'{}' ({backend})", info.name)
        })
        .collect();
    format!(
        "the adapters here: {}; pick one with WGPU_ADAPTER_NAME=<part of its name> and \
         WGPU_BACKEND=<its backend> (vulkan, gl, metal, dx12), or unset them for the first",
        listed.join(", ")
    )
}

fn device_rank(t: wgpu::DeviceType) -> u8 {
    match t {
        wgpu::DeviceType::DiscreteGpu => 0,
        wgpu::DeviceType::IntegratedGpu => 1,
        wgpu::DeviceType::VirtualGpu => 2,
        wgpu::DeviceType::Cpu => 3,
        wgpu::DeviceType::Other => 4,
    }
}

/// Run `create` inside a validation + out-of-memory error scope, so that a failure becomes
/// [`Error::Gpu`] naming `operation` instead of wgpu's default panic.
pub fn checked<T>(device: &wgpu::Device, operation: &str, create: impl FnOnce() -> T) -> Result<T> {
    let oom = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
    let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let value = create();
    let errors = [
        pollster::block_on(validation.pop()),
        pollster::block_on(oom.pop()),
    ];
    match errors.into_iter().flatten().next() {
        None => Ok(value),
        Some(e) => Err(Error::Gpu {
            operation: operation.to_string(),
            message: format!("{e:?}"),
        }),
    }
}
