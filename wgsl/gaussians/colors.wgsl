// The single pass's colour table (docs/GAUSSIANS.md): a Gaussian's colour in a view depends on
// the Gaussian and the view only (the direction from that view's camera centre to its mean),
// so it is evaluated once per Gaussian and view — as graphdeco's preprocessing does per view —
// instead of once per subpixel. Entry i·N + v: RGB as half floats, two words.
#import shared/frame.wgsl
#import gaussians/shared/gaussian.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by gaussians/shared/gaussian.wgsl.
@group(1) @binding(0) var<storage, read> geometry: array<Gaussian>;
@group(1) @binding(1) var<storage, read> sh: array<u32>;
@group(1) @binding(2) var<uniform> params: GaussianParams;
@group(2) @binding(0) var<storage, read_write> colors: array<vec2<u32>>;

override WORKGROUP: u32 = 64u;

@compute @workgroup_size(WORKGROUP)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let i = id.x + id.y * groups.x * WORKGROUP;
    if (i >= params.count) {
        return;
    }
    let views = frame.camera.views;
    let mean = geometry[i].mean_opacity.xyz;
    for (var v = 0u; v < views; v++) {
        let vd = (f32(v) - 0.5 * f32(views - 1u)) * frame.camera.separation;
        let basis = sh_basis(view_direction(mean, vd));
        let rgb = vec3<f32>(sh_channel(i, basis, 0u), sh_channel(i, basis, 1u),
            sh_channel(i, basis, 2u));
        // The same words `half_rgb` rounds to.
        colors[i * views + v] = vec2<u32>(pack2x16float(rgb.rg), pack2x16float(vec2<f32>(rgb.b, 0.0)));
    }
}
