//! Drawing: a pure function of the [`App`] state.

use super::app::{App, Focus, Tone};
use super::format::{decade, num3, qty, qty3};
use ratatui::Frame;
use ratatui::buffer::Buffer;
use ratatui::layout::{Alignment, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Block, Borders, Chart, Clear, Dataset, GraphType, Paragraph, Wrap};
use rime_core::params::{Kind, PARAMETERS, Value};
use rime_core::scene::{ContactEnd, Damping, DampingFormula, LayerReading};
use rime_core::{Status, StickClass};

/// Replaces spaces by non-breaking ones (a value and its unit stay on one line).
fn nb(s: String) -> String {
    s.replace(' ', "\u{a0}")
}

/// Smallest usable terminal.
pub const MIN_SIZE: (u16, u16) = (60, 20);

/// Where each part of the screen goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// Parameter panel.
    pub panel: Rect,
    /// ε_N chart (with its title and readout rows).
    pub chart: Rect,
    /// Stick map (with its title and readout rows).
    pub map: Rect,
    /// Derived quantities line.
    pub derived: Rect,
    /// Status line (accuracy, compute time, warnings).
    pub status: Rect,
    /// Message / input line (None on short terminals: the message joins the status line).
    pub message: Option<Rect>,
}

/// Splits a `w × h` screen, or `None` if it is below [`MIN_SIZE`].
pub fn layout(w: u16, h: u16) -> Option<Layout> {
    if w < MIN_SIZE.0 || h < MIN_SIZE.1 {
        return None;
    }
    let bottom = if h >= 24 { 3 } else { 2 };
    let main_h = h - bottom;
    let panel_w = (w * 3 / 8).clamp(26, 40);
    let right_w = w - panel_w;
    let chart_h = main_h * 11 / 20;
    Some(Layout {
        panel: Rect::new(0, 0, panel_w, main_h),
        chart: Rect::new(panel_w, 0, right_w, chart_h),
        map: Rect::new(panel_w, chart_h, right_w, main_h - chart_h),
        derived: Rect::new(0, main_h, w, 1),
        status: Rect::new(0, main_h + 1, w, 1),
        message: (bottom == 3).then(|| Rect::new(0, main_h + 2, w, 1)),
    })
}

/// Colour of each stick-map class (all distinct).
pub fn class_color(c: StickClass) -> Color {
    match c {
        StickClass::Rolling => Color::Green,
        StickClass::Sliding => Color::Blue,
        StickClass::RollingStop => Color::Yellow,
        StickClass::SlidingGap => Color::Magenta,
        StickClass::Aggregation => Color::Red,
        StickClass::NormalStickOnly => Color::Cyan,
        StickClass::Undefined => Color::DarkGray,
    }
}

/// Legend name of a class (the JSON name with spaces).
fn class_label(c: StickClass) -> String {
    c.name().replace('_', " ")
}

const FAMILY_COLORS: [Color; 5] = [
    Color::Blue,
    Color::Cyan,
    Color::Green,
    Color::LightMagenta,
    Color::LightBlue,
];
const CURRENT: Color = Color::Yellow;
const CLEAN: Color = Color::Gray;
const GS_LAYER: Color = Color::Red;
const GS_ADHESION: Color = Color::LightRed;
/// The Bridges et al. (1984) law: a dim line beneath the model's curves.
const BRIDGES: Color = Color::DarkGray;
/// The microgravity experiments' boxes (Heißelmann et al. 2010, Hill et al. 2015).
const BAND_COLORS: [Color; 2] = [Color::Magenta, Color::Indexed(208)];
/// Short legend names of the bands, in the order of `experiments::bands`.
const BAND_SHORT: [&str; 2] = ["Heißelmann'10", "Hill'15"];
const BAND_TINY: [&str; 2] = ["H10", "H15"];

