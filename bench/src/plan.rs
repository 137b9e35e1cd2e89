//! What a bench run measures: sizes, view counts and studies, from the command line's run
//! flags.

use std::path::PathBuf;

use super::{sweep_display, BenchArgs};

/// What a run measures.
pub struct Plan {
    pub quick: bool,
    /// `--duplication`: N = 8 only, no studies.
    pub duplication: bool,
    /// `--sweep`: N = 1…64 at 256² only, no studies.
    pub sweep: bool,
    /// `--warp`: N = 8 and 45 at 512², the warp study only.
    pub warp: bool,
    /// `--view-scale`: N = 8 at 512², the view-scale study only.
    pub view_scale: bool,
    /// `--volumes`: volumes only, N = 8 and 64 at 512², the approximations' studies only.
    pub volumes: bool,
    pub size: [u32; 2],
    pub views: Vec<u32>,
    /// N-pass is measured up to this N (it grows linearly).
    pub npass_max_views: u32,
    /// Sizes measured on the paper's display only (the 1920×1080 subset).
    pub extra_sizes: Vec<[u32; 2]>,
    pub frames: u32,
    /// `--data`: the folder of fetched data sets.
    pub data: PathBuf,
}

impl Plan {
    pub(super) fn new(args: &BenchArgs) -> Self {
        const ALL_N: [u32; 7] = [1, 2, 4, 8, 16, 32, 64];
        // (size, views, N-pass up to, sizes on the paper's display only)
        let (size, views, npass_max_views, extra_sizes) = if args.duplication {
            ([512, 512], vec![8], 8, vec![[1920, 1080]])
        } else if args.sweep {
            ([256, 256], ALL_N.to_vec(), 64, vec![])
        } else if args.warp {
            ([512, 512], vec![8, 45], 45, vec![])
        } else if args.view_scale {
            ([512, 512], vec![8], 8, vec![])
        } else if args.volumes {
            ([512, 512], vec![8, 64], 64, vec![])
        } else if args.quick {
            ([256, 256], vec![2, 8, 64], 8, vec![])
        } else {
            ([512, 512], ALL_N.to_vec(), 64, vec![[1920, 1080]])
        };
        Self {
            quick: args.quick,
            duplication: args.duplication,
            sweep: args.sweep,
            warp: args.warp,
            view_scale: args.view_scale,
            volumes: args.volumes,
            size,
            views,
            npass_max_views,
            extra_sizes,
            frames: args.frames,
            data: args.data.clone(),
        }
    }

    /// `quick`, `duplication`, `sweep` or `full`.
    pub fn name(&self) -> &'static str {
        run_name(
            self.quick,
            self.duplication,
            self.sweep,
            self.warp,
            self.view_scale,
            self.volumes,
        )
    }

    /// Whether the speed/accuracy and economy studies run.
    pub fn studies(&self) -> bool {
        !self.duplication && !self.sweep && !self.warp && !self.view_scale && !self.volumes
    }

    /// Frames per trade-off and economy measurement (each setting is a separate render).
    pub fn study_frames(&self) -> u32 {
        if self.quick {
            3
        } else {
            5
        }
    }

    /// (display spec, size) of every configuration; N-pass runs on the N sweep.
    pub(super) fn configs(&self) -> Vec<(String, [u32; 2])> {
        let mut c: Vec<(String, [u32; 2])> = self
            .views
            .iter()
            .map(|&n| (sweep_display(n), self.size))
            .collect();
        if self.studies() {
            c.push(("lenticular:8".into(), self.size));
        }
        for size in &self.extra_sizes {
            c.push(("hubner8".into(), *size));
        }
        c
    }
}

pub(super) fn run_name(
    quick: bool,
    duplication: bool,
    sweep: bool,
    warp: bool,
    view_scale: bool,
    volumes: bool,
) -> &'static str {
    match (quick, duplication, sweep, warp, view_scale, volumes) {
        (true, ..) => "quick",
        (_, true, ..) => "duplication",
        (_, _, true, ..) => "sweep",
        (_, _, _, true, ..) => "warp",
        (_, _, _, _, true, _) => "view-scale",
        (.., true) => "volumes",
        _ => "full",
    }
}
