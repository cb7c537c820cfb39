//! The parameter panel: every parameter of [`PARAMETERS`] with its value, the selected one marked.

use crate::explore::format::qty;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Paragraph};
use rime_core::Scene;
use rime_core::params::{Kind, PARAMETERS, Value};

/// The text of a parameter's value with its unit (`—` when inactive).
pub fn value_text(scene: &Scene, path: &str, unit: &str) -> (String, bool) {
    match scene.get(path) {
        Ok(Value::Number(v)) => (qty(v, unit), true),
        Ok(Value::Choice(c)) => (c.to_string(), true),
        Ok(Value::Enabled(b)) => ((if b { "on" } else { "off" }).to_string(), true),
        Ok(Value::Inactive) | Err(_) => ("—".to_string(), false),
    }
}

/// What the parameter panel shows.
#[derive(Debug, Clone, Copy)]
pub struct PanelView<'a> {
    /// The scene whose parameters are listed.
    pub scene: &'a Scene,
    /// Index into [`rime_core::Preset::ALL`] of the preset in use (None: custom).
    pub preset: Option<usize>,
    /// Selected row of [`PARAMETERS`].
    pub selected: usize,
    /// Whether the panel has the focus.
    pub focused: bool,
}

/// Draws the parameter panel.
pub fn panel(frame: &mut Frame, area: Rect, view: &PanelView) {
    let block = Block::new()
        .borders(Borders::RIGHT)
        .border_style(Style::new().fg(Color::DarkGray));
    let inner = block.inner(area);
    frame.render_widget(block, area);
    if inner.height == 0 || inner.width < 4 {
        return;
    }
    let preset = view
        .preset
        .and_then(|i| rime_core::Preset::ALL.get(i))
        .map_or("custom".to_string(), |p| p.name().to_string());
    let title_style = if view.focused {
        Style::new().add_modifier(Modifier::BOLD).fg(Color::White)
    } else {
        Style::new().add_modifier(Modifier::BOLD).fg(Color::Gray)
    };
    let mut lines = vec![Line::from(vec![
        Span::styled("Parameters", title_style),
        Span::styled(format!(" · {preset}"), Style::new().fg(Color::Gray)),
    ])];
    let rows = inner.height.saturating_sub(1) as usize;
    let offset = if view.selected >= rows {
        view.selected + 1 - rows
    } else {
        0
    };
    let w = inner.width as usize;
    for (k, p) in PARAMETERS.iter().enumerate().skip(offset).take(rows) {
        let (value, active) = value_text(view.scene, p.path, p.unit);
        let header = matches!(p.kind, Kind::Toggle);
        let selected = k == view.selected;
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
            style = if view.focused {
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
