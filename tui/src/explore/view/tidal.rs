//! The tidal-appendix calculator's view: the inputs, Eq. (A.1)–(A.7) beside the paper's printed
//! numbers (compared only when the inputs are the paper's), and the verdict.

use crate::explore::format::{qty3, sig};
use crate::explore::tidal::TidalView;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Wrap};
use rime_core::tidal::{PAPER_QUOTED, TidalInput};

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

/// How a computed value compares with the printed one.
fn compare(computed: f64, printed: f64) -> (String, Color) {
    let rel = (computed - printed) / printed;
    if rel.abs() < 0.002 {
        ("✓".into(), Color::Green)
    } else if rel.abs() < 0.05 {
        (format!("≈ {:+.1} %", rel * 100.0), Color::Yellow)
    } else {
        (
            format!("✗ ×{}", sig(computed / printed, 3)),
            Color::LightRed,
        )
    }
}

/// The calculator's lines.
// Long by design: the appendix's rows (A.1)–(A.7) in the paper's order, one short block each.
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
    if t.inside_planet {
        out.push(Line::from(Span::styled(
            format!(
                "⚠ d is inside Saturn (radius {}): no ring particle orbits there",
                v(crate::explore::tidal::SATURN_RADIUS, "m")
            ),
            Style::new()
                .fg(Color::LightRed)
                .add_modifier(Modifier::BOLD),
        )));
    }
    let tidal = match &t.result {
        Ok(r) => *r,
        Err(e) => {
            out.push(Line::from(Span::styled(
                format!("cannot evaluate: {e}"),
                Style::new().fg(Color::LightRed),
            )));
            return out;
        }
    };
    let q = PAPER_QUOTED;
    // (name, computed, paper's number, note key)
    let r_max = match tidal.r_max {
        Some(r) => v(r, "m"),
        None => "none: outside the Roche zone".to_string(),
    };
    let rows: [(&str, String, Option<f64>, &str, &str); 7] = [
        (
            "ΔF tide A.1",
            v(tidal.delta_f, "N"),
            Some(q.delta_f),
            "N",
            "",
        ),
        (
            "F_s adh A.2",
            v(tidal.surface_force, "N"),
            Some(q.surface_force),
            "N",
            "¹",
        ),
        (
            "  = πγr",
            v(tidal.surface_force_paper, "N"),
            Some(q.surface_force),
            "N",
            "",
        ),
        ("F_g grav A.3", v(tidal.gravity, "N"), None, "", ""),
        (
            "d_Roche A.7",
            v(tidal.d_roche, "m"),
            Some(q.d_roche),
            "m",
            "",
        ),
        ("d_min A.6", v(tidal.d_min, "m"), Some(q.d_min), "m", "²"),
        ("r_max A.5", r_max, Some(q.r_max), "m", "³"),
    ];
    let computed_values = [
        Some(tidal.delta_f),
        Some(tidal.surface_force),
        Some(tidal.surface_force_paper),
        Some(tidal.gravity),
        Some(tidal.d_roche),
        Some(tidal.d_min),
        tidal.r_max,
    ];
    let paper_head = if t.paper_inputs {
        "paper"
    } else {
        "paper (its inputs)"
    };
    out.push(Line::from(Span::styled(
        format!("{:<13}{:>12}  {paper_head}", "", "this"),
        dim.add_modifier(Modifier::BOLD),
    )));
    for ((name, computed, printed, unit, note), value) in rows.into_iter().zip(computed_values) {
        let mut spans = vec![Span::styled(format!("{name:<13}"), dim)];
        if value.is_none() {
            spans.push(Span::styled(computed, Style::new().fg(Color::LightYellow)));
            out.push(Line::from(spans));
            continue;
        }
        spans.push(Span::styled(
            format!("{computed:>12}"),
            Style::new().fg(Color::LightYellow),
        ));
        let paper = printed.map_or("—".to_string(), |p| v(p, unit));
        spans.push(Span::raw(format!("  {paper:<11}")));
        if let (true, Some(c), Some(p)) = (t.paper_inputs, value, printed) {
            let (mark, color) = compare(c, p);
            spans.push(Span::styled(format!(" {mark}"), Style::new().fg(color)));
        }
        if t.paper_inputs && !note.is_empty() {
            spans.push(Span::styled(
                note.to_string(),
                Style::new().fg(Color::Yellow),
            ));
        }
        out.push(Line::from(spans));
    }
    // Verdict: the pair separates where the tidal pull exceeds adhesion plus self-gravity.
    // The core's one verdict (the page and `rime tidal` say the same).
    let color = if tidal.holds() {
        Color::Green
    } else {
        Color::LightRed
    };
    out.push(Line::from(Span::styled(
        tidal.verdict(),
        Style::new().fg(color),
    )));
    if t.paper_inputs {
        let notes = [
            "¹ A.2 is πγR_eff, R_eff = r/2; the print is πγr",
            "² the printed 5.43e4 m does not follow from A.6",
            "³ r_max is very sensitive to 4M/d³ − πρ/3",
        ];
        for n in notes {
            out.push(Line::from(Span::styled(n, Style::new().fg(Color::Gray))));
        }
    } else {
        out.push(Line::from(Span::styled(
            "inputs differ from the paper's example (r 2 cm, ρ 900, γ 0.1, Encke): printed numbers not comparable",
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
