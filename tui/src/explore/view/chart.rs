//! The ε_N chart: this scene's curve, the family over a swept parameter, the clean surface, the
//! critical speeds, the experimental context and the cursor, on log–log axes.

use super::{
    BAND_COLORS, BAND_SHORT, BAND_TINY, BRIDGES, CLEAN, CURRENT, FAMILY_COLORS, GS_ADHESION,
    GS_LAYER, OVERLAY_COLORS, PINNED, nb,
};
use crate::explore::compute::{FrameData, Sweep};
use crate::explore::format::{decade, num3, qty, qty3, sig};
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Block, Borders, Chart, Dataset, GraphType, Paragraph, Wrap};
use rime_core::Status;

/// Integer axis bounds `lo..hi` widened so that at most `max_labels` decade labels divide it evenly.
fn decade_axis(lo: i32, hi: i32, max_labels: i32) -> (i32, i32, i32) {
    let span = (hi - lo).max(1);
    let mut step = 1;
    while span.div_euclid(step) + 1 > max_labels.max(2) {
        step += 1;
    }
    let span = (span + step - 1) / step * step;
    (hi - span, hi, step)
}

fn labels(lo: i32, hi: i32, step: i32, unit: &str) -> Vec<Span<'static>> {
    let mut out = Vec::new();
    let mut k = lo;
    while k <= hi {
        let mut s = decade(k);
        if k == hi && !unit.is_empty() {
            s.push_str(unit);
        }
        out.push(Span::raw(s));
        k += step;
    }
    out
}

/// How the ε_N axis maps a value: log10 (values below `lo` dropped) or linear (0 … 1, sticking
/// on the bottom line).
#[derive(Debug, Clone, Copy)]
struct YScale {
    log: bool,
    lo: f64,
}

impl YScale {
    fn y(self, e: f64) -> Option<f64> {
        if !e.is_finite() {
            return None;
        }
        if self.log {
            (e > 0.0 && e.log10() >= self.lo).then(|| e.log10())
        } else {
            (e >= 0.0).then_some(e.min(1.0))
        }
    }
}

fn log_points(g: &[f64], eps: impl Iterator<Item = f64>, y: YScale) -> Vec<(f64, f64)> {
    g.iter()
        .zip(eps)
        .filter_map(|(g, e)| Some((g.log10(), y.y(e)?)))
        .collect()
}

/// Rows that `spans` take when word-wrapped at `width` (breaks at plain spaces only; non-breaking
/// spaces keep a value with its unit).
fn wrapped_rows(spans: &[Span], width: usize) -> usize {
    let text: String = spans.iter().map(|s| s.content.as_ref()).collect();
    let mut rows = 1;
    let mut used = 0;
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        let w = word.chars().count();
        if used > 0 && used + 1 + w > width {
            rows += 1;
            used = 0;
        }
        used += if used > 0 { 1 + w } else { w };
        while used > width {
            rows += 1;
            used -= width;
        }
    }
    rows
}

/// A polyline cut into dashes (runs of `run` points, every other run left out).
fn dashes(pts: &[(f64, f64)], run: usize) -> Vec<Vec<(f64, f64)>> {
    pts.chunks(run.max(2))
        .step_by(2)
        .map(<[(f64, f64)]>::to_vec)
        .collect()
}

/// A tick label for `m`·10^`k` (m = 1, 2, 5): plain between 0.01 and 1000, else `2e-5`.
fn tick_label(m: f64, k: i32) -> String {
    if (-2..=3).contains(&k) {
        sig(m * 10f64.powi(k), 2)
    } else if m == 1.0 {
        decade(k)
    } else {
        format!("{m}e{k}")
    }
}

/// Describes ε_N at one point for readouts: `0.3602 rebound`, `0 stuck in layer`.
pub fn status_text(s: Status) -> &'static str {
    match s {
        Status::Rebound => "rebound",
        Status::StuckInLayer => "stuck in layer",
        Status::StuckByAdhesion => "stuck by adhesion",
        Status::Overdamped => "overdamped",
    }
}

