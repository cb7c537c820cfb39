//! The one adapter from the core's figure descriptions ([`rime_core::figure::Figure`]) to the
//! terminal: series by their role's colour and their stroke, bands, markers, axes with the core's
//! ticks and labels, and the legend; and the one mapping of the palette to terminal colours
//! ([`Colors::color`]), which degrades to the 16 ANSI colours and to none (`NO_COLOR`), where the
//! strokes and marks carry every difference (in [`crate::explore::colors`], re-exported). What
//! this draws is what `x` exports.

pub use crate::explore::colors::Colors;
use crate::explore::layout::LogAxis;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker as Dots;
use ratatui::widgets::Widget;
use ratatui::widgets::canvas::{Canvas, Line as CanvasLine};
use rime_core::explorer::palette::{self, Rgb};
use rime_core::figure::{Axis, Corner, Figure, Stroke};

/// A series' colour: its role in the one palette.
pub fn series_rgb(index: usize) -> Rgb {
    palette::SERIES[index % palette::SERIES.len()]
}

/// The legend's sample of a stroke.
pub fn swatch(stroke: Stroke) -> &'static str {
    match stroke {
        Stroke::Solid => "━━",
        Stroke::Dashed => "╍╍",
        Stroke::Dotted => "┈┈",
        Stroke::Points => "×",
        Stroke::LongDash => "━╺",
    }
}

/// Marks that tell series apart without colour (drawn along a line that shares its stroke with
/// another series).
const TAGS: [char; 10] = ['○', '△', '□', '◇', '▽', '☆', '+', '*', '#', '%'];

/// How the figure is drawn.
#[derive(Debug, Clone, Copy)]
pub struct Options {
    /// The terminal's colours.
    pub colors: Colors,
    /// A vertical cursor at this x value.
    pub cursor: Option<f64>,
    /// Most rows the legend may take above the plot when it does not fit inside it.
    pub legend_rows: u16,
    /// The series drawn bold (this scene's curve).
    pub bold: Option<usize>,
    /// Whether the y axis' title gets a row above the graph at any height (else only on tall
    /// plots: the ε_N chart's pane title names its axis).
    pub y_title: bool,
}

/// One legend entry.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// Swatch (stroke sample, band or marker glyph, and the tag without colour).
    pub swatch: String,
    /// The core's short label.
    pub text: String,
    /// Its colour.
    pub rgb: Rgb,
    /// Further members of a group, each its value and colour (`η* = 500 Pa s  1 kPa s  2 kPa s`:
    /// series whose labels share `symbol = ` and a stroke).
    pub more: Vec<(String, Rgb)>,
}

impl Entry {
    /// Width in cells.
    pub fn width(&self) -> usize {
        self.swatch.chars().count()
            + 1
            + self.text.chars().count()
            + self
                .more
                .iter()
                .map(|(t, _)| 1 + t.chars().count())
                .sum::<usize>()
    }
}

