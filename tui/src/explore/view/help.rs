//! The `?` overlay: every key (from the keymap table), what each stick-map class means, a glossary
//! of the symbols on screen, and the sources of the experimental context. It scrolls (↑↓, PgUp/PgDn,
//! Home/End, the wheel) when it is taller than the terminal, so every line is reachable at 60×20.

use crate::explore::keymap::KEYMAP;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph};
use rime_core::StickClass;

/// Where the citations are, after the sources' lines.
const CITATIONS: &str = "citations: docs/physics.md";

/// What each stick-map class means (the core's words, [`StickClass::meaning`]), and whether it is
/// an artifact of the printed law rather than a physical regime.
pub fn class_meaning(c: StickClass) -> (&'static str, bool) {
    (c.meaning(), rime_core::explorer::help::class_is_artifact(c))
}

/// Splits `text` into lines of at most `width` characters at spaces.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let width = width.max(8);
    let mut out = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let (lw, ww) = (line.chars().count(), word.chars().count());
        if lw > 0 && lw + 1 + ww > width {
            out.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
        // A word longer than the line: cut it.
        while line.chars().count() > width {
            let head: String = line.chars().take(width).collect();
            line = line.chars().skip(width).collect();
            out.push(head);
        }
    }
    if !line.is_empty() {
        out.push(line);
    }
    out
}

/// A two-column entry (`name` right-aligned in `name_w`, `text` wrapped beside it with a hanging
/// indent).
fn entry(
    name: &str,
    name_style: Style,
    text: &str,
    text_style: Style,
    name_w: usize,
    inner_w: usize,
) -> Vec<Line<'static>> {
    let text_w = inner_w.saturating_sub(name_w + 2).max(8);
    wrap(text, text_w)
        .into_iter()
        .enumerate()
        .map(|(k, part)| {
            let head = if k == 0 {
                format!("{name:>name_w$}  ")
            } else {
                " ".repeat(name_w + 2)
            };
            Line::from(vec![
                Span::styled(head, name_style),
                Span::styled(part, text_style),
            ])
        })
        .collect()
}

fn heading(text: &str) -> Line<'static> {
    Line::from(Span::styled(
        text.to_string(),
        Style::new()
            .fg(Color::White)
            .add_modifier(Modifier::BOLD | Modifier::UNDERLINED),
    ))
}

/// Every line of the help at inner width `inner_w`.
pub fn content(inner_w: usize) -> Vec<Line<'static>> {
    let keys = Style::new().fg(Color::Yellow);
    let plain = Style::new();
    let dim = Style::new().fg(Color::Gray);
    let name_w = KEYMAP
        .iter()
        .map(|r| r.keys.chars().count())
        .max()
        .unwrap_or(10)
        .min(inner_w / 2);
    let mut lines = vec![heading("Keys")];
    for row in KEYMAP {
        lines.extend(entry(row.keys, keys, row.does, plain, name_w, inner_w));
    }
    lines.push(Line::default());
    lines.push(heading("Stick map: the class of each (g_N, g_T)"));
    for c in StickClass::ALL {
        let (text, artifact) = class_meaning(c);
        let style = if artifact {
            Style::new().fg(Color::LightYellow)
        } else {
            plain
        };
        let name = format!("{}{}", if artifact { "⚠ " } else { "" }, c.letter());
        lines.extend(entry(&name, keys, text, style, 3, inner_w));
    }
    lines.extend(entry(
        "",
        keys,
        "stuck means ε_N = 0 exactly; an ε_N below 1e-9 still counts as a rebound (docs/physics.md#decision-7)",
        dim,
        3,
        inner_w,
    ));
    lines.push(Line::default());
    lines.push(heading("Glossary"));
    let gw = rime_core::explorer::help::GLOSSARY
        .iter()
        .map(|(n, _)| n.chars().count())
        .max()
        .unwrap_or(8)
        .min(inner_w / 3);
    for (name, text) in rime_core::explorer::help::GLOSSARY {
        lines.extend(entry(name, keys, text, plain, gw, inner_w));
    }
    lines.push(Line::default());
    // The core's warnings, as the status line names them (the page and the CLI say the same).
    lines.push(heading("Warnings (status line)"));
    let ww = rime_core::explorer::warning::Warning::ALL
        .iter()
        .map(|w| w.short().chars().count())
        .max()
        .unwrap_or(8)
        .min(inner_w / 3);
    for w in rime_core::explorer::warning::Warning::ALL {
        let text = format!("{} ({})", w.help(), w.equation());
        lines.extend(entry(w.short(), keys, &text, plain, ww, inner_w));
    }
    lines.push(Line::default());
    lines.push(heading("Sources"));
    let sources = rime_core::explorer::help::experiment_sources();
    for source in sources.iter().map(String::as_str).chain([CITATIONS]) {
        for part in wrap(source, inner_w) {
            lines.push(Line::from(Span::styled(part, dim)));
        }
    }
    lines
}

/// The help box on a `w × h` screen.
fn frame_rect(w: u16, h: u16) -> Rect {
    let bw = 90.min(w);
    let inner_w = bw.saturating_sub(2).max(1) as usize;
    let bh = (content(inner_w).len() as u16 + 2).min(h);
    Rect::new(w.saturating_sub(bw) / 2, h.saturating_sub(bh) / 2, bw, bh)
}

/// Rows of help text visible at once on a `w × h` screen.
pub fn page_rows(w: u16, h: u16) -> u16 {
    frame_rect(w, h).height.saturating_sub(2)
}

/// The largest useful scroll offset on a `w × h` screen.
pub fn max_scroll(w: u16, h: u16) -> u16 {
    let r = frame_rect(w, h);
    let total = content(r.width.saturating_sub(2).max(1) as usize).len() as u16;
    total.saturating_sub(page_rows(w, h))
}

/// Draws the help overlay centred in `area`, from line `scroll`.
pub fn help(frame: &mut Frame, area: Rect, scroll: u16) {
    let r = frame_rect(area.width, area.height);
    let r = Rect::new(area.x + r.x, area.y + r.y, r.width, r.height);
    let inner_w = r.width.saturating_sub(2).max(1) as usize;
    let lines = content(inner_w);
    let total = lines.len() as u16;
    let page = r.height.saturating_sub(2);
    let scroll = scroll.min(total.saturating_sub(page));
    let shown: Vec<Line> = lines
        .into_iter()
        .skip(usize::from(scroll))
        .take(usize::from(page))
        .collect();
    let footer = if total > page {
        format!(
            " ↑↓ PgDn scroll {}–{}/{total} · q Esc or any other key closes ",
            scroll + 1,
            (scroll + page).min(total)
        )
    } else {
        " q Esc or any other key closes ".to_string()
    };
    frame.render_widget(Clear, r);
    frame.render_widget(
        Paragraph::new(shown).block(
            Block::bordered()
                .title(" rime — keys, classes, glossary ")
                .title_bottom(Span::styled(footer, Style::new().fg(Color::Yellow))),
        ),
        r,
    );
}
