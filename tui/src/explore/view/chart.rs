//! The ε_N chart: the core's figure of the frame ([`figures::eps_figure`], what `x` exports and
//! the page draws) drawn by the one terminal adapter ([`super::plot`]), with the cursor and its
//! readout.

use super::plot::{self, Colors};
use crate::explore::compute::{Computed, Sweep};
use crate::explore::format::{num3, qty3};
use crate::explore::layout::LogAxis;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Paragraph, Wrap};
use rime_core::Status;
use rime_core::explorer::figures::{self, Pinned};
use rime_core::explorer::palette;
use rime_core::figure::Stroke;

/// What the ε_N chart shows.
#[derive(Debug, Clone, Copy)]
pub struct ChartView<'a> {
    /// The latest frame (None before the first one).
    pub data: Option<&'a Computed>,
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
    pub pinned: Option<&'a Pinned>,
    /// Whether the chart shares its pane with the stick map (the title says how to switch).
    pub shared: bool,
    /// The terminal's colours.
    pub colors: Colors,
    /// The ring card, whose ε_cr line and meeting point go on the chart.
    pub ring: Option<&'a rime_core::explorer::ring::RingCard>,
}

/// The figure this chart shows: the core's, for the same view `x` exports.
pub fn figure(data: &Computed, app: &ChartView) -> rime_core::figure::Figure {
    let view = figures::View {
        y_log: app.y_log,
        experiments: app.experiments,
        pinned: app.pinned.cloned(),
    };
    let mut fig = figures::eps_figure(&data.frame, &view, env!("CARGO_PKG_VERSION"));
    if let Some(card) = app.ring {
        card.overlay(&mut fig);
    }
    fig
}

/// Draws the ε_N chart: the core's figure with the cursor, and the readout. Returns the speed
/// axis as drawn (for mouse clicks).
// Long by design: one pane drawn top to bottom (title, figure, cursor readout) with the layout
// shared by its parts.
pub fn chart(frame: &mut Frame, area: Rect, app: &ChartView) -> Option<LogAxis> {
    let focus = app.focused;
    let axis_word = if app.y_log { "log" } else { "linear" };
    let mut title_spans = vec![
        Span::styled(
            " ε_N(g_N) ",
            Style::new().add_modifier(Modifier::BOLD).fg(if focus {
                Color::Cyan
            } else {
                Color::Gray
            }),
        ),
        Span::styled(
            if app.shared {
                format!("{axis_word} axis ")
            } else {
                let sweep = app.sweep;
                match app.data.filter(|d| sweep.available(&d.request.scene)) {
                    Some(d) => {
                        let value = format!(
                            "this scene: {} {}",
                            sweep.symbol,
                            qty3(sweep.current(&d.request.scene), sweep.unit)
                        );
                        // What the family is, where the title has room for it.
                        let long = figures::family_meaning(&d.frame)
                            .map(|m| format!("{value} · {m} · {axis_word} axis "))
                            .filter(|t| t.chars().count() + 16 <= usize::from(area.width));
                        long.unwrap_or(format!("{value} · {axis_word} axis "))
                    }
                    None => format!("normal restitution · {axis_word} axis "),
                }
            },
            Style::new().fg(Color::Gray),
        ),
    ];
    if app.shared {
        title_spans.push(Span::styled(
            "│ stick map: Tab ",
            Style::new().fg(Color::Yellow),
        ));
    }
    let (kind, border_style) = super::pane_border(focus);
    let block = Block::new()
        .borders(Borders::TOP | Borders::BOTTOM)
        .border_type(kind)
        .border_style(border_style)
        .title(Line::from(title_spans))
        .title_bottom(chart_readout(app.data, app.cursor, app.colors, area.width));
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let Some(data) = app.data else {
        frame.render_widget(Paragraph::new("computing…"), inner);
        return None;
    };
    if inner.height < 4 {
        return None;
    }
    if let Some(e) = data.problem()
        && data.contact.is_none()
    {
        frame.render_widget(
            Paragraph::new(format!("cannot evaluate this scene: {e}"))
                .style(Style::new().fg(Color::Red))
                .wrap(Wrap { trim: true }),
            inner,
        );
        return None;
    }
    let fig = figure(data, app);
    let bold = fig
        .series
        .iter()
        .position(|s| s.color == palette::SERIES_SCENE && s.stroke == Stroke::Solid);
    let opts = plot::Options {
        colors: app.colors,
        cursor: data.g.get(app.cursor).copied(),
        // Tall charts give each comparison (`c`) a row: they carry temperature, geometry, score.
        legend_rows: if inner.height >= 16 {
            2 + data.overlays.len().clamp(1, 5) as u16
        } else {
            2
        },
        bold,
        y_title: false,
    };
    let drawn = plot::draw(frame.buffer_mut(), inner, &fig, &opts)?;
    // Nothing of this scene on the axis: say why rather than show an empty chart.
    let shown = bold.and_then(|k| fig.series.get(k)).is_some_and(|s| {
        s.points
            .iter()
            .any(|(_, e)| e.is_finite() && (!fig.y.log || *e > 0.0))
    });
    if !shown {
        let first = data
            .curve
            .iter()
            .flat_map(|c| c.points.iter().flatten())
            .next();
        let msg = match first.map(|n| n.status) {
            Some(Status::Overdamped) => "overdamped everywhere: ε_N below the plotted range",
            Some(Status::StuckInLayer | Status::StuckByAdhesion) => "stuck at every speed shown",
            _ => "no rebound to plot",
        };
        let plot = drawn.graph;
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
    Some(drawn.x_axis)
}

/// The chart's readout at the cursor: speed, ε_N, status, contact time and δ, within `width`
/// cells: fields are dropped whole from the end (δ, then t_c; δ is also on the derived line when
/// there is room), never cut mid-number (issue 37: `δ 2.` for 2.25e4 at 80 columns); what still
/// does not fit ends in `…`.
fn chart_readout(
    data: Option<&Computed>,
    cursor: usize,
    colors: Colors,
    width: u16,
) -> Line<'static> {
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
    // Fields that may be dropped whole, most telling first.
    let mut optional = Vec::new();
    match data.point(cursor) {
        Some(n) => {
            let eps = match n.status {
                Status::StuckInLayer | Status::StuckByAdhesion => "0".to_string(),
                _ => num3(n.eps),
            };
            spans.push(Span::styled(
                format!("ε_N {eps} "),
                colors.fg(palette::SCENE).add_modifier(Modifier::BOLD),
            ));
            let st_color = match n.status {
                Status::Rebound => Color::Green,
                _ => Color::Red,
            };
            spans.push(Span::styled(n.status.label(), Style::new().fg(st_color)));
            let t_c = if n.t_c.is_finite() {
                qty3(n.t_c, "s")
            } else {
                "— (stuck)".into()
            };
            let delta = data.contact.map_or("—".to_string(), |c| num3(c.delta(g)));
            optional.push(Span::raw(format!("  t_c {t_c}")));
            optional.push(Span::raw(format!("  δ {delta}")));
        }
        None => spans.push(Span::raw("ε_N — ")),
    }
    // The block has top and bottom borders only: the title may take the whole width.
    let room = usize::from(width);
    let len = |spans: &[Span]| {
        spans
            .iter()
            .map(|s| s.content.chars().count())
            .sum::<usize>()
    };
    let mut keep = optional.len();
    while keep > 0 && len(&spans) + len(&optional[..keep]) > room {
        keep -= 1;
    }
    spans.extend(optional.into_iter().take(keep));
    if len(&spans) < room {
        spans.push(Span::raw(" "));
    }
    super::lines::fit(spans, room, "…")
}
