// Splat geometry pass, tiled duplication (de Sorbier et al.): instance v is view v's copy of the
// group's splats, its quads in view v's tile of the group image with one depth buffer (the
// image is the atlas, or one band of its tile rows whose first view is params.first_view:
// `quilt` is then the band's own grid); each fragment casts view v's ray through its pixel of
// the tile (one ray per pixel: exact, as the N-pass).
#import points/shared/splat.wgsl
#import points/shared/cover_rect.wgsl
#import points/shared/ray_sample.wgsl
#import points/shared/view_quad.wgsl
#import shared/quilt.wgsl

// Bindings read by points/shared/view_quad.wgsl.
@group(1) @binding(0) var<storage, read> eye_splats: array<Splat>;
// Bindings read by points/shared/splat.wgsl.
@group(2) @binding(0) var<uniform> params: SplatParams;
// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(3) @binding(0) var<uniform> quilt: Quilt;

@vertex
fn vs_splat(@builtin(vertex_index) vertex: u32, @builtin(instance_index) view: u32) -> ViewQuadOut {
    var position = view_quad_corner(vertex, view);
    if (position.x > -2.0) {
        position = quilt_clip(quilt, view - params.first_view, position);
    }
    return view_quad_out(position, vertex, view);
}

@fragment
fn fs_main(in: ViewQuadOut) -> PixelOut {
    let local = in.position.xy - vec2<f32>(quilt_tile_origin(quilt, in.view - params.first_view));
    let r = ray_sample(view_quad_splat(in), local, view_offset(in.view));
    if (r.weight <= 0.0) {
        discard;
    }
    return one_ray_texel(r);
}