/// The legend of `fig`, most telling first (a short legend drops the end): this scene, the
/// pinned curve, the markers, the comparisons, the other series in draw order, the bands.
pub fn legend(fig: &Figure, tags: &[Option<char>]) -> Vec<Entry> {
    let rank = |i: usize| {
        let s = &fig.series[i];
        if s.color == palette::SERIES_SCENE && s.stroke == Stroke::Solid {
            0
        } else if s.color == palette::SERIES_PINNED {
            1
        } else if s.color >= palette::SERIES_OVERLAY {
            2
        } else {
            3
        }
    };
    let mut order: Vec<usize> = (0..fig.series.len()).collect();
    order.sort_by_key(|&i| rank(i));
    let lead = order.iter().take_while(|&&i| rank(i) < 2).count();
    let entry = |i: usize| {
        let s = &fig.series[i];
        let tag = tags.get(i).copied().flatten();
        Entry {
            swatch: match tag {
                Some(t) => format!("{}{t}", swatch(s.stroke)),
                None => swatch(s.stroke).to_string(),
            },
            text: s.short.clone(),
            rgb: series_rgb(s.color),
            more: Vec::new(),
        }
    };
    // Consecutive series of one stroke labelled `symbol = value` share one entry (without colour
    // each keeps its own, tagged, entry).
    let group = |entries: Vec<Entry>| -> Vec<Entry> {
        let mut out: Vec<Entry> = Vec::new();
        for e in entries {
            let prefix = |t: &str| t.split_once(" = ").map(|(p, _)| p.to_string());
            if let Some(last) = out.last_mut()
                && last.swatch == e.swatch
                && prefix(&last.text).is_some()
                && prefix(&last.text) == prefix(&e.text)
                && let Some((_, value)) = e.text.split_once(" = ")
            {
                last.more.push((value.to_string(), e.rgb));
                continue;
            }
            out.push(e);
        }
        out
    };
    let mut out: Vec<Entry> = order.iter().take(lead).map(|&i| entry(i)).collect();
    out.extend(fig.markers.iter().map(|m| Entry {
        swatch: "┊".to_string(),
        text: m.short.clone(),
        rgb: series_rgb(m.color),
        more: Vec::new(),
    }));
    let bands = fig.bands.iter().map(|b| Entry {
        swatch: "▭".to_string(),
        text: b.short.clone(),
        rgb: series_rgb(b.color),
        more: Vec::new(),
    });
    // With comparisons, their ranges (bands) follow their laws; else the bands come last.
    let compared = order.iter().filter(|&&i| rank(i) == 2).count();
    out.extend(order.iter().skip(lead).take(compared).map(|&i| entry(i)));
    if compared > 0 {
        out.extend(bands.clone());
    }
    out.extend(group(
        order
            .iter()
            .skip(lead + compared)
            .map(|&i| entry(i))
            .collect(),
    ));
    if compared == 0 {
        out.extend(bands);
    }
    out
}

/// Where a figure went on screen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drawn {
    /// The graph's cells (inside the axes).
    pub graph: Rect,
    /// The x axis in drawing units (log₁₀ on a log axis), for mouse hits.
    pub x_axis: LogAxis,
}

/// `v` in drawing units (log₁₀ on a log axis).
fn unit(axis: &Axis, v: f64) -> Option<f64> {
    if axis.log {
        (v > 0.0 && v.is_finite()).then(|| v.log10())
    } else {
        v.is_finite().then_some(v)
    }
}

/// The row of `v` on a graph of `rows` rows from `top`, as ratatui's canvas draws it (four dots a
/// cell, rounded): tick labels sit on the row their value is drawn on.
fn row_of(v: f64, lo: f64, hi: f64, top: u16, rows: u16) -> Option<u16> {
    let dots = f64::from(rows) * 4.0 - 1.0;
    let d = ((hi - v) * dots / (hi - lo)).round();
    (d >= 0.0 && d <= dots).then(|| top + (d as u16) / 4)
}

/// Splits a polyline (drawing units) into the pieces a stroke draws: dashes of two cells with a
/// one-cell gap, dots of half a cell every cell and a half, or the whole line.
fn pieces(pts: &[(f64, f64)], stroke: Stroke, scale: (f64, f64)) -> Vec<((f64, f64), (f64, f64))> {
    let (on, off) = match stroke {
        Stroke::Dashed => (2.0, 1.0),
        Stroke::Dotted => (0.5, 1.0),
        Stroke::LongDash => (3.5, 1.0),
        _ => (f64::INFINITY, 0.0),
    };
    let mut out = Vec::new();
    let mut phase = 0.0;
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        // Length in cells (a cell is about twice as tall as wide: y counts double).
        let len = ((b.0 - a.0) * scale.0).hypot((b.1 - a.1) * scale.1 * 2.0);
        if !len.is_finite() || len == 0.0 {
            continue;
        }
        let mut s = 0.0;
        while s < len {
            let in_on = phase < on;
            let left = if in_on { on - phase } else { on + off - phase };
            let step = left.min(len - s);
            if in_on {
                let (t0, t1) = (s / len, (s + step) / len);
                let p = |t: f64| (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
                out.push((p(t0), p(t1)));
            }
            s += step;
            phase += step;
            if phase >= on + off {
                phase = 0.0;
            }
        }
    }
    out
}

