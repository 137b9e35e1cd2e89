//! `autostereo.show`: the library's viewer window (autostereo-viewer) on a scene, from a
//! notebook without blocking it. Windows run one after another on one thread of their own,
//! which holds the process's one event loop (`autostereo_viewer::Windows`); `show` returns a
//! `Window` at once, whose `wait()` gives the viewer's report when the window closes.

use std::sync::mpsc::{channel, Receiver, RecvTimeoutError, Sender};
use std::sync::{Mutex, OnceLock};
use std::time::Duration;

use autostereo::render::Method;
use autostereo::RendererOptions;
use autostereo_viewer::{Options, Preview, Report};
use pyo3::exceptions::{PyRuntimeError, PyTimeoutError, PyValueError};
use pyo3::prelude::*;

use crate::camera::PyCamera;
use crate::display::PyDisplay;
use crate::names::by_name;
use crate::scene::PyScene;

type Outcome = Result<Report, String>;

/// A window to open: the scene, the run's options, where its report goes.
struct Job {
    scene: autostereo_viewer::Scene,
    options: Options,
    done: Sender<Outcome>,
}

static WINDOWS: OnceLock<Mutex<Sender<Job>>> = OnceLock::new();

/// The windows' thread, started the first time: it makes the event loop and runs each job's
/// window to its end (a failure to make the loop is each job's error).
fn windows() -> Sender<Job> {
    let sender = WINDOWS.get_or_init(|| {
        let (tx, rx) = channel::<Job>();
        std::thread::Builder::new()
            .name("autostereo viewer".into())
            .spawn(move || {
                let mut windows = autostereo_viewer::Windows::new().map_err(|e| e.to_string());
                for job in rx {
                    let outcome = match &mut windows {
                        Ok(w) => w.run(job.scene, job.options).map_err(|e| e.to_string()),
                        Err(e) => Err(format!("no window: {e}")),
                    };
                    let _ = job.done.send(outcome);
                }
            })
            .expect("a thread for the viewer");
        Mutex::new(tx)
    });
    sender.lock().expect("not poisoned").clone()
}

fn preview(name: &str) -> PyResult<Preview> {
    const ALL: [Preview; 5] = [
        Preview::Spatial,
        Preview::View,
        Preview::Anaglyph,
        Preview::SideBySide,
        Preview::Quilt,
    ];
    by_name(name, "preview", &ALL, Preview::name)
}

/// An open (or closed) viewer window.
#[pyclass(name = "Window", module = "autostereo", frozen)]
pub struct PyWindow {
    pending: Mutex<Option<Receiver<Outcome>>>,
    outcome: Mutex<Option<Outcome>>,
}

impl PyWindow {
    /// The report, once the window has closed: waits up to `timeout` (forever where none).
    fn outcome(&self, py: Python<'_>, timeout: Option<f64>) -> PyResult<Option<Outcome>> {
        if let Some(done) = self.outcome.lock().expect("not poisoned").clone() {
            return Ok(Some(done));
        }
        let mut pending = self.pending.lock().expect("not poisoned");
        let Some(rx) = pending.take() else {
            return Err(PyRuntimeError::new_err("the window's thread ended"));
        };
        let (got, rx) = py.detach(move || {
            let got = match timeout {
                Some(t) => rx.recv_timeout(Duration::from_secs_f64(t.max(0.0))),
                None => rx.recv().map_err(|_| RecvTimeoutError::Disconnected),
            };
            (got, rx)
        });
        match got {
            Ok(outcome) => {
                *self.outcome.lock().expect("not poisoned") = Some(outcome.clone());
                Ok(Some(outcome))
            }
            Err(RecvTimeoutError::Timeout) => {
                *pending = Some(rx);
                Ok(None)
            }
            Err(RecvTimeoutError::Disconnected) => {
                Err(PyRuntimeError::new_err("the window's thread ended"))
            }
        }
    }
}

#[pymethods]
impl PyWindow {
    /// Whether the window has closed.
    #[getter]
    fn closed(&self, py: Python<'_>) -> PyResult<bool> {
        Ok(self.outcome(py, Some(0.0))?.is_some())
    }

