//! The collision panel (`i`): one collision at the ε_N cursor from the inside — the overlap ξ(t),
//! the force–overlap loop F(ξ) with the phase instants, and the energy ledger as bars
//! (docs/physics.md#collision).

use crate::explore::format::{qty3, sig};
use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Block, Chart, Clear, Dataset, GraphType, Paragraph};
use rime_core::collision::Trajectory;

/// What the panel shows: the trajectory at the cursor speed, or why there is none.
pub struct CollisionView<'a> {
    /// Impact speed \[m/s\].
    pub g: f64,
    /// The trajectory, or the error that prevented it.
    pub trajectory: Result<&'a Trajectory, &'a str>,
    /// With adhesion: the dynamic JKR model's force–overlap loop (brilliantov2007, docs/physics.md
    /// #models) as (ξ, F) points, with its neck (ξ < 0) and pull-off jump.
    pub dynamic_loop: &'a [(f64, f64)],
}

fn bounds(v: &[f64]) -> [f64; 2] {
    let lo = v
        .iter()
        .copied()
        .filter(|x| x.is_finite())
        .fold(f64::INFINITY, f64::min);
    let hi = v
        .iter()
        .copied()
        .filter(|x| x.is_finite())
        .fold(f64::NEG_INFINITY, f64::max);
    if lo.is_finite() && hi > lo {
        [lo, hi]
    } else {
        [0.0, 1.0]
    }
}

/// The ledger's lines: each term as a bar in units of the kinetic energy brought in.
pub fn ledger_lines(t: &Trajectory, width: u16) -> Vec<Line<'static>> {
    let l = t.ledger;
    let bar_w = width.saturating_sub(32).max(4) as f64;
    let row = |name: &str, value: f64, color: Color| {
        let frac = if l.kinetic_in > 0.0 {
            value / l.kinetic_in
        } else {
            0.0
        };
        let n = (frac.clamp(0.0, 1.0) * bar_w).round() as usize;
        Line::from(vec![
            Span::styled(format!("{name:<19}"), Style::new().fg(Color::Gray)),
            Span::styled("█".repeat(n), Style::new().fg(color)),
            Span::raw(format!(" {:>5.1} %", 100.0 * frac)),
        ])
    };
    vec![
        row("kinetic out", l.kinetic_out, Color::Rgb(0x00, 0x9E, 0x73)),
        row(
            "bulk, Eq. (4)",
            l.dissipated_bulk,
            Color::Rgb(0xE6, 0x9F, 0x00),
        ),
        row(
            "layer, Eq. (8)",
            l.dissipated_layer,
            Color::Rgb(0x56, 0xB4, 0xE9),
        ),
        row(
            "adhesion, Eq. (12)",
            l.adhesion,
            Color::Rgb(0xCC, 0x79, 0xA7),
        ),
        row(
            "left in the bulk",
            l.elastic_retained,
            Color::Rgb(0xBB, 0xBB, 0xBB),
        ),
        Line::from(Span::styled(
            format!(
                "in {} · closure {:.1e}{}",
                qty3(l.kinetic_in, "J"),
                l.closure,
                if t.resolved { "" } else { " (end not sampled)" }
            ),
            Style::new().fg(Color::Gray),
        )),
    ]
}