/// The tags of series that share a stroke with another (only without colour: with colour, colour
/// and stroke tell every pair apart).
pub fn tags(fig: &Figure, colors: Colors) -> Vec<Option<char>> {
    let mut next = 0;
    fig.series
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let shared = fig
                .series
                .iter()
                .enumerate()
                .any(|(j, t)| j != i && t.stroke == s.stroke);
            if colors == Colors::None && shared && s.stroke != Stroke::Points {
                let t = TAGS[next % TAGS.len()];
                next += 1;
                Some(t)
            } else {
                None
            }
        })
        .collect()
}

/// Lays out legend entries in rows of at most `width` cells; entries that do not fit in `rows`
/// rows are counted, not drawn.
fn flow(entries: &[Entry], width: u16, rows: u16) -> (Vec<Vec<usize>>, usize) {
    let mut lines: Vec<Vec<usize>> = vec![Vec::new()];
    let mut used = 0usize;
    let mut left_out = 0;
    for (k, e) in entries.iter().enumerate() {
        let w = e.width() + 2;
        if used > 0 && used + w > width as usize {
            if lines.len() as u16 >= rows {
                left_out = entries.len() - k;
                break;
            }
            lines.push(Vec::new());
            used = 0;
        }
        if let Some(l) = lines.last_mut() {
            l.push(k);
        }
        used += w;
    }
    (lines, left_out)
}

fn put_entry(buf: &mut Buffer, x: u16, y: u16, e: &Entry, max_x: u16, colors: Colors) -> u16 {
    let style = colors.fg(e.rgb);
    let mut x = x;
    for (text, st) in [
        (e.swatch.as_str(), style),
        (" ", Style::new()),
        (e.text.as_str(), style),
    ] {
        if x >= max_x {
            break;
        }
        let room = (max_x - x) as usize;
        // A text cut at the pane's edge ends in `…` (issue 37: legends were cut silently).
        let (nx, _) = if text.chars().count() > room && room > 1 {
            let cut: String = text.chars().take(room - 1).collect();
            buf.set_stringn(x, y, cut + "…", room, st)
        } else {
            buf.set_stringn(x, y, text, room, st)
        };
        x = nx;
    }
    for (text, rgb) in &e.more {
        if x + 1 >= max_x {
            break;
        }
        let (nx, _) = buf.set_stringn(x + 1, y, text, (max_x - x - 1) as usize, colors.fg(*rgb));
        x = nx;
    }
    x
}

/// Where the parts of a figure go in its area.
struct Frame {
    /// The whole area.
    area: Rect,
    /// The graph's cells (inside the axes).
    graph: Rect,
    /// The x axis' row (the labels are on the next one, the title on the one after when
    /// `x_title_row`).
    axis_row: u16,
    /// Whether the x title has a row of its own.
    x_title_row: bool,
    /// Whether the y title has a row above the graph.
    y_title_row: bool,
    /// Legend rows above the graph (indices into the entries) and how many entries did not fit.
    above: (Vec<Vec<usize>>, usize),
    /// Whether the legend goes inside the graph (where the core says).
    inside: bool,
    /// The legend's width in cells.
    legend_w: u16,
    /// The axes' ends in drawing units (log₁₀ on log axes): x lo, x hi, y lo, y hi.
    bounds: (f64, f64, f64, f64),
}

