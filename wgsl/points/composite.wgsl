// Splat compositing pass (paper §3.5.2, after Zhang & Pajarola 2006): per subpixel, the nearest
// depth d over the K group images, then the colour·weight and weight of every group within
// d + ε summed and normalised; background where nothing was hit.
#import points/shared/splat.wgsl

// Bindings read by points/shared/splat.wgsl.
@group(2) @binding(0) var<uniform> params: SplatParams;
// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

// One layer per group: per pixel (pixel depth) or per subpixel (exact depth), see
// points/pixel.wgsl and points/subpixel.wgsl. Depth bits 0 = nothing drawn.
@group(1) @binding(0) var groups: texture_2d_array<u32>;

override SUBPIXEL_DEPTH: bool = false;

const FAR: f32 = 3.0e38;

// The layered method keeps N views per group, group-major (src/points/passes/duplicate.rs);
// every other pipeline compiles the plain index (measured: the general form cost the exact
// single pass ≈ 10 % on llvmpipe).
override LAYERED_GROUPS: bool = false;

// The layer of group g.
fn group_layer(g: u32) -> u32 {
    if (LAYERED_GROUPS) {
        return g * params.group_stride + params.group_base;
    }
    return g;
}

// Normalised colour of one subpixel from the (packed, depth bits) samples of every group.
fn blend_subpixel(coord: vec2<u32>, background: f32) -> f32 {
    let layers = params.groups;
    var nearest = FAR;
    for (var g = 0u; g < layers; g++) {
        let t = textureLoad(groups, coord, group_layer(g), 0).xy;
        if (t.y != 0u) {
            nearest = min(nearest, bitcast<f32>(t.y));
        }
    }
    var sum = vec2<f32>(0.0);
    for (var g = 0u; g < layers; g++) {
        let t = textureLoad(groups, coord, group_layer(g), 0).xy;
        if (t.y != 0u && bitcast<f32>(t.y) <= nearest + params.epsilon) {
            sum += unpack2x16float(t.x);
        }
    }
    return select(background, sum.x / sum.y, sum.y > 0.0);
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    // The group images' texel under this pixel: the tiled method composites one band of tile
    // rows of the atlas at a time (image_row = the band's first atlas row; 0 elsewhere).
    let px = vec2<u32>(position.xy) - vec2<u32>(0u, params.image_row);
    let background = frame.background.rgb;
    if (SUBPIXEL_DEPTH) {
        var out = background;
        for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
            out[c] = blend_subpixel(vec2<u32>(px.x * VIEWS_PER_PIXEL + c, px.y), background[c]);
        }
        return vec4<f32>(out, 1.0);
    }
    let blended = blend_pixel(px);
    return vec4<f32>(select(background, blended.color, blended.seen), 1.0);
}

// Normalised colour and nearest depth of one pixel (one depth per pixel).
struct PixelBlend {
    color: vec3<f32>,
    seen: vec3<bool>,
    depth: f32,
}

fn blend_pixel(px: vec2<u32>) -> PixelBlend {
    let layers = params.groups;
    var nearest = FAR;
    for (var g = 0u; g < layers; g++) {
        let t = textureLoad(groups, px, group_layer(g), 0);
        if (t.w != 0u) {
            nearest = min(nearest, bitcast<f32>(t.w));
        }
    }
    var color = vec3<f32>(0.0);
    var weight = vec3<f32>(0.0);
    for (var g = 0u; g < layers; g++) {
        let t = textureLoad(groups, px, group_layer(g), 0);
        if (t.w != 0u && bitcast<f32>(t.w) <= nearest + params.epsilon) {
            let r = unpack2x16float(t.x);
            let gr = unpack2x16float(t.y);
            let b = unpack2x16float(t.z);
            color += vec3<f32>(r.x, gr.x, b.x);
            weight += vec3<f32>(r.y, gr.y, b.y);
        }
    }
    let seen = weight > vec3<f32>(0.0);
    return PixelBlend(color / select(vec3<f32>(1.0), weight, seen), seen, nearest);
}

// A reference view of a warp (src/warp): the same colour, and the nearness fd / d of the
// nearest splat (0 where none was hit), as bits.
struct ReferenceOut {
    @location(0) color: vec4<f32>,
    @location(1) nearness: u32,
}

@fragment
fn fs_reference(@builtin(position) position: vec4<f32>) -> ReferenceOut {
    let blended = blend_pixel(vec2<u32>(position.xy));
    let color = vec4<f32>(select(frame.background.rgb, blended.color, blended.seen), 1.0);
    let nearness = select(0.0, frame.camera.focal_distance / blended.depth, blended.depth < FAR);
    return ReferenceOut(color, bitcast<u32>(nearness));
}
