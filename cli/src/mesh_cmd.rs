//! `autostereo mesh`: render a triangle mesh for a multi-view display.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use autostereo::mesh::{CoverBounds, TileClip, ViewClusters, Visibility};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::render::Method;
use autostereo::{MeshOptions, RendererOptions};

use crate::args::{gpu, RenderArgs};
use crate::parse::OrAuto;
use crate::run::{render_and_save, report, run_summary, Rendered};

#[derive(clap::Args)]
pub struct MeshArgs {
    /// Mesh file: OBJ, PLY with faces, STL, glTF (.gltf, .glb); a generated torus scene when
    /// omitted.
    file: Option<PathBuf>,
    #[command(flatten)]
    common: RenderArgs,
    #[command(flatten)]
    warp: crate::warp_cmd::WarpArgs,
    #[command(flatten, next_help_heading = "Method")]
    mesh: MeshFlags,
}

/// How a mesh is prepared and rendered: the flags `mesh` and `view` share.
#[derive(clap::Args, Clone, Debug, PartialEq)]
pub struct MeshFlags {
    /// Single-pass visibility: auto | compute | atomic | exact (per-subpixel depth) | fast (the
    /// paper's one depth per pixel); auto = compute where 64-bit atomics exist, else exact.
    #[arg(long, default_value = "auto", value_parser = OrAuto::<Visibility>::parser(
        "The fastest exact mode the adapter supports (compute, else exact)"
    ))]
    visibility: OrAuto<Visibility>,
    /// Single-pass covering-quad bounds: exact (vd·|1 − fd/d| per vertex) or the paper's printed
    /// formula.
    #[arg(long, value_enum, default_value = "exact")]
    bounds: CoverBounds,
    /// Tiled method: how each view's copy is kept inside its tile.
    #[arg(long, value_enum, default_value = "auto")]
    tile_clip: TileClip,
    /// Single pass, compute visibility: clusters of adjacent views each triangle is tested in
    /// (docs/DESIGN.md §3): 1 = every view at once (the fastest measured on lavapipe); C up to
    /// the view count; auto = chosen per triangle by the cost model. The image is the same for
    /// every value.
    #[arg(long, default_value = "1", value_parser = crate::parse::view_clusters)]
    clusters: ViewClusters,
    /// Reorder triangles along a Morton curve before rendering (locality; every method).
    #[arg(long)]
    sort_triangles: bool,
}

impl MeshFlags {
    /// Refuse a setting the chosen method would ignore, naming the method that uses it.
    pub fn check(&self, method: Method) -> Result<()> {
        let single_pass_only = [
            ("--visibility", self.visibility.0.is_some()),
            ("--bounds", self.bounds != CoverBounds::Exact),
            ("--clusters", self.clusters != ViewClusters::default()),
        ];
        for (flag, set) in single_pass_only {
            if set && method != Method::SinglePass {
                anyhow::bail!(
                    "{flag}: only the single pass uses it (the {method} method renders each view \
                     with its own depth buffer); drop it or use --method single-pass"
                );
            }
        }
        if self.tile_clip != TileClip::Auto && method != Method::Tiled {
            anyhow::bail!(
                "--tile-clip: only --method tiled keeps views inside tiles (the method is \
                 {method}); drop it or use --method tiled"
            );
        }
        Ok(())
    }

    /// How the library prepares a mesh file (`autostereo::load`).
    pub fn load_options(&self) -> autostereo::MeshLoad {
        autostereo::MeshLoad {
            sort_triangles: self.sort_triangles,
        }
    }

    /// The mesh in `file` (the generated torus scene without one), reordered if asked.
    pub fn load(&self, file: Option<&Path>) -> Result<Mesh> {
        let mut mesh = match file {
            Some(path) => {
                crate::progress::during(&crate::progress::loading(path), || Mesh::load(path))?
            }
            None => Mesh::torus_scene(),
        };
        if self.sort_triangles {
            mesh.sort_triangles_spatially();
        }
        Ok(mesh)
    }

    /// The mesh options the flags say.
    pub fn options(&self) -> MeshOptions {
        MeshOptions {
            visibility: self.visibility.0,
            bounds: self.bounds,
            tile_clip: self.tile_clip,
            clusters: self.clusters,
        }
    }
}

pub fn run(args: MeshArgs) -> Result<()> {
    let mut plan = args
        .common
        .plan(args.file.as_deref(), autostereo::DataKind::Mesh, args.warp)?;
    plan.check_flags(&autostereo::mesh::METHODS, |m| args.mesh.check(m))?;
    let mesh = args.mesh.load(args.file.as_deref())?;
    let bounds = mesh.bounds().context("the mesh has no vertices")?;
    let frame = plan.frame(bounds)?;
    let frame = plan.decide(
        frame,
        bounds,
        |f| {
            autostereo::render::auto::Workload::Mesh(autostereo::render::auto::MeshCensus::of(
                &mesh, f,
            ))
        },
        &autostereo::mesh::METHODS,
        |m| args.mesh.check(m),
    )?;
    let ctx = gpu()?;
    let device = &ctx.device;
    let buffers = MeshBuffers::new(device, &mesh)?;
    let options = RendererOptions {
        mesh: args.mesh.options(),
        ..plan.options
    };
    let mut renderer = options.mesh_renderer(device)?;
    let Rendered {
        run,
        mut fields,
        diff,
    } = render_and_save(
        &ctx,
        &mut plan,
        &options,
        renderer.as_mut(),
        |o| o.mesh_renderer(device),
        RendererOptions {
            method: Method::NPass,
            ..options
        },
        &buffers,
        &frame,
        bounds,
        serde_json::json!({
            "triangles": mesh.triangle_count(),
            "textures": mesh.textures.len(),
        }),
    )?;
    let method_name = plan.method.name();
    if plan.method == Method::SinglePass {
        fields["visibility"] = options.mesh_single_pass(device).visibility.name().into();
        fields["bounds"] = format!("{:?}", args.mesh.bounds).to_lowercase().into();
    }
    let textures = match mesh.textures.len() {
        0 => String::new(),
        1 => " (1 texture)".into(),
        n => format!(" ({n} textures)"),
    };
    let summary = format!(
        "{method_name}: {} triangles{textures}, {}",
        mesh.triangle_count(),
        run_summary(&ctx, &plan, &frame, &run)
    );
    report(plan.output.json, fields, diff, &summary);
    Ok(())
}