impl Frame {
    /// The rows: [legend rows above] [y title] graph… [x axis] [x labels] [x title]. Axis titles
    /// get rows of their own on tall plots; else the x title shares the labels' row (as much of
    /// its end as fits) and the pane's title names the y axis.
    fn lay_out(area: Rect, fig: &Figure, entries: &[Entry], opts: &Options) -> Option<Frame> {
        if area.width < 12 || area.height < 5 {
            return None;
        }
        let bounds = (
            unit(&fig.x, fig.x.min)?,
            unit(&fig.x, fig.x.max)?,
            unit(&fig.y, fig.y.min)?,
            unit(&fig.y, fig.y.max)?,
        );
        let legend_w: u16 = entries.iter().map(|e| e.width() as u16).max().unwrap_or(0) + 1;
        let y_title_row = area.height >= 24 || (opts.y_title && area.height >= 8);
        let x_title_row = area.height >= 16;
        // The y labels' width: the widest label of the ticks that fit.
        let rough_rows = area
            .height
            .saturating_sub(3 + u16::from(y_title_row) + u16::from(x_title_row));
        let y_label_w = fig
            .y
            .ticks(usize::from((rough_rows / 3).max(3)))
            .iter()
            .filter_map(|t| t.label.as_ref())
            .map(|l| l.chars().count() as u16)
            .max()
            .unwrap_or(1);
        let graph_x = area.x + y_label_w + 1;
        let graph_w = area.right().saturating_sub(graph_x);
        // Inside the graph when it covers at most a third of its width and half its rows.
        let inside = !entries.is_empty()
            && legend_w <= graph_w / 3 + 4
            && (entries.len() as u16) <= rough_rows / 2;
        let above = if inside || entries.is_empty() {
            (Vec::new(), 0)
        } else {
            flow(entries, area.width, opts.legend_rows.max(1))
        };
        let top = area.y + above.0.len() as u16 + u16::from(y_title_row);
        let axis_row = area.bottom().checked_sub(2 + u16::from(x_title_row))?;
        if axis_row <= top + 1 || graph_w < 4 {
            return None;
        }
        Some(Frame {
            area,
            graph: Rect::new(graph_x, top, graph_w, axis_row - top),
            axis_row,
            x_title_row,
            y_title_row,
            above,
            inside,
            legend_w,
            bounds,
        })
    }

    /// The x axis as drawn (for mouse hits and tick columns).
    fn x_axis(&self) -> LogAxis {
        LogAxis {
            x: self.graph.x,
            width: self.graph.width,
            axis_row: self.axis_row,
            label_row: self.axis_row + 1,
            left: self.area.x,
            lo: self.bounds.0,
            hi: self.bounds.1,
        }
    }
}

const AXIS: Style = Style::new().fg(Color::Gray);
const DIM: Style = Style::new().fg(Color::DarkGray);

/// Draws `fig` in `area`: the legend (inside the graph in the corner the core picks when it fits
/// there, else in rows above), the y axis title, the graph with its axes, ticks and labels.
pub fn draw(buf: &mut Buffer, area: Rect, fig: &Figure, opts: &Options) -> Option<Drawn> {
    let tags = tags(fig, opts.colors);
    let entries = legend(fig, &tags);
    let f = Frame::lay_out(area, fig, &entries, opts)?;
    legend_above(buf, &f, &entries, opts.colors);
    if f.y_title_row {
        let y = area.y + f.above.0.len() as u16;
        buf.set_stringn(area.x, y, &fig.y.label, area.width as usize, AXIS);
    }
    graph(buf, &f, fig, opts, &tags);
    y_axis(buf, &f, fig);
    x_axis(buf, &f, fig);
    if f.inside {
        legend_inside(buf, &f, fig, &entries, opts.colors);
    }
    Some(Drawn {
        graph: f.graph,
        x_axis: f.x_axis(),
    })
}

/// The legend's rows above the graph, with a count of what did not fit.
fn legend_above(buf: &mut Buffer, f: &Frame, entries: &[Entry], colors: Colors) {
    let (rows, left_out) = &f.above;
    for (r, line) in rows.iter().enumerate() {
        let y = f.area.y + r as u16;
        let mut x = f.area.x;
        for &k in line {
            x = put_entry(buf, x, y, &entries[k], f.area.right(), colors) + 2;
        }
        if r + 1 == rows.len() && *left_out > 0 {
            let room = f.area.right().saturating_sub(x) as usize;
            // The longest wording that fits, never one cut mid-word (issue 37: `+1 m`).
            let more = [
                format!("+{left_out} more (x exports all)"),
                format!("+{left_out} more"),
                format!("+{left_out}"),
            ]
            .into_iter()
            .find(|t| t.chars().count() <= room)
            .unwrap_or_default();
            buf.set_stringn(x, y, more, room, DIM);
        }
    }
}

