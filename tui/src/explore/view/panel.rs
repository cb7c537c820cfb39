//! The parameter panel: every parameter of [`PARAMETERS`] with its value, the selected one marked.

use crate::explore::format::qty;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Paragraph};
use rime_core::Scene;
use rime_core::params::{Kind, PARAMETERS, Value};

/// Human words for a choice's JSON name: (long, short). The JSON name stays in the scene file, on
/// the command line and in the message after a change.
pub fn choice_label(name: &str) -> (&'static str, &'static str) {
    match name {
        "brilliantov" => ("Brilliantov et al. 1996", "Brilliantov"),
        "as_printed" => ("as printed in the paper", "as printed"),
        "force_zero" => ("force returns to zero", "force → 0"),
        "zero_overlap" => ("overlap returns to zero", "overlap → 0"),
        "offset" => ("layer crushed, bulk offset", "offset"),
        "literal" => ("literally, piecewise in ξ", "literal"),
        "consistent" => ("consistent with Eq. (4)", "consistent"),
        "paper" => ("the paper's Eq. (23)", "paper's"),
        "walton" => ("Walton's linear law", "Walton"),
        _ => ("", ""),
    }
}

/// The text of a parameter's value with its unit (`—` when inactive), choices in human words
/// (the long ones when `long`).
pub fn value_text_fit(scene: &Scene, path: &str, unit: &str, long: bool) -> (String, bool) {
    match scene.get(path) {
        Ok(Value::Choice(c)) => {
            let (l, s) = choice_label(c);
            let text = if long { l } else { s };
            (if text.is_empty() { c } else { text }.to_string(), true)
        }
        _ => value_text(scene, path, unit),
    }
}

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

/// Index of the first parameter shown when `rows` rows hold the list and `selected` is selected.
pub fn first_row(selected: usize, rows: usize) -> usize {
    if selected >= rows {
        selected + 1 - rows
    } else {
        0
    }
}

/// Draws the parameter panel; returns the screen row of the first parameter and its index (for
/// mouse clicks).
pub fn panel(frame: &mut Frame, area: Rect, view: &PanelView) -> Option<(u16, usize)> {
    let (kind, style) = super::pane_border(view.focused);
    let block = Block::new()
        .borders(Borders::RIGHT)
        .border_type(kind)
        .border_style(style);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    if inner.height == 0 || inner.width < 4 {
        return None;
    }
    let preset = view
        .preset
        .and_then(|i| rime_core::Preset::ALL.get(i))
        .map_or("custom".to_string(), |p| p.name().to_string());
    let title_style = if view.focused {
        Style::new().add_modifier(Modifier::BOLD).fg(Color::Cyan)
    } else {
        Style::new().add_modifier(Modifier::BOLD).fg(Color::Gray)
    };
    let mut lines = vec![Line::from(vec![
        Span::styled("Parameters", title_style),
        Span::styled(format!(" · {preset}"), Style::new().fg(Color::Gray)),
    ])];
    let rows = inner.height.saturating_sub(1) as usize;
    let offset = first_row(view.selected, rows);
    let w = inner.width as usize;
    for (k, p) in PARAMETERS.iter().enumerate().skip(offset).take(rows) {
        let (long, active) = value_text_fit(view.scene, p.path, p.unit, true);
        // The long words where the label still fits beside them, else the short ones.
        let (value, active) = if long.chars().count() + p.label.chars().count() + 3 <= w {
            (long, active)
        } else {
            value_text_fit(view.scene, p.path, p.unit, false)
        };
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
    Some((inner.y + 1, offset))
}
