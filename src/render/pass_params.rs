//! One uniform struct per pass of a frame (one per camera of an N-pass render), in one buffer
//! bound with a dynamic offset, so a frame uploads its constants once.

use std::marker::PhantomData;

use bytemuck::Pod;

/// Per-pass constants of type `T`, `stride` bytes apart.
pub(crate) struct PassParams<T> {
    buffer: Option<(wgpu::Buffer, usize)>,
    /// Bytes between consecutive passes' constants (the dynamic-offset alignment).
    pub stride: u64,
    label: &'static str,
    _t: PhantomData<T>,
}

impl<T: Pod> PassParams<T> {
    pub fn new(device: &wgpu::Device, label: &'static str) -> Self {
        let align = device.limits().min_uniform_buffer_offset_alignment as u64;
        Self {
            buffer: None,
            stride: (std::mem::size_of::<T>() as u64).div_ceil(align) * align,
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

    /// Upload one `T` per pass (the buffer grows as needed).
    pub fn write(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, passes: &[T]) {
        let count = passes.len().max(1);
        if self.buffer.as_ref().is_none_or(|(_, c)| *c < count) {
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(self.label),
                size: self.stride * count as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            self.buffer = Some((buffer, count));
        }
        let mut bytes = vec![0u8; (self.stride * count as u64) as usize];
        for (i, p) in passes.iter().enumerate() {
            let at = i * self.stride as usize;
            bytes[at..at + std::mem::size_of::<T>()].copy_from_slice(bytemuck::bytes_of(p));
        }
        queue.write_buffer(self.buffer(), 0, &bytes);
    }

    fn buffer(&self) -> &wgpu::Buffer {
        &self.buffer.as_ref().expect("written before use").0
    }

    /// The binding resource for a bind-group entry (one `T`, offset chosen per pass).
    pub fn binding(&self) -> wgpu::BindingResource<'_> {
        wgpu::BindingResource::Buffer(wgpu::BufferBinding {
            buffer: self.buffer(),
            offset: 0,
            size: wgpu::BufferSize::new(std::mem::size_of::<T>() as u64),
        })
    }

    /// Dynamic offset of pass `i`.
    pub fn offset(&self, i: usize) -> u32 {
        (i as u64 * self.stride) as u32
    }
}
