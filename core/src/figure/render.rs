//! Rendering a [`Figure`] with plotters (feature `plot`): SVG and PNG from one description.
//!
//! Log axes are drawn in log₁₀ coordinates with labels `1e-6`, `1e-3`, …, which keeps one code
//! path for every combination of scales. Text uses the embedded DejaVu Sans (bitmap backends have
//! no system fonts here).

use super::{Figure, PALETTE, Stroke, class_color};
use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::format;
use std::string::String;
use std::vec;
use std::vec::Vec;

static FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");

fn plot_err<E>(_: E) -> Error {
    Error::Plot {
        reason: "drawing backend error",
    }
}

fn ensure_font() -> Result<()> {
    use std::sync::OnceLock;
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font("sans-serif", FontStyle::Normal, FONT).is_ok()
    });
    if ok {
        Ok(())
    } else {
        Err(Error::Plot {
            reason: "the embedded font could not be registered",
        })
    }
}

fn rgb(c: (u8, u8, u8)) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

fn to_axis(v: f64, log: bool) -> f64 {
    if log { v.log10() } else { v }
}

pub use super::IMAGE_LABELS;

/// The axis' key points in drawing coordinates (log₁₀ on log axes) and their labels, from the
/// core's one axis description ([`super::Axis::ticks`]).
fn key_points(axis: &super::Axis) -> (Vec<f64>, Vec<f64>, Vec<(f64, String)>) {
    let mut bold = Vec::new();
    let mut light = Vec::new();
    let mut labels = Vec::new();
    for t in axis.ticks(IMAGE_LABELS) {
        let v = to_axis(t.value, axis.log);
        match t.label {
            Some(l) => {
                bold.push(v);
                labels.push((v, l));
            }
            None => light.push(v),
        }
    }
    (bold, light, labels)
}

/// A linear coordinate in drawing units with the core's ticks as its key points (plotters'
/// `WithKeyPoints` over `f64` cannot take a label formatter).
struct Keyed {
    inner: plotters::coord::types::RangedCoordf64,
    bold: Vec<f64>,
    light: Vec<f64>,
}

impl Keyed {
    fn new(range: std::ops::Range<f64>, (bold, light): (Vec<f64>, Vec<f64>)) -> Keyed {
        Keyed {
            inner: range.into(),
            bold,
            light,
        }
    }
}

impl plotters::coord::ranged1d::Ranged for Keyed {
    type ValueType = f64;
    type FormatOption = plotters::coord::ranged1d::DefaultFormatting;

    fn range(&self) -> std::ops::Range<f64> {
        self.inner.range()
    }

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }

    fn key_points<H: plotters::coord::ranged1d::KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.light.clone()
        } else {
            self.bold.clone()
        }
    }
}

/// The label of key point `v` (the nearest one: the mesh hands back the values it was given).
fn label_at(labels: &[(f64, String)], v: f64) -> String {
    labels
        .iter()
        .min_by(|a, b| (a.0 - v).abs().total_cmp(&(b.0 - v).abs()))
        .filter(|(k, _)| (k - v).abs() < 1e-9 * (1.0 + v.abs()))
        .map(|(_, l)| l.clone())
        .unwrap_or_default()
}

/// How a legend entry shows its series.
#[derive(Clone, Copy)]
enum Swatch {
    /// A filled box (stick-map class, measured range) with its opacity.
    Box(RGBColor, f64),
    /// A line drawn with its stroke.
    Line(RGBColor, Stroke),
    /// A marker: the short vertical dashed line the plot draws at its speed.
    Marker(RGBColor),
}