/// The graph: bands, series (by stroke), markers and the cursor, each in its own canvas layer
/// (later on top); this scene's curve bold; point marks and tags over it. About 100 lines: one
/// canvas paint whose layer order is the figure's draw order, kept in one place on purpose.
// Long by design: draws the graph area of a figure in paint order (bands, series, markers, cursor)
// over one braille canvas.
fn graph(buf: &mut Buffer, f: &Frame, fig: &Figure, opts: &Options, tags: &[Option<char>]) {
    let (x_lo, x_hi, y_lo, y_hi) = f.bounds;
    let colors = opts.colors;
    let g = f.graph;
    let scale = (
        f64::from(g.width) / (x_hi - x_lo),
        f64::from(g.height) / (y_hi - y_lo),
    );
    let marks: std::cell::RefCell<Vec<(f64, f64, char, Rgb)>> = std::cell::RefCell::default();
    let canvas = Canvas::default()
        .marker(Dots::Braille)
        .x_bounds([x_lo, x_hi])
        .y_bounds([y_lo, y_hi])
        .paint(|ctx| {
            for b in &fig.bands {
                let (Some(x0), Some(x1), Some(b0), Some(b1)) = (
                    unit(&fig.x, b.x.0),
                    unit(&fig.x, b.x.1),
                    unit(&fig.y, b.y.0),
                    unit(&fig.y, b.y.1),
                ) else {
                    continue;
                };
                let (x0, x1) = (x0.clamp(x_lo, x_hi), x1.clamp(x_lo, x_hi));
                let (y0, y1) = (b0.clamp(y_lo, y_hi), b1.clamp(y_lo, y_hi));
                let color = colors.color(series_rgb(b.color));
                let corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)];
                for w in corners.windows(2) {
                    ctx.draw(&CanvasLine::new(w[0].0, w[0].1, w[1].0, w[1].1, color));
                }
                ctx.layer();
            }
            for (i, s) in fig.series.iter().enumerate() {
                let color = colors.color(series_rgb(s.color));
                let runs = runs(fig, s, f.bounds);
                if s.stroke == Stroke::Points {
                    for &(x, y) in runs.iter().flatten() {
                        marks.borrow_mut().push((x, y, '×', series_rgb(s.color)));
                    }
                } else {
                    for r in &runs {
                        for (a, b) in pieces(r, s.stroke, scale) {
                            ctx.draw(&CanvasLine::new(a.0, a.1, b.0, b.1, color));
                        }
                    }
                    // Without colour, a tag every dozen cells along the line.
                    if let Some(t) = tags.get(i).copied().flatten() {
                        let every = 12.0 / scale.0;
                        let mut next = x_lo + every * (0.3 + 0.1 * i as f64);
                        for &(x, y) in runs.iter().flatten() {
                            if x >= next {
                                marks.borrow_mut().push((x, y, t, series_rgb(s.color)));
                                next = x + every;
                            }
                        }
                    }
                }
                ctx.layer();
            }
            for m in &fig.markers {
                if let Some(x) = unit(&fig.x, m.x).filter(|x| *x > x_lo && *x < x_hi) {
                    let color = colors.color(series_rgb(m.color));
                    for (a, b) in pieces(&[(x, y_lo), (x, y_hi)], Stroke::Dashed, scale) {
                        ctx.draw(&CanvasLine::new(a.0, a.1, b.0, b.1, color));
                    }
                }
            }
            ctx.layer();
            if let Some(x) = opts.cursor.and_then(|c| unit(&fig.x, c)) {
                ctx.draw(&CanvasLine::new(x, y_lo, x, y_hi, Color::White));
            }
        });
    canvas.render(g, buf);
    // The scene's curve bold: its cells, in its colour.
    if let Some(s) = opts.bold.and_then(|k| fig.series.get(k))
        && colors != Colors::None
    {
        let c = colors.color(series_rgb(s.color));
        for (x, y) in (g.top()..g.bottom()).flat_map(|y| (g.left()..g.right()).map(move |x| (x, y)))
        {
            if let Some(cell) = buf.cell_mut((x, y))
                && cell.fg == c
            {
                cell.modifier.insert(Modifier::BOLD);
            }
        }
    }
    for (x, y, ch, rgb) in marks.into_inner() {
        let col = f64::from(g.x)
            + ((x - x_lo) * (f64::from(g.width) * 2.0 - 1.0) / (x_hi - x_lo)).round() / 2.0;
        if let Some(row) = row_of(y, y_lo, y_hi, g.y, g.height)
            && let Some(cell) = buf.cell_mut((col as u16, row))
        {
            cell.set_char(ch).set_style(colors.fg(rgb));
        }
    }
}

