//! Rendering a [`Figure`] with plotters (feature `plot`): SVG and PNG from one description.
//!
//! Log axes are drawn in log₁₀ coordinates with labels `1e-6`, `1e-3`, …, which keeps one code
//! path for every combination of scales. Text uses the embedded DejaVu Sans (bitmap backends have
//! no system fonts here).

use super::{Figure, PALETTE, class_color};
use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::string::{String, ToString};
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

fn tick_label(v: f64, log: bool) -> String {
    if log {
        let r = v.round();
        if (v - r).abs() < 1e-9 {
            match r as i32 {
                0 => "1".to_string(),
                1 => "10".to_string(),
                -1 => "0.1".to_string(),
                k => std::format!("1e{k}"),
            }
        } else {
            String::new()
        }
    } else if v != 0.0 && v.abs() < 1e-2 {
        // Small speeds: mantissa and exponent, e.g. 2.5e-5.
        let s = std::format!("{v:.2e}");
        match s.split_once('e') {
            Some((m, e)) => {
                let m = m.trim_end_matches('0').trim_end_matches('.');
                std::format!("{m}e{e}")
            }
            None => s,
        }
    } else {
        let s = std::format!("{v:.3}");
        let s = s.trim_end_matches('0').trim_end_matches('.').to_string();
        if s == "-0" { "0".to_string() } else { s }
    }
}

/// How a legend entry shows its series.
#[derive(Clone, Copy)]
enum Swatch {
    /// A filled box (stick-map class, measured range) with its opacity.
    Box(RGBColor, f64),
    /// A line, dashed or solid.
    Line(RGBColor, bool),
}

/// The legend's entries in drawing order: map classes present, measured ranges, curves.
fn legend_entries(fig: &Figure) -> Vec<(String, Swatch)> {
    let mut out = Vec::new();
    if let Some(map) = &fig.map {
        for c in crate::tangential::StickClass::ALL {
            if map.classes.contains(&c) {
                out.push((c.label().to_string(), Swatch::Box(rgb(class_color(c)), 1.0)));
            }
        }
    }
    for band in &fig.bands {
        let color = rgb(PALETTE[band.color % PALETTE.len()]);
        out.push((band.label.clone(), Swatch::Box(color, 0.3)));
    }
    for s in &fig.series {
        let drawable = s.points.iter().any(|&(x, y)| {
            x.is_finite() && y.is_finite() && (!fig.x.log || x > 0.0) && (!fig.y.log || y > 0.0)
        });
        if drawable {
            let color = rgb(PALETTE[s.color % PALETTE.len()]);
            out.push((s.name.clone(), Swatch::Line(color, s.dashed)));
        }
    }
    out
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
            Some(Swatch::Line(color, dashed)) => {
                let style = color.stroke_width(if *dashed { 1 } else { 2 });
                if *dashed {
                    for x in [2, 10, 18] {
                        area.draw(&PathElement::new(vec![(x, y), (x + 5, y)], style))
                            .map_err(plot_err)?;
                    }
                } else {
                    area.draw(&PathElement::new(vec![(2, y), (22, y)], style))
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
    // fills its whole plot; curves reach every corner of a log chart).
    let entries = legend_entries(fig);
    let width = body.dim_in_pixel().0 as i32;
    let (label_width, legend_lines) = wrap_legend(&entries, (width as f64 * 0.3) as usize / 7);
    let legend_width = if entries.is_empty() {
        0
    } else {
        (7 * label_width as i32 + 40).min(width * 2 / 5)
    };
    let (plot_area, legend_area) = body.split_horizontally(width - legend_width);
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(&fig.title, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(56)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(plot_err)?;
    let (xl, yl) = (fig.x.log, fig.y.log);
    let x_ticks = if xl {
        ((x1 - x0).round() as usize).clamp(2, 20) + 1
    } else {
        6
    };
    chart
        .configure_mesh()
        .x_desc(fig.x.label.as_str())
        .y_desc(fig.y.label.as_str())
        .x_labels(x_ticks)
        .y_labels(if yl {
            ((y1 - y0).round() as usize).clamp(2, 20) + 1
        } else {
            6
        })
        .x_label_formatter(&|v| tick_label(*v, xl))
        .y_label_formatter(&|v| tick_label(*v, yl))
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(plot_err)?;

    if let Some(map) = &fig.map {
        let n = map.g.len();
        let step = if n > 1 { map.g[1] - map.g[0] } else { 1.0 };
        for i in 0..n {
            for j in 0..n {
                let Some(c) = map.classes.get(i * n + j) else {
                    continue;
                };
                let (gx, gy) = (map.g[j], map.g[i]);
                let rect = Rectangle::new(
                    [
                        (
                            to_axis((gx - step / 2.0).max(fig.x.min), xl),
                            to_axis((gy - step / 2.0).max(fig.y.min), yl),
                        ),
                        (
                            to_axis((gx + step / 2.0).min(fig.x.max), xl),
                            to_axis((gy + step / 2.0).min(fig.y.max), yl),
                        ),
                    ],
                    rgb(class_color(*c)).filled(),
                );
                chart.draw_series(std::iter::once(rect)).map_err(plot_err)?;
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
            stroke_width: if s.dashed { 1 } else { 2 },
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
        let mut first = true;
        for seg in segments.into_iter().filter(|seg| seg.len() > 1) {
            let drawn = if s.dashed {
                chart
                    .draw_series(DashedLineSeries::new(seg, 6, 4, style))
                    .map_err(plot_err)?
            } else {
                chart
                    .draw_series(LineSeries::new(seg, style))
                    .map_err(plot_err)?
            };
            if first {
                drawn
                    .label(s.name.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
                first = false;
            }
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
