//! The process's one GPU context, made on first use (the adapter the library picks:
//! `WGPU_BACKEND`, `WGPU_ADAPTER_NAME` as for the CLI) and shared by every renderer and scene.

use std::sync::OnceLock;

use autostereo::gpu::GpuContext;
use pyo3::PyResult;

use crate::errors::to_py;

static CONTEXT: OnceLock<GpuContext> = OnceLock::new();

/// The shared context, created the first time.
pub fn context() -> PyResult<&'static GpuContext> {
    if let Some(ctx) = CONTEXT.get() {
        return Ok(ctx);
    }
    let ctx = GpuContext::new(&Default::default()).map_err(to_py)?;
    Ok(CONTEXT.get_or_init(|| ctx))
}
