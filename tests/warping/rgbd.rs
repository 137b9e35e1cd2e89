//! RGB-D → spatial image by warping (src/rgbd/): a picture at the focus depth is the picture
//! on every display; a constant depth off the focus shifts every view by the predicted
//! disparity; disocclusions are filled from the background and smooth surfaces stay closed;
//! the spatial image is each view's image through the CPU mask.

use crate::common;

use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::render::Renderer;
use autostereo::rgbd::{RgbdImage, RgbdScene};
use autostereo::target::SpatialTarget;
use autostereo::warp::predicted_shift;
use autostereo::warp::{RgbdWarp, WarpOptions, WarpPath};

const DISPLAYS: &[&str] = &[
    "lenticular:1",
    "slanted:2,2.5,1/3,0.1",
    "hubner8",
    "lenticular:8",
    "slanted:45,7.5,1/6,0.2",
];

/// A colour pattern with every channel varying.
fn pattern(w: u32, h: u32) -> RgbImage {
    let mut image = RgbImage::new(w, h);
    for y in 0..h {
        for x in 0..w {
            image.set(x, y, 0, (x * 7 + y * 3) as u8);
            image.set(x, y, 1, (x * 2 + y * 11) as u8);
            image.set(x, y, 2, (x ^ y) as u8);
        }
    }
    image
}

/// The spatial image of `image` for `spec` (or view `view` everywhere).
fn warp(image: &RgbdImage, spec: &str, options: WarpOptions) -> RgbImage {
    let ctx = common::gpu();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let frame = Frame::for_display(Display::parse(spec).unwrap(), image.size()).unwrap();
    let scene = RgbdScene::new(device, queue, image).unwrap();
    let mut warp = RgbdWarp::new(device, options).unwrap();
    let target = SpatialTarget::new(device, image.size()).unwrap();
    warp.render(device, queue, &scene, &frame, &target).unwrap();
    target.read(device, queue).unwrap()
}

#[test]
fn a_picture_at_the_focus_depth_is_the_picture_on_every_display() {
    let color = pattern(64, 48);
    for focus in [0.5, 0.2] {
        let image = RgbdImage::flat(color.clone(), focus).unwrap();
        for spec in DISPLAYS {
            let options = WarpOptions {
                focus,
                depthiness: 3.0,
                ..WarpOptions::default()
            };
            assert_eq!(warp(&image, spec, options), color, "{spec}, focus {focus}");
        }
    }
}

/// Warping every view into its own image first (Beck's way), then compositing, gives the
/// direct warp's image exactly: the same sample per subpixel.
#[test]
fn the_per_view_path_equals_the_direct_path() {
    let (w, h) = (64, 48);
    let color = pattern(w, h);
    let nearness = (0..w * h)
        .map(|i| ((i % w) as f32 / w as f32 * 3.0).fract())
        .collect();
    let image = RgbdImage::new(color, nearness).unwrap();
    for spec in DISPLAYS {
        let options = WarpOptions {
            depthiness: 2.0,
            ..WarpOptions::default()
        };
        let direct = warp(&image, spec, options);
        let per_view = warp(
            &image,
            spec,
            WarpOptions {
                path: WarpPath::PerView,
                ..options
            },
        );
        assert_eq!(direct, per_view, "{spec}");
    }
}

#[test]
fn a_constant_depth_off_the_focus_shifts_each_view_by_the_predicted_disparity() {
    // Black left of column 128, white from it: linear interpolation keeps the white area, so
    // a view's shift s reads off any row as (white columns of the reference) − Σ value / 255,
    // to within the rounding of the one edge pixel (the borders extend black and white).
    let (w, h) = (256, 8);
    let mut color = RgbImage::new(w, h);
    for y in 0..h {
        for x in 128..w {
            for c in 0..3 {
                color.set(x, y, c, 255);
            }
        }
    }
    let nearness = 0.8;
    let image = RgbdImage::flat(color, nearness).unwrap();
    let options = WarpOptions::default();
    let spec = "hubner8";
    let display = Display::parse(spec).unwrap();
    let views = display.views();
    let mut view_images = Vec::new();
    for v in 0..views {
        let one = warp(
            &image,
            spec,
            WarpOptions {
                view: Some(v),
                ..options
            },
        );
        let predicted = predicted_shift(&options, w, nearness, v, views);
        assert!(
            predicted.abs() > 0.5 || v == 3 || v == 4,
            "shifts too small to see"
        );
        eprintln!(
            "view {v}: {:?}",
            (100..110).map(|x| one.get(x, 0, 0)).collect::<Vec<_>>()
        );
        for y in 0..h {
            for c in 0..3 {
                let white: f64 = (0..w).map(|x| one.get(x, y, c) as f64 / 255.0).sum();
                let measured = (w - 128) as f64 - white;
                assert!(
                    (measured - predicted as f64).abs() < 0.01,
                    "view {v}, row {y}, channel {c}: measured shift {measured:.4} px, \
                     predicted {predicted:.4}"
                );
            }
        }
        view_images.push(one);
    }
    // The spatial image is each subpixel's view through the CPU mask.
    let spatial = warp(&image, spec, options);
    let mask = display.mask();
    for y in 0..h {
        for x in 0..w {
            for c in 0..3 {
                let v = mask.view(x, y, c) as usize;
                assert_eq!(
                    spatial.get(x, y, c),
                    view_images[v].get(x, y, c),
                    "({x},{y},{c})"
                );
            }
        }
    }
}

