// Splat geometry pass, layered duplication (Beck et al.): one multiview draw of the group's
// splats into layers first_view .. of the group's views; layer i is view
// params.first_view + i, one ray per pixel (exact, as the N-pass).
#import points/shared/splat.wgsl
#import points/shared/cover_rect.wgsl
#import points/shared/ray_sample.wgsl
#import points/shared/view_quad.wgsl

// Bindings read by points/shared/view_quad.wgsl.
@group(1) @binding(0) var<storage, read> eye_splats: array<Splat>;
// Bindings read by points/shared/splat.wgsl.
@group(2) @binding(0) var<uniform> params: SplatParams;
// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@vertex
fn vs_splat(@builtin(vertex_index) vertex: u32, @builtin(view_index) layer: u32) -> ViewQuadOut {
    let view = params.first_view + layer;
    return view_quad_out(view_quad_corner(vertex, view), vertex, view);
}

@fragment
fn fs_main(in: ViewQuadOut) -> PixelOut {
    let r = ray_sample(view_quad_splat(in), in.position.xy, view_offset(in.view));
    if (r.weight <= 0.0) {
        discard;
    }
    return one_ray_texel(r);
}
