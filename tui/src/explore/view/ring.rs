//! The ring card (issue 24): what the scene's law does to a ring at τ and Ω, drawn from the core's
//! [`RingCard`] (`rime_core::explorer::ring`), the same card the page shows and the same numbers
//! `rime ring` prints. The ε_cr line, the meeting point and the impact-speed marker go on the ε_N
//! chart through [`RingCard::overlay`] (the chart's figure), not here.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::Text;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Wrap};
use rime_core::explorer::format::{qty, sig};
use rime_core::explorer::ring::RingCard;

/// The card's lines: the inputs, the verdict, the printed rows, then the verdict's sentence.
pub fn lines(card: &RingCard) -> Vec<Line<'static>> {
    let dim = Style::new().fg(Color::Gray);
    let r = &card.record;
    let verdict_style = if card.equilibrium {
        Style::new().fg(Color::Green)
    } else {
        Style::new().fg(Color::LightRed)
    }
    .add_modifier(Modifier::BOLD);
    let mut out = vec![
        Line::from(vec![
            Span::styled("τ ", dim),
            Span::raw(sig(r.tau, 4)),
            Span::styled("  Ω ", dim),
            Span::raw(format!("{} 1/s", sig(r.omega, 4))),
            Span::styled(format!(" ({})", orbit_words(r.omega)), dim),
            Span::styled("  R ", dim),
            Span::raw(qty(r.radius, "m")),
        ]),
        Line::from(Span::styled(card.verdict.to_string(), verdict_style)),
    ];
    // The numbers before the sentence: a small terminal cuts the card from the bottom.
    for row in &card.rows {
        out.push(Line::from(vec![
            Span::styled(format!("{}: ", row.label), dim),
            Span::raw(row.text.clone()),
        ]));
    }
    out.push(Line::from(card.sentence.clone()));
    out
}

/// Which Ω the card uses, in words: Saturn's A ring (as the README and `rime ring --help`), or
/// that ring moved with the planet distance (`<` `>`; Ω ∝ d^(−3/2)).
fn orbit_words(omega: f64) -> String {
    let factor = (crate::explore::state::RING_OMEGA / omega).powf(2.0 / 3.0);
    if (factor - 1.0).abs() < 1e-9 {
        "Saturn's A ring".into()
    } else {
        format!("A ring, d ×{}", sig(factor, 3))
    }
}

/// Draws the card over `area`.
pub fn render(frame: &mut Frame, area: Rect, card: &RingCard) {
    draw(frame, area, lines(card).into());
}

/// The card's frame (title, keys) around `text`.
fn draw(frame: &mut Frame, area: Rect, text: Text<'static>) {
    let inner = super::overlay_panel(
        frame,
        area,
        "ring: what the law does to it",
        "( ) τ · < > planet distance · g sizes · r closes",
    );
    let text = fit_rows(text, inner.width, inner.height);
    frame.render_widget(Paragraph::new(text).wrap(Wrap { trim: false }), inner);
}

/// How many rows `line` takes wrapped at word boundaries into `width` cells (as [`Wrap`] does).
fn wrapped_rows(line: &Line, width: u16) -> usize {
    let width = usize::from(width.max(1));
    let text: String = line.spans.iter().map(|s| s.content.as_ref()).collect();
    let (mut rows, mut used) = (1, 0);
    for word in text.split(' ') {
        let n = word.chars().count();
        let need = if used == 0 { n } else { used + 1 + n };
        if need <= width {
            used = need;
        } else {
            rows += 1;
            // A word longer than the row is broken over rows of its own.
            used = n % width;
            rows += n.saturating_sub(1) / width;
        }
    }
    rows
}

