//! [`GaussianSplatter`] as a [`Renderer`]: what `prepare` makes for a scene and frame (the
//! sort, the colour table, per method its targets), and what `encode` records per method.

use super::*;
use crate::param::Param;

impl Renderer<GaussianScene> for GaussianSplatter {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        scene: &GaussianScene,
        frame: &Frame,
    ) -> Result<()> {
        let last = self.prepared.take().map(|p| p.made);
        begin_prepare(device, frame, &mut self.prepared)?;
        if frame.camera.model == CameraModel::ToeIn && frame.camera.separation != 0.0 {
            return Err(Error::invalid(
                Param::CameraModel,
                "toe-in: turned cameras see the Gaussians at different depths, so no one sort \
                 serves every view; Gaussian splats use skewed or parallel cameras",
            ));
        }
        match self.method {
            Method::SinglePass => frame.check_full_views("Gaussian single-pass")?,
            Method::SingleView => frame.check_full_views("Gaussian single-view")?,
            _ => {}
        }
        let key = self.key(device, scene, frame);
        self.ensure_pipeline(device, key.spec)?;
        self.sort.prepare(device, scene)?;
        let table_bytes = if key.color_table {
            color_table_bytes(scene, frame)
        } else {
            0
        };
        let what = || {
            format!(
                "the colour table ({} Gaussians × {} views)",
                scene.count, frame.camera.views
            )
        };
        self.colors.ensure(device, what, table_bytes)?;
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
        let (last_accumulation, last_layers, last_atlas) = match last {
            Some(m) => (m.accumulation, m.layers, m.atlas),
            None => (None, None, None),
        };
        let made = match self.method {
            Method::NPass => {
                let fits =
                    |l: &ViewLayers| l.size() == key.view_size && l.layers() == frame.camera.views;
                drop(last_accumulation);
                drop(last_atlas);
                let layers = match last_layers {
                    Some(l) if fits(&l) => l,
                    last => {
                        drop(last);
                        ViewLayers::with_format(
                            device,
                            ("Gaussian view layers", Param::Views),
                            key.view_size,
                            frame.camera.views,
                            ACCUMULATION_FORMAT,
                            wgpu::TextureUsages::empty(),
                        )?
                    }
                };
                Made {
                    accumulation: None,
                    layers: Some(layers),
                    atlas: None,
                }
            }
            Method::Tiled => {
                drop(last_layers);
                let layout = QuiltLayout::for_views(frame.camera.views, key.view_size);
                let atlas = match last_atlas {
                    Some(atlas) if atlas.fits(&layout, false) => atlas,
                    last => {
                        drop(last);
                        Atlas::new(device, layout, false)?
                    }
                };
                let accumulation = texture_2d_reusing(
                    last_accumulation,
                    device,
                    "gaussian quilt accumulation",
                    layout.size(),
                    ACCUMULATION_FORMAT,
                    usage,
                )?;
                Made {
                    accumulation: Some(accumulation),
                    layers: None,
                    atlas: Some(atlas),
                }
            }
            _ => {
                drop(last_layers);
                drop(last_atlas);
                let accumulation = texture_2d_reusing(
                    last_accumulation,
                    device,
                    "gaussian accumulation",
                    frame.size,
                    ACCUMULATION_FORMAT,
                    usage,
                )?;
                Made {
                    accumulation: Some(accumulation),
                    layers: None,
                    atlas: None,
                }
            }
        };
        self.prepared = Some(Prepared { key, made });
        Ok(())
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &GaussianScene,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let wanted = self.key(device, scene, frame);
        crate::render::check_target(frame, target)?;
        prepared_state("GaussianSplatter", &self.prepared, &wanted)?;
        let camera = &frame.camera;
        let spread = camera.max_offset();
        let passes: Vec<GaussianParams> = match self.method {
            Method::SinglePass => vec![GaussianParams::new(scene, frame, -spread, spread, None)],
            Method::SingleView => vec![GaussianParams::new(scene, frame, 0.0, 0.0, Some(0.0))],
            _ => {
                let layout = QuiltLayout::for_views(camera.views, frame.view_size());
                (0..camera.views)
                    .map(|v| {
                        let vd = camera.view_offset(v);
                        let mut params = GaussianParams::new(scene, frame, vd, vd, Some(vd));
                        if self.method == Method::Tiled {
                            let [x, y] = layout.tile_origin(v);
                            params.tile = [x as f32, y as f32, 0.0, 0.0];
                        }
                        params
                    })
                    .collect()
            }
        };
        let mut passes = passes;
        for p in &mut passes {
            p.color_table = wanted.color_table as u32;
        }
        self.params.write(device, &passes);
        self.frame.write(device, frame);
        let scene_group = self.scene_group(device, scene, None);
        if wanted.color_table {
            self.encode_colors(device, encoder, scene, &scene_group);
        }
        let order = self
            .sort
            .encode(device, encoder, scene, frame, &self.frame, &scene_group)?;
        let splat_group = self.scene_group(device, scene, Some(&order));
        let spec = wanted.spec;
        let made = &prepared_state("GaussianSplatter", &self.prepared, &wanted)?.made;
        let background = frame.background;
        match (&made.accumulation, &made.layers) {
            (_, Some(layers)) if self.method == Method::NPass => {
                let views = frame.for_view_images();
                self.views_frame.write(device, &views);
                for v in 0..camera.views {
                    let draw = Draw {
                        frame: &self.views_frame,
                        background,
                        group: &splat_group,
                        offset: self.params.offset(v as usize),
                        spec,
                        count: scene.count,
                    };
                    self.draw(encoder, &draw, &layers.layer_views[v as usize])?;
                }
                self.compositor.encode(
                    device,
                    encoder,
                    &self.frame,
                    &layers.array_view,
                    layers.size(),
                    target,
                );
            }
            (Some(accumulation), _) if self.method == Method::Tiled => {
                let atlas = made.atlas.made("GaussianSplatter quilt atlas")?;
                let views = frame.for_view_images();
                self.views_frame.write(device, &views);
                let draw = Draw {
                    frame: &self.views_frame,
                    background,
                    group: &splat_group,
                    offset: 0,
                    spec,
                    count: scene.count,
                };
                self.draw_tiles(encoder, &draw, atlas, accumulation)?;
                self.resolve.encode(
                    device,
                    encoder,
                    &self.frame,
                    &accumulation.view,
                    &atlas.color.view,
                );
                self.atlas_compositor.encode(
                    device,
                    encoder,
                    &self.frame,
                    atlas,
                    target,
                    TileSampling::Bilinear,
                );
            }
            (Some(accumulation), _) => {
                let draw = Draw {
                    frame: &self.frame,
                    background,
                    group: &splat_group,
                    offset: self.params.offset(0),
                    spec,
                    count: scene.count,
                };
                self.draw(encoder, &draw, &accumulation.view)?;
                self.resolve.encode(
                    device,
                    encoder,
                    &self.frame,
                    &accumulation.view,
                    &target.view,
                );
            }
            _ => {
                return Err(Error::NotPrepared {
                    renderer: "GaussianSplatter",
                    frame: format!("{wanted:?}"),
                    prepared: "no target for this method".into(),
                })
            }
        }
        self.crop.encode(device, encoder, frame, target);
        Ok(())
    }

    fn atlas(&self) -> Option<&Atlas> {
        self.prepared.as_ref().and_then(|p| p.made.atlas.as_ref())
    }
}