/// The legend's entries in drawing order: map classes present, measured ranges, curves; each with
/// its full text and its short one.
fn legend_entries(fig: &Figure) -> Vec<(String, String, Swatch)> {
    let mut out = Vec::new();
    if let Some(map) = &fig.map {
        for c in crate::tangential::StickClass::ALL {
            if map.classes.contains(&c) {
                out.push((
                    String::from(c.label()),
                    String::from(c.label()),
                    Swatch::Box(rgb(class_color(c)), 1.0),
                ));
            }
        }
    }
    for band in &fig.bands {
        let color = rgb(PALETTE[band.color % PALETTE.len()]);
        out.push((
            band.label.clone(),
            band.short.clone(),
            Swatch::Box(color, 0.3),
        ));
    }
    for s in &fig.series {
        let drawable = s.points.iter().any(|&(x, y)| {
            x.is_finite() && y.is_finite() && (!fig.x.log || x > 0.0) && (!fig.y.log || y > 0.0)
        });
        if drawable {
            let color = rgb(PALETTE[s.color % PALETTE.len()]);
            out.push((
                s.name.clone(),
                s.short.clone(),
                Swatch::Line(color, s.stroke),
            ));
        }
    }
    // Every marker the plot draws (those inside the x range) is explained, as on screen.
    for m in fig
        .markers
        .iter()
        .filter(|m| m.x > fig.x.min && m.x < fig.x.max)
    {
        let color = rgb(PALETTE[m.color % PALETTE.len()]);
        out.push((m.label.clone(), m.short.clone(), Swatch::Marker(color)));
    }
    out
}

/// The legend's lines within `rows` lines of `max_chars`: every full text wrapped (never cut) when
/// they fit, else the short texts (a figure with every comparison on: the full citations are in
/// the caption's sources and the records), else as many entries as fit and a last line saying how
/// many are left out. Returns the widest line and the lines.
fn fit_legend(
    entries: &[(String, String, Swatch)],
    max_chars: usize,
    rows: usize,
) -> (usize, Vec<(String, Option<Swatch>)>) {
    let full: Vec<(String, Swatch)> = entries.iter().map(|(n, _, s)| (n.clone(), *s)).collect();
    let (w, lines) = wrap_legend(&full, max_chars);
    if lines.len() <= rows {
        return (w, lines);
    }
    let short: Vec<(String, Swatch)> = entries.iter().map(|(_, n, s)| (n.clone(), *s)).collect();
    let (w, mut lines) = wrap_legend(&short, max_chars);
    if lines.len() > rows {
        // Whole entries only (never a label's first half), then how many are left out.
        let keep = rows.saturating_sub(1);
        let starts: Vec<usize> = (0..lines.len()).filter(|&k| lines[k].1.is_some()).collect();
        let (mut end, mut shown) = (0, 0);
        for (i, _) in starts.iter().enumerate() {
            let stop = starts.get(i + 1).copied().unwrap_or(lines.len());
            if stop > keep {
                break;
            }
            end = stop;
            shown += 1;
        }
        lines.truncate(end);
        lines.push((format!("… and {} more", entries.len() - shown), None));
    }
    (w, lines)
}

/// The legend's lines: each label wrapped at word boundaries to at most `max_chars` characters
/// (never cut), the swatch on its first line. Returns the widest line and the lines.
fn wrap_legend(
    entries: &[(String, Swatch)],
    max_chars: usize,
) -> (usize, Vec<(String, Option<Swatch>)>) {
    let max_chars = max_chars.max(16);
    let mut lines = Vec::new();
    let mut widest = 0;
    for (label, swatch) in entries {
        let mut current = String::new();
        let mut first = true;
        for word in label.split_whitespace() {
            if !current.is_empty() && current.chars().count() + 1 + word.chars().count() > max_chars
            {
                widest = widest.max(current.chars().count());
                lines.push((core::mem::take(&mut current), first.then_some(*swatch)));
                first = false;
            }
            if !current.is_empty() {
                current.push(' ');
            }
            current.push_str(word);
        }
        widest = widest.max(current.chars().count());
        lines.push((current, first.then_some(*swatch)));
    }
    (widest, lines)
}

/// The legend's sample of `stroke` as segments, offsets from the line's left end and middle
/// \[px\]: a line, dashes, dots, or for points the diagonal cross the plot draws at each point.
fn legend_sample(stroke: Stroke) -> Vec<[(i32, i32); 2]> {
    let flat = |parts: &[[i32; 2]]| parts.iter().map(|&[a, b]| [(a, 0), (b, 0)]).collect();
    match stroke {
        Stroke::Solid => flat(&[[2, 22]]),
        Stroke::Dashed => flat(&[[2, 8], [11, 17], [20, 24]]),
        Stroke::Dotted => flat(&[[2, 4], [7, 9], [12, 14], [17, 19], [22, 24]]),
        Stroke::Points => vec![[(8, -4), (16, 4)], [(8, 4), (16, -4)]],
        Stroke::LongDash => flat(&[[2, 16], [20, 24]]),
    }
}

fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    lines: &[(String, Option<Swatch>)],
) -> Result<()> {
    let top = 44;
    for (k, (text, swatch)) in lines.iter().enumerate() {
        let y = top + 16 * k as i32;
        match swatch {
            Some(Swatch::Box(color, alpha)) => {
                area.draw(&Rectangle::new(
                    [(4, y - 5), (20, y + 6)],
                    color.mix(*alpha).filled(),
                ))
                .map_err(plot_err)?;
            }
            Some(Swatch::Line(color, stroke)) => {
                let style = color.stroke_width(if *stroke == Stroke::Solid { 2 } else { 1 });
                // A sample of the stroke: a line, dashes, dots, or for points the plot's own
                // glyph, a diagonal cross × (plotters' `Cross`), never an upright +.
                for segment in legend_sample(*stroke) {
                    let path: Vec<(i32, i32)> =
                        segment.iter().map(|&(dx, dy)| (dx, y + dy)).collect();
                    area.draw(&PathElement::new(path, style))
                        .map_err(plot_err)?;
                }
            }
            Some(Swatch::Marker(color)) => {
                for (a, b) in [(-7, -4), (-1, 2), (5, 8)] {
                    area.draw(&PathElement::new(
                        vec![(12, y + a), (12, y + b)],
                        color.stroke_width(1),
                    ))
                    .map_err(plot_err)?;
                }
            }
            None => {}
        }
        area.draw(&Text::new(
            text.clone(),
            (28, y - 7),
            ("sans-serif", 13).into_font().color(&BLACK),
        ))
        .map_err(plot_err)?;
    }
    Ok(())
}

