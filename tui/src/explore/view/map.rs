//! The stick map: one terminal cell per grid cell, the class letter on the class colour.

use super::plot::Colors;
use crate::explore::compute::Computed;
use crate::explore::format::{num3, qty3};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Paragraph, Widget, Wrap};
use rime_core::StickClass;
use rime_core::explorer::figures;
use rime_core::explorer::palette;

/// A class's cell: its colour ([`palette::class`]) with the letter colour that reads on it,
/// through the one palette mapping ([`Colors`]).
fn class_cell(c: StickClass, colors: Colors) -> Style {
    colors.cell(palette::class(c))
}

/// Legend name of a class in the narrow terminal legend: the core's name in words (`sliding gap`);
/// [`legend_label`] marks the artifact, the core's [`StickClass::label`] (tables, figures) spells
/// it out.
pub fn class_label(c: StickClass) -> String {
    c.name().replace('_', " ")
}

/// The legend's name of a class, marking the artifact (`sliding gap: artifact`), within `w` cells.
pub fn legend_label(c: StickClass, w: usize) -> String {
    let long = if super::help::class_meaning(c).1 {
        format!("{}: artifact", class_label(c))
    } else {
        class_label(c)
    };
    if long.chars().count() <= w || c != StickClass::SlidingGap {
        long
    } else {
        "gap: artifact".to_string()
    }
}

