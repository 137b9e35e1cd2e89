//! Writes a synthetic RGB-D pair — a chequered far wall, a shaded sphere and a thin near pole —
//! as `DIR/scene.png` (colour) and `DIR/scene_depth.png` (16-bit nearness, white = near), the
//! input of docs/tools/warping_pictures.sh. Usage: cargo run --example rgbd_scene -- DIR

use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(std::env::args().nth(1).ok_or("usage: rgbd_scene DIR")?);
    let (w, h) = (256u32, 192u32);
    let mut color = image::RgbImage::new(w, h);
    let mut depth = image::ImageBuffer::<image::Luma<u16>, Vec<u16>>::new(w, h);
    let (cx, cy, r) = (150.0f32, 100.0f32, 56.0f32);
    for y in 0..h {
        for x in 0..w {
            let (xf, yf) = (x as f32, y as f32);
            // The wall: a chequerboard, nearness 0.05 (top) … 0.25 (bottom).
            let check = ((x / 16) + (y / 16)) % 2 == 0;
            let mut rgb = if check {
                [210, 210, 190]
            } else {
                [60, 90, 140]
            };
            let mut near = 0.05 + 0.2 * yf / h as f32;
            // The sphere: nearness 0.55 at its rim … 0.9 at its centre, shaded from the left.
            let (dx, dy) = ((xf - cx) / r, (yf - cy) / r);
            let d2 = dx * dx + dy * dy;
            if d2 < 1.0 {
                let z = (1.0 - d2).sqrt();
                let light = (0.3 + 0.7 * (-0.5 * dx - 0.4 * dy + 0.77 * z).max(0.0)).min(1.0);
                rgb = [
                    (235.0 * light) as u8,
                    (120.0 * light) as u8,
                    (40.0 * light) as u8,
                ];
                near = 0.55 + 0.35 * z;
            }
            // A thin near pole: its disocclusions are filled by stretching the wall.
            if (60..64).contains(&x) && y > 20 {
                rgb = [40, 200, 80];
                near = 0.95;
            }
            color.put_pixel(x, y, image::Rgb(rgb));
            depth.put_pixel(x, y, image::Luma([(near * 65535.0).round() as u16]));
        }
    }
    color.save(dir.join("scene.png"))?;
    depth.save(dir.join("scene_depth.png"))?;
    println!("wrote {0}/scene.png and {0}/scene_depth.png", dir.display());
    Ok(())
}
