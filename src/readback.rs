//! GPU → CPU copies: textures (rows padded to 256 bytes for the copy, unpadded on return) and
//! buffers.

use crate::error::{Error, Result};

/// Read `layer` of a 4-bytes-per-texel 2D (array) texture into tightly packed rows.
pub fn read_texture_rgba8(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
    layer: u32,
) -> Result<Vec<u8>> {
    let (width, height) = (texture.width(), texture.height());
    let unpadded = width as u64 * 4;
    let align = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as u64;
    let padded = unpadded.div_ceil(align) * align;
    let size = padded * height as u64;
    if size > device.limits().max_buffer_size {
        return Err(Error::LimitExceeded {
            what: "read-back buffer bytes".into(),
            value: size,
            limit: device.limits().max_buffer_size,
            param: None,
            advice: None,
        });
    }
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("read-back"),
        size,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("read-back"),
    });
    encoder.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d {
                x: 0,
                y: 0,
                z: layer,
            },
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded as u32),
                rows_per_image: Some(height),
            },
        },
        wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
    );
    queue.submit([encoder.finish()]);
    let bytes = map_read(device, &buffer)?;
    let mut out = Vec::with_capacity((unpadded * height as u64) as usize);
    for row in bytes.chunks_exact(padded as usize) {
        out.extend_from_slice(&row[..unpadded as usize]);
    }
    Ok(out)
}

/// Read the first `bytes` of `source` (a `COPY_SRC` buffer) back.
pub fn read_buffer(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    source: &wgpu::Buffer,
    bytes: u64,
) -> Result<Vec<u8>> {
    let size = bytes.min(source.size()).div_ceil(4) * 4;
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("read-back"),
        size: size.max(4),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("read-back"),
    });
    encoder.copy_buffer_to_buffer(source, 0, &buffer, 0, size);
    queue.submit([encoder.finish()]);
    let mut out = map_read(device, &buffer)?;
    out.truncate(bytes as usize);
    Ok(out)
}

/// Map a submitted `MAP_READ` buffer, wait for it and copy its bytes out.
fn map_read(device: &wgpu::Device, buffer: &wgpu::Buffer) -> Result<Vec<u8>> {
    let (tx, rx) = std::sync::mpsc::channel();
    buffer.map_async(wgpu::MapMode::Read, .., move |r| {
        let _ = tx.send(r);
    });
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| gpu_error("waiting for read-back", e))?;
    rx.recv()
        .map_err(|e| gpu_error("read-back", e))?
        .map_err(|e| gpu_error("mapping read-back buffer", e))?;
    let view = buffer
        .get_mapped_range(..)
        .map_err(|e| gpu_error("read-back range", e))?;
    let out = view.to_vec();
    drop(view);
    buffer.unmap();
    Ok(out)
}

fn gpu_error(operation: &str, e: impl std::fmt::Display) -> Error {
    Error::Gpu {
        operation: operation.into(),
        message: e.to_string(),
    }
}

/// Submit nothing new; wait until the queue is idle.
pub fn wait_idle(device: &wgpu::Device) -> Result<()> {
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map(|_| ())
        .map_err(|e| gpu_error("waiting for the GPU", e))
}