/// Draws the stick map of `data` with the cursor at grid cell `cursor` = (i for g_N, j for g_T);
/// `shared`: the map shares its pane with the chart (the title says how to switch). Returns the
/// cells of the map grid (for mouse clicks).
pub fn map(
    buf: &mut Buffer,
    area: Rect,
    data: Option<&Computed>,
    cursor: (usize, usize),
    focused: bool,
    shared: bool,
    colors: Colors,
) -> Option<Rect> {
    let focus = focused;
    let mut title = vec![
        Span::styled(
            " stick map ",
            Style::new().add_modifier(Modifier::BOLD).fg(if focus {
                Color::Cyan
            } else {
                Color::Gray
            }),
        ),
        Span::styled(
            if shared {
                ""
            } else {
                "classes over (g_N ↑, g_T →) "
            },
            Style::new().fg(Color::Gray),
        ),
    ];
    if shared {
        title.push(Span::styled(
            "│ ε_N chart: Tab ",
            Style::new().fg(Color::Yellow),
        ));
    }
    let (kind, style) = super::pane_border(focus);
    let block = Block::new()
        .borders(Borders::TOP | Borders::BOTTOM)
        .border_type(kind)
        .border_style(style)
        .title(Line::from(title))
        .title_bottom(map_readout(data, cursor, colors));
    let inner = block.inner(area);
    block.render(area, buf);
    let data = data?;
    let Some(m) = data.stick_map() else {
        let text = if data.request.scene.friction.is_none() {
            "friction is off: no tangential restitution (select 'friction', press Enter)"
        } else {
            "no stick map"
        };
        Paragraph::new(text)
            .style(Style::new().fg(Color::Gray))
            .wrap(Wrap { trim: true })
            .render(inner, buf);
        return None;
    };
    let n = m.n();
    if n < 2 || inner.height < 3 || inner.width < 20 {
        return None;
    }
    // The core's figure of the map (what `x` exports): its axes' ticks and labels.
    let fig = figures::map_figure(&data.frame, env!("CARGO_PKG_VERSION"))?;
    let max = fig.x.max;
    let legend_w: u16 = if inner.width >= 60 { 24 } else { 20 };
    let too_small = inner.height < 6;
    let y_ticks: Vec<(f64, String)> = fig
        .y
        .ticks(usize::from((inner.height / 4).clamp(2, 6)))
        .into_iter()
        .filter_map(|t| Some((t.value, t.label?)))
        .collect();
    let axis_w: u16 = y_ticks
        .iter()
        .map(|(_, l)| l.chars().count() as u16 + 1)
        .max()
        .unwrap_or(2)
        .max(6);
    let show_legend = inner.width >= axis_w + legend_w + 12;
    let plot_w = inner.width - axis_w - if show_legend { legend_w + 1 } else { 0 };
    // Too narrow for the legend beside the map but tall: a compact legend below it.
    let legend_below = !show_legend && inner.height >= 12;
    let below_rows: u16 = match (legend_below, inner.height >= 14) {
        (false, _) => 0,
        (true, true) => 4,
        (true, false) => 3,
    };
    let plot_h = inner.height - 1 - below_rows;
    let px = inner.x + axis_w;
    let py = inner.y;
    let gray = Style::new().fg(Color::Gray);
    // Where a speed is drawn: the cell of the grid point nearest it.
    let col_of = |v: f64| (v / max * f64::from(plot_w - 1)).round() as u16;
    let row_of = |v: f64| plot_h - 1 - (v / max * f64::from(plot_h - 1)).round() as u16;
    // Y labels on the rows of their values, g_N on a free row between them.
    let mut taken_rows = Vec::new();
    for (v, label) in &y_ticks {
        let r = row_of(*v);
        if r < plot_h && !taken_rows.contains(&r) && !too_small {
            buf.set_stringn(inner.x, py + r, label, (axis_w - 1) as usize, gray);
            taken_rows.push(r);
        }
    }
    if let Some(r) = (plot_h / 3..plot_h).find(|r| !taken_rows.iter().any(|t| t.abs_diff(*r) < 1)) {
        buf.set_stringn(inner.x, py + r, "g_N ↑", (axis_w - 1) as usize, gray);
        // The unit of both axes (the x title may not fit).
        if r + 1 < plot_h && !taken_rows.contains(&(r + 1)) {
            buf.set_stringn(inner.x, py + r + 1, "[m/s]", (axis_w - 1) as usize, gray);
        }
    }
    // X labels centred on their columns where they fit, then the axis' title with its unit.
    let ly = py + plot_h;
    let mut taken: Vec<(u16, u16)> = Vec::new();
    let x_ticks = fig.x.ticks(usize::from((plot_w / 9).max(2)));
    for t in &x_ticks {
        let Some(label) = &t.label else { continue };
        let w = label.chars().count() as u16;
        let c = px + col_of(t.value);
        let start = c
            .saturating_sub(w / 2)
            .max(px)
            .min((px + plot_w).saturating_sub(w));
        if taken.iter().all(|(a, b)| start + w < *a || start > *b + 1) {
            buf.set_string(start, ly, label, gray);
            taken.push((start, start + w));
        }
    }
    let free_from = taken.iter().map(|(_, b)| *b + 2).max().unwrap_or(px);
    let end = px + plot_w;
    let words: Vec<&str> = fig.x.label.split(' ').collect();
    if let Some(tail) = (0..words.len())
        .map(|k| words[k..].join(" "))
        .find(|t| free_from + t.chars().count() as u16 <= end)
    {
        let w = tail.chars().count() as u16;
        buf.set_string(end - w, ly, &tail, gray);
    }
    // One cell per terminal cell: the class letter on the class colour (readable without colour).
    let index = |k: u16, len: u16| -> usize {
        if len <= 1 {
            0
        } else {
            ((f64::from(k) * (n - 1) as f64 / f64::from(len - 1)).round() as usize).min(n - 1)
        }
    };
    for r in 0..plot_h {
        let i = index(plot_h - 1 - r, plot_h);
        for c in 0..plot_w {
            let j = index(c, plot_w);
            let Some(class) = m.class.get(i * n + j).copied() else {
                continue;
            };
            if let Some(cell) = buf.cell_mut((px + c, py + r)) {
                cell.set_char(class.letter())
                    .set_style(class_cell(class, colors));
            }
        }
    }
    // Cursor.
    let (ci, cj) = cursor;
    let to_cell = |k: usize, len: u16| -> u16 {
        ((k as f64 * f64::from(len - 1) / (n - 1) as f64).round() as u16).min(len - 1)
    };
    let cc = to_cell(cj, plot_w);
    let cr = plot_h - 1 - to_cell(ci, plot_h);
    if let Some(cell) = buf.cell_mut((px + cc, py + cr)) {
        cell.set_symbol("┼")
            .set_style(Style::new().fg(Color::Black).bg(Color::White));
    }
    // Legend.
    if legend_below {
        let mut spans = Vec::new();
        for c in StickClass::ALL {
            let artifact = super::help::class_meaning(c).1;
            spans.push(Span::styled(c.letter().to_string(), class_cell(c, colors)));
            let name = if artifact {
                format!(
                    "\u{a0}{}\u{a0}(artifact) ",
                    class_label(c).replace(' ', "\u{a0}")
                )
            } else {
                format!("\u{a0}{} ", class_label(c).replace(' ', "\u{a0}"))
            };
            spans.push(Span::styled(
                name,
                Style::new().fg(if artifact {
                    Color::LightYellow
                } else {
                    Color::Gray
                }),
            ));
        }
        spans.push(Span::styled(
            "· ? explains",
            Style::new().fg(Color::DarkGray),
        ));
        Paragraph::new(Line::from(spans))
            .wrap(Wrap { trim: true })
            .render(
                Rect::new(inner.x, py + plot_h + 1, inner.width, below_rows),
                buf,
            );
    }
    if show_legend {
        let lx = px + plot_w + 1;
        for (k, c) in StickClass::ALL.iter().enumerate() {
            let y = py + k as u16;
            if y >= inner.y + inner.height {
                break;
            }
            buf.set_string(lx, y, format!("{}", c.letter()), class_cell(*c, colors));
            let artifact = super::help::class_meaning(*c).1;
            buf.set_stringn(
                lx + 2,
                y,
                legend_label(*c, (legend_w - 3) as usize),
                (legend_w - 3) as usize,
                Style::new().fg(if artifact {
                    Color::LightYellow
                } else {
                    Color::Gray
                }),
            );
        }
        // The convention behind "stuck" (docs/physics.md#decision-7).
        let y = py + StickClass::ALL.len() as u16;
        if y < inner.y + inner.height {
            buf.set_stringn(
                lx,
                y,
                "ε_N<1e-9 = rebound",
                legend_w as usize,
                Style::new().fg(Color::DarkGray),
            );
        }
        if y + 1 < inner.y + inner.height {
            buf.set_stringn(
                lx,
                y + 1,
                "? explains classes",
                legend_w as usize,
                Style::new().fg(Color::DarkGray),
            );
        }
    }
    Some(Rect::new(px, py, plot_w, plot_h))
}

/// The map's readout at the cursor: speeds, ε_T and the class.
fn map_readout(data: Option<&Computed>, cursor: (usize, usize), colors: Colors) -> Line<'static> {
    let Some(m) = data.and_then(|d| d.stick_map()) else {
        return Line::default();
    };
    let n = m.n();
    let (i, j) = cursor;
    let (Some(gn), Some(gt)) = (m.g.get(i), m.g.get(j)) else {
        return Line::default();
    };
    let k = i * n + j;
    let (Some(class), Some(eps_t)) = (m.class.get(k), m.eps_t.get(k)) else {
        return Line::default();
    };
    Line::from(vec![
        Span::styled(" ▸ ", Style::new().fg(Color::White)),
        Span::raw(format!(
            "g_N {}  g_T {}  ε_T {} ",
            qty3(*gn, "m/s"),
            qty3(*gt, "m/s"),
            num3(*eps_t)
        )),
        Span::styled(
            format!("{} ", class_label(*class)),
            colors.fg(palette::class(*class)),
        ),
        Span::styled(
            if *class == StickClass::SlidingGap {
                "(artifact of Eq. (23); W: Walton) "
            } else {
                ""
            },
            Style::new().fg(Color::LightYellow),
        ),
    ])
}
