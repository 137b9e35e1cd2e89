//! Which measurements a bench run makes, and how long it should take.

use super::scenes::{BenchScene, Kind, MethodEntry};
use super::{in_sweep, Plan};

/// Whether `kind` is measured for this configuration: N-pass on the N sweep up to the plan's
/// limit (always for volumes, whose targets are stated at N = 64) and on the extra sizes, single
/// view once per size (it has no views). The quick run sweeps N with each primitive's `primary`
/// single pass only; the others at N = 8.
pub(super) fn measured(
    plan: &Plan,
    primitive: &str,
    kind: Kind,
    primary: bool,
    display: &str,
    n: u32,
    size: [u32; 2],
) -> bool {
    let extra = size != plan.size;
    match kind {
        Kind::SinglePass => primary || !plan.quick || n == 8,
        Kind::NPass | Kind::Duplication | Kind::Warp => {
            extra || (in_sweep(display) && (n <= plan.npass_max_views || primitive == "volume"))
        }
        Kind::SingleView => extra || display == "hubner8",
    }
}

pub(super) fn count_measurements(
    plan: &Plan,
    scenes: &[BenchScene],
    methods: &[Vec<MethodEntry>],
) -> usize {
    let mut total = 0;
    for (scene, methods) in scenes.iter().zip(methods) {
        for (display, size) in plan.configs() {
            let n = autostereo::display::Display::parse(&display).map_or(0, |d| d.views());
            total += methods
                .iter()
                .enumerate()
                .filter(|(i, m)| {
                    measured(plan, scene.primitive, m.kind, *i == 0, &display, n, size)
                })
                .count();
        }
    }
    total
}

/// Seconds the run should take: single view ≈ `probe`, single pass ≈ 2.5 × probe, N-pass ≈ N ×
/// probe, scaled by pixels; plus ~20 % for the trade-offs.
pub(super) fn estimate_seconds(
    plan: &Plan,
    scenes: &[BenchScene],
    methods: &[Vec<MethodEntry>],
    probe_ms: &[f64],
) -> f64 {
    let frames = (plan.frames + 2) as f64;
    let mut ms = 0.0;
    for ((scene, methods), probe) in scenes.iter().zip(methods).zip(probe_ms) {
        let singles = methods
            .iter()
            .filter(|m| m.kind == Kind::SinglePass)
            .count() as f64;
        for (display, size) in plan.configs() {
            let n = autostereo::display::Display::parse(&display).map_or(1, |d| d.views());
            let scale = (size[0] * size[1]) as f64 / (plan.size[0] * plan.size[1]) as f64;
            ms += 2.5 * probe * scale * frames;
            if measured(
                plan,
                scene.primitive,
                Kind::SinglePass,
                false,
                &display,
                n,
                size,
            ) {
                ms += (singles - 1.0) * 2.5 * probe * scale * frames;
            }
            if measured(plan, scene.primitive, Kind::NPass, false, &display, n, size) {
                ms += n as f64 * probe * scale * frames;
            }
            // A warp renders its references (R = 2) by N-pass: about two views.
            let duplications = methods
                .iter()
                .filter(|m| m.kind == Kind::Duplication)
                .count() as f64
                + methods.iter().filter(|m| m.kind == Kind::Warp).count() as f64 * 2.0
                    / n.max(1) as f64;
            if measured(
                plan,
                scene.primitive,
                Kind::Duplication,
                false,
                &display,
                n,
                size,
            ) {
                ms += duplications * n as f64 * probe * scale * frames;
            }
            if measured(
                plan,
                scene.primitive,
                Kind::SingleView,
                false,
                &display,
                n,
                size,
            ) {
                ms += probe * scale * frames;
            }
        }
    }
    ms * 1.2 / 1e3
}
