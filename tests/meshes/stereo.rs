//! Stereo outputs (`render::StereoCompositor`): each format puts the right eye's pixel in the
//! right place, against a CPU reference, on two eyes of distinct patterns; bad sizes are
//! refused by name.

use crate::common;

use autostereo::render::{StereoCompositor, StereoFormat};
use autostereo::target::{SpatialTarget, SPATIAL_FORMAT};

const EYE: [u32; 2] = [24, 16];

/// Eye pixel (x, y): left (8x, 10y, 50), right (250 − 8x, 60, 15y).
fn eye_pixel(left: bool, x: u32, y: u32) -> [u8; 3] {
    if left {
        [(8 * x) as u8, (10 * y) as u8, 50]
    } else {
        [(250 - 8 * x) as u8, 60, (15 * y) as u8]
    }
}

fn eye_target(device: &wgpu::Device, queue: &wgpu::Queue, left: bool) -> SpatialTarget {
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("eye"),
        size: wgpu::Extent3d {
            width: EYE[0],
            height: EYE[1],
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: SPATIAL_FORMAT,
        usage: SpatialTarget::REQUIRED_USAGES
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    let mut rgba = Vec::new();
    for y in 0..EYE[1] {
        for x in 0..EYE[0] {
            rgba.extend(eye_pixel(left, x, y));
            rgba.push(255);
        }
    }
    queue.write_texture(
        texture.as_image_copy(),
        &rgba,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(EYE[0] * 4),
            rows_per_image: None,
        },
        texture.size(),
    );
    SpatialTarget::from_texture(texture).unwrap()
}

/// The CPU reference of `format` at output pixel (x, y).
fn expected(format: StereoFormat, x: u32, y: u32) -> [f32; 3] {
    let f = |p: [u8; 3]| p.map(|v| v as f32 / 255.0);
    let pick = |left: bool, x: u32, y: u32| f(eye_pixel(left, x, y));
    let (l, r) = (
        pick(true, x % EYE[0], y % EYE[1]),
        pick(false, x % EYE[0], y % EYE[1]),
    );
    let dot = |a: [f32; 3], b: [f32; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    match format {
        StereoFormat::AnaglyphColor => [l[0], r[1], r[2]],
        StereoFormat::AnaglyphHalfColor => [dot(l, [0.299, 0.587, 0.114]), r[1], r[2]],
        StereoFormat::AnaglyphDubois => [
            dot([0.456, 0.500, 0.176], l) + dot([-0.043, -0.088, -0.002], r),
            dot([-0.040, -0.038, -0.016], l) + dot([0.378, 0.734, -0.018], r),
            dot([-0.015, -0.021, -0.005], l) + dot([-0.072, -0.113, 1.226], r),
        ]
        .map(|v| v.clamp(0.0, 1.0)),
        StereoFormat::SideBySide => pick(x < EYE[0], x % EYE[0], y),
        StereoFormat::TopBottom => pick(y < EYE[1], x, y % EYE[1]),
        StereoFormat::Rows => pick(y.is_multiple_of(2), x, y),
        StereoFormat::Columns => pick(x.is_multiple_of(2), x, y),
        StereoFormat::Checkerboard => pick((x + y).is_multiple_of(2), x, y),
    }
}

#[test]
fn every_stereo_format_puts_each_eye_where_it_belongs() {
    let ctx = common::gpu();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let left = eye_target(device, queue, true);
    let right = eye_target(device, queue, false);
    let compositor = StereoCompositor::new(device).unwrap();
    for format in StereoFormat::ALL {
        let size = format.output_size(EYE);
        let output = SpatialTarget::new(device, size).unwrap();
        let mut encoder = device.create_command_encoder(&Default::default());
        compositor
            .encode(device, &mut encoder, format, &left, &right, &output)
            .unwrap();
        queue.submit([encoder.finish()]);
        let image = output.read(device, queue).unwrap();
        for y in 0..size[1] {
            for x in 0..size[0] {
                let i = ((y * size[0] + x) * 3) as usize;
                let want = expected(format, x, y).map(|v| (v * 255.0).round() as i32);
                for (c, want) in want.iter().enumerate() {
                    let got = image.data[i + c] as i32;
                    assert!(
                        (got - want).abs() <= 1,
                        "{} at ({x}, {y}) channel {c}: {got}, expected {want}",
                        format.name()
                    );
                }
            }
        }
    }
}

#[test]
fn stereo_sizes_are_checked() {
    let ctx = common::gpu();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let left = eye_target(device, queue, true);
    let right = eye_target(device, queue, false);
    let compositor = StereoCompositor::new(device).unwrap();
    let mut encoder = device.create_command_encoder(&Default::default());
    // Side by side needs twice the width (one spare column allowed, not more).
    let narrow = SpatialTarget::new(device, EYE).unwrap();
    let error = compositor
        .encode(
            device,
            &mut encoder,
            StereoFormat::SideBySide,
            &left,
            &right,
            &narrow,
        )
        .unwrap_err();
    assert!(error.to_string().contains("side-by-side"), "{error}");
    let odd = SpatialTarget::new(device, [2 * EYE[0] + 1, EYE[1]]).unwrap();
    compositor
        .encode(
            device,
            &mut encoder,
            StereoFormat::SideBySide,
            &left,
            &right,
            &odd,
        )
        .unwrap();
    let other = SpatialTarget::new(device, [8, 8]).unwrap();
    let error = compositor
        .encode(
            device,
            &mut encoder,
            StereoFormat::Rows,
            &left,
            &other,
            &narrow,
        )
        .unwrap_err();
    assert!(error.to_string().contains("differ in size"), "{error}");
}
