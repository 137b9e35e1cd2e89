// The depth sort's keys (docs/GAUSSIANS.md): per Gaussian the centre camera's eye depth as a
// key that sorts farthest first (back to front), its index as the value; Gaussians outside the
// near and far planes, and the padding up to the sort's power of two, get the largest key and an
// index past the scene (the splat pass culls those).
#import shared/frame.wgsl
#import gaussians/shared/gaussian.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by gaussians/shared/gaussian.wgsl.
@group(1) @binding(0) var<storage, read> geometry: array<Gaussian>;
@group(1) @binding(1) var<storage, read> sh: array<u32>;
@group(1) @binding(2) var<uniform> params: GaussianParams;
// Keys and values of the sort (gaussians/sort_step.wgsl), as long as its power of two.
@group(2) @binding(0) var<storage, read_write> keys: array<u32>;
@group(2) @binding(1) var<storage, read_write> values: array<u32>;

override WORKGROUP: u32 = 256u;

@compute @workgroup_size(WORKGROUP)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if (i >= arrayLength(&keys)) {
        return;
    }
    var key = 0xffffffffu;
    var value = params.count;
    if (i < params.count) {
        let mean = geometry[i].mean_opacity.xyz;
        let depth = -(frame.camera.eye_from_world * vec4<f32>(mean, 1.0)).z;
        if (depth > frame.camera.near && depth < frame.camera.far) {
            // Positive floats order as their bits; inverted, the farthest comes first.
            key = ~bitcast<u32>(depth);
            value = i;
        }
    }
    keys[i] = key;
    values[i] = value;
}
