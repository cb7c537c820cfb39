//! The `?` overlay: every key (from the keymap table) and the sources of the experimental context.

use crate::explore::keymap::KEYMAP;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Wrap};

/// Sources of the experimental context and the tidal calculator, shown in the help.
pub const SOURCES: &str = "B84 Bridges et al. 1984: ε = 0.32 (v/1 cm/s)^−0.234 · \
H10 Heißelmann et al. 2010: 6–22 cm/s · H15 Hill et al. 2015: 0.27–0.51 m/s · \
citations: docs/physics.md";

/// Draws the help overlay centred in `area`.
pub fn help(frame: &mut Frame, area: Rect) {
    let w = 78.min(area.width);
    let inner_w = w.saturating_sub(2).max(1) as usize;
    let source_rows = SOURCES.chars().count().div_ceil(inner_w) as u16 + 1;
    let h = (KEYMAP.len() as u16 + 3 + source_rows).min(area.height);
    let r = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    let mut lines: Vec<Line> = KEYMAP
        .iter()
        .map(|row| {
            Line::from(vec![
                Span::styled(
                    format!("{:>18}  ", row.keys),
                    Style::new().fg(Color::Yellow),
                ),
                Span::raw(row.does),
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
