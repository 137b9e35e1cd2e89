// Per-triangle data made by mesh/single_pass_cover.wgsl for the single-pass mesh stages (group 1, bindings
// 2 and 3, read-only here). Keep in sync with src/mesh/passes/single_pass/.
#import mesh/shared/eye_triangle.wgsl