/// What the ε_N chart shows.
#[derive(Debug, Clone, Copy)]
pub struct ChartView<'a> {
    /// The latest frame (None before the first one).
    pub data: Option<&'a FrameData>,
    /// The swept parameter of the family of curves.
    pub sweep: Sweep,
    /// Cursor: index into the curve speeds.
    pub cursor: usize,
    /// Whether the experimental context is drawn.
    pub experiments: bool,
    /// Whether the chart has the focus.
    pub focused: bool,
    /// Whether the ε_N axis is logarithmic (else linear, 0 … 1).
    pub y_log: bool,
    /// A pinned curve to draw dashed.
    pub pinned: Option<&'a crate::explore::app::Pinned>,
    /// Whether the chart shares its pane with the stick map (the title says how to switch).
    pub shared: bool,
}

/// Draws the ε_N chart: legend, curves, markers, experiments, cursor and readout. Returns the
/// speed axis as drawn (for mouse clicks).
pub fn chart(frame: &mut Frame, area: Rect, app: &ChartView) -> Option<LogAxis> {
    let sweep = app.sweep;
    let focus = app.focused;
    let title_name = Span::styled(
        " ε_N(g_N) ",
        Style::new()
            .add_modifier(Modifier::BOLD)
            .fg(if focus { Color::Cyan } else { Color::Gray }),
    );
    let switch = Span::styled("│ stick map: Tab ", Style::new().fg(Color::Yellow));
    let axis_word = if app.y_log { "log" } else { "linear" };
    let mut title_spans = vec![
        title_name.clone(),
        Span::styled(
            if app.shared {
                format!("{axis_word} axis ")
            } else {
                format!("normal restitution · {axis_word} axis ")
            },
            Style::new().fg(Color::Gray),
        ),
    ];
    if app.shared {
        title_spans.push(switch.clone());
    }
    let title = Line::from(title_spans);
    let (kind, border_style) = super::pane_border(focus);
    let block = Block::new()
        .borders(Borders::TOP | Borders::BOTTOM)
        .border_type(kind)
        .border_style(border_style)
        .title_bottom(chart_readout(app.data, app.cursor));
    let inner = block.inner(area);
    let Some(data) = app.data else {
        frame.render_widget(block.title(title), area);
        frame.render_widget(Paragraph::new("computing…"), inner);
        return None;
    };
    if inner.height < 4 {
        return None;
    }
    // Legend line.
    let mut legend: Vec<Span> = Vec::new();
    let this = if sweep.available(&data.scene) {
        nb(format!(
            "━ this scene ({} {})",
            sweep.symbol,
            qty3(sweep.current(&data.scene), sweep.unit)
        ))
    } else {
        nb("━ this scene".to_string())
    };
    legend.push(Span::styled(this + " ", Style::new().fg(CURRENT)));
    if let Some(p) = app.pinned {
        legend.push(Span::styled(
            nb(format!("┅ pinned ({}) ", p.label)),
            Style::new().fg(PINNED),
        ));
    }
    // The comparisons first: with them on, the legend's second row may not hold everything.
    for (k, o) in data.overlays.iter().enumerate() {
        let key = o.overlay.key();
        let name = key
            .split_once(':')
            .map_or(key.as_str(), |(_, n)| n)
            .to_string();
        let score = o
            .score
            .map(|r| format!("\u{a0}rms\u{a0}{}", sig(r, 2)))
            .unwrap_or_default();
        // Measured data with its temperature and geometry (docs/physics.md#data-atlas).
        let context = match o.overlay {
            rime_core::explorer::frame::Overlay::Atlas(e) => {
                let [lo, hi] = e.temperature;
                let t = if lo == hi {
                    format!("{lo}\u{a0}K")
                } else {
                    format!("{lo}–{hi}\u{a0}K")
                };
                format!("\u{a0}({t},\u{a0}{})", e.geometry.name())
            }
            rime_core::explorer::frame::Overlay::Model(_) => String::new(),
        };
        legend.push(Span::styled(
            format!(
                "{}\u{a0}{name}{context}{score} ",
                if o.band { "▭" } else { "┅" }
            ),
            Style::new().fg(OVERLAY_COLORS[k % OVERLAY_COLORS.len()]),
        ));
    }

    if data.clean.is_some() {
        legend.push(Span::styled(
            "━\u{a0}clean\u{a0}surface ",
            Style::new().fg(CLEAN),
        ));
    }
    // What the family is: this scene with one parameter varied around its value (the long words
    // where the legend's two rows hold them, decided below).
    let mut family_label = None;
    if !data.family.is_empty() {
        family_label = Some(legend.len());
        legend.push(Span::raw(nb(format!("{} varied:", sweep.symbol))));
        for (k, m) in data.family.iter().enumerate() {
            legend.push(Span::styled(
                format!(" {}", qty(m.value, sweep.unit).replace(' ', "\u{a0}")),
                Style::new().fg(FAMILY_COLORS[k % FAMILY_COLORS.len()]),
            ));
        }
        legend.push(Span::raw(" "));
    }
    if let Some(c) = &data.contact {
        if let Some(l) = c.layer {
            legend.push(Span::styled(
                format!(
                    "┊\u{a0}g_s\u{a0}layer\u{a0}{} ",
                    nb(qty(l.critical_velocity, "m/s"))
                ),
                Style::new().fg(GS_LAYER),
            ));
        }
        if let Some(a) = c.adhesion {
            legend.push(Span::styled(
                // Eq. (15)'s g_s is a rebound speed drawn on the impact axis (the help explains).
                format!(
                    "┊\u{a0}g_s\u{a0}adhesion\u{a0}{}\u{a0}(a\u{a0}rebound\u{a0}speed) ",
                    nb(qty(a.critical_velocity, "m/s"))
                ),
                Style::new().fg(GS_ADHESION),
            ));
        }
    }
    // A comparison (`c`) replaces the fixed experimental context: it holds the same sources, each
    // over its own measured speeds, with the scene's score.
    let experiments = app.experiments && data.overlays.is_empty();
    let bands = rime_core::figure::experiments::bands(0);
    // The legend may take three rows on a tall chart, two on a medium one. The experiments' legend:
    // long names where the rows hold them, else short ones (the help names them), else in the
    // chart's title.
    let max_rows = if inner.height >= 18 && !data.overlays.is_empty() {
        // One comparison per row (measured laws carry temperature, geometry and score).
        2 + data.overlays.len().min(5)
    } else if inner.height >= 16 {
        3
    } else if inner.height >= 8 {
        2
    } else {
        1
    };
    let width = inner.width as usize;
    let mut experiments_in_title = false;
    if experiments {
        let with = |long: bool| {
            let mut l = legend.clone();
            l.extend(experiment_legend(long));
            wrapped_rows(&l, width)
        };
        if with(true) <= max_rows {
            legend.extend(experiment_legend(true));
        } else if with(false) <= max_rows {
            legend.extend(experiment_legend(false));
        } else {
            experiments_in_title = true;
        }
    }
    if let Some(k) = family_label {
        let mut l = legend.clone();
        l[k] = Span::raw(nb(format!("{} varied around this scene:", sweep.symbol)));
        if wrapped_rows(&l, width) <= max_rows {
            legend = l;
        }
    }
    if experiments_in_title {
        let mut spans = vec![
            title_name,
            Span::styled(
                format!(
                    "· over {}{} ",
                    sweep.symbol,
                    if app.y_log { "" } else { " · linear" }
                ),
                Style::new().fg(Color::Gray),
            ),
        ];
        spans.extend(experiment_legend(false));
        if app.shared {
            spans.push(switch);
        }
        frame.render_widget(block.title(Line::from(spans)), area);
    } else {
        frame.render_widget(block.title(title), area);
    }
    let legend_h = wrapped_rows(&legend, width).clamp(1, max_rows) as u16;
    frame.render_widget(
        Paragraph::new(Line::from(legend)).wrap(Wrap { trim: true }),
        Rect::new(inner.x, inner.y, inner.width, legend_h),
    );
    let plot = Rect::new(
        inner.x,
        inner.y + legend_h,
        inner.width,
        inner.height - legend_h,
    );
    if let Some(e) = &data.error
        && data.contact.is_none()
    {
        frame.render_widget(
            Paragraph::new(format!("cannot evaluate this scene: {e}"))
                .style(Style::new().fg(Color::Red))
                .wrap(Wrap { trim: true }),
            plot,
        );
        return None;
    }
    // Axis ranges (log10): the speeds computed, exactly (decades unless zoomed or panned).
    let (Some(g0), Some(g1)) = (data.g.first(), data.g.last()) else {
        return None;
    };
    let (x_lo_f, x_hi_f) = (g0.log10(), g1.log10());
    let (_, _, x_step) = decade_axis(
        (x_lo_f + 1e-9).floor() as i32,
        (x_hi_f - 1e-9).ceil() as i32,
        if plot.width >= 36 { 5 } else { 4 },
    );
    let mut min_eps = f64::INFINITY;
    let all = data
        .current
        .iter()
        .map(|n| n.map_or(f64::NAN, |n| n.eps))
        .chain(data.clean.iter().flatten().copied())
        .chain(data.family.iter().flat_map(|m| m.eps.iter().copied()));
    for e in all {
        if e.is_finite() && e > 0.0 {
            min_eps = min_eps.min(e);
        }
    }
    if experiments {
        // Keep the experiments' boxes whole on the ε axis.
        for b in &bands {
            min_eps = min_eps.min(b.y.0);
        }
    }
    let y_floor = if min_eps.is_finite() {
        (min_eps.log10().floor() as i32).clamp(-12, -1)
    } else {
        -1
    };
    let (y_lo, y_hi, y_step) = decade_axis(y_floor, 0, if plot.height >= 12 { 5 } else { 3 });
    let (y_lo_f, y_hi_f) = if app.y_log {
        (f64::from(y_lo), f64::from(y_hi))
    } else {
        (0.0, 1.0)
    };
    let ys = YScale {
        log: app.y_log,
        lo: y_lo_f,
    };
    let stuck_is_zero = |n: Option<rime_core::Normal>| {
        n.map_or(f64::NAN, |n| match n.status {
            Status::StuckInLayer | Status::StuckByAdhesion => 0.0,
            _ => n.eps,
        })
    };
    let current_pts = log_points(&data.g, data.current.iter().map(|n| stuck_is_zero(*n)), ys);
    let clean_pts = data
        .clean
        .as_ref()
        .map(|c| log_points(&data.g, c.iter().copied(), ys));
    let family_pts: Vec<Vec<(f64, f64)>> = data
        .family
        .iter()
        .map(|m| log_points(&data.g, m.eps.iter().copied(), ys))
        .collect();
    // The pinned curve, where its speeds are on this axis, in dashes.
    let pinned_pts: Vec<Vec<(f64, f64)>> = app
        .pinned
        .map(|p| {
            let pts: Vec<(f64, f64)> = log_points(&p.g, p.eps.iter().copied(), ys)
                .into_iter()
                .filter(|(x, _)| (x_lo_f..=x_hi_f).contains(x))
                .collect();
            dashes(&pts, 6)
        })
        .unwrap_or_default();
    let vline = |x: f64| vec![(x, y_lo_f), (x, y_hi_f)];
    let markers: Vec<(Vec<(f64, f64)>, Color)> = data
        .contact
        .iter()
        .flat_map(|c| {
            [
                c.layer.map(|l| (l.critical_velocity, GS_LAYER)),
                c.adhesion.map(|a| (a.critical_velocity, GS_ADHESION)),
            ]
        })
        .flatten()
        .filter(|(g, _)| g.is_finite() && *g > 0.0)
        .map(|(g, c)| (vline(g.log10()), c))
        .collect();
    let cursor_pts = data.g.get(app.cursor).map(|g| vline(g.log10()));
    let clip_y = |e: f64| {
        if app.y_log {
            e.log10().clamp(y_lo_f, y_hi_f)
        } else {
            e.clamp(0.0, 1.0)
        }
    };
    // The core's one description of the law: only over the speeds it was measured at, unclamped
    // (it stays below 1 there), drawn beneath the model's curves.
    let (g_first, g_last) = (
        data.g.first().copied().unwrap_or(1e-7),
        data.g.last().copied().unwrap_or(10.0),
    );
    let bridges_pts: Vec<(f64, f64)> = if experiments {
        rime_core::figure::experiments::bridges_measured(g_first, g_last, 0)
            .map(|s| {
                s.points
                    .into_iter()
                    .filter_map(|(g, e)| Some((g.log10(), ys.y(e)?)))
                    .collect()
            })
            .unwrap_or_default()
    } else {
        Vec::new()
    };
    // The overlays: laws over their measured speeds, ranges as boxes, models over the whole axis,
    // and the models' characteristic speeds (g_cr, v_yield) as markers in their colour.
    let mut overlay_pts: Vec<(Vec<(f64, f64)>, Color)> = Vec::new();
    for (k, o) in data.overlays.iter().enumerate() {
        let color = OVERLAY_COLORS[k % OVERLAY_COLORS.len()];
        if o.band && o.g.len() == 2 && o.eps.len() == 2 {
            let (x0, x1) = (o.g[0].log10(), o.g[1].log10());
            let (y0, y1) = (clip_y(o.eps[0]), clip_y(o.eps[1]));
            overlay_pts.push((
                vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)],
                color,
            ));
        } else {
            overlay_pts.push((log_points(&o.g, o.eps.iter().copied(), ys), color));
        }
        for (_, g) in &o.speeds {
            if g.is_finite() && *g > 0.0 {
                overlay_pts.push((vline(g.log10()), color));
            }
        }
    }
    let band_pts: Vec<(Vec<(f64, f64)>, Color)> = if experiments {
        bands
            .iter()
            .enumerate()
            .map(|(k, b)| {
                let (x0, x1) = (b.x.0.log10(), b.x.1.log10());
                let (y0, y1) = (clip_y(b.y.0), clip_y(b.y.1));
                (
                    vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)],
                    BAND_COLORS[k % 2],
                )
            })
            .collect()
    } else {
        Vec::new()
    };
    // Every chart line is a Braille polyline in one style; draw order is what differs.
    fn line(pts: &[(f64, f64)], style: Style) -> Dataset<'_> {
        Dataset::default()
            .marker(Marker::Braille)
            .graph_type(GraphType::Line)
            .style(style)
            .data(pts)
    }
    let fg = |c: Color| Style::new().fg(c);
    let mut datasets = Vec::new();
    // Measured laws first, beneath every model curve (the core's figure description draws them in
    // the same order): the Bridges law and the compared laws. The boxes are outlines: drawn beneath,
    // a Braille cell a curve passes through would hide them whole, so they go above the family and
    // below this scene's curve.
    if !bridges_pts.is_empty() {
        datasets.push(line(&bridges_pts, fg(BRIDGES)));
    }
    for (pts, color) in &overlay_pts {
        datasets.push(line(pts, fg(*color)));
    }
    for (k, pts) in family_pts.iter().enumerate() {
        datasets.push(line(pts, fg(FAMILY_COLORS[k % FAMILY_COLORS.len()])));
    }
    if let Some(pts) = &clean_pts {
        datasets.push(line(pts, fg(CLEAN)));
    }
    for (pts, color) in &band_pts {
        datasets.push(line(pts, fg(*color)));
    }
    for (pts, color) in &markers {
        datasets.push(line(pts, fg(*color)));
    }
    for pts in &pinned_pts {
        datasets.push(line(pts, fg(PINNED)));
    }
    if let Some(pts) = &cursor_pts {
        datasets.push(line(pts, fg(Color::White)));
    }
    datasets.push(line(
        &current_pts,
        Style::new().fg(CURRENT).add_modifier(Modifier::BOLD),
    ));
    let axis_style = Style::new().fg(Color::Gray);
    let y_labels = if app.y_log {
        labels(y_lo, y_hi, y_step, "")
    } else if plot.height >= 12 {
        ["0", "0.25", "0.5", "0.75", "1"].map(Span::raw).to_vec()
    } else {
        ["0", "0.5", "1"].map(Span::raw).to_vec()
    };
    let chart = Chart::new(datasets)
        .x_axis(
            Axis::default()
                .title("g_N m/s")
                .style(axis_style)
                .bounds([x_lo_f, x_hi_f])
                // Placeholders that reserve the label row; `log_ticks` writes the labels at their
                // values (ratatui spreads labels evenly, which puts them up to 0.4 decade off).
                .labels(vec![Span::raw(""), Span::raw("")]),
        )
        .y_axis(
            Axis::default()
                .title("ε_N")
                .style(axis_style)
                .bounds([y_lo_f, y_hi_f])
                .labels(y_labels.clone()),
        )
        .legend_position(None);
    let y_label_w = y_labels.iter().map(|l| l.width() as u16).max().unwrap_or(0);
    frame.render_widget(chart, plot);
    let axis = LogAxis::under(plot, y_label_w, x_lo_f, x_hi_f);
    log_ticks(frame.buffer_mut(), &axis, x_step, axis_style);
    if current_pts.is_empty() {
        let msg = match data.current.iter().flatten().next().map(|n| n.status) {
            Some(Status::Overdamped) => "overdamped everywhere: ε_N below the plotted range",
            Some(Status::StuckInLayer | Status::StuckByAdhesion) => "stuck at every speed shown",
            _ => "no rebound to plot",
        };
        let w = (msg.chars().count() as u16).min(plot.width);
        frame.render_widget(
            Paragraph::new(msg).style(Style::new().fg(Color::Red)),
            Rect::new(
                plot.x + plot.width.saturating_sub(w) / 2,
                plot.y + plot.height / 3,
                w,
                1,
            ),
        );
    }
    Some(axis)
}

