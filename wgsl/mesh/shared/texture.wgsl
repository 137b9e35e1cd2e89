// Base-colour textures (src/mesh/texture_buffers.rs), sampled the same way by every mesh method:
// the single pass at its ray hits' barycentric texture coordinates, the rasterised baselines at
// their perspective-correct interpolated ones. Bilinear (or nearest) in linear colour, each
// texture wrapped at its own edges, no mipmaps (src/mesh/texture.rs says why). Reads
// `mesh_texels` and `mesh_textures`, which the stage files declare as group 3.

// Keep in sync with `GpuTexture` in src/mesh/texture_buffers.rs.
struct MeshTexture {
    offset: u32,
    width: u32,
    height: u32,
    wrap_u: u32,
    wrap_v: u32,
    filtering: u32,
    _pad0: u32,
    _pad1: u32,
}

const NO_TEXTURE: u32 = 0xffffffffu;
// False for a mesh without textures: the sampling is compiled out. (A software rasteriser runs
// both sides of a branch under a mask, so the untaken texture fetches would cost every mesh
// 1.5–3×; src/mesh/scene.rs's `textured` sets it.)
override TEXTURED: bool = true;
const WRAP_CLAMP: u32 = 1u;
const WRAP_MIRROR: u32 = 2u;
const FILTER_NEAREST: u32 = 0u;

// Texel index i of a row or column of n texels, wrapped by `mode` (repeat by default).
fn wrap_texel(i: i32, n: i32, mode: u32) -> i32 {
    if (mode == WRAP_CLAMP) {
        return clamp(i, 0, n - 1);
    }
    if (mode == WRAP_MIRROR) {
        let period = 2 * n;
        let m = ((i % period) + period) % period;
        return select(m, period - 1 - m, m >= n);
    }
    return ((i % n) + n) % n;
}

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    return select(pow((c + 0.055) / 1.055, vec3<f32>(2.4)), c / 12.92, c <= vec3<f32>(0.04045));
}

// Linear colour of texel (x, y) of `t`, wrapped.
fn texel(t: MeshTexture, x: i32, y: i32) -> vec3<f32> {
    let size = vec2<i32>(i32(t.width), i32(t.height));
    let xi = u32(wrap_texel(x, size.x, t.wrap_u));
    let yi = u32(wrap_texel(y, size.y, t.wrap_v));
    let packed = mesh_texels[t.offset + yi * t.width + xi];
    return srgb_to_linear(unpack4x8unorm(packed).rgb);
}

// The colour texture `id` gives texture coordinate `uv` ((0, 0) the image's top-left corner);
// white for NO_TEXTURE, so untextured vertices keep their colour.
fn texture_color(id: u32, uv: vec2<f32>) -> vec3<f32> {
    if (!TEXTURED || id == NO_TEXTURE) {
        return vec3<f32>(1.0);
    }
    let t = mesh_textures[id];
    let size = vec2<f32>(f32(t.width), f32(t.height));
    // Far outside 0..1 the float texel position has no fraction left; keep the integers exact.
    let s = clamp(uv * size, vec2<f32>(-8.0e6), vec2<f32>(8.0e6));
    if (t.filtering == FILTER_NEAREST) {
        let p = vec2<i32>(floor(s));
        return texel(t, p.x, p.y);
    }
    let centred = s - 0.5;
    let base = floor(centred);
    let f = centred - base;
    let p = vec2<i32>(base);
    let top = mix(texel(t, p.x, p.y), texel(t, p.x + 1, p.y), f.x);
    let bottom = mix(texel(t, p.x, p.y + 1), texel(t, p.x + 1, p.y + 1), f.x);
    return mix(top, bottom, f.y);
}