/// Draws the whole screen.
pub fn render(app: &App, frame: &mut Frame) {
    let area = frame.area();
    let Some(l) = layout(area.width, area.height) else {
        too_small(frame, area);
        return;
    };
    panel(app, frame, l.panel);
    chart(app, frame, l.chart);
    map(app, frame.buffer_mut(), l.map);
    frame.render_widget(
        Paragraph::new(derived_line(app, l.derived.width)),
        l.derived,
    );
    let message = message_line(app);
    match l.message {
        Some(r) => {
            frame.render_widget(Paragraph::new(status_line(app, l.status.width)), l.status);
            frame.render_widget(Paragraph::new(message), r);
        }
        None => {
            let mut line = if app.input.is_some() || app.open.is_some() {
                Line::default()
            } else {
                status_line(app, l.status.width)
            };
            if !line.spans.is_empty() {
                line.spans.push(Span::raw(" │ "));
            }
            line.spans.extend(message.spans);
            frame.render_widget(Paragraph::new(line), l.status);
        }
    }
    if app.tidal {
        let r = Rect::new(
            l.chart.x,
            l.chart.y,
            l.chart.width,
            l.chart.height + l.map.height,
        );
        super::tidal::render(app, frame, r);
    }
    if app.help {
        help(frame, area);
    }
}

fn too_small(frame: &mut Frame, area: Rect) {
    let text = vec![
        Line::from(Span::styled(
            format!("terminal too small (need {}×{})", MIN_SIZE.0, MIN_SIZE.1),
            Style::new().add_modifier(Modifier::BOLD),
        )),
        Line::from(format!("now {}×{}", area.width, area.height)),
        Line::from("enlarge the window, or q to quit"),
    ];
    let h = (text.len() as u16).min(area.height);
    let y = area.y + area.height.saturating_sub(h) / 2;
    frame.render_widget(
        Paragraph::new(text)
            .alignment(Alignment::Center)
            .wrap(Wrap { trim: true }),
        Rect::new(area.x, y, area.width, h),
    );
}

/// The text of a parameter's value with its unit (`—` when inactive).
pub fn value_text(app: &App, path: &str, unit: &str) -> (String, bool) {
    match app.scene.get(path) {
        Ok(Value::Number(v)) => (qty(v, unit), true),
        Ok(Value::Choice(c)) => (c.to_string(), true),
        Ok(Value::Enabled(b)) => ((if b { "on" } else { "off" }).to_string(), true),
        Ok(Value::Inactive) | Err(_) => ("—".to_string(), false),
    }
}

fn panel(app: &App, frame: &mut Frame, area: Rect) {
    let block = Block::new()
        .borders(Borders::RIGHT)
        .border_style(Style::new().fg(Color::DarkGray));
    let inner = block.inner(area);
    frame.render_widget(block, area);
    if inner.height == 0 || inner.width < 4 {
        return;
    }
    let preset = app
        .preset
        .and_then(|i| rime_core::Preset::ALL.get(i))
        .map_or("custom".to_string(), |p| p.name().to_string());
    let title_style = if app.focus == Focus::Panel {
        Style::new().add_modifier(Modifier::BOLD).fg(Color::White)
    } else {
        Style::new().add_modifier(Modifier::BOLD).fg(Color::Gray)
    };
    let mut lines = vec![Line::from(vec![
        Span::styled("Parameters", title_style),
        Span::styled(format!(" · {preset}"), Style::new().fg(Color::Gray)),
    ])];
    let rows = inner.height.saturating_sub(1) as usize;
    let offset = if app.selected >= rows {
        app.selected + 1 - rows
    } else {
        0
    };
    let w = inner.width as usize;
    for (k, p) in PARAMETERS.iter().enumerate().skip(offset).take(rows) {
        let (value, active) = value_text(app, p.path, p.unit);
        let header = matches!(p.kind, Kind::Toggle);
        let selected = k == app.selected;
        let marker = if selected { "▸" } else { " " };
        let vw = value.chars().count();
        let label_w = w.saturating_sub(vw + 2);
        let mut label: String = p.label.chars().take(label_w).collect();
        let pad = label_w.saturating_sub(label.chars().count());
        label.push_str(&" ".repeat(pad));
        let mut style = Style::new();
        if !active {
            style = style.fg(Color::DarkGray);
        } else if header {
            style = style.add_modifier(Modifier::BOLD);
        }
        if selected {
            style = if app.focus == Focus::Panel {
                style.bg(Color::Blue).fg(Color::White)
            } else {
                style.bg(Color::DarkGray)
            };
        }
        let value_style = if active && !header {
            style.fg(if selected {
                Color::White
            } else {
                Color::LightYellow
            })
        } else {
            style
        };
        lines.push(Line::from(vec![
            Span::styled(format!("{marker}{label} "), style),
            Span::styled(value, value_style),
        ]));
    }
    frame.render_widget(Paragraph::new(lines), inner);
}

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