const BACKGROUND: [u8; 3] = [0, 40, 200];
const FRONT: [u8; 3] = [230, 20, 10];

fn pixel(image: &RgbImage, x: u32, y: u32) -> [u8; 3] {
    [image.get(x, y, 0), image.get(x, y, 1), image.get(x, y, 2)]
}

#[test]
fn disocclusions_fill_from_the_background() {
    // A near square (nearness 1) over a far background at the focus (0): in the last view the
    // square moves left by 3 % · depthiness · width; what it uncovers must be background.
    let (w, h) = (128, 32);
    let (x0, x1) = (48, 80); // the square's columns
    let mut color = RgbImage::new(w, h);
    let mut nearness = vec![0.0; (w * h) as usize];
    for y in 0..h {
        for x in 0..w {
            let front = (x0..x1).contains(&x) && (8..24).contains(&y);
            let rgb = if front { FRONT } else { BACKGROUND };
            for c in 0..3 {
                color.set(x, y, c, rgb[c as usize]);
            }
            if front {
                nearness[(y * w + x) as usize] = 1.0;
            }
        }
    }
    let image = RgbdImage::new(color, nearness).unwrap();
    let options = WarpOptions {
        focus: 0.0,
        depthiness: 2.0,
        view: Some(7),
        ..WarpOptions::default()
    };
    let shift = predicted_shift(&options, w, 1.0, 7, 8);
    assert!(shift < -7.0, "{shift}");
    let out = warp(&image, "hubner8", options);
    let (lo, hi) = (x0 as f32 + shift, (x1 - 1) as f32 + shift);
    for y in 0..h {
        for x in 0..w {
            let xf = x as f32;
            let front = (8..24).contains(&y) && xf >= lo && xf <= hi;
            let want = if front { FRONT } else { BACKGROUND };
            assert_eq!(
                pixel(&out, x, y),
                want,
                "({x},{y}); square now at {lo:.2}…{hi:.2}"
            );
        }
    }
    // The hole mask marks exactly what the square uncovered: right of its new place up to
    // its old right edge.
    let mask = warp(
        &image,
        "hubner8",
        WarpOptions {
            hole_mask: true,
            ..options
        },
    );
    for y in 0..h {
        for x in 0..w {
            let uncovered = (8..24).contains(&y) && x as f32 > hi && x < x1;
            let want = if uncovered { 255 } else { 0 };
            assert_eq!(pixel(&mask, x, y), [want; 3], "hole mask at ({x},{y})");
        }
    }
}

#[test]
fn smooth_surfaces_stay_closed_in_every_view() {
    // A hemisphere of nearness 0.5 … 1 on a far background: in every view each row crosses it
    // in one unbroken run of its colour, no background crack inside.
    let (w, h) = (96, 64);
    let (cx, cy, r) = (48.0f32, 32.0f32, 24.0f32);
    let mut color = RgbImage::new(w, h);
    let mut nearness = vec![0.0; (w * h) as usize];
    for y in 0..h {
        for x in 0..w {
            let d2 = ((x as f32 - cx).powi(2) + (y as f32 - cy).powi(2)) / (r * r);
            let inside = d2 < 1.0;
            let rgb = if inside { FRONT } else { BACKGROUND };
            for c in 0..3 {
                color.set(x, y, c, rgb[c as usize]);
            }
            if inside {
                nearness[(y * w + x) as usize] = 0.5 + 0.5 * (1.0 - d2).sqrt();
            }
        }
    }
    let image = RgbdImage::new(color, nearness).unwrap();
    for v in 0..8 {
        let options = WarpOptions {
            focus: 0.3,
            depthiness: 2.0,
            view: Some(v),
            ..WarpOptions::default()
        };
        let out = warp(&image, "hubner8", options);
        for y in 0..h {
            let front: Vec<u32> = (0..w).filter(|&x| pixel(&out, x, y) == FRONT).collect();
            let source = (0..w)
                .filter(|&x| pixel(&image.color, x, y) == FRONT)
                .count();
            if let (Some(&first), Some(&last)) = (front.first(), front.last()) {
                assert_eq!(
                    (last - first + 1) as usize,
                    front.len(),
                    "view {v}, row {y}: a crack in the surface"
                );
            }
            assert!(
                front.len() + 2 >= source,
                "view {v}, row {y}: {} of {source} pixels of the surface left",
                front.len()
            );
        }
    }
}

