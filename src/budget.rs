//! The memory budget: what a loader or renderer may allocate, checked from a file's header and
//! the flags before anything is allocated. It covers the CPU side of loading (per input) and,
//! as a running total, every GPU texture and buffer the crate allocates that outlives a frame
//! (scenes, targets, view layers, quilt atlases, scratch): each holds a [`GpuCharge`] for its
//! bytes, given back when it is dropped, so a 64-view duplication at 1080p, or a second
//! renderer's scratch on top of the first's, is refused with its figure instead of exhausting
//! the adapter (software adapters allocate from the same RAM). Per-frame constants and
//! read-back staging are small and transient, and not counted.
//!
//! A budget is a value: [`Budget::new`] gives one of its own figure and its own running total,
//! so two hosts in one process (a viewer beside a notebook) each keep theirs. The library's
//! loaders and GPU allocations charge the budget *current on the calling thread*: the innermost
//! one entered there ([`Budget::enter`], [`Budget::in_scope`]), else the process's default
//! (8 GiB, [`Budget::current`] outside every scope) — the pattern of `tracing`'s dispatchers,
//! chosen over a budget parameter on each of the ~140 constructors and loaders that allocate.
//! A [`GpuCharge`] gives its bytes back to the budget it was taken from, wherever it is dropped.
//! Inputs whose cost is over the figure are refused with [`crate::Error::MemoryBudget`], which
//! names the figure, the budget and how to raise it; so a 1 MB file that claims a 1024³ volume
//! is an error, not an abort on a 32 GiB allocation.

use std::cell::RefCell;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, OnceLock};

use crate::error::{Error, Result};

/// The default budget: 8 GiB.
pub const DEFAULT_MAX_MEMORY: u64 = 8 << 30;

/// A memory budget: its figure and the GPU bytes its live [`GpuCharge`]s hold. Clones share
/// both (a handle).
#[derive(Clone, Debug)]
pub struct Budget {
    inner: Arc<Inner>,
}

#[derive(Debug)]
struct Inner {
    max: AtomicU64,
    gpu_held: AtomicU64,
}

impl Default for Budget {
    /// A budget of its own of [`DEFAULT_MAX_MEMORY`].
    fn default() -> Self {
        Self::new(DEFAULT_MAX_MEMORY)
    }
}

thread_local! {
    /// The budgets entered on this thread, innermost last.
    static ENTERED: RefCell<Vec<Budget>> = const { RefCell::new(Vec::new()) };
}

/// The budget of code that enters none.
fn process_default() -> &'static Budget {
    static DEFAULT: OnceLock<Budget> = OnceLock::new();
    DEFAULT.get_or_init(Budget::default)
}

impl Budget {
    /// A budget of `max_bytes`, holding nothing.
    pub fn new(max_bytes: u64) -> Self {
        Self {
            inner: Arc::new(Inner {
                max: AtomicU64::new(max_bytes),
                gpu_held: AtomicU64::new(0),
            }),
        }
    }

    /// The budget the library charges on this thread now: the innermost entered, else the
    /// process's default.
    pub fn current() -> Budget {
        ENTERED
            .with(|e| e.borrow().last().cloned())
            .unwrap_or_else(|| process_default().clone())
    }

    /// Make this the current budget on this thread until the guard is dropped.
    pub fn enter(&self) -> Entered {
        ENTERED.with(|e| e.borrow_mut().push(self.clone()));
        Entered {
            _not_send: std::marker::PhantomData,
        }
    }

    /// Run `f` with this as the current budget.
    pub fn in_scope<R>(&self, f: impl FnOnce() -> R) -> R {
        let _entered = self.enter();
        f()
    }

    /// The figure, in bytes.
    pub fn max(&self) -> u64 {
        self.inner.max.load(Ordering::Relaxed)
    }

    /// Change the figure (for this budget and its clones).
    pub fn set_max(&self, bytes: u64) {
        self.inner.max.store(bytes, Ordering::Relaxed);
    }

    /// Bytes of GPU memory this budget's live charges hold.
    pub fn gpu_held(&self) -> u64 {
        self.inner.gpu_held.load(Ordering::Relaxed)
    }