/// Legend entries of the Bridges law and the experiments' boxes (long or short names).
fn experiment_legend(long: bool) -> Vec<Span<'static>> {
    let mut out = vec![Span::styled(
        if long {
            "┄\u{a0}Bridges'84 "
        } else {
            "┄B84 "
        },
        // The swatch is the drawn colour (it was grey over a dark-grey line).
        Style::new().fg(BRIDGES),
    )];
    for k in 0..2 {
        let name = if long { BAND_SHORT[k] } else { BAND_TINY[k] };
        let gap = if long { "\u{a0}" } else { "" };
        out.push(Span::styled(
            format!("▭{gap}{name} "),
            Style::new().fg(BAND_COLORS[k]),
        ));
    }
    out
}

/// The chart's readout at the cursor: speed, ε_N, status, contact time and δ.
fn chart_readout(data: Option<&FrameData>, cursor: usize) -> Line<'static> {
    let Some(data) = data else {
        return Line::default();
    };
    let Some(g) = data.g.get(cursor).copied() else {
        return Line::default();
    };
    let mut spans = vec![
        Span::styled(" ▸ ", Style::new().fg(Color::White)),
        Span::raw(format!("{}  ", qty3(g, "m/s"))),
    ];
    match data.current.get(cursor).copied().flatten() {
        Some(n) => {
            let eps = match n.status {
                Status::StuckInLayer | Status::StuckByAdhesion => "0".to_string(),
                _ => num3(n.eps),
            };
            spans.push(Span::styled(
                format!("ε_N {eps} "),
                Style::new().fg(CURRENT).add_modifier(Modifier::BOLD),
            ));
            let st_color = match n.status {
                Status::Rebound => Color::Green,
                _ => Color::Red,
            };
            spans.push(Span::styled(
                status_text(n.status),
                Style::new().fg(st_color),
            ));
            let t_c = if n.t_c.is_finite() {
                qty3(n.t_c, "s")
            } else {
                "— (stuck)".into()
            };
            let delta = data.contact.map_or("—".to_string(), |c| num3(c.delta(g)));
            spans.push(Span::raw(format!("  t_c {t_c}  δ {delta} ")));
        }
        None => spans.push(Span::raw("ε_N — ")),
    }
    Line::from(spans)
}

