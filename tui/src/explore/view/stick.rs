//! The sticking-thresholds panel (`v`): v_stick(radius, temperature) for dust codes, from the
//! adhesion model with γ(T) of Musiolik & Wurm (2019) in this scene's material, beside the measured
//! 9.6 m/s for µm ice (docs/physics.md#sticking).

use super::plot::{self, Colors};
use crate::explore::format::qty3;
use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Wrap};
use rime_core::explorer::thresholds::thresholds_figure;
use rime_core::stick::{MEASURED_UM_ICE, Threshold, ThresholdTable};

/// How a table shows one threshold.
type CellText = fn(&Threshold) -> String;

/// The panel's lines: two narrow tables (they fit an 80×24 terminal) and the gap to the measurement.
/// Each table's title says which values it uses: v_stick the scene's A (and layer), v_el A = 0.
pub fn lines(table: &ThresholdTable) -> Vec<Line<'static>> {
    let dim = Style::new().fg(Color::Gray);
    let mut out = vec![Line::from(Span::styled(
        "γ(T) of Musiolik & Wurm 2019 and the row's radius, this scene's material",
        dim,
    ))];
    let tables: [(String, CellText); 2] = [
        (format!("v_stick, {}", table.v_stick_note()), |t| {
            t.v_stick.map_or("always".into(), |v| qty3(v, "m/s"))
        }),
        ("v_el, Eq. (15): A = 0, no layer".into(), |t| {
            qty3(t.v_elastic, "m/s")
        }),
    ];
    for (title, cell) in tables {
        out.push(Line::from(Span::styled(
            title,
            Style::new().fg(Color::White),
        )));
        let mut head = vec![Span::styled(format!("{:>17}", "radius"), dim)];
        for t in &table.temperatures {
            head.push(Span::styled(format!("{:>10}", format!("{t} K")), dim));
        }
        out.push(Line::from(head));
        for (i, r) in table.radii.iter().enumerate() {
            let mut spans = vec![Span::raw(format!("{:>17}", qty3(*r, "m")))];
            for j in 0..table.temperatures.len() {
                let text = match table.cell(i, j).and_then(|c| c.threshold.as_ref()) {
                    Some(t) => cell(t),
                    None => "error".into(),
                };
                spans.push(Span::raw(format!("{text:>10}")));
            }
            out.push(Line::from(spans));
        }
    }
    // The gap to the measurement, plainly (the smallest radius at the warmest temperature, where
    // γ is largest).
    let last = table.temperatures.len().saturating_sub(1);
    if let Some(t) = table.cell(0, last).and_then(|c| c.threshold.as_ref()) {
        out.push(Line::from(Span::styled(
            format!(
                "µm ice sticks up to {MEASURED_UM_ICE} m/s (Gundlach & Blum 2015); JKR alone gives {}, {:.1}× short",
                qty3(t.v_elastic, "m/s"),
                MEASURED_UM_ICE / t.v_elastic
            ),
            Style::new().fg(Color::Yellow),
        )));
    }
    out
}

/// Rows the figure needs to be worth drawing (axes, legend and a few rows of graph).
const FIGURE_MIN_ROWS: u16 = 12;

/// Draws the panel over `area`: the tables, and below them, where the terminal is tall enough, the
/// core's figure of the same numbers ([`thresholds_figure`]) drawn by the one adapter.
pub fn render(frame: &mut Frame, area: Rect, table: &ThresholdTable, colors: Colors) {
    let inner = super::overlay_panel(
        frame,
        area,
        "sticking thresholds for dust codes",
        "rime stick --out DIR: table + C function · v closes",
    );
    let text = lines(table);
    // Rows the tables take once wrapped to the panel's width.
    let wrapped: u16 = text
        .iter()
        .map(|l| (l.width() as u16).div_ceil(inner.width.max(1)).max(1))
        .sum();
    let spare = inner.height.saturating_sub(wrapped + 1);
    let (tables, plot) = if spare >= FIGURE_MIN_ROWS {
        let [t, _, p] = Layout::vertical([
            Constraint::Length(wrapped),
            Constraint::Length(1),
            Constraint::Fill(1),
        ])
        .areas(inner);
        (t, Some(p))
    } else {
        (inner, None)
    };
    frame.render_widget(Paragraph::new(text).wrap(Wrap { trim: false }), tables);
    if let Some(p) = plot {
        let opts = plot::Options {
            colors,
            cursor: None,
            legend_rows: 3,
            bold: None,
            y_title: true,
        };
        plot::draw(frame.buffer_mut(), p, &thresholds_figure(table), &opts);
    }
}
