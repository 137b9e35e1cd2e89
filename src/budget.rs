//! The memory budget: what a loader or renderer may allocate, checked from a file's header and
//! the flags before anything is allocated. It covers the CPU side of loading (per input) and,
//! as a running total, every GPU texture and buffer the crate allocates that outlives a frame
//! (scenes, targets, view layers, quilt atlases, scratch): each holds a [`GpuCharge`] for its
//! bytes, given back when it is dropped, so a 64-view duplication at 1080p, or a second
//! renderer's scratch on top of the first's, is refused with its figure instead of exhausting
//! the adapter (software adapters allocate from the same RAM). Per-frame constants and
//! read-back staging are small and transient, and not counted.
//!
//! One process-wide figure, 8 GiB by default, raised or lowered with [`set_max_memory`] (the
//! CLI's `--max-memory`). Inputs whose cost is over it are refused with
//! [`crate::Error::MemoryBudget`], which names the figure, the budget and how to raise it; so a
//! 1 MB file that claims a 1024³ volume is an error, not an abort on a 32 GiB allocation.

use std::sync::atomic::{AtomicU64, Ordering};

use crate::error::{Error, Result};

/// The default budget: 8 GiB.
pub const DEFAULT_MAX_MEMORY: u64 = 8 << 30;

static MAX_MEMORY: AtomicU64 = AtomicU64::new(DEFAULT_MAX_MEMORY);

/// Bytes the live [`GpuCharge`]s hold.
static GPU_HELD: AtomicU64 = AtomicU64::new(0);

/// The budget now, in bytes.
pub fn max_memory() -> u64 {
    MAX_MEMORY.load(Ordering::Relaxed)
}

/// Set the budget for this process.
pub fn set_max_memory(bytes: u64) {
    MAX_MEMORY.store(bytes, Ordering::Relaxed);
}

/// `Err(MemoryBudget)` when `bytes` (the cost of `what`) exceed the budget.
pub fn check(what: impl FnOnce() -> String, bytes: u64) -> Result<()> {
    let budget = max_memory();
    if bytes > budget {
        return Err(Error::MemoryBudget {
            what: what(),
            bytes,
            budget,
        });
    }
    Ok(())
}

/// A GPU resource's share of the budget, given back when it is dropped (with the resource).
#[derive(Debug)]
pub struct GpuCharge(u64);

impl GpuCharge {
    /// The bytes charged.
    pub fn bytes(&self) -> u64 {
        self.0
    }
}

impl Drop for GpuCharge {
    fn drop(&mut self) {
        GPU_HELD.fetch_sub(self.0, Ordering::Relaxed);
    }
}

/// Bytes of GPU memory this process's textures and buffers hold now.
pub fn gpu_held() -> u64 {
    GPU_HELD.load(Ordering::Relaxed)
}

/// Charge `bytes` of GPU memory for `what` against the budget, on top of what is held:
/// `Err(MemoryBudget)` (naming what is already held) when the total would exceed it.
pub fn charge_gpu(what: impl FnOnce() -> String, bytes: u64) -> Result<GpuCharge> {
    let budget = max_memory();
    let mut held = GPU_HELD.load(Ordering::Relaxed);
    loop {
        let total = held.saturating_add(bytes);
        if total > budget {
            return Err(Error::MemoryBudget {
                what: format!(
                    "{} ({bytes} bytes) with the {held} bytes of GPU memory already held",
                    what()
                ),
                bytes: total,
                budget,
            });
        }
        match GPU_HELD.compare_exchange_weak(held, total, Ordering::Relaxed, Ordering::Relaxed) {
            Ok(_) => return Ok(GpuCharge(bytes)),
            Err(now) => held = now,
        }
    }
}

/// Bytes per texel of `format` (depth formats by their depth aspect).
pub(crate) fn texel_bytes(format: wgpu::TextureFormat) -> u64 {
    format
        .block_copy_size(None)
        .or_else(|| format.block_copy_size(Some(wgpu::TextureAspect::DepthOnly)))
        .unwrap_or(4)
        .into()
}

/// `2G`, `512M`, `64K` or plain bytes (binary units), as `--max-memory` takes them.
pub fn parse_bytes(text: &str) -> std::result::Result<u64, String> {
    let t = text.trim();
    let (digits, shift) = match t.char_indices().last() {
        Some((i, 'K' | 'k')) => (&t[..i], 10),
        Some((i, 'M' | 'm')) => (&t[..i], 20),
        Some((i, 'G' | 'g')) => (&t[..i], 30),
        Some((i, 'T' | 't')) => (&t[..i], 40),
        _ => (t, 0),
    };
    let n: u64 = digits
        .trim()
        .parse()
        .map_err(|_| format!("'{text}' is not a size (bytes, or with K, M, G, T)"))?;
    n.checked_mul(1u64 << shift)
        .filter(|&b| b > 0)
        .ok_or_else(|| format!("'{text}': must be between 1 byte and 16 EiB"))
}

#[cfg(test)]
mod tests {
    use super::parse_bytes;

    #[test]
    fn sizes_parse() {
        assert_eq!(parse_bytes("4096"), Ok(4096));
        assert_eq!(parse_bytes("2G"), Ok(2 << 30));
        assert_eq!(parse_bytes("512m"), Ok(512 << 20));
        assert!(parse_bytes("0").is_err());
        assert!(parse_bytes("x").is_err());
        assert!(parse_bytes("99999999999T").is_err());
    }
}