/// Draws the panel over `area`.
pub fn render(frame: &mut Frame, area: Rect, view: &CollisionView) {
    frame.render_widget(Clear, area);
    let title = format!(
        " inside one collision at g_N {} · i closes ",
        qty3(view.g, "m/s")
    );
    let block = Block::bordered().title(title);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let t = match view.trajectory {
        Ok(t) => t,
        Err(e) => {
            frame.render_widget(
                Paragraph::new(format!("no collision to show: {e}"))
                    .style(Style::new().fg(Color::LightRed)),
                inner,
            );
            return;
        }
    };
    let [head, plots, ledger] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Min(4),
        Constraint::Length(6),
    ])
    .areas(inner);
    let phases: Vec<String> = t
        .phases
        .iter()
        .map(|p| format!("{} {}", p.name.replace('_', " "), qty3(p.t, "s")))
        .collect();
    frame.render_widget(
        Paragraph::new(Line::from(vec![
            Span::raw(format!(
                "ε_N {} {} · t_c {} · ξ_max {} │ ",
                sig(t.eps_n, 4),
                t.status.name(),
                if t.t_c.is_finite() {
                    qty3(t.t_c, "s")
                } else {
                    "—".into()
                },
                qty3(t.xi_max, "m")
            )),
            Span::styled(phases.join(" · "), Style::new().fg(Color::Gray)),
        ])),
        head,
    );
    let [left, right] =
        Layout::horizontal([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(plots);
    let xi_t: Vec<(f64, f64)> = t.t.iter().zip(&t.xi).map(|(a, b)| (*a, *b)).collect();
    let loop_: Vec<(f64, f64)> = t.xi.iter().zip(&t.force).map(|(a, b)| (*a, *b)).collect();
    // The phase instants, marked on both plots (they are among the samples).
    let at_phase = |k: usize| t.phases.iter().any(|p| p.t == t.t[k]);
    let marks_t: Vec<(f64, f64)> = (0..t.t.len())
        .filter(|&k| at_phase(k))
        .map(|k| (t.t[k], t.xi[k]))
        .collect();
    let marks_f: Vec<(f64, f64)> = (0..t.t.len())
        .filter(|&k| at_phase(k))
        .map(|k| (t.xi[k], t.force[k]))
        .collect();
    fn chart<'a>(
        data: &'a [(f64, f64)],
        second: &'a [(f64, f64)],
        marks: &'a [(f64, f64)],
        x: [f64; 2],
        y: [f64; 2],
        xl: &str,
        yl: &str,
    ) -> Chart<'a> {
        let orange = Style::new().fg(Color::Rgb(0xE6, 0x9F, 0x00));
        let purple = Style::new().fg(Color::Rgb(0xCC, 0x79, 0xA7));
        let mut sets = vec![
            Dataset::default()
                .marker(Marker::Braille)
                .graph_type(GraphType::Line)
                .style(orange)
                .data(data),
        ];
        if !second.is_empty() {
            sets.push(
                Dataset::default()
                    .marker(Marker::Braille)
                    .graph_type(GraphType::Line)
                    .style(purple)
                    .data(second),
            );
        }
        sets.push(
            Dataset::default()
                .marker(Marker::Block)
                .graph_type(GraphType::Scatter)
                .style(Style::new().fg(Color::White))
                .data(marks),
        );
        Chart::new(sets)
            .x_axis(
                Axis::default()
                    .title(xl.to_string())
                    .bounds(x)
                    .labels(vec![Span::raw(sig(x[0], 2)), Span::raw(sig(x[1], 2))]),
            )
            .y_axis(
                Axis::default()
                    .title(yl.to_string())
                    .bounds(y)
                    .labels(vec![Span::raw(sig(y[0], 2)), Span::raw(sig(y[1], 2))]),
            )
    }
    frame.render_widget(
        chart(
            &xi_t,
            &[],
            &marks_t,
            bounds(&t.t),
            bounds(&t.xi),
            "t [s]",
            "ξ [m]",
        ),
        left,
    );
    // With adhesion the dynamic JKR model's loop (pink) beside the paper's (orange).
    let all_xi: Vec<f64> =
        t.xi.iter()
            .copied()
            .chain(view.dynamic_loop.iter().map(|p| p.0))
            .collect();
    let all_f: Vec<f64> = t
        .force
        .iter()
        .copied()
        .chain(view.dynamic_loop.iter().map(|p| p.1))
        .collect();
    let title = if view.dynamic_loop.is_empty() {
        "F [N]"
    } else {
        "F [N] (pink: brilliantov2007)"
    };
    frame.render_widget(
        chart(
            &loop_,
            view.dynamic_loop,
            &marks_f,
            bounds(&all_xi),
            bounds(&all_f),
            "ξ [m]",
            title,
        ),
        right,
    );
    frame.render_widget(Paragraph::new(ledger_lines(t, ledger.width)), ledger);
}
