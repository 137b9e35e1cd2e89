//! The examples each subcommand's `--help` ends with: real command lines (the unit test below
//! parses every one), for the data and displays people have.

pub const MESH: &str = "Examples:
  autostereo mesh bunny.obj --display lkg --out bunny.png
      the attached Looking Glass's calibration, its panel size and view count
  autostereo mesh scene.glb --display lenticular:8 --size 1920x1080 --out scene.png
  autostereo mesh bunny.obj --output anaglyph --out bunny_anaglyph.png
      red-cyan glasses instead of a panel (--eyes L,R picks the views)
  autostereo mesh bunny.obj --display lkg:calibration.json --output quilt --out bunny.png
      a Looking Glass quilt (bunny_qs7x7a1.7778.png)
  autostereo mesh bunny.obj --method n-pass --frames 10 --json
      time ten frames of another method, write nothing";

pub const POINTS: &str = "Examples:
  autostereo points dragon.ply --out dragon.png
  autostereo points scan.laz --display slanted:45,7.5,1/6,0.2 --size 1920x1080 --out scan.png
  autostereo points dragon.ply --compare --json
      the single pass against the N-pass: PSNR and the share of subpixels off";

pub const VOLUME: &str = "Examples:
  autostereo volume --out head.png
      the built-in CT head
  autostereo volume series/ --tf ct-bone --out ct.png
      a DICOM folder (also .nrrd, .nii.gz, .mha/.mhd, .vti, .vtk), the patient upright,
      face to the viewer
  autostereo volume series/ --window 400,40 --out soft.png
      a radiologist's window in HU (--window alone: the file's own)
  autostereo volume brain.nii.gz --display lkg --output views --out views/brain.png
      every view as views/brain_00.png, views/brain_01.png, …
  autostereo volume --path slices --alpha paper --out head_slices.png
      the paper's proxy slices with its averaged alpha";

pub const GAUSSIANS: &str = "Examples:
  autostereo gaussians point_cloud.ply --display lkg --out garden.png
      a graphdeco 3DGS capture (also .splat, .spz)
  autostereo gaussians scene.splat --look-from 0,0,-4 --look-at 0,0,0 --up 0,-1,0 --out s.png
      captures with y down need --up 0,-1,0
  autostereo gaussians --method tiled --compare --json
      the generated scene as a quilt (Looking Glass's way), against the N-pass";

pub const RGBD: &str = "Examples:
  autostereo rgbd photo.jpg depth.png --display lkg --out photo_spatial.png
  autostereo rgbd photo_rgbd.png --sbs --display lkg:calibration.json --output quilt --out photo.png
  autostereo rgbd photo.jpg depth.png --display lenticular:8 --output views --out views/photo.png
  autostereo rgbd photo.jpg depth.png --hole-mask holes.png --json";

pub const INTERLEAVE: &str = "Examples:
  autostereo interleave scene_qs5x9a0.75.png --display lkg --out scene_spatial.png
      a quilt from Looking Glass software onto the attached Looking Glass
  autostereo interleave views.png --quilt 4x2 --display hubner8 --out spatial.png";

pub const VIEW: &str = "Examples:
  autostereo view bunny.obj --display lkg --fullscreen
      full screen on the Looking Glass (the monitor of its calibration's size)
  autostereo view --list-monitors
      the monitors: number, name, size, position
  autostereo view --kind volume --preview side-by-side
      the built-in head on an ordinary screen
  autostereo view scan.laz --position -1920,0 --size 1920x1080
      a window on a monitor left of the primary";

pub const VIEWS: &str = "Examples:
  autostereo views spatial.png --display hubner8 --view 3 --out view3.png
  autostereo views spatial.png --display hubner8 --eyes 3,4 --out anaglyph.png";

pub const MASK: &str = "Examples:
  autostereo mask --display lkg:calibration.json --size 3840x2160 --out mask.png
  autostereo mask --display slanted:45,7.5,1/6,0.2 --size 256x256 --gpu --out mask.png";

#[cfg(test)]
mod tests {
    use clap::Parser;

    /// Every example parses (nothing runs): a renamed or retired flag fails here first.
    #[test]
    fn every_example_parses() {
        let all = [
            super::MESH,
            super::POINTS,
            super::VOLUME,
            super::GAUSSIANS,
            super::RGBD,
            super::INTERLEAVE,
            super::VIEW,
            super::VIEWS,
            super::MASK,
        ];
        let mut count = 0;
        for text in all {
            for line in text
                .lines()
                .filter(|l| l.trim_start().starts_with("autostereo "))
            {
                let words: Vec<&str> = line.split_whitespace().collect();
                if let Err(e) = crate::Cli::try_parse_from(&words) {
                    panic!("{line}\n{e}");
                }
                count += 1;
            }
        }
        assert!(count >= 25, "{count} examples");
    }
}