fn log_points(g: &[f64], eps: impl Iterator<Item = f64>, y_lo: f64) -> Vec<(f64, f64)> {
    g.iter()
        .zip(eps)
        .filter(|(_, e)| e.is_finite() && *e > 0.0 && e.log10() >= y_lo)
        .map(|(g, e)| (g.log10(), e.log10()))
        .collect()
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

fn chart(app: &App, frame: &mut Frame, area: Rect) {
    let sweep = app.sweep_def();
    let focus = app.focus == Focus::Chart;
    let title_name = Span::styled(
        " ε_N(g_N) ",
        Style::new().add_modifier(Modifier::BOLD).fg(if focus {
            Color::White
        } else {
            Color::Gray
        }),
    );
    let title = Line::from(vec![
        title_name.clone(),
        Span::styled(
            format!("normal restitution · family over {} ", sweep.symbol),
            Style::new().fg(Color::Gray),
        ),
    ]);
    let block = Block::new()
        .borders(Borders::TOP | Borders::BOTTOM)
        .border_style(Style::new().fg(if focus { Color::White } else { Color::DarkGray }))
        .title_bottom(chart_readout(app));
    let inner = block.inner(area);
    let Some(data) = app.data.as_ref() else {
        frame.render_widget(block.title(title), area);
        frame.render_widget(Paragraph::new("computing…"), inner);
        return;
    };
    if inner.height < 4 {
        return;
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
    if data.clean.is_some() {
        legend.push(Span::styled(
            "━\u{a0}clean\u{a0}surface ",
            Style::new().fg(CLEAN),
        ));
    }
    if !data.family.is_empty() {
        legend.push(Span::raw(format!("{}:", sweep.symbol)));
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
                format!(
                    "┊\u{a0}g_s\u{a0}adhesion\u{a0}{} ",
                    nb(qty(a.critical_velocity, "m/s"))
                ),
                Style::new().fg(GS_ADHESION),
            ));
        }
    }
    let bands = rime_core::figure::experiments::bands(0);
    // The experiments' legend: long names where two legend rows hold them, else short ones (the
    // help names them), else in the chart's title.
    let mut experiments_in_title = false;
    if app.experiments {
        let used: usize = legend.iter().map(|s| s.content.chars().count()).sum();
        // Word wrapping wastes a few cells per row.
        let room = (2 * inner.width as usize).saturating_sub(8);
        let long = used + 40 <= room;
        if long || used + 16 <= room {
            legend.extend(experiment_legend(long));
        } else {
            experiments_in_title = true;
        }
    }
    if experiments_in_title {
        let mut spans = vec![
            title_name,
            Span::styled(
                format!("· over {} ", sweep.symbol),
                Style::new().fg(Color::Gray),
            ),
        ];
        spans.extend(experiment_legend(false));
        frame.render_widget(block.title(Line::from(spans)), area);
    } else {
        frame.render_widget(block.title(title), area);
    }
    let legend_w: usize = legend.iter().map(|s| s.content.chars().count()).sum();
    let legend_h = if legend_w > inner.width as usize && inner.height >= 8 {
        2
    } else {
        1
    };
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
        return;
    }
    // Axis ranges (log10).
    let (Some(g0), Some(g1)) = (data.g.first(), data.g.last()) else {
        return;
    };
    let (x_lo, x_hi, x_step) = decade_axis(
        g0.log10().floor() as i32,
        g1.log10().ceil() as i32,
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
    if app.experiments {
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
    let y_lo_f = f64::from(y_lo);
    let current_pts = log_points(
        &data.g,
        data.current.iter().map(|n| n.map_or(f64::NAN, |n| n.eps)),
        y_lo_f,
    );
    let clean_pts = data
        .clean
        .as_ref()
        .map(|c| log_points(&data.g, c.iter().copied(), y_lo_f));
    let family_pts: Vec<Vec<(f64, f64)>> = data
        .family
        .iter()
        .map(|m| log_points(&data.g, m.eps.iter().copied(), y_lo_f))
        .collect();
    let vline = |x: f64| vec![(x, y_lo_f), (x, f64::from(y_hi))];
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
    let y_hi_f = f64::from(y_hi);
    let clip_y = |e: f64| e.log10().clamp(y_lo_f, y_hi_f);
    let bridges_pts: Vec<(f64, f64)> = if app.experiments {
        data.g
            .iter()
            .map(|&g| {
                let e = rime_core::fit::BRIDGES_1984.eval(g).min(1.0);
                (g.log10(), e.log10())
            })
            .filter(|(_, e)| e.is_finite() && *e >= y_lo_f)
            .collect()
    } else {
        Vec::new()
    };
    let band_pts: Vec<(Vec<(f64, f64)>, Color)> = if app.experiments {
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
    for (k, pts) in family_pts.iter().enumerate() {
        datasets.push(line(pts, fg(FAMILY_COLORS[k % FAMILY_COLORS.len()])));
    }
    if let Some(pts) = &clean_pts {
        datasets.push(line(pts, fg(CLEAN)));
    }
    // The experiments above the family (else the curves hide them), below this scene's curve.
    if !bridges_pts.is_empty() {
        datasets.push(line(&bridges_pts, fg(BRIDGES)));
    }
    for (pts, color) in band_pts.iter().chain(&markers) {
        datasets.push(line(pts, fg(*color)));
    }
    if let Some(pts) = &cursor_pts {
        datasets.push(line(pts, fg(Color::White)));
    }
    datasets.push(line(
        &current_pts,
        Style::new().fg(CURRENT).add_modifier(Modifier::BOLD),
    ));
    let axis_style = Style::new().fg(Color::Gray);
    let chart = Chart::new(datasets)
        .x_axis(
            Axis::default()
                .title("g_N")
                .style(axis_style)
                .bounds([f64::from(x_lo), f64::from(x_hi)])
                .labels(labels(x_lo, x_hi, x_step, " m/s")),
        )
        .y_axis(
            Axis::default()
                .title("ε_N")
                .style(axis_style)
                .bounds([y_lo_f, f64::from(y_hi)])
                .labels(labels(y_lo, y_hi, y_step, "")),
        )
        .legend_position(None);
    frame.render_widget(chart, plot);
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
}

/// Legend entries of the Bridges law and the experiments' boxes (long or short names).
fn experiment_legend(long: bool) -> Vec<Span<'static>> {
    let mut out = vec![Span::styled(
        if long {
            "┄\u{a0}Bridges'84 "
        } else {
            "┄B84 "
        },
        Style::new().fg(Color::Gray),
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

fn chart_readout(app: &App) -> Line<'static> {
    let Some(data) = app.data.as_ref() else {
        return Line::default();
    };
    let Some(g) = data.g.get(app.cursor).copied() else {
        return Line::default();
    };
    let mut spans = vec![
        Span::styled(" ▸ ", Style::new().fg(Color::White)),
        Span::raw(format!("{}  ", qty3(g, "m/s"))),
    ];
    match data.current.get(app.cursor).copied().flatten() {
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

fn map(app: &App, buf: &mut Buffer, area: Rect) {
    use ratatui::widgets::Widget;
    let focus = app.focus == Focus::Map;
    let title = Line::from(vec![
        Span::styled(
            " stick map ",
            Style::new().add_modifier(Modifier::BOLD).fg(if focus {
                Color::White
            } else {
                Color::Gray
            }),
        ),
        Span::styled("classes over (g_N ↑, g_T →) ", Style::new().fg(Color::Gray)),
    ]);
    let block = Block::new()
        .borders(Borders::TOP | Borders::BOTTOM)
        .border_style(Style::new().fg(if focus { Color::White } else { Color::DarkGray }))
        .title(title)
        .title_bottom(map_readout(app));
    let inner = block.inner(area);
    block.render(area, buf);
    let Some(data) = app.data.as_ref() else {
        return;
    };
    let Some(m) = data.map.as_ref() else {
        let text = if data.scene.friction.is_none() {
            "friction is off: no tangential restitution (select 'friction', press Enter)"
        } else {
            "no stick map"
        };
        Paragraph::new(text)
            .style(Style::new().fg(Color::Gray))
            .wrap(Wrap { trim: true })
            .render(inner, buf);
        return;
    };
    let n = m.n();
    if n < 2 || inner.height < 3 || inner.width < 20 {
        return;
    }
    let legend_w: u16 = 20;
    let max_label = qty3(data.map_max, "m/s");
    let axis_w: u16 = (max_label.chars().count() as u16 + 1).max(6);
    let show_legend = inner.width >= axis_w + legend_w + 12;
    let plot_w = inner.width - axis_w - if show_legend { legend_w + 1 } else { 0 };
    let plot_h = inner.height - 1;
    let px = inner.x + axis_w;
    let py = inner.y;
    // Y axis labels.
    let put = |buf: &mut Buffer, x: u16, y: u16, s: &str, w: u16| {
        buf.set_stringn(x, y, s, w as usize, Style::new().fg(Color::Gray));
    };
    put(buf, inner.x, py, &max_label, axis_w - 1);
    if plot_h >= 3 {
        put(buf, inner.x, py + plot_h / 2, "g_N ↑", axis_w - 1);
    }
    put(buf, inner.x, py + plot_h - 1, "0", axis_w - 1);
    // X axis labels.
    let ly = py + plot_h;
    put(buf, px, ly, "0", plot_w);
    let mid = "g_T →";
    if plot_w > 16 {
        put(buf, px + plot_w / 2 - 3, ly, mid, 6);
    }
    let mw = max_label.chars().count() as u16;
    if plot_w > mw + 2 {
        put(buf, px + plot_w - mw, ly, &max_label, mw);
    }
    // One cell per terminal cell: the class letter on the class colour (readable without colour).
    let index = |k: u16, len: u16| -> usize {
        if len <= 1 {
            0
        } else {
            ((f64::from(k) * (n - 1) as f64 / f64::from(len - 1)).round() as usize).min(n - 1)
        }
    };
    for r in 0..plot_h {
        let i = index(plot_h - 1 - r, plot_h);
        for c in 0..plot_w {
            let j = index(c, plot_w);
            let Some(class) = m.class.get(i * n + j).copied() else {
                continue;
            };
            if let Some(cell) = buf.cell_mut((px + c, py + r)) {
                cell.set_char(class.letter())
                    .set_fg(Color::Black)
                    .set_bg(class_color(class));
            }
        }
    }
    // Cursor.
    let (ci, cj) = app.map_cursor;
    let to_cell = |k: usize, len: u16| -> u16 {
        ((k as f64 * f64::from(len - 1) / (n - 1) as f64).round() as u16).min(len - 1)
    };
    let cc = to_cell(cj, plot_w);
    let cr = plot_h - 1 - to_cell(ci, plot_h);
    if let Some(cell) = buf.cell_mut((px + cc, py + cr)) {
        cell.set_symbol("┼")
            .set_style(Style::new().fg(Color::Black).bg(Color::White));
    }
    // Legend.
    if show_legend {
        let lx = px + plot_w + 1;
        for (k, c) in StickClass::ALL.iter().enumerate() {
            let y = py + k as u16;
            if y >= inner.y + inner.height {
                break;
            }
            buf.set_string(
                lx,
                y,
                format!("{}", c.letter()),
                Style::new().fg(Color::Black).bg(class_color(*c)),
            );
            buf.set_stringn(
                lx + 2,
                y,
                class_label(*c),
                (legend_w - 3) as usize,
                Style::new().fg(Color::Gray),
            );
        }
        // The convention behind "stuck" (docs/physics.md#decision-7).
        let y = py + StickClass::ALL.len() as u16;
        if y < inner.y + inner.height {
            buf.set_stringn(
                lx,
                y,
                "ε_N<1e-9 = rebound",
                legend_w as usize,
                Style::new().fg(Color::DarkGray),
            );
        }
    }
}

fn map_readout(app: &App) -> Line<'static> {
    let Some(m) = app.data.as_ref().and_then(|d| d.map.as_ref()) else {
        return Line::default();
    };
    let n = m.n();
    let (i, j) = app.map_cursor;
    let (Some(gn), Some(gt)) = (m.g.get(i), m.g.get(j)) else {
        return Line::default();
    };
    let k = i * n + j;
    let (Some(class), Some(eps_t)) = (m.class.get(k), m.eps_t.get(k)) else {
        return Line::default();
    };
    Line::from(vec![
        Span::styled(" ▸ ", Style::new().fg(Color::White)),
        Span::raw(format!(
            "g_N {}  g_T {}  ε_T {} ",
            qty3(*gn, "m/s"),
            qty3(*gt, "m/s"),
            num3(*eps_t)
        )),
        Span::styled(
            format!("{} ", class_label(*class)),
            Style::new().fg(class_color(*class)),
        ),
    ])
}

fn derived_line(app: &App, width: u16) -> Line<'static> {
    let Some(data) = app.data.as_ref() else {
        return Line::from("computing…");
    };
    let Some(c) = data.contact.as_ref() else {
        return Line::from(Span::styled(
            data.error.clone().unwrap_or_default(),
            Style::new().fg(Color::Red),
        ));
    };
    let dim = Style::new().fg(Color::Gray);
    let g = data.g.get(app.cursor).copied().unwrap_or(f64::NAN);
    let delta = if g.is_finite() {
        num3(c.delta(g))
    } else {
        "—".into()
    };
    let tan = c.friction.map_or("—".to_string(), |f| {
        num3(rime_core::tangential::tan_psi0(&f))
    });
    let mut items = vec![
        ("R_eff", qty3(c.r_eff, "m")),
        ("m_eff", qty3(c.m_eff, "kg")),
        ("A", qty3(c.damping_time, "s")),
    ];
    if let Some(l) = c.layer {
        items.push(("g_s(layer)", qty3(l.critical_velocity, "m/s")));
    }
    if let Some(a) = c.adhesion {
        items.push(("g_s(adh.)", qty3(a.critical_velocity, "m/s")));
    }
    items.push(("tan ψ₀", tan));
    // δ at the cursor is also in the chart's readout; keep it here when there is room.
    let used: usize = items
        .iter()
        .map(|(n, v)| n.chars().count() + v.chars().count() + 3)
        .sum();
    if used + 6 + delta.chars().count() <= width as usize {
        items.push(("δ(g)", delta));
    }
    let mut spans = Vec::new();
    for (k, (name, value)) in items.into_iter().enumerate() {
        if k > 0 {
            spans.push(Span::raw("  "));
        }
        spans.push(Span::styled(format!("{name} "), dim));
        spans.push(Span::raw(value));
    }
    Line::from(spans)
}

/// Options in use that deviate from a physically consistent reading of the paper.
pub fn paper_options(app: &App) -> Vec<&'static str> {
    let s = &app.scene;
    let mut out = Vec::new();
    if s.layer.is_some_and(|l| l.reading == LayerReading::Literal) {
        out.push("layer.reading=literal");
    }
    if s.contact_end == ContactEnd::ZeroOverlap {
        out.push("contact_end=zero_overlap");
    }
    if matches!(s.bulk.damping, Damping::Viscosities(v) if v.formula == DampingFormula::AsPrinted) {
        out.push("A formula as_printed");
    }
    out
}

fn status_line(app: &App, width: u16) -> Line<'static> {
    let mut spans = vec![Span::styled(
        format!(" {} ", app.accuracy.name()),
        Style::new().fg(Color::Black).bg(Color::Cyan),
    )];
    if let Some(d) = &app.data {
        let t = app.fixed_elapsed.unwrap_or(d.elapsed);
        spans.push(Span::raw(format!(" {} ", qty(t.as_secs_f64(), "s"))));
    }
    if app.computing() {
        spans.push(Span::styled(" computing… ", Style::new().fg(Color::Yellow)));
    }
    let warn = Style::new().fg(Color::LightRed);
    if let Some(d) = &app.data {
        if let Some(Some(n)) = d.current.get(app.cursor)
            && n.status == Status::Overdamped
        {
            spans.push(Span::styled("│ ⚠ overdamped at cursor ", warn));
        }
        if let (Some(e), Some(_)) = (&d.error, &d.contact) {
            spans.push(Span::styled(format!("│ ⚠ {e} "), warn));
        }
        for note in &d.notes {
            spans.push(Span::styled(format!("│ {note} "), warn));
        }
    }
    let opts = paper_options(app);
    if !opts.is_empty() {
        let used: usize = spans.iter().map(|s| s.content.chars().count()).sum();
        let long = format!("│ ⚠ paper-inconsistent option in use: {}", opts.join(", "));
        let text = if used + long.chars().count() <= width as usize {
            long
        } else {
            format!("│ ⚠ paper-inconsistent: {}", opts.join(", "))
        };
        spans.push(Span::styled(text, Style::new().fg(Color::Yellow)));
    }
    Line::from(spans)
}

fn message_line(app: &App) -> Line<'static> {
    if let Some(text) = &app.open {
        return Line::from(vec![
            Span::styled(
                " open scene file: ",
                Style::new().fg(Color::Black).bg(Color::Yellow),
            ),
            Span::raw(format!(" {text}")),
            Span::styled("▏", Style::new().fg(Color::Yellow)),
            Span::styled(
                "  Enter load · Esc cancel · Ctrl-U clear",
                Style::new().fg(Color::Gray),
            ),
        ]);
    }
    if let Some(text) = &app.input {
        let p = PARAMETERS.get(app.selected);
        let label = p.map_or("", |p| p.label);
        let unit = p.map_or("", |p| p.unit);
        let unit = if unit.is_empty() {
            String::new()
        } else {
            format!(" [{unit}]")
        };
        return Line::from(vec![
            Span::styled(
                format!(" set {label}{unit}: "),
                Style::new().fg(Color::Black).bg(Color::Yellow),
            ),
            Span::raw(format!(" {text}")),
            Span::styled("▏", Style::new().fg(Color::Yellow)),
            Span::styled(
                "  Enter apply · Esc cancel · units ok (2 um, 1 kPa s)",
                Style::new().fg(Color::Gray),
            ),
        ]);
    }
    match &app.message {
        Some((text, Tone::Error)) => Line::from(Span::styled(
            format!(" ✗ {text}"),
            Style::new().fg(Color::LightRed),
        )),
        Some((text, Tone::Info)) => Line::from(Span::raw(format!(" {text}"))),
        None => Line::default(),
    }
}