/// A series' runs of drawable points in drawing units (a NaN, or a value off a log axis or off
/// the x range, breaks the line); y clamped to the axis.
fn runs(
    fig: &Figure,
    s: &rime_core::figure::Series,
    (x_lo, x_hi, y_lo, y_hi): (f64, f64, f64, f64),
) -> Vec<Vec<(f64, f64)>> {
    let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for &(x, y) in &s.points {
        match (unit(&fig.x, x), unit(&fig.y, y)) {
            (Some(x), Some(y)) if x >= x_lo && x <= x_hi => {
                if let Some(r) = runs.last_mut() {
                    r.push((x, y.clamp(y_lo, y_hi)));
                }
            }
            _ => runs.push(Vec::new()),
        }
    }
    runs
}

/// The y axis line and its labelled ticks, each label on the row its value is drawn on.
fn y_axis(buf: &mut Buffer, f: &Frame, fig: &Figure) {
    let (g, area) = (f.graph, f.area);
    let (_, _, y_lo, y_hi) = f.bounds;
    for y in g.top()..f.axis_row {
        buf.set_string(g.x - 1, y, "│", AXIS);
    }
    let mut taken_rows: Vec<u16> = Vec::new();
    for t in fig.y.ticks(usize::from((g.height / 3).max(3))) {
        let (Some(v), Some(label)) = (unit(&fig.y, t.value), t.label) else {
            continue;
        };
        let Some(row) = row_of(v, y_lo, y_hi, g.y, g.height) else {
            continue;
        };
        if taken_rows.contains(&row) {
            continue;
        }
        taken_rows.push(row);
        let w = label.chars().count() as u16;
        buf.set_string(g.x - 1 - w.min(g.x - 1 - area.x), row, &label, AXIS);
        buf.set_string(g.x - 1, row, "┤", AXIS);
    }
}

