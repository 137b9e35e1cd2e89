// The tiled method's copy of a vertex for one view (de Sorbier et al.): the view's camera, then
// moved into the view's tile of the quilt atlas (shared/quilt.wgsl). Reads `frame`, `views`
// and `quilt`.

struct TiledVertex {
    view: ViewVertex,
    // View-space clip distances to the tile's four edges (≥ 0 inside): x ≥ −w, x ≤ w, y ≥ −w,
    // y ≤ w of the view's own clip position.
    edges: array<f32, 4>,
}

fn tiled_vertex(v: VertexIn, view: u32) -> TiledVertex {
    var o = view_vertex(v, views[view]);
    let c = o.clip;
    let edges = array<f32, 4>(c.w + c.x, c.w - c.x, c.w + c.y, c.w - c.y);
    o.clip = quilt_clip(quilt, view, c);
    return TiledVertex(o, edges);
}