    /// `Err(MemoryBudget)` when `bytes` (the cost of `what`) exceed the figure.
    pub fn check(&self, what: impl FnOnce() -> String, bytes: u64) -> Result<()> {
        let budget = self.max();
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

    /// Charge `bytes` of GPU memory for `what`, on top of what is held: `Err(MemoryBudget)`
    /// (naming what is already held) when the total would exceed the figure.
    pub fn charge_gpu(&self, what: impl FnOnce() -> String, bytes: u64) -> Result<GpuCharge> {
        let budget = self.max();
        let held_now = &self.inner.gpu_held;
        let mut held = held_now.load(Ordering::Relaxed);
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
            match held_now.compare_exchange_weak(held, total, Ordering::Relaxed, Ordering::Relaxed)
            {
                Ok(_) => {
                    return Ok(GpuCharge {
                        bytes,
                        budget: self.inner.clone(),
                    })
                }
                Err(now) => held = now,
            }
        }
    }
}

/// While alive, its [`Budget`] is the current one on this thread ([`Budget::enter`]).
#[must_use = "the budget is current only while the guard lives"]
pub struct Entered {
    /// Entered on one thread, left on it.
    _not_send: std::marker::PhantomData<*const ()>,
}

impl Drop for Entered {
    fn drop(&mut self) {
        ENTERED.with(|e| e.borrow_mut().pop());
    }
}

/// `Err(MemoryBudget)` when `bytes` (the cost of `what`) exceed the current budget.
pub(crate) fn check(what: impl FnOnce() -> String, bytes: u64) -> Result<()> {
    Budget::current().check(what, bytes)
}

/// Charge `bytes` of GPU memory for `what` to the current budget.
pub(crate) fn charge_gpu(what: impl FnOnce() -> String, bytes: u64) -> Result<GpuCharge> {
    Budget::current().charge_gpu(what, bytes)
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

/// A GPU resource's share of a budget, given back when it is dropped (with the resource).
#[derive(Debug)]
pub struct GpuCharge {
    bytes: u64,
    budget: Arc<Inner>,
}

impl GpuCharge {
    /// The bytes charged.
    pub fn bytes(&self) -> u64 {
        self.bytes
    }
}

impl Drop for GpuCharge {
    fn drop(&mut self) {
        self.budget
            .gpu_held
            .fetch_sub(self.bytes, Ordering::Relaxed);
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

    /// Two hosts' budgets keep their own figures and totals: a charge is refused against the
    /// smaller, held by the one it came from, and given back to it wherever it is dropped.
    #[test]
    fn budgets_are_values_of_their_own() {
        use super::Budget;
        let (small, large) = (Budget::new(1000), Budget::new(1 << 20));
        let charge = small
            .in_scope(|| super::charge_gpu(|| "a".into(), 600))
            .unwrap();
        assert_eq!((small.gpu_held(), large.gpu_held()), (600, 0));
        let refused = small.in_scope(|| super::charge_gpu(|| "b".into(), 600));
        let text = refused.unwrap_err().to_string();
        assert!(
            text.contains("already held") && text.contains("1000"),
            "{text}"
        );
        let other = large
            .in_scope(|| super::charge_gpu(|| "b".into(), 600))
            .unwrap();
        assert_eq!((small.gpu_held(), large.gpu_held()), (600, 600));
        drop(charge);
        assert_eq!((small.gpu_held(), large.gpu_held()), (0, 600));
        drop(other);
        assert_eq!(large.gpu_held(), 0);
        // Clones are the same budget; a new figure applies to every clone.
        let clone = small.clone();
        clone.set_max(10);
        assert!(small.in_scope(|| super::check(|| "c".into(), 11)).is_err());
    }

    /// The innermost budget entered is current; leaving restores the one outside.
    #[test]
    fn the_innermost_entered_budget_is_current() {
        use super::Budget;
        let (outer, inner) = (Budget::new(100), Budget::new(200));
        let _outer = outer.enter();
        assert_eq!(Budget::current().max(), 100);
        inner.in_scope(|| assert_eq!(Budget::current().max(), 200));
        assert_eq!(Budget::current().max(), 100);
        // Another thread enters none: the process's default.
        let there = std::thread::spawn(|| Budget::current().max())
            .join()
            .unwrap();
        assert_eq!(there, super::DEFAULT_MAX_MEMORY);
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