/// The lines of `text` that fit `height` rows of `width` cells, whole lines only; when some are
/// left out, the last row says how many (issue 37: at 80×24 the card ended mid-way with no hint).
fn fit_rows(text: Text<'static>, width: u16, height: u16) -> Text<'static> {
    let rows: Vec<usize> = text.lines.iter().map(|l| wrapped_rows(l, width)).collect();
    if rows.iter().sum::<usize>() <= usize::from(height) {
        return text;
    }
    let room = usize::from(height.saturating_sub(1));
    let (mut used, mut keep) = (0, 0);
    while keep < rows.len() && used + rows[keep] <= room {
        used += rows[keep];
        keep += 1;
    }
    let left = text.lines.len() - keep;
    let mut lines: Vec<Line<'static>> = text.lines.into_iter().take(keep).collect();
    // The longest wording that fits the one row kept for it.
    let note = [
        format!("… {left} more lines: a taller terminal shows them (rime ring prints all)"),
        format!("… {left} more lines: a taller terminal shows them"),
        format!("… {left} more lines"),
    ]
    .into_iter()
    .find(|n| n.chars().count() <= usize::from(width))
    .unwrap_or_else(|| format!("… +{left}"));
    lines.push(Line::from(Span::styled(
        note,
        Style::new().fg(Color::Yellow),
    )));
    lines.into()
}

/// Draws the card where it leaves the ε_N chart (and its ε_cr line) in view: over the stick map's
/// pane, or, where the chart and the map share one pane, over the pane's lower part. `card` is
/// `None` before the first frame, and an error names the field that stopped it.
pub fn render_over(
    frame: &mut Frame,
    map: Rect,
    views: Rect,
    shared: bool,
    card: Option<&Result<RingCard, String>>,
) {
    let text: Text<'static> = match card {
        Some(Ok(c)) => lines(c).into(),
        Some(Err(e)) => Line::from(Span::styled(
            format!("no ring card: {e}"),
            Style::new().fg(Color::LightRed),
        ))
        .into(),
        None => Line::from(Span::styled("computing…", Style::new().fg(Color::Gray))).into(),
    };
    let area = if shared {
        let rows: usize = text
            .lines
            .iter()
            .map(|l| wrapped_rows(l, views.width.saturating_sub(2)))
            .sum();
        let h = (u16::try_from(rows).unwrap_or(u16::MAX).saturating_add(2))
            .min(views.height / 2)
            .max(3);
        Rect::new(views.x, views.y + views.height - h, views.width, h)
    } else {
        map
    };
    match card {
        Some(Ok(c)) => render(frame, area, c),
        _ => draw(frame, area, text),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;
    use rime_core::explorer::ring::ring_card;
    use rime_core::ring::{Orbit, RingInput};

    fn screen(card: &RingCard) -> String {
        let mut t = Terminal::new(TestBackend::new(100, 20)).expect("terminal");
        t.draw(|f| render(f, f.area(), card)).expect("draw");
        let buf = t.backend().buffer();
        let mut s = String::new();
        for y in 0..buf.area.height {
            for x in 0..buf.area.width {
                s.push_str(buf[(x, y)].symbol());
            }
            s.push('\n');
        }
        s
    }

    #[test]
    fn issue_24_the_terminal_card_shows_the_cores_verdict_and_numbers() {
        let mut scene = rime_core::Preset::Ice.scene();
        scene.grains.radius_1 = 0.02;
        scene.grains.radius_2 = 0.02;
        let input = RingInput {
            tau: 0.5,
            orbit: Orbit::Omega(1.3143527e-4),
            damping_set_for_radius: None,
        };
        let card = ring_card(&scene, &input, (1e-7, 1.0)).expect("card");
        let text = screen(&card);
        assert!(
            text.contains("equilibrium at the monolayer floor"),
            "{text}"
        );
        // The printed dispersion is the core row's (2RΩ = 5.257 µm/s at the floor).
        assert!(
            text.contains("velocity dispersion c: 5.257 µm/s (2 RΩ)"),
            "{text}"
        );
        assert!(
            text.contains("smooth grains (no friction): equilibrium"),
            "{text}"
        );
        // A heating ring says so.
        scene.grains.radius_1 = 1.0;
        scene.grains.radius_2 = 1.0;
        let hot = ring_card(&scene, &input, (1e-7, 1.0)).expect("card");
        let text = screen(&hot);
        assert!(text.contains("heats"), "{text}");
        assert!(text.contains("Heats (with the scene's friction)"), "{text}");
    }

    #[test]
    fn issue_24_the_overlay_draws_on_the_terminals_eps_n_chart() {
        use crate::explore::view::plot::{Colors, Options, draw, legend, tags};
        use rime_core::figure::{Axis, Figure, Series, Stroke};
        let mut scene = rime_core::Preset::Ice.scene();
        scene.friction = None;
        let input = RingInput {
            tau: 0.5,
            orbit: Orbit::Omega(1.3143527e-4),
            damping_set_for_radius: None,
        };
        let card = ring_card(&scene, &input, (1e-7, 1.0)).expect("card");
        // The scene's ε_N curve on the chart's log speed axis, then the card on top of it.
        let contact = rime_core::Contact::new(&scene).expect("contact");
        let points = (0..=70)
            .map(|k| {
                let g = 1e-7 * 10f64.powf(k as f64 / 10.0);
                (g, contact.eps_n(g, rime_core::Accuracy::Fast).expect("eps"))
            })
            .collect();
        let axis = |label: &str, log: bool, min: f64, max: f64| Axis {
            label: label.into(),
            log,
            min,
            max,
        };
        let mut fig = Figure::stick_map(
            String::new(),
            String::new(),
            String::new(),
            vec![],
            vec![],
            1.0,
        );
        fig.x = axis("g_N [m/s]", true, 1e-7, 1.0);
        fig.y = axis("ε_N", false, 0.0, 1.0);
        fig.series.push(Series {
            name: "this scene".into(),
            short: "scene".into(),
            points,
            color: rime_core::explorer::palette::SERIES_SCENE,
            stroke: Stroke::Solid,
        });
        card.overlay(&mut fig);
        let opts = Options {
            colors: Colors::Rgb,
            cursor: None,
            legend_rows: 4,
            bold: Some(0),
            y_title: false,
        };
        let entries = legend(&fig, &tags(&fig, opts.colors));
        assert!(entries.iter().any(|e| e.text == "ring ε_cr"), "{entries:?}");
        let area = Rect::new(0, 0, 90, 24);
        let mut buf = ratatui::buffer::Buffer::empty(area);
        assert!(draw(&mut buf, area, &fig, &opts).is_some());
        // The line is drawn in the ring's colour (palette series 5).
        let ring = rime_core::explorer::palette::SERIES[card.eps_cr_line.color];
        let inked = buf
            .content()
            .iter()
            .filter(|c| c.fg == Color::Rgb(ring.r, ring.g, ring.b) && c.symbol() != " ")
            .count();
        assert!(inked > 10, "only {inked} cells in the ring's colour");
    }
}