/// A log x axis as ratatui's chart lays it out: the graph's columns and the axis and label rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogAxis {
    /// First column of the graph.
    pub x: u16,
    /// Width of the graph in cells.
    pub width: u16,
    /// Row of the axis line.
    pub axis_row: u16,
    /// Row of the labels.
    pub label_row: u16,
    /// Left end of the column span the labels may use (the y labels' column).
    pub left: u16,
    /// log10 of the axis ends.
    pub lo: f64,
    /// log10 of the axis ends.
    pub hi: f64,
}

impl LogAxis {
    /// The axis of a chart drawn in `plot` with y labels `y_label_w` cells wide (ratatui's
    /// `Chart::layout` with x labels of zero width: labels on the last row, the axis above).
    pub fn under(plot: Rect, y_label_w: u16, lo: f64, hi: f64) -> LogAxis {
        let x = plot.x + y_label_w.min(plot.width / 3) + 1;
        LogAxis {
            x,
            width: plot.right().saturating_sub(x),
            axis_row: plot.bottom().saturating_sub(2),
            label_row: plot.bottom().saturating_sub(1),
            left: plot.x,
            lo,
            hi,
        }
    }

    /// The column where log10 value `t` is drawn (ratatui's Braille grid: two dots per cell).
    pub fn column(&self, t: f64) -> Option<u16> {
        let span = self.hi - self.lo;
        if self.width == 0 || span.is_nan() || span <= 0.0 || t < self.lo || t > self.hi {
            return None;
        }
        let dots = f64::from(self.width) * 2.0 - 1.0;
        let dot = ((t - self.lo) * dots / (self.hi - self.lo)).round() as u16;
        Some(self.x + dot / 2)
    }
}