    /// Wait until the window closes (at most `timeout` seconds) and return the viewer's report
    /// as a dict (`frames`, `method`, `display`, `window_size`, `adapter`, `written`, …);
    /// `TimeoutError` if it is still open then, `RuntimeError` with the viewer's message if it
    /// failed.
    #[pyo3(signature = (timeout = None))]
    fn wait<'py>(&self, py: Python<'py>, timeout: Option<f64>) -> PyResult<Bound<'py, PyAny>> {
        match self.outcome(py, timeout)? {
            Some(Ok(report)) => {
                let json = serde_json::to_string(&report)
                    .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
                py.import("json")?.call_method1("loads", (json,))
            }
            Some(Err(e)) => Err(PyRuntimeError::new_err(e)),
            None => Err(PyTimeoutError::new_err("the window is still open")),
        }
    }
}

/// Open the viewer window on `scene` for `display` (a `Display` or a spec; default hubner8)
/// and return at once: `size` the window's
/// client area, `method` and `preview` what it starts with (keys m and p switch), `camera`
/// where it starts (an orbit included), `fullscreen` the monitor's number (or True: the
/// display's panel); `frames` closes it after that many frames, `screenshot` saves what it
/// presented as PNG (then closes unless `keep_open`). Mouse and keys as `autostereo view`.
#[pyfunction]
#[pyo3(signature = (scene, display = None, size = (512, 512), method = "single-pass",
    preview = "spatial", camera = None, fullscreen = None, frames = None, screenshot = None,
    keep_open = false))]
#[allow(clippy::too_many_arguments)]
pub fn show(
    scene: &PyScene,
    display: Option<&Bound<'_, PyAny>>,
    size: (u32, u32),
    method: &str,
    preview: &str,
    camera: Option<&PyCamera>,
    fullscreen: Option<&Bound<'_, PyAny>>,
    frames: Option<u32>,
    screenshot: Option<std::path::PathBuf>,
    keep_open: bool,
) -> PyResult<PyWindow> {
    let (display, name) = match display.map(|d| (d.cast::<PyDisplay>(), d)) {
        Some((Ok(d), _)) => (d.get().display.clone(), d.get().spec.clone()),
        Some((Err(_), d)) => {
            let spec: String = d.extract()?;
            (PyDisplay::parse(&spec)?.display, spec)
        }
        None => (PyDisplay::parse("hubner8")?.display, "hubner8".to_string()),
    };
    let method: Method = crate::renderer::method(method)?;
    let mut options = Options::new(display, name);
    options.size = [size.0, size.1];
    options.method = method;
    options.preview = self::preview(preview)?;
    if let Some(c) = camera {
        options.camera = c.settings;
        options.orbit = c.orbit;
    }
    options.fullscreen = match fullscreen {
        None => None,
        // A bool first: Python's True is also the int 1.
        Some(f) => match f.extract::<bool>() {
            Ok(panel) => panel.then_some(autostereo_viewer::Monitor::Panel),
            Err(_) => Some(autostereo_viewer::Monitor::Index(f.extract()?)),
        },
    };
    options.quit_after_frames = frames;
    options.screenshot = screenshot;
    options.keep_open = keep_open;
    let bounds = crate::renderer::framed(&scene.data)
        .ok_or_else(|| PyValueError::new_err("the scene has nothing to frame"))?;
    let viewed = autostereo_viewer::Scene::new(
        scene.data.clone(),
        RendererOptions::new(method),
        format!("python {}", scene.data.kind().name()),
    )
    .map_err(|e| PyValueError::new_err(e.to_string()))?
    .with_bounds(bounds);
    let (done, pending) = channel();
    windows()
        .send(Job {
            scene: viewed,
            options,
            done,
        })
        .map_err(|_| PyRuntimeError::new_err("the viewer's thread has ended"))?;
    Ok(PyWindow {
        pending: Mutex::new(Some(pending)),
        outcome: Mutex::new(None),
    })
}
