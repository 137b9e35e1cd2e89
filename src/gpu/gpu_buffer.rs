//! GPU buffers the renderers size for a scene and a frame: one type, one growth policy, one
//! limit check.
//!
//! Growth policy: a buffer is reallocated when a frame needs more than it holds or less than a
//! quarter of it (so memory follows the scene down too); bindings cover exactly the bytes in
//! use, so `arrayLength` in a shader is the count the frame asked for.

use crate::error::{Error, Result};

/// The storage-binding limit: the most bytes one storage buffer binding may hold here.
pub fn storage_binding_limit(device: &wgpu::Device) -> u64 {
    let limits = device.limits();
    limits
        .max_storage_buffer_binding_size
        .min(limits.max_buffer_size)
}

/// `Err(LimitExceeded)` naming `what` when `bytes` do not fit one storage binding: checked
/// before anything is allocated.
pub fn check_storage_bytes(
    device: &wgpu::Device,
    what: impl Into<String>,
    bytes: u64,
) -> Result<()> {
    let limit = storage_binding_limit(device);
    if bytes > limit {
        return Err(Error::LimitExceeded {
            what: what.into(),
            value: bytes,
            limit,
            param: None,
            advice: None,
        });
    }
    Ok(())
}

/// Smallest allocation and binding: wgpu rejects empty bindings.
const MIN_BYTES: u64 = 16;

/// A buffer of fixed usage whose size follows what each frame needs.
pub(crate) struct GpuBuffer {
    label: &'static str,
    usage: wgpu::BufferUsages,
    /// At least [`MIN_BYTES`] from the start, so every binding has a buffer.
    buffer: wgpu::Buffer,
    used: u64,
    /// The buffer's share of the memory budget.
    charge: Option<crate::budget::GpuCharge>,
}

impl GpuBuffer {
    pub fn new(device: &wgpu::Device, label: &'static str, usage: wgpu::BufferUsages) -> Self {
        Self {
            label,
            usage,
            buffer: Self::allocate(device, label, usage, MIN_BYTES),
            used: MIN_BYTES,
            charge: None,
        }
    }

    fn allocate(
        device: &wgpu::Device,
        label: &'static str,
        usage: wgpu::BufferUsages,
        bytes: u64,
    ) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: bytes,
            usage,
            mapped_at_creation: false,
        })
    }

    /// Room for `bytes` (`what` names them in the error when they exceed the storage-binding
    /// limit), allocated per the module's growth policy.
    pub fn ensure(
        &mut self,
        device: &wgpu::Device,
        what: impl FnOnce() -> String,
        bytes: u64,
    ) -> Result<()> {
        let what = what();
        if self.usage.contains(wgpu::BufferUsages::STORAGE) {
            check_storage_bytes(device, what.clone(), bytes)?;
        }
        let bytes = bytes.max(MIN_BYTES);
        let capacity = self.buffer.size();
        if bytes > capacity || bytes < capacity / 4 {
            // Free before allocating (and charging) the replacement.
            self.buffer = Self::allocate(device, self.label, self.usage, MIN_BYTES);
            (self.used, self.charge) = (MIN_BYTES, None);
            self.charge = Some(crate::budget::charge_gpu(|| what, bytes)?);
            self.buffer = Self::allocate(device, self.label, self.usage, bytes);
        }
        self.used = bytes;
        Ok(())
    }

    /// The buffer (of [`MIN_BYTES`] until the first [`GpuBuffer::ensure`]).
    pub fn buffer(&self) -> &wgpu::Buffer {
        &self.buffer
    }

    /// Bytes in use (what the last [`GpuBuffer::ensure`] asked for, at least 16).
    pub fn used(&self) -> u64 {
        self.used
    }

    /// A binding of exactly the bytes in use.
    pub fn binding(&self) -> wgpu::BindingResource<'_> {
        wgpu::BindingResource::Buffer(wgpu::BufferBinding {
            buffer: &self.buffer,
            offset: 0,
            size: wgpu::BufferSize::new(self.used),
        })
    }
}
