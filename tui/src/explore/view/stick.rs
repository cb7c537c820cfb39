//! The sticking-thresholds panel (`v`): v_stick(radius, temperature) for dust codes, from the
//! adhesion model with γ(T) of Musiolik & Wurm (2019) in this scene's material, beside the measured
//! 9.6 m/s for µm ice (docs/physics.md#sticking).

use crate::explore::format::qty3;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Wrap};
use rime_core::stick::{Convention, MEASURED_UM_ICE, Threshold, threshold};
use rime_core::{Accuracy, Scene};

/// Radii of the table \[m\].
pub const RADII: [f64; 5] = [1e-6, 1e-5, 1e-4, 1e-3, 1e-2];
/// Temperatures of the table \[K\].
pub const TEMPERATURES: [f64; 3] = [150.0, 180.0, 200.0];

/// The table: one row per radius, one threshold (or the error) per temperature.
pub fn table(scene: &Scene, accuracy: Accuracy) -> Vec<Vec<Result<Threshold, String>>> {
    RADII
        .iter()
        .map(|&r| {
            TEMPERATURES
                .iter()
                .map(|&t| {
                    threshold(scene, r, t, Convention::SurfaceEnergy, accuracy)
                        .map_err(|e| e.to_string())
                })
                .collect()
        })
        .collect()
}

/// How a table shows one threshold.
type CellText = fn(&Threshold) -> String;

/// The panel's lines: two narrow tables (they fit an 80×24 terminal) and the gap to the measurement.
pub fn lines(rows: &[Vec<Result<Threshold, String>>]) -> Vec<Line<'static>> {
    let dim = Style::new().fg(Color::Gray);
    let mut out = vec![Line::from(Span::styled(
        "γ(T) of Musiolik & Wurm 2019, this scene's material",
        dim,
    ))];
    let tables: [(&str, CellText); 2] = [
        ("v_stick (model)", |t| {
            t.v_stick.map_or("always".into(), |v| qty3(v, "m/s"))
        }),
        ("v_el (Eq. (15))", |t| qty3(t.v_elastic, "m/s")),
    ];
    for (title, cell) in tables {
        let mut head = vec![Span::styled(
            format!("{title:<17}"),
            Style::new().fg(Color::White),
        )];
        for t in TEMPERATURES {
            head.push(Span::styled(format!("{:>10}", format!("{t} K")), dim));
        }
        out.push(Line::from(head));
        for (r, row) in RADII.iter().zip(rows) {
            let mut spans = vec![Span::raw(format!("{:>17}", qty3(*r, "m")))];
            for c in row {
                let text = match c {
                    Ok(t) => cell(t),
                    Err(_) => "error".into(),
                };
                spans.push(Span::raw(format!("{text:>10}")));
            }
            out.push(Line::from(spans));
        }
    }
    // The gap to the measurement, plainly (1 µm at 200 K, where γ is largest).
    if let Some(Ok(t)) = rows.first().and_then(|r| r.last()) {
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

/// Draws the panel over `area`.
pub fn render(frame: &mut Frame, area: Rect, rows: &[Vec<Result<Threshold, String>>]) {
    frame.render_widget(Clear, area);
    let block = Block::bordered()
        .border_style(Style::new().fg(Color::White))
        .title(Span::styled(
            " sticking thresholds for dust codes ",
            Style::new().add_modifier(Modifier::BOLD),
        ))
        .title_bottom(" rime stick --out DIR: table + C function · v closes ");
    let inner = block.inner(area);
    frame.render_widget(block, area);
    frame.render_widget(
        Paragraph::new(lines(rows)).wrap(Wrap { trim: false }),
        inner,
    );
}
