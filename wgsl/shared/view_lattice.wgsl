// The pixels of one row whose channel c shows a view of a range [v0, v1), found without testing
// every pixel (the view-clustered single pass, docs/DESIGN.md §3): along the row, every
// `mask_lattice_stride`-th pixel's lens phase (shared/mask.wgsl `mask_phase`) steps by one
// constant, so the pixels of a phase window [k + lo, k + hi) are a run of consecutive lattice
// pixels, one run per lens. Runs are padded by PHASE_PAD: they are candidates, and the caller
// keeps a pixel only if its `mask_view` is in the range (exact: the same integer arithmetic).
// Reads `frame.mask`.

struct LatticeRun {
    start: f32, // lens phase of the run's pixel 0 (reflected where the step is over ½)
    step: f32,  // phase step from one lattice pixel to the next, in [0, ½]
    lo: f32,    // wanted phases [lo, hi), unwrapped, in the same reflection
    hi: f32,
    count: u32, // lattice pixels on the row's span
    every: bool, // every pixel is a candidate: the range is (nearly) every view, or no step
}

// Float error of the phases (24-bit fractions, steps summed over ≤ 2^13 pixels) is below 1e-3.
const PHASE_PAD: f32 = 1.0e-3;

fn phase_fraction(t: u32) -> f32 {
    return f32(t >> 8u) * (1.0 / 16777216.0);
}

// The lattice of pixels x0, x0 + stride, … (count of them) on row y, channel c, views [v0, v1).
fn lattice_run(x0: u32, y: u32, stride: u32, count: u32, c: u32, v0: u32, v1: u32) -> LatticeRun {
    let m = frame.mask;
    let t0 = mask_phase(m, vec2<u32>(x0, y), c);
    let dt = mask_phase(m, vec2<u32>(x0 + stride, y), c) - t0;
    var start = phase_fraction(t0);
    var step = phase_fraction(dt);
    // mask_view counts views down from the flipped end: its [v0, v1) is (N − v1, N − v0] before.
    let flip = (m.flags & MASK_FLIP) != 0u;
    let n = f32(m.views);
    var lo = f32(select(v0, m.views - v1, flip)) / n;
    var hi = f32(select(v1, m.views - v0, flip)) / n;
    if (step > 0.5) {
        // A step s over ½ is a step back by 1 − s: reflect every phase p ↦ 1 − p.
        step = 1.0 - step;
        start = 1.0 - start;
        let l = 1.0 - hi;
        hi = 1.0 - lo;
        lo = l;
    }
    let every = hi - lo >= 1.0 - 2.0 * PHASE_PAD || step < 1.0e-6;
    return LatticeRun(start, step, lo, hi, count, every);
}

// Lens windows k = −1 … run_windows(r) − 2 cover the run (k = −1 only through the padding).
fn run_windows(r: LatticeRun) -> i32 {
    let top = r.start + f32(r.count - 1u) * r.step;
    return i32(floor(top - r.lo + PHASE_PAD)) + 2;
}

// Lattice pixels [first, last] of window k (last < first: none).
fn run_window(r: LatticeRun, k: i32) -> vec2<i32> {
    let first = ceil((f32(k) + r.lo - r.start - PHASE_PAD) / r.step);
    let last = floor((f32(k) + r.hi - r.start + PHASE_PAD) / r.step);
    return vec2<i32>(i32(max(first, 0.0)), i32(min(last, f32(r.count) - 1.0)));
}
