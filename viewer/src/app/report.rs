//! What the viewer says when it ends: the scene, method and display last shown, the window,
//! the frames and the files written; an exercise run's memory report (cli/tests/viewer reads
//! it).

use super::State;
use crate::Report;

/// The run's report.
pub(super) fn report(state: &State) -> Report {
    Report {
        scene: state.scene.name.clone(),
        primitive: state.scene.scene.primitive().to_string(),
        method: state.methods[state.method].name().to_string(),
        display: state.displays[state.display].0.clone(),
        window_size: [state.config.width, state.config.height],
        frames: state.frames,
        adapter: state.ctx.adapter_label(),
        written: state.written.clone(),
        exercise: state.exercise_report.clone(),
    }
}
