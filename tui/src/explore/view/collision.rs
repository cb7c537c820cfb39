//! The collision panel (`i`): one collision at the ε_N cursor from the inside — the overlap ξ(t),
//! the force–overlap loop F(ξ) with the phase instants, and the energy ledger as bars
//! (docs/physics.md#collision).

use super::plot::{self, Colors};
use crate::explore::format::{qty3, sig};
use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph};
use rime_core::collision::Trajectory;
use rime_core::explorer::figures::collision_figures;
use rime_core::explorer::palette;

/// What the panel shows: the trajectory at the cursor speed, or why there is none.
pub struct CollisionView<'a> {
    /// Impact speed \[m/s\].
    pub g: f64,
    /// The trajectory, or the error that prevented it.
    pub trajectory: Result<&'a Trajectory, &'a str>,
    /// With adhesion: the dynamic JKR model's force–overlap loop (brilliantov2007, docs/physics.md
    /// #models) as (ξ, F) points, with its neck (ξ < 0) and pull-off jump.
    pub dynamic_loop: &'a [(f64, f64)],
    /// The terminal's colours.
    pub colors: Colors,
}

/// The ledger's lines: each term as a bar in units of the kinetic energy brought in.
pub fn ledger_lines(t: &Trajectory, width: u16, colors: Colors) -> Vec<Line<'static>> {
    let l = t.ledger;
    let bar_w = width.saturating_sub(32).max(4) as f64;
    let row = |name: &str, value: f64, color: palette::Rgb| {
        let frac = if l.kinetic_in > 0.0 {
            value / l.kinetic_in
        } else {
            0.0
        };
        let n = (frac.clamp(0.0, 1.0) * bar_w).round() as usize;
        Line::from(vec![
            Span::styled(format!("{name:<19}"), Style::new().fg(Color::Gray)),
            Span::styled("█".repeat(n), colors.fg(color)),
            Span::raw(format!(" {:>5.1} %", 100.0 * frac)),
        ])
    };
    vec![
        row("kinetic out", l.kinetic_out, palette::BLUISH_GREEN),
        row("bulk, Eq. (4)", l.dissipated_bulk, palette::ORANGE),
        row("layer, Eq. (8)", l.dissipated_layer, palette::SKY_BLUE),
        row("adhesion, Eq. (12)", l.adhesion, palette::REDDISH_PURPLE),
        row("left in the bulk", l.elastic_retained, palette::GREY_LIGHT),
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
    let summary = format!(
        "ε_N {} {} · t_c {} · ξ_max {} │ ",
        sig(t.eps_n, 4),
        t.status.label(),
        if t.t_c.is_finite() {
            qty3(t.t_c, "s")
        } else {
            "—".into()
        },
        qty3(t.xi_max, "m")
    );
    frame.render_widget(
        Paragraph::new(Line::from(vec![
            Span::raw(summary.clone()),
            Span::styled(
                whole_phases(
                    &phases,
                    usize::from(head.width).saturating_sub(summary.chars().count()),
                ),
                Style::new().fg(Color::Gray),
            ),
        ])),
        head,
    );
    let [left, right] =
        Layout::horizontal([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(plots);
    // The core's two figures of this collision, drawn by the one adapter.
    let figs = collision_figures(view.g, t, view.dynamic_loop);
    let opts = plot::Options {
        colors: view.colors,
        cursor: None,
        legend_rows: 2,
        bold: None,
        y_title: true,
    };
    for (fig, area) in figs.iter().zip([left, right]) {
        plot::draw(frame.buffer_mut(), area, fig, &opts);
    }
    frame.render_widget(
        Paragraph::new(ledger_lines(t, ledger.width, view.colors)),
        ledger,
    );
}

/// The phase instants that fit `room` cells, whole ones only, joined by ` · `; the ones left out
/// are counted (`· +2 more: a wider terminal`) instead of a phase cut mid-word (issue 37).
fn whole_phases(phases: &[String], room: usize) -> String {
    let all = phases.join(" · ");
    if all.chars().count() <= room {
        return all;
    }
    let mut shown = String::new();
    for (k, p) in phases.iter().enumerate() {
        let left = phases.len() - k - 1;
        let candidate = if shown.is_empty() {
            p.clone()
        } else {
            format!("{shown} · {p}")
        };
        let tail = if left == 0 {
            String::new()
        } else {
            format!(" · +{left} more")
        };
        if candidate.chars().count() + tail.chars().count() > room {
            let left = phases.len() - k;
            return if shown.is_empty() {
                let count = format!("+{left} phases");
                if count.chars().count() <= room {
                    count
                } else {
                    String::new()
                }
            } else {
                format!("{shown} · +{left} more")
            };
        }
        shown = candidate;
    }
    shown
}
