// Volumes, the paper's fragment path (§3.3.1, §3.5.1): view-aligned proxy slices at the eye
// depths d = k·Δ, drawn back to front as rectangles covering the slice's intersection with the
// box in every view (docs/DESIGN.md §3 widening). Per fragment and subpixel view, the view's ray meets
// slices k and k+1 at the centre view's position shifted by Eq. 1; the segment between them is
// pre-integrated and shaded, and composited "over" what lies behind.
//   paper α: one α per pixel, the mean of the K views' (2007 GPUs had one blend α);
//   exact α: dual-source blending, one α per channel (matches N-pass).
// Accumulates in an RGBA16F target cleared to the background (render/accumulation_resolve.wgsl
// copies it to the spatial image).
enable dual_source_blending;
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import volume/shared/volume.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by volume/shared/volume.wgsl.
@group(1) @binding(0) var volume: texture_3d<f32>;
@group(1) @binding(1) var linear_clamp: sampler;
@group(1) @binding(2) var preintegration: texture_2d<f32>;
@group(1) @binding(3) var<uniform> params: VolumeParams;

// One proxy slice. Keep in sync with `SliceRect` in src/volume/passes/slices.rs.
struct Slice {
    depth: vec4<f32>, // x: eye depth of the slice's front plane (the back plane is x + Δ)
    rect: vec4<f32>,  // NDC rectangle lo.xy, hi.xy covering it in every view
}

@group(2) @binding(0) var<storage, read> slices: array<Slice>;

override EXACT_ALPHA: bool = true;

struct SliceOut {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) slice: u32,
}

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, @builtin(instance_index) slice: u32) -> SliceOut {
    let rect = slices[slice].rect;
    let corner = array<u32, 6>(0u, 1u, 2u, 2u, 1u, 3u)[vertex];
    let x = select(rect.x, rect.z, (corner & 1u) != 0u);
    let y = select(rect.y, rect.w, (corner & 2u) != 0u);
    return SliceOut(vec4<f32>(x, y, 0.5, 1.0), slice);
}

// Inside the box and on the kept side of the clipping planes: a segment is drawn where both
// its ends are (the region is convex, so all of it is), as the march's span keeps it.
fn inside_box(p: vec3<f32>) -> bool {
    return all(p >= vec3<f32>(0.0)) && all(p <= vec3<f32>(1.0)) && inside_clip(p);
}

// The shaded segment of view `view` between this slice and the next, or 0 outside the box.
fn view_segment(frag: vec2<f32>, view: u32, depth: f32) -> vec4<f32> {
    let fd = frame.camera.focal_distance;
    let origin = vec3<f32>(view_offset(view), 0.0, 0.0);
    let dir = camera_ray_direction(frame.camera, frag, origin.x);
    let o = (params.tex_from_eye * vec4<f32>(origin, 1.0)).xyz;
    let d = (params.tex_from_eye * vec4<f32>(dir, 0.0)).xyz;
    let t_front = o + (depth / fd) * d;
    let t_back = o + ((depth + params.step) / fd) * d;
    if (!inside_box(t_front) || !inside_box(t_back)) {
        return vec4<f32>(0.0);
    }
    let front = textureSampleLevel(volume, linear_clamp, t_front, 0.0);
    let back = textureSampleLevel(volume, linear_clamp, t_back, 0.0);
    return shaded_segment(front, back, origin + ((depth + params.step) / fd) * dir, origin);
}

struct BlendOut {
    @location(0) @blend_src(0) color: vec4<f32>,
    @location(0) @blend_src(1) alpha: vec4<f32>,
}

@fragment
fn fs_main(in: SliceOut) -> BlendOut {
    let px = vec2<u32>(in.position.xy);
    let depth = slices[in.slice].depth.x;
    var color = vec3<f32>(0.0);
    var alpha = vec3<f32>(0.0);
    for (var k = 0u; k < VIEWS_PER_PIXEL; k++) {
        let seg = view_segment(in.position.xy, ray_view(px, k), depth);
        if (VIEWS_PER_PIXEL == 1u) {
            color = seg.rgb;
            alpha = vec3<f32>(seg.a);
        } else {
            color[k] = seg[k];
            alpha[k] = seg.a;
        }
    }
    if (!EXACT_ALPHA) {
        // The paper: one α for the pixel, the mean over its views.
        alpha = vec3<f32>((alpha.x + alpha.y + alpha.z) / 3.0);
    }
    // dst = color + (1 − α_c)·dst per channel (blend factors One, OneMinusSrc1).
    return BlendOut(vec4<f32>(color, 1.0), vec4<f32>(alpha, 1.0));
}
