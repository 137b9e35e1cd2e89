//! One uniform struct per pass of a frame (one per camera of an N-pass render), in one buffer
//! bound with a dynamic offset, so a frame uploads its constants once.
//!
//! Per-frame constants never go through `Queue::write_buffer`: a queue write lands before the
//! next submit, so two frames encoded before one submit would both see the last one. Each
//! frame's constants get a buffer of their own, created with its contents
//! ([`constants_buffer`]); the commands recorded for the frame keep it alive.

use std::marker::PhantomData;

use bytemuck::Pod;

/// Per-pass constants of type `T`, `stride` bytes apart.
pub(crate) struct PassParams<T> {
    /// This frame's constants (zeros for one pass until the first write).
    buffer: wgpu::Buffer,
    /// Bytes between consecutive passes' constants (the dynamic-offset alignment).
    pub stride: u64,
    label: &'static str,
    _t: PhantomData<T>,
}

impl<T: Pod> PassParams<T> {
    pub fn new(device: &wgpu::Device, label: &'static str) -> Self {
        let align = device.limits().min_uniform_buffer_offset_alignment as u64;
        let stride = (std::mem::size_of::<T>() as u64).div_ceil(align) * align;
        let zeros = vec![0u8; stride as usize];
        Self {
            buffer: constants_buffer(device, label, wgpu::BufferUsages::UNIFORM, &zeros),
            stride,
            label,
            _t: PhantomData,
        }
    }

    /// The group-layout entry at `binding`: a uniform `T` with a dynamic offset.
    pub fn layout_entry(binding: u32, stages: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
        wgpu::BindGroupLayoutEntry {
            binding,
            visibility: stages,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: true,
                min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<T>() as u64),
            },
            count: None,
        }
    }

    /// This frame's constants, one `T` per pass, in a buffer of their own (module docs).
    pub fn write(&mut self, device: &wgpu::Device, passes: &[T]) {
        let count = passes.len().max(1);
        let mut bytes = vec![0u8; (self.stride * count as u64) as usize];
        for (i, p) in passes.iter().enumerate() {
            let at = i * self.stride as usize;
            bytes[at..at + std::mem::size_of::<T>()].copy_from_slice(bytemuck::bytes_of(p));
        }
        let buffer = constants_buffer(device, self.label, wgpu::BufferUsages::UNIFORM, &bytes);
        self.buffer = buffer;
    }

    /// The binding resource for a bind-group entry (one `T`, offset chosen per pass).
    pub fn binding(&self) -> wgpu::BindingResource<'_> {
        wgpu::BindingResource::Buffer(wgpu::BufferBinding {
            buffer: &self.buffer,
            offset: 0,
            size: wgpu::BufferSize::new(std::mem::size_of::<T>() as u64),
        })
    }

    /// Dynamic offset of pass `i`.
    pub fn offset(&self, i: usize) -> u32 {
        (i as u64 * self.stride) as u32
    }
}

/// A buffer of `usage` holding `bytes` from its creation: how every per-frame constant reaches
/// the GPU (module docs).
pub(crate) fn constants_buffer(
    device: &wgpu::Device,
    label: &str,
    usage: wgpu::BufferUsages,
    bytes: &[u8],
) -> wgpu::Buffer {
    use wgpu::util::DeviceExt;
    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(label),
        contents: bytes,
        usage,
    })
}
