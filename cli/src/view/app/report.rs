//! What the viewer prints when it ends: with `--json`, one object saying what it showed and
//! the files it wrote (`written`), as every command's `--json` does; an exercise run's memory
//! report in that object, or alone without `--json` (cli/tests/viewer.rs reads it).

use super::super::ViewArgs;
use super::State;

/// Print the run's report, if it has one to print.
pub(super) fn print(state: &State, args: &ViewArgs) {
    let exercise = state.exercise_report.clone();
    if !args.json {
        if let Some(report) = exercise {
            println!("{report}");
        }
        return;
    }
    let mut report = exercise.unwrap_or_else(|| serde_json::json!({}));
    report["scene"] = state.scene.name.clone().into();
    report["primitive"] = state.scene.scene.primitive().into();
    report["method"] = state.methods[state.method].name().into();
    report["display"] = state.displays[state.display].0.clone().into();
    report["window_size"] = serde_json::json!([state.config.width, state.config.height]);
    report["frames"] = state.frames.into();
    report["adapter"] = state.ctx.adapter_label().into();
    report["written"] = serde_json::json!(state.written);
    println!("{report}");
}
