//! What a volume renderer was prepared for, and the check that starts both volume renderers'
//! `encode` (the ray caster's and the proxy slicer's).

use super::super::resources::VolumeResources;
use crate::error::Result;
use crate::frame::Frame;
use crate::render::specialize::Specialization;
use crate::render::{check_prepared, check_target, Method};
use crate::target::SpatialTarget;
use crate::volume::{VolumeScene, VolumeSettings};

/// What a volume renderer was prepared for: display specialisation, empty-space skipping,
/// size and views (the scene's uploads are checked by `VolumeResources::uploaded_for`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct PreparedFor {
    pub spec: Specialization,
    pub skip_empty: bool,
    /// The single pass shares samples among a pixel's K rays.
    pub share_samples: bool,
    /// Probing stride through transparent material (`VolumeSettings::empty_stride`).
    pub empty_stride: u32,
    /// Thin-material threshold of the probes (`VolumeSettings::thin_alpha`, as bits).
    pub thin_alpha_bits: u32,
    /// `Projection::code`: 0 composites; a projection samples every plane (no skipping,
    /// sharing or probes: transparency means nothing to it).
    pub projection: u32,
    /// `VolumeSettings::isovalue` as bits where the projection is the isosurface, else 0.
    pub iso_bits: u32,
    pub size: [u32; 2],
    pub views: u32,
}

impl PreparedFor {
    pub fn of(settings: &VolumeSettings, frame: &Frame, method: Method) -> Self {
        let spec = Specialization::of(frame);
        let composite = settings.projection == crate::volume::Projection::Composite;
        Self {
            spec,
            skip_empty: settings.skip_empty && composite,
            share_samples: method == Method::SinglePass
                && spec.views_per_pixel == 3
                && settings.share_samples > 0.0
                && composite,
            empty_stride: if composite { settings.empty_stride } else { 1 },
            thin_alpha_bits: if composite {
                settings.thin_alpha.to_bits()
            } else {
                0
            },
            projection: settings.projection.code(),
            iso_bits: match settings.projection {
                crate::volume::Projection::Isosurface => settings.isovalue.to_bits(),
                _ => 0,
            },
            size: frame.size,
            views: frame.camera.views,
        }
    }

    /// The proxy slices have no empty-space skipping, sample sharing or probing stride:
    /// toggling them needs no new prepare.
    pub fn for_slices(settings: &VolumeSettings, frame: &Frame) -> Self {
        Self {
            skip_empty: false,
            share_samples: false,
            empty_stride: 1,
            thin_alpha_bits: 0,
            projection: 0,
            iso_bits: 0,
            ..Self::of(settings, frame, Method::SinglePass)
        }
    }
}

/// The start of both volume renderers' `encode`: a valid scene, a target of the frame's size,
/// and `Err(NotPrepared)` unless `prepared` is `wanted` and the scene's uploads are current.
pub(crate) struct VolumeEncode<'a> {
    pub renderer: &'static str,
    pub prepared: Option<PreparedFor>,
    pub resources: &'a VolumeResources,
    pub settings: &'a VolumeSettings,
    pub wanted: PreparedFor,
}

impl VolumeEncode<'_> {
    pub fn check(&self, scene: &VolumeScene, frame: &Frame, target: &SpatialTarget) -> Result<()> {
        scene.validate()?;
        self.settings.validate_for(scene)?;
        check_target(frame, target)?;
        self.check_current(scene)
    }

    /// `Err(NotPrepared)` unless `prepared` is `wanted` and the scene's uploads are current
    /// (the reference views' encode, which has no spatial target, checks this alone).
    pub fn check_current(&self, scene: &VolumeScene) -> Result<()> {
        let current = self.prepared.filter(|_| {
            self.resources
                .uploaded_for(scene, self.settings, self.wanted.skip_empty)
        });
        check_prepared(self.renderer, &current, &self.wanted)
    }
}
