//! The tidal-appendix calculator's view: the inputs, Eq. (A.1)–(A.7) beside the paper's printed
//! numbers (compared only when the inputs are the paper's), and the verdict.

use crate::explore::format::{qty3, sig};
use crate::explore::tidal::TidalView;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Wrap};
use rime_core::explorer::tidal::{Comparison, NOT_COMPARABLE, SATURN_RADIUS};
use rime_core::tidal::TidalInput;

/// A value with its unit in the calculator's format: 4 significant digits, plain SI, powers of ten
/// outside 0.1 … 1e4 (as the paper prints them).
fn v(x: f64, unit: &str) -> String {
    let a = x.abs();
    if a == 0.0 || (0.1..1e4).contains(&a) || !x.is_finite() {
        return format!("{} {unit}", sig(x, 4));
    }
    let s = format!("{x:.3e}");
    match s.split_once('e') {
        Some((m, e)) => {
            let m = m.trim_end_matches('0').trim_end_matches('.');
            format!("{m}e{e} {unit}")
        }
        None => format!("{s} {unit}"),
    }
}

/// The colour of a comparison's mark: green where the print is reproduced, yellow within 5 %,
/// red beyond.
fn mark_color(c: &Comparison) -> Color {
    if c.agrees {
        Color::Green
    } else if c.relative.abs() < 0.05 {
        Color::Yellow
    } else {
        Color::LightRed
    }
}

/// The calculator's lines: the core's card laid out (its rows, marks, notes and verdict).
pub fn lines(t: &TidalView) -> Vec<Line<'static>> {
    let dim = Style::new().fg(Color::Gray);
    let input = t.input;
    let mut out = vec![
        Line::from(vec![
            Span::styled("planet ", dim),
            Span::raw(format!("Saturn, M {} kg", sig(input.planet_mass, 4))),
        ]),
        Line::from(vec![
            Span::styled("d ", dim),
            Span::raw(v(input.distance, "m")),
            Span::styled(
                format!(
                    " = Encke division ×{} (< >)",
                    sig(input.distance / TidalInput::default().distance, 4)
                ),
                dim,
            ),
        ]),
        Line::from(vec![
            Span::styled("grains ", dim),
            Span::raw(format!(
                "r {} · ρ {} kg/m³",
                qty3(input.radius, "m"),
                sig(input.density, 4)
            )),
            Span::styled(" (scene)", dim),
        ]),
        Line::from(vec![
            Span::styled("γ ", dim),
            Span::raw(format!("{} J/m²", sig(input.surface_energy, 4))),
            if t.gamma_from_paper {
                Span::styled(
                    " paper's value: adhesion is off",
                    Style::new().fg(Color::Yellow),
                )
            } else {
                Span::styled(" (scene's adhesion)", dim)
            },
        ]),
    ];
    let card = match &t.card {
        Ok(c) => c,
        Err(e) => {
            out.push(Line::from(Span::styled(
                format!("cannot evaluate: {e}"),
                Style::new().fg(Color::LightRed),
            )));
            return out;
        }
    };
    if card.inside_planet {
        out.push(Line::from(Span::styled(
            format!(
                "⚠ d is inside Saturn (radius {}): no ring particle orbits there",
                v(SATURN_RADIUS, "m")
            ),
            Style::new()
                .fg(Color::LightRed)
                .add_modifier(Modifier::BOLD),
        )));
    }
    let paper_head = if card.paper_inputs {
        "paper"
    } else {
        "paper (its inputs)"
    };
    out.push(Line::from(Span::styled(
        format!("{:<13}{:>12}  {paper_head}", "", "this"),
        dim.add_modifier(Modifier::BOLD),
    )));
    const SUPERSCRIPTS: [&str; 4] = ["¹", "²", "³", "⁴"];
    let mut footnotes = Vec::new();
    for row in &card.rows {
        let name = if row.equation.is_empty() {
            row.short.to_string()
        } else {
            format!("{} {}", row.short, row.equation)
        };
        let mut spans = vec![Span::styled(format!("{name:<13}"), dim)];
        let Some(value) = row.computed else {
            spans.push(Span::styled(
                row.note.to_string(),
                Style::new().fg(Color::LightYellow),
            ));
            out.push(Line::from(spans));
            continue;
        };
        spans.push(Span::styled(
            format!("{:>12}", v(value, row.unit)),
            Style::new().fg(Color::LightYellow),
        ));
        let paper = row.printed.map_or("—".to_string(), |p| v(p, row.unit));
        spans.push(Span::raw(format!("  {paper:<10}")));
        if let Some(c) = &row.comparison {
            spans.push(Span::styled(
                format!(" {}", c.mark),
                Style::new().fg(mark_color(c)),
            ));
        }
        if card.paper_inputs && !row.footnote.is_empty() {
            let mark = SUPERSCRIPTS[footnotes.len().min(SUPERSCRIPTS.len() - 1)];
            footnotes.push(format!("{mark} {}", row.footnote));
            spans.push(Span::styled(mark, Style::new().fg(Color::Yellow)));
        }
        out.push(Line::from(spans));
    }
    // The core's one verdict (the page and `rime tidal` say the same).
    let color = if card.holds {
        Color::Green
    } else {
        Color::LightRed
    };
    out.push(Line::from(Span::styled(
        card.verdict.clone(),
        Style::new().fg(color),
    )));
    if card.paper_inputs {
        for n in footnotes {
            out.push(Line::from(Span::styled(n, Style::new().fg(Color::Gray))));
        }
    } else {
        out.push(Line::from(Span::styled(
            NOT_COMPARABLE,
            Style::new().fg(Color::Gray),
        )));
    }
    out
}

/// Draws the calculator over `area` (the chart and the stick map).
pub fn render(frame: &mut Frame, area: Rect, view: &TidalView) {
    let inner = super::overlay_panel(
        frame,
        area,
        "tidal appendix A.1–A.7",
        "< > distance ÷×1.05 · t/Esc closes",
    );
    frame.render_widget(
        Paragraph::new(lines(view)).wrap(Wrap { trim: false }),
        inner,
    );
}
