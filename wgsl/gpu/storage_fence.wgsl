// A compute pass that touches nothing (src/gpu/storage_fence.rs). Binding scratch buffers
// read-write here, between one frame's draws that read them and the next frame's compute pass
// that writes them, makes wgpu's GL backend emit the memory barrier it otherwise skips.

@group(0) @binding(0) var<storage, read_write> first: array<u32>;
@group(0) @binding(1) var<storage, read_write> second: array<u32>;

@compute @workgroup_size(1)
fn cs_main() {
}