// Long by design: one plotters drawing pass in paint order (map, bands, series, markers, legend,
// caption); split, each part would need the chart's whole coordinate state.
fn draw<DB: DrawingBackend>(fig: &Figure, root: DrawingArea<DB, Shift>) -> Result<()> {
    root.fill(&WHITE).map_err(plot_err)?;
    // Caption: wrapped over at most five lines; the figure gives up the height they need.
    let words: Vec<&str> = fig.caption.split_whitespace().collect();
    let width_chars = (root.dim_in_pixel().0 as usize / 7).max(40);
    let mut lines = vec![String::new()];
    for w in words {
        let too_long = lines
            .last()
            .is_some_and(|l| l.chars().count() + w.chars().count() + 1 > width_chars);
        if too_long {
            if lines.len() == 5 {
                if let Some(l) = lines.last_mut() {
                    l.push_str(" …");
                }
                break;
            }
            lines.push(String::new());
        }
        if let Some(l) = lines.last_mut() {
            if !l.is_empty() {
                l.push(' ');
            }
            l.push_str(w);
        }
    }
    let caption_height = 14 * lines.len() as i32 + 8;
    let (body, caption_area) = root.split_vertically(root.dim_in_pixel().1 as i32 - caption_height);
    let (x0, x1) = (
        to_axis(
            fig.x.min.max(if fig.x.log { 1e-300 } else { f64::MIN }),
            fig.x.log,
        ),
        to_axis(fig.x.max, fig.x.log),
    );
    let (y0, y1) = (
        to_axis(
            fig.y.min.max(if fig.y.log { 1e-300 } else { f64::MIN }),
            fig.y.log,
        ),
        to_axis(fig.y.max, fig.y.log),
    );
    // The legend sits in its own column right of the plot, so it never covers data (a stick map
    // fills its whole plot; curves reach every corner of a log chart). Surfaces without that room
    // (a terminal pane) place it with `Figure::legend_corner` instead.
    let entries = legend_entries(fig);
    let width = body.dim_in_pixel().0 as i32;
    let rows = ((body.dim_in_pixel().1 as i32 - 44 - 8) / 16).max(1) as usize;
    let (label_width, legend_lines) = fit_legend(&entries, (width as f64 * 0.3) as usize / 7, rows);
    let legend_width = if entries.is_empty() {
        0
    } else {
        (7 * label_width as i32 + 40).min(width * 2 / 5)
    };
    let (plot_area, legend_area) = body.split_horizontally(width - legend_width);
    let (x_bold, x_light, x_labels) = key_points(&fig.x);
    let (y_bold, y_light, y_labels) = key_points(&fig.y);
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(&fig.title, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(56)
        .build_cartesian_2d(
            Keyed::new(x0..x1, (x_bold, x_light)),
            Keyed::new(y0..y1, (y_bold, y_light)),
        )
        .map_err(plot_err)?;
    let (xl, yl) = (fig.x.log, fig.y.log);
    chart
        .configure_mesh()
        .x_desc(fig.x.label.as_str())
        .y_desc(fig.y.label.as_str())
        .x_label_formatter(&|v| label_at(&x_labels, *v))
        .y_label_formatter(&|v| label_at(&y_labels, *v))
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(plot_err)?;

    if let Some(map) = &fig.map {
        let n = map.g.len();
        let step = if n > 1 { map.g[1] - map.g[0] } else { 1.0 };
        for i in 0..n {
            // One rectangle per run of equal cells along the row (issue 37 X1: a rectangle per
            // cell made each stick-map SVG 2.2 MB); the same picture.
            let mut j = 0;
            while j < n {
                let Some(c) = map.classes.get(i * n + j) else {
                    j += 1;
                    continue;
                };
                let mut end = j;
                while end + 1 < n && map.classes.get(i * n + end + 1) == Some(c) {
                    end += 1;
                }
                let (gx0, gx1, gy) = (map.g[j], map.g[end], map.g[i]);
                let rect = Rectangle::new(
                    [
                        (
                            to_axis((gx0 - step / 2.0).max(fig.x.min), xl),
                            to_axis((gy - step / 2.0).max(fig.y.min), yl),
                        ),
                        (
                            to_axis((gx1 + step / 2.0).min(fig.x.max), xl),
                            to_axis((gy + step / 2.0).min(fig.y.max), yl),
                        ),
                    ],
                    rgb(class_color(*c)).filled(),
                );
                chart.draw_series(std::iter::once(rect)).map_err(plot_err)?;
                j = end + 1;
            }
        }
        // Legend of the classes present.
        for c in crate::tangential::StickClass::ALL {
            if map.classes.contains(&c) {
                let color = rgb(class_color(c));
                chart
                    .draw_series(std::iter::empty::<Rectangle<(f64, f64)>>())
                    .map_err(plot_err)?
                    .label(c.name())
                    .legend(move |(x, y)| {
                        Rectangle::new([(x, y - 6), (x + 14, y + 6)], color.filled())
                    });
            }
        }
    }

    for band in &fig.bands {
        let color = rgb(PALETTE[band.color % PALETTE.len()]);
        let rect = Rectangle::new(
            [
                (to_axis(band.x.0, xl), to_axis(band.y.0, yl)),
                (to_axis(band.x.1, xl), to_axis(band.y.1, yl)),
            ],
            color.mix(0.18).filled(),
        );
        chart
            .draw_series(std::iter::once(rect))
            .map_err(plot_err)?
            .label(band.label.as_str())
            .legend(move |(x, y)| {
                Rectangle::new([(x, y - 6), (x + 14, y + 6)], color.mix(0.3).filled())
            });
    }

    for s in &fig.series {
        let color = rgb(PALETTE[s.color % PALETTE.len()]);
        let style = ShapeStyle {
            color: color.to_rgba(),
            filled: false,
            stroke_width: if s.stroke == Stroke::Solid { 2 } else { 1 },
        };
        // Split at points that cannot be drawn (outside a log axis).
        let mut segments: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
        for &(x, y) in &s.points {
            let ok = x.is_finite() && y.is_finite() && (!xl || x > 0.0) && (!yl || y > 0.0);
            if ok {
                if let Some(seg) = segments.last_mut() {
                    seg.push((to_axis(x, xl), to_axis(y, yl)));
                }
            } else if segments.last().is_some_and(|seg| !seg.is_empty()) {
                segments.push(Vec::new());
            }
        }
        let stroke = s.stroke;
        let min_len = if stroke == Stroke::Points { 1 } else { 2 };
        for seg in segments.into_iter().filter(|seg| seg.len() >= min_len) {
            match stroke {
                Stroke::Solid => chart
                    .draw_series(LineSeries::new(seg, style))
                    .map_err(plot_err)?,
                Stroke::Dashed => chart
                    .draw_series(DashedLineSeries::new(seg, 6, 4, style))
                    .map_err(plot_err)?,
                Stroke::Dotted => chart
                    .draw_series(DashedLineSeries::new(seg, 2, 3, style))
                    .map_err(plot_err)?,
                Stroke::Points => chart
                    .draw_series(seg.into_iter().map(|p| Cross::new(p, 4, style)))
                    .map_err(plot_err)?,
                Stroke::LongDash => chart
                    .draw_series(DashedLineSeries::new(seg, 14, 4, style))
                    .map_err(plot_err)?,
            };
        }
    }

    for m in &fig.markers {
        if !(m.x > fig.x.min && m.x < fig.x.max) {
            continue;
        }
        let color = rgb(PALETTE[m.color % PALETTE.len()]);
        let x = to_axis(m.x, xl);
        chart
            .draw_series(DashedLineSeries::new(
                vec![(x, y0), (x, y1)],
                3,
                3,
                color.stroke_width(1),
            ))
            .map_err(plot_err)?;
    }

    draw_legend(&legend_area, &legend_lines)?;

    for (k, l) in lines.iter().enumerate() {
        caption_area
            .draw(&Text::new(
                l.clone(),
                (12, 2 + 14 * k as i32),
                ("sans-serif", 12).into_font().color(&RGBColor(60, 60, 60)),
            ))
            .map_err(plot_err)?;
    }
    root.present().map_err(plot_err)?;
    Ok(())
}

/// Renders `fig` as an SVG document of `width × height` pixels.
pub fn render_svg(fig: &Figure, width: u32, height: u32) -> Result<String> {
    ensure_font()?;
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (width, height)).into_drawing_area();
        draw(fig, root)?;
    }
    Ok(out)
}

