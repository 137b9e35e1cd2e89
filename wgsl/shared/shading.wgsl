// Blinn-Phong with an eye-space directional light: the one shading every mesh path uses
// (N-pass, single view, single pass), so that images differ only by the method.
// Keep in sync with `LightUniform` in src/frame.rs.

struct Light {
    direction: vec4<f32>, // eye space, towards the light, unit length
    ambient: vec4<f32>,   // rgb intensity
    diffuse: vec4<f32>,   // rgb intensity
    specular: vec4<f32>,  // rgb intensity, w = shininess
}

// Shade a surface point `position` (eye space) with normal `normal` seen from the camera at
// eye-space `origin`. Two-sided: the normal is turned towards the viewer.
fn shade_blinn_phong(light: Light, normal: vec3<f32>, position: vec3<f32>, origin: vec3<f32>, base: vec3<f32>) -> vec3<f32> {
    let to_eye = normalize(origin - position);
    var n = normalize(normal);
    if (dot(n, to_eye) < 0.0) {
        n = -n;
    }
    let l = light.direction.xyz;
    let h = normalize(l + to_eye);
    let diffuse = max(dot(n, l), 0.0);
    let specular = pow(max(dot(n, h), 0.0), light.specular.w) * select(0.0, 1.0, diffuse > 0.0);
    return base * (light.ambient.rgb + light.diffuse.rgb * diffuse) + light.specular.rgb * specular;
}
