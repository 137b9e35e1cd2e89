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
            raise_to: rounded_up(bytes),
        });
    }
    Ok(())
}

/// Peak bytes per point from file to a rendered frame: the cloud and its splats (positions,
/// normals, colours, radii: 40 bytes each), the estimation and grouping grids, the group sort,
/// and the GPU's splat, eye-splat and rectangle buffers (80), which a software adapter keeps
/// in RAM. Measured: 294 bytes per point of peak resident memory (the dragon's PLYs, 23k to
/// 438k points, docs/RELIABILITY.md); 400 leaves headroom.
pub const PEAK_BYTES_PER_POINT: u64 = 400;

/// `Err(MemoryBudget)` when `points` points exceed the budget (`crate::budget`).
pub(crate) fn check_points(points: u64) -> Result<()> {
    check(
        || format!("{points} points × {PEAK_BYTES_PER_POINT} bytes from file to GPU"),
        points.saturating_mul(PEAK_BYTES_PER_POINT),
    )
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
            // What is already held only where there is some: "(0 bytes held)" is noise.
            let what = match held {
                0 => what(),
                _ => format!(
                    "{} ({bytes} bytes) with the {held} bytes of GPU memory already held",
                    what()
                ),
            };
            return Err(Error::MemoryBudget {
                what,
                bytes: total,
                budget,
                raise_to: rounded_up(total),
            });
        }
        match GPU_HELD.compare_exchange_weak(held, total, Ordering::Relaxed, Ordering::Relaxed) {
            Ok(_) => return Ok(GpuCharge(bytes)),
            Err(now) => held = now,
        }
    }
}

/// `bytes` rounded up to a figure `--max-memory` takes, in the largest unit that keeps it
/// within an eighth above (`168624` → `165K`, `22708224` → `22M`): what to raise the budget to.
pub fn rounded_up(bytes: u64) -> String {
    for (unit, shift) in [("T", 40), ("G", 30), ("M", 20), ("K", 10)] {
        let n = bytes.div_ceil(1 << shift);
        if n >= 8 || (n << shift) == bytes {
            return format!("{n}{unit}");
        }
    }
    bytes.to_string()
}

/// Bytes per texel of `format` (depth formats by their depth aspect).
pub(crate) fn texel_bytes(format: wgpu::TextureFormat) -> u64 {
    format
        .block_copy_size(None)
        .or_else(|| format.block_copy_size(Some(wgpu::TextureAspect::DepthOnly)))
        .unwrap_or(4)
        .into()
}

/// A size as `--max-memory` takes it: plain bytes (`4096`, `4096B`) or a whole number with a
/// unit, case-insensitive: `K`, `M`, `G`, `T`, each alone or followed by `B` or `iB` (`64K`,
/// `512MB`, `2GiB`, `1tb`), with or without a space before it.
///
/// The units are binary, whichever way they are written: K = KB = KiB = 1024 bytes, M = MB =
/// MiB = 1024², G = GB = GiB = 1024³, T = TB = TiB = 1024⁴. That is what `K`, `M`, `G` and `T`
/// have always meant here, and memory is counted in powers of two, so `MB` means the same as
/// `M` rather than 10⁶ bytes.
pub fn parse_bytes(text: &str) -> std::result::Result<u64, String> {
    let bad = || {
        format!(
            "'{text}' is not a size: bytes, or a whole number with K, M, G or T \
             (binary: K = KB = KiB = 1024 bytes), e.g. 512M, 2GB, 1GiB"
        )
    };
    let t = text.trim();
    let lower = t.to_ascii_lowercase();
    // The unit's letters, from the end: an optional `b` (after an optional `i`), then the
    // multiplier's letter.
    let mut rest = lower.as_str();
    if let Some(r) = rest.strip_suffix("ib") {
        // `KiB` and the like: `iB` needs a multiplier before it.
        if !r.ends_with(['k', 'm', 'g', 't']) {
            return Err(bad());
        }
        rest = r;
    } else if let Some(r) = rest.strip_suffix('b') {
        rest = r;
    }
    let (digits, shift) = match rest.char_indices().last() {
        Some((i, 'k')) => (&rest[..i], 10),
        Some((i, 'm')) => (&rest[..i], 20),
        Some((i, 'g')) => (&rest[..i], 30),
        Some((i, 't')) => (&rest[..i], 40),
        _ => (rest, 0),
    };
    let digits = digits.trim();
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad());
    }
    let n: u64 = digits
        .parse()
        .map_err(|_| format!("'{text}': must be between 1 byte and 16 EiB"))?;
    n.checked_mul(1u64 << shift)
        .filter(|&b| b > 0)
        .ok_or_else(|| format!("'{text}': must be between 1 byte and 16 EiB"))
}

#[cfg(test)]
mod tests {
    use super::parse_bytes;

    #[test]
    fn budgets_round_up_to_a_figure_max_memory_takes() {
        use super::rounded_up;
        assert_eq!(rounded_up(168_624), "165K");
        assert_eq!(rounded_up(22_708_224), "22M");
        assert_eq!(rounded_up(1 << 30), "1G");
        assert_eq!(rounded_up(3 << 30), "3G");
        assert_eq!(rounded_up(100), "100");
        for bytes in [1, 1000, 168_624, 22_708_224, 5 << 30, u64::MAX / 2] {
            let figure = parse_bytes(&rounded_up(bytes)).unwrap();
            assert!(
                figure >= bytes && figure - bytes <= bytes / 8 + 1024,
                "{bytes}"
            );
        }
    }

    #[test]
    fn sizes_parse() {
        assert_eq!(parse_bytes("4096"), Ok(4096));
        assert_eq!(parse_bytes("2G"), Ok(2 << 30));
        assert_eq!(parse_bytes("512m"), Ok(512 << 20));
        assert!(parse_bytes("0").is_err());
        assert!(parse_bytes("x").is_err());
        assert!(parse_bytes("99999999999T").is_err());
    }

    #[test]
    fn units_with_b_and_ib_are_the_same_binary_units() {
        for (unit, shift) in [("k", 10), ("m", 20), ("g", 30), ("t", 40)] {
            let want = Ok(3u64 << shift);
            let upper = unit.to_ascii_uppercase();
            for form in [
                format!("3{unit}"),
                format!("3{upper}"),
                format!("3{upper}B"),
                format!("3{unit}b"),
                format!("3{upper}iB"),
                format!("3{unit}ib"),
                format!("3 {upper}B"),
                format!(" 3{upper}iB "),
            ] {
                assert_eq!(parse_bytes(&form), want, "{form}");
            }
        }
        assert_eq!(parse_bytes("1MB"), parse_bytes("1M"));
        assert_eq!(parse_bytes("1MB"), Ok(1 << 20));
        assert_eq!(parse_bytes("4096B"), Ok(4096));
        assert_eq!(parse_bytes("4096b"), Ok(4096));
    }

    #[test]
    fn malformed_sizes_are_refused_with_the_units() {
        for bad in [
            "", "B", "MB", "iB", "5iB", "1.5G", "-1M", "1KK", "1 M B", "1PB", "0MB",
        ] {
            assert!(parse_bytes(bad).is_err(), "{bad:?} parsed");
        }
        let e = parse_bytes("12 parsecs").unwrap_err();
        assert!(e.contains("K, M, G or T") && e.contains("1024"), "{e}");
    }
}
