//! PNG plots of the report (the `plots` feature: plotters with system fonts). Without the
//! feature the report is written with its tables only.

/// One named series of (x, y) points.
pub type Series = (String, Vec<(f64, f64)>);

/// Axes of a plot.
#[cfg_attr(not(feature = "plots"), allow(dead_code))]
pub struct Axes<'a> {
    pub title: &'a str,
    pub x: &'a str,
    pub y: &'a str,
    pub log_x: bool,
    pub log_y: bool,
    /// Draw lines between points (else markers only).
    pub lines: bool,
}

#[cfg(not(feature = "plots"))]
pub fn draw(_path: &std::path::Path, _axes: &Axes, _series: &[Series]) -> anyhow::Result<bool> {
    Ok(false)
}

#[cfg(feature = "plots")]
pub fn draw(path: &std::path::Path, axes: &Axes, series: &[Series]) -> anyhow::Result<bool> {
    use plotters::prelude::*;

    let points: Vec<(f64, f64)> = series.iter().flat_map(|(_, p)| p.iter().copied()).collect();
    if points.is_empty() {
        return Ok(false);
    }
    let range = |values: Vec<f64>, log: bool| {
        let lo = values.iter().copied().fold(f64::MAX, f64::min);
        let hi = values.iter().copied().fold(f64::MIN, f64::max);
        if log {
            (lo * 0.8, hi * 1.25)
        } else {
            let pad = ((hi - lo) * 0.08).max(1e-9);
            (lo - pad, hi + pad)
        }
    };
    let (x0, x1) = range(points.iter().map(|p| p.0).collect(), axes.log_x);
    let (y0, y1) = range(points.iter().map(|p| p.1).collect(), axes.log_y);
    let root = BitMapBackend::new(path, (760, 480)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut builder = ChartBuilder::on(&root);
    builder
        .caption(axes.title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(64);
    macro_rules! finish {
        ($chart:expr) => {{
            let mut chart = $chart;
            chart
                .configure_mesh()
                .x_desc(axes.x)
                .y_desc(axes.y)
                .label_style(("sans-serif", 13))
                .draw()?;
            for (i, (name, pts)) in series.iter().enumerate() {
                let color = Palette99::pick(i).to_rgba();
                if axes.lines {
                    chart
                        .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))?
                        .label(name.as_str())
                        .legend(move |(x, y)| {
                            PathElement::new([(x, y), (x + 16, y)], color.stroke_width(2))
                        });
                    chart.draw_series(pts.iter().map(|p| Circle::new(*p, 3, color.filled())))?;
                } else {
                    chart
                        .draw_series(pts.iter().map(|p| Circle::new(*p, 4, color.filled())))?
                        .label(name.as_str())
                        .legend(move |(x, y)| Circle::new((x + 8, y), 4, color.filled()));
                }
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 13))
                .draw()?;
        }};
    }
    match (axes.log_x, axes.log_y) {
        (true, true) => {
            finish!(builder.build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())?)
        }
        (true, false) => finish!(builder.build_cartesian_2d((x0..x1).log_scale(), y0..y1)?),
        (false, true) => finish!(builder.build_cartesian_2d(x0..x1, (y0..y1).log_scale())?),
        (false, false) => finish!(builder.build_cartesian_2d(x0..x1, y0..y1)?),
    }
    root.present()?;
    super::note_written(path);
    Ok(true)
}

/// Add `point` to the series called `name`, starting it if there is none.
pub fn push(series: &mut Vec<Series>, name: &str, point: (f64, f64)) {
    match series.iter_mut().find(|x| x.0 == name) {
        Some(x) => x.1.push(point),
        None => series.push((name.to_string(), vec![point])),
    }
}
