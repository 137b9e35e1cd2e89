// The nearness range of the surfaces in each row of each reference view (src/warp/scene.rs):
// the warp searches only the samples whose landing can reach a subpixel, and that window is
// the row's range times the view's shift. One invocation per row and reference; (lo, hi) with
// lo > hi for a row that shows no surface (nearness 0 everywhere).

@group(0) @binding(0) var nearness: texture_2d_array<u32>; // the bits of f32 nearness
@group(0) @binding(1) var<storage, read_write> row_bounds: array<vec2<f32>>;

@compute @workgroup_size(64)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = textureDimensions(nearness);
    let row = id.x;
    let reference = id.y;
    if (row >= size.y) {
        return;
    }
    var lo = 3.0e38;
    var hi = -3.0e38;
    for (var x = 0u; x < size.x; x++) {
        let n = bitcast<f32>(textureLoad(nearness, vec2<u32>(x, row), reference, 0).r);
        if (n > 0.0) {
            lo = min(lo, n);
            hi = max(hi, n);
        }
    }
    row_bounds[reference * size.y + row] = vec2<f32>(lo, hi);
}