/// Major ticks and labels at every `step`-th decade, minor ticks at 2…9 × 10^k (at 2 and 5 when a
/// decade is narrow, none when it is very narrow), each where its value is drawn.
fn log_ticks(buf: &mut ratatui::buffer::Buffer, axis: &LogAxis, step: i32, style: Style) {
    let (lo, hi) = (
        (axis.lo - 1e-9).floor() as i32,
        (axis.hi + 1e-9).ceil() as i32,
    );
    let decade_w = f64::from(axis.width) / (axis.hi - axis.lo).max(1e-3);
    let minors: &[f64] = if decade_w >= 12.0 {
        &[2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]
    } else if decade_w >= 5.0 {
        &[2.0, 5.0]
    } else {
        &[]
    };
    let right = axis.x + axis.width;
    let mut majors = Vec::new();
    for k in lo..=hi {
        if let Some(c) = axis.column(f64::from(k)) {
            majors.push(c);
            if let Some(cell) = buf.cell_mut((c, axis.axis_row)) {
                cell.set_symbol("┼").set_style(style);
            }
        }
        for m in minors {
            let Some(c) = axis.column(f64::from(k) + m.log10()) else {
                continue;
            };
            if !majors.contains(&c)
                && let Some(cell) = buf.cell_mut((c, axis.axis_row))
            {
                cell.set_symbol("┴").set_style(style.fg(Color::DarkGray));
            }
        }
    }
    // Labels centred on their ticks, left to right, never overlapping; every decade where a
    // label fits in one.
    let step = (1..step)
        .find(|s| decade_w * f64::from(*s) >= 6.0)
        .unwrap_or(step);
    let mut taken: Vec<(u16, u16)> = Vec::new();
    let free = |taken: &[(u16, u16)], start: u16, w: u16| {
        start >= axis.left
            && start + w <= right
            && taken.iter().all(|(a, b)| start + w < *a || start > *b)
    };
    let mut k = hi - (hi - lo) / step * step;
    while k <= hi {
        let text = decade(k);
        let w = text.chars().count() as u16;
        if let Some(c) = axis.column(f64::from(k)) {
            let start = c.saturating_sub(w / 2);
            if free(&taken, start, w) {
                buf.set_string(start, axis.label_row, &text, style);
                taken.push((start, start + w));
            }
        }
        k += step;
    }
    // Zoomed in to a few decades or less: label 2× and 5× too, each at its value, where they fit.
    if axis.hi - axis.lo < 3.0 {
        for k in lo..=hi {
            for m in [2.0, 5.0] {
                let Some(c) = axis.column(f64::from(k) + f64::log10(m)) else {
                    continue;
                };
                let text = tick_label(m, k);
                let w = text.chars().count() as u16;
                let start = c.saturating_sub(w / 2);
                if free(&taken, start, w) {
                    buf.set_string(start, axis.label_row, &text, style.fg(Color::DarkGray));
                    taken.push((start, start + w));
                }
            }
        }
    }
}