/// The key map shown by `?` (key, what it does).
pub const KEYS: &[(&str, &str)] = &[
    ("↑/↓  j/k", "select parameter"),
    ("←/→  h/l", "change: ×/÷1.25 (log) or ±5% of range"),
    ("Shift+←/→  H/L", "fine change: ×/÷1.02 or ±1%"),
    ("Enter/space", "cycle a choice, switch an effect on/off"),
    ("e", "type an exact value with units (2 um)"),
    ("p", "next preset"),
    ("a", "next accuracy (fast/balanced/precise)"),
    ("s", "next swept parameter (family of curves)"),
    ("[ ] { }  wheel", "move the g_N cursor (fine, coarse)"),
    ("Tab", "focus: parameters → chart → stick map"),
    ("arrows (map focus)", "move the map cursor"),
    ("+ / - / 0", "stick map range ×2, ÷2, automatic"),
    ("b", "experiments on the ε_N chart on/off (sources below)"),
    (
        "t  (then < >)",
        "tidal appendix A.1–A.7 (planet distance ÷/×1.05)",
    ),
    ("x", "export CSV, SVG, PNG + scene JSON to rime-export-*/"),
    ("w / o", "save / open a scene JSON (rime-scene.json)"),
    ("?  /  q Esc Ctrl-C", "this help (any key closes) / quit"),
];