/// The x axis line, its ticks (major labelled, minor where a decade has room), the labels that
/// fit, and the axis title (a row of its own, else as much of its end as fits).
fn x_axis(buf: &mut Buffer, f: &Frame, fig: &Figure) {
    let (g, area, axis_row) = (f.graph, f.area, f.axis_row);
    let axis = f.x_axis();
    buf.set_string(g.x - 1, axis_row, "└", AXIS);
    for x in g.left()..g.right() {
        buf.set_string(x, axis_row, "─", AXIS);
    }
    let label_row = axis_row + 1;
    // As many labels as fit with a gap of two cells (labels are up to five wide).
    let x_budget = (f64::from(g.width) / 7.0).floor().max(2.0) as usize;
    let per_unit = f64::from(g.width) / (axis.hi - axis.lo);
    let mut taken: Vec<(u16, u16)> = Vec::new();
    for t in &fig.x.ticks(x_budget) {
        let Some(v) = unit(&fig.x, t.value) else {
            continue;
        };
        let Some(c) = axis.column(v) else {
            continue;
        };
        // Minor ticks where a decade has room for them: all of 2…9, or 2 and 5.
        let minor_room = per_unit >= 12.0
            || (per_unit >= 5.0 && {
                let m = t.value / 10f64.powf(v.floor());
                (m - 2.0).abs() < 1e-6 || (m - 5.0).abs() < 1e-6
            });
        match &t.label {
            Some(label) => {
                buf.set_string(c, axis_row, "┼", AXIS);
                let w = label.chars().count() as u16;
                // Centred on its tick; at the plot's right end, ending at the edge (it was dropped).
                let start = c
                    .saturating_sub(w / 2)
                    .max(area.x)
                    .min(area.right().saturating_sub(w));
                let free = start + w <= area.right()
                    && taken.iter().all(|(a, b)| start + w < *a || start > *b);
                if free {
                    buf.set_string(start, label_row, label, AXIS);
                    taken.push((start, start + w));
                }
            }
            None if minor_room
                && buf
                    .cell((c, axis_row))
                    .is_some_and(|cell| cell.symbol() == "─") =>
            {
                buf.set_string(c, axis_row, "┴", DIM);
            }
            None => {}
        }
    }
    let title = &fig.x.label;
    if f.x_title_row {
        let start = area
            .right()
            .saturating_sub(title.chars().count() as u16)
            .max(area.x);
        buf.set_stringn(start, label_row + 1, title, area.width as usize, AXIS);
    } else {
        // The longest end of the title (whole words: `g_N [m/s]`) right of the last label.
        let free_from = taken.iter().map(|(_, b)| *b + 2).max().unwrap_or(area.x);
        let room = area.right().saturating_sub(free_from) as usize;
        let words: Vec<&str> = title.split(' ').collect();
        if let Some(tail) = (0..words.len())
            .map(|k| words[k..].join(" "))
            .find(|t| t.chars().count() <= room)
        {
            let start = area.right() - tail.chars().count() as u16;
            buf.set_string(start, label_row, &tail, AXIS);
        }
    }
}

/// The legend inside the graph, in the corner the core picks for its footprint in cells.
fn legend_inside(buf: &mut Buffer, f: &Frame, fig: &Figure, entries: &[Entry], colors: Colors) {
    let (g, legend_w) = (f.graph, f.legend_w);
    let h = entries.len() as u16;
    let corner = fig.legend_corner(
        (f64::from(g.width), f64::from(g.height)),
        (f64::from(legend_w + 1), f64::from(h)),
    );
    let x = match corner {
        Corner::TopLeft | Corner::BottomLeft => g.x + 1,
        Corner::TopRight | Corner::BottomRight => g.right().saturating_sub(legend_w),
    };
    let y = match corner {
        Corner::TopLeft | Corner::TopRight => g.y,
        Corner::BottomLeft | Corner::BottomRight => g.bottom().saturating_sub(h),
    };
    for (k, e) in entries.iter().enumerate() {
        let row = y + k as u16;
        for cx in x.saturating_sub(1)..g.right().min(x + legend_w) {
            if let Some(cell) = buf.cell_mut((cx, row)) {
                cell.reset();
            }
        }
        put_entry(buf, x, row, e, g.right(), colors);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dashes_alternate_on_and_off() {
        // A horizontal line 10 cells long: dashes of 2 cells, gaps of 1 → 4 dashes (2+1+2+1+2+1+1).
        let p = pieces(&[(0.0, 0.0), (10.0, 0.0)], Stroke::Dashed, (1.0, 1.0));
        assert_eq!(p.len(), 4, "{p:?}");
        assert_eq!(p[0], ((0.0, 0.0), (2.0, 0.0)));
        assert_eq!(p[1], ((3.0, 0.0), (5.0, 0.0)));
        let solid = pieces(&[(0.0, 0.0), (10.0, 0.0)], Stroke::Solid, (1.0, 1.0));
        assert_eq!(solid, [((0.0, 0.0), (10.0, 0.0))]);
    }
}
