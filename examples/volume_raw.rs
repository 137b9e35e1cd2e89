//! A volume as another renderer would take it: the scalars autostereo renders (a file through
//! the same loaders, or the built-in head) written as raw little-endian f32 in 0…1, x fastest,
//! and on stdout one JSON line with its dimensions and spacing and the camera `autostereo
//! volume` frames it with (default flags, N views, `--fov` 30°). docs/tools/peer_vtk.py feeds
//! both to VTK so the peer renders the same data from the same viewpoints.
//!
//! `cargo run --release --example volume_raw -- (FILE | --builtin) OUT.raw [N] [WxH]`

use anyhow::{bail, Context, Result};
use autostereo::camera::MultiViewCamera;
use autostereo::volume::{generate, load};

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [input, out, rest @ ..] = &args[..] else {
        bail!("usage: volume_raw (FILE | --builtin) OUT.raw [N] [WxH]");
    };
    let views: u32 = rest.first().map_or(Ok(8), |n| n.parse()).context("N")?;
    let size: Vec<u32> = rest
        .get(1)
        .map_or("512x512", String::as_str)
        .split('x')
        .map(str::parse)
        .collect::<Result<_, _>>()
        .context("WxH")?;
    let volume = if input == "--builtin" {
        generate::ct_head(96)?
    } else {
        load::load_any(input.as_ref())?
    };
    let bytes: Vec<u8> = volume.data.iter().flat_map(|v| v.to_le_bytes()).collect();
    std::fs::write(out, bytes).with_context(|| format!("writing {out}"))?;
    let aspect = size[0] as f32 / size[1] as f32;
    let camera =
        MultiViewCamera::framing(volume.bounds(), views, None, 30f32.to_radians(), aspect)?;
    println!(
        "{}",
        serde_json::json!({
            "dims": volume.dims,
            "spacing": volume.spacing,
            "extent": volume.extent().to_array(),
            "views": views,
            "distance": camera.focal_distance,
            "separation": camera.separation,
            "fov_y_degrees": 30.0,
            "near": camera.near,
            "far": camera.far,
        })
    );
    Ok(())
}