#[test]
fn the_callers_textures_are_checked() {
    let ctx = common::gpu();
    let device = &ctx.device;
    let texture = |format| {
        device.create_texture(&wgpu::TextureDescriptor {
            label: None,
            size: wgpu::Extent3d {
                width: 16,
                height: 8,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        })
    };
    let color = texture(wgpu::TextureFormat::Rgba8Unorm);
    let depth = texture(wgpu::TextureFormat::R32Float);
    assert!(RgbdScene::from_textures(&color, &depth).is_ok());
    let wrong = texture(wgpu::TextureFormat::R16Float);
    let err = RgbdScene::from_textures(&color, &wrong).err().unwrap();
    assert!(
        err.to_string().contains("nearness") && err.to_string().contains("R32Float"),
        "{err}"
    );
    let options = WarpOptions {
        focus: 1.5,
        ..WarpOptions::default()
    };
    let image = RgbdImage::flat(RgbImage::new(16, 8), 0.5).unwrap();
    let frame = Frame::for_display(Display::parse("hubner8").unwrap(), [16, 8]).unwrap();
    let scene = RgbdScene::new(device, &ctx.queue, &image).unwrap();
    // Refused when the warp is built, and when options set later reach prepare.
    let err = RgbdWarp::new(device, options).err().unwrap();
    assert!(err.to_string().contains("focus"), "{err}");
    let mut warp = RgbdWarp::new(device, WarpOptions::default()).unwrap();
    warp.set_options(options);
    let err = warp
        .prepare(device, &ctx.queue, &scene, &frame)
        .unwrap_err();
    assert!(err.to_string().contains("focus"), "{err}");
}

/// Encode checks what prepare got ready against everything the frame can change: a frame with
/// a new size, view count or display, encoded without a new prepare, is `NotPrepared` (the
/// per-view path would otherwise draw into stale per-view layers of the old frame).
#[test]
fn a_frame_that_changed_since_prepare_is_not_prepared() {
    let ctx = common::gpu();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let image = RgbdImage::flat(pattern(64, 48), 0.3).unwrap();
    let scene = RgbdScene::new(device, queue, &image).unwrap();
    let options = WarpOptions {
        path: WarpPath::PerView,
        ..WarpOptions::default()
    };
    let mut warp = RgbdWarp::new(device, options).unwrap();
    let prepared = Frame::for_display(Display::parse("hubner8").unwrap(), [64, 48]).unwrap();
    warp.prepare(device, queue, &scene, &prepared).unwrap();
    let changed = [
        (
            "size",
            Frame::for_display(Display::parse("hubner8").unwrap(), [32, 24]),
        ),
        (
            "views",
            Frame::for_display(Display::parse("lenticular:5").unwrap(), [64, 48]),
        ),
        (
            "display",
            Frame::for_display(Display::parse("slanted:8,7.5,1/6,0.2").unwrap(), [64, 48]),
        ),
    ];
    for (what, frame) in changed {
        let frame = frame.unwrap();
        let target = SpatialTarget::new(device, frame.size).unwrap();
        let mut encoder = device.create_command_encoder(&Default::default());
        let error = warp
            .encode(device, &mut encoder, &scene, &frame, &target)
            .expect_err(what);
        assert!(
            matches!(error, autostereo::Error::NotPrepared { .. }),
            "{what}: {error}"
        );
    }
    // The frame it was prepared for still encodes.
    let target = SpatialTarget::new(device, prepared.size).unwrap();
    let mut encoder = device.create_command_encoder(&Default::default());
    warp.encode(device, &mut encoder, &scene, &prepared, &target)
        .unwrap();
}