/// Sources of the experimental context and the tidal calculator, shown in the help.
pub const SOURCES: &str = "B84 Bridges, Hatzes & Lin 1984, Nature 309: ε = 0.32 (v/1 cm/s)^−0.234 · \
H10 Heißelmann et al. 2010, Icarus 206: 6–22 cm/s, ε 0.06–0.84 · \
H15 Hill et al. 2015, A&A 575: 0.27–0.51 m/s, ε 0.08–0.65 · t: Hertzsch 2002, appendix";

fn help(frame: &mut Frame, area: Rect) {
    let w = 78.min(area.width);
    let inner_w = w.saturating_sub(2).max(1) as usize;
    let source_rows = SOURCES.chars().count().div_ceil(inner_w) as u16 + 1;
    let h = (KEYS.len() as u16 + 3 + source_rows).min(area.height);
    let r = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    let mut lines: Vec<Line> = KEYS
        .iter()
        .map(|(k, d)| {
            Line::from(vec![
                Span::styled(format!("{k:>18}  "), Style::new().fg(Color::Yellow)),
                Span::raw(*d),
            ])
        })
        .collect();
    lines.push(Line::from(Span::styled(
        "ε_N: normal, ε_T: tangential restitution; speeds in m/s",
        Style::new().fg(Color::Gray),
    )));
    lines.push(Line::from(Span::styled(
        SOURCES,
        Style::new().fg(Color::Gray),
    )));
    frame.render_widget(Clear, r);
    frame.render_widget(
        Paragraph::new(lines).wrap(Wrap { trim: false }).block(
            Block::bordered()
                .title(" rime — keys ")
                .title_bottom(" any key closes "),
        ),
        r,
    );
}