/// Renders `fig` as a PNG file of `width × height` pixels at `path`.
pub fn render_png(fig: &Figure, path: &std::path::Path, width: u32, height: u32) -> Result<()> {
    ensure_font()?;
    let root = BitMapBackend::new(path, (width, height)).into_drawing_area();
    draw(fig, root)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::ToString;

    /// Issue 37 item 7: the legend's sample of a point series is the glyph the plot draws at each
    /// point, plotters' `Cross`: two diagonals of equal slope magnitude through one centre (an
    /// upright `+` has a horizontal and a vertical stroke).
    #[test]
    fn issue_37_the_points_legend_is_the_plotted_cross() {
        let sample = legend_sample(Stroke::Points);
        assert_eq!(sample.len(), 2);
        let centre = |[(x0, y0), (x1, y1)]: [(i32, i32); 2]| (x0 + x1, y0 + y1);
        assert_eq!(centre(sample[0]), centre(sample[1]));
        let mut slopes = Vec::new();
        for [(x0, y0), (x1, y1)] in sample {
            let (dx, dy) = (x1 - x0, y1 - y0);
            assert!(dx != 0 && dy != 0, "a horizontal or vertical stroke: not ×");
            assert_eq!(dx.abs(), dy.abs(), "a 45° diagonal, as Cross draws");
            slopes.push(dx.signum() * dy.signum());
        }
        assert_ne!(slopes[0], slopes[1], "the two diagonals cross");
    }

    /// Issue 37 item 7: every marker the plot draws (inside the x range) has a legend entry.
    #[test]
    fn issue_37_markers_are_in_the_legend() {
        let axis = |label: &str| super::super::Axis {
            label: label.to_string(),
            log: false,
            min: 1.0,
            max: 10.0,
        };
        let mut fig = Figure {
            name: "t".to_string(),
            title: String::new(),
            caption: String::new(),
            x: axis("x"),
            y: axis("y"),
            series: Vec::new(),
            markers: Vec::new(),
            bands: Vec::new(),
            map: None,
        };
        fig.markers.push(super::super::Marker {
            x: 3.0,
            label: "g_s inside".to_string(),
            short: "g_s".to_string(),
            color: 1,
        });
        fig.markers.push(super::super::Marker {
            x: 30.0,
            label: "outside the axis".to_string(),
            short: "out".to_string(),
            color: 1,
        });
        let names: Vec<String> = legend_entries(&fig).into_iter().map(|e| e.0).collect();
        assert_eq!(names, ["g_s inside"]);
    }
}
