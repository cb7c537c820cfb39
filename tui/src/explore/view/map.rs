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
// Long by design: the pane's sizing decisions (legend beside or below, label widths, plot size)
// made once and handed to the parts it calls.
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
    let plot = Rect::new(px, py, plot_w, plot_h);
    let labels = AxisLabels {
        left: inner.x,
        width: axis_w,
        y_ticks: if too_small { &[] } else { &y_ticks },
    };
    draw_axes(buf, plot, &labels, &fig);
    draw_cells(buf, plot, m, cursor, colors);
    if legend_below {
        legend_below_map(
            buf,
            Rect::new(inner.x, py + plot_h + 1, inner.width, below_rows),
            colors,
        );
    }
    if show_legend {
        let rows = Rect::new(px + plot_w + 1, py, legend_w, inner.y + inner.height - py);
        legend_beside_map(buf, rows, colors);
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

/// The class legend below the map (narrow terminals): one wrapped line of letters and names.
fn legend_below_map(buf: &mut Buffer, area: Rect, colors: Colors) {
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
        .render(area, buf);
}

/// The class legend beside the map, one class per row, then the stuck convention and the help key.
fn legend_beside_map(buf: &mut Buffer, area: Rect, colors: Colors) {
    let lx = area.x;
    for (k, c) in StickClass::ALL.iter().enumerate() {
        let y = area.y + k as u16;
        if y >= area.y + area.height {
            break;
        }
        buf.set_string(lx, y, format!("{}", c.letter()), class_cell(*c, colors));
        let artifact = super::help::class_meaning(*c).1;
        buf.set_stringn(
            lx + 2,
            y,
            legend_label(*c, (area.width - 3) as usize),
            (area.width - 3) as usize,
            Style::new().fg(if artifact {
                Color::LightYellow
            } else {
                Color::Gray
            }),
        );
    }
    // The convention behind "stuck" (docs/physics.md#decision-7).
    let y = area.y + StickClass::ALL.len() as u16;
    if y < area.y + area.height {
        buf.set_stringn(
            lx,
            y,
            "ε_N<1e-9 = rebound",
            area.width as usize,
            Style::new().fg(Color::DarkGray),
        );
    }
    if y + 1 < area.y + area.height {
        buf.set_stringn(
            lx,
            y + 1,
            "? explains classes",
            area.width as usize,
            Style::new().fg(Color::DarkGray),
        );
    }
}

/// The map's cells, one per terminal cell (the class letter on the class colour, readable without
/// colour), and the cursor at grid cell `cursor` = (i for g_N, j for g_T).
fn draw_cells(
    buf: &mut Buffer,
    plot: Rect,
    m: &rime_core::sweep::StickMap,
    cursor: (usize, usize),
    colors: Colors,
) {
    let n = m.n();
    let index = |k: u16, len: u16| -> usize {
        if len <= 1 {
            0
        } else {
            ((f64::from(k) * (n - 1) as f64 / f64::from(len - 1)).round() as usize).min(n - 1)
        }
    };
    for r in 0..plot.height {
        let i = index(plot.height - 1 - r, plot.height);
        for c in 0..plot.width {
            let j = index(c, plot.width);
            let Some(class) = m.class.get(i * n + j).copied() else {
                continue;
            };
            if let Some(cell) = buf.cell_mut((plot.x + c, plot.y + r)) {
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
    let cc = to_cell(cj, plot.width);
    let cr = plot.height - 1 - to_cell(ci, plot.height);
    if let Some(cell) = buf.cell_mut((plot.x + cc, plot.y + cr)) {
        cell.set_symbol("┼")
            .set_style(Style::new().fg(Color::Black).bg(Color::White));
    }
}

/// Where the map's axis labels go: the column left of the plot and the y ticks to label.
struct AxisLabels<'a> {
    /// First column of the y labels.
    left: u16,
    /// Width of the y labels' column (the plot starts after it).
    width: u16,
    /// The y ticks (value, label); none on a map too small for them.
    y_ticks: &'a [(f64, String)],
}

/// The map's axes from the core's figure: y labels on the rows of their values with g_N and the
/// unit on a free row, x labels centred on their columns where they fit, then the x title.
fn draw_axes(buf: &mut Buffer, plot: Rect, labels: &AxisLabels, fig: &rime_core::figure::Figure) {
    let max = fig.x.max;
    let gray = Style::new().fg(Color::Gray);
    // Where a speed is drawn: the cell of the grid point nearest it.
    let col_of = |v: f64| (v / max * f64::from(plot.width - 1)).round() as u16;
    let row_of = |v: f64| plot.height - 1 - (v / max * f64::from(plot.height - 1)).round() as u16;
    // Y labels on the rows of their values, g_N on a free row between them.
    let mut taken_rows = Vec::new();
    for (v, label) in labels.y_ticks {
        let r = row_of(*v);
        if r < plot.height && !taken_rows.contains(&r) {
            buf.set_stringn(
                labels.left,
                plot.y + r,
                label,
                (labels.width - 1) as usize,
                gray,
            );
            taken_rows.push(r);
        }
    }
    if let Some(r) =
        (plot.height / 3..plot.height).find(|r| !taken_rows.iter().any(|t| t.abs_diff(*r) < 1))
    {
        buf.set_stringn(
            labels.left,
            plot.y + r,
            "g_N ↑",
            (labels.width - 1) as usize,
            gray,
        );
        // The unit of both axes (the x title may not fit).
        if r + 1 < plot.height && !taken_rows.contains(&(r + 1)) {
            buf.set_stringn(
                labels.left,
                plot.y + r + 1,
                "[m/s]",
                (labels.width - 1) as usize,
                gray,
            );
        }
    }
    // X labels centred on their columns where they fit, then the axis' title with its unit in
    // the widest gap between them (issue 37 E12: the title was looked for only right of the last
    // label, which sits at the axis' end, so g_T had none). Fewer ticks where "g_T [m/s]" would
    // not fit between them.
    let ly = plot.y + plot.height;
    let end = plot.x + plot.width;
    let layout = |count: usize| -> Vec<(u16, u16, String)> {
        let mut taken: Vec<(u16, u16, String)> = Vec::new();
        for t in fig.x.ticks(count) {
            let Some(label) = t.label else { continue };
            let w = label.chars().count() as u16;
            let c = plot.x + col_of(t.value);
            let start = c
                .saturating_sub(w / 2)
                .max(plot.x)
                .min(end.saturating_sub(w));
            if taken
                .iter()
                .all(|(a, b, _)| start + w < *a || start > *b + 1)
            {
                taken.push((start, start + w, label));
            }
        }
        taken.sort_unstable();
        taken
    };
    let widest_gap = |taken: &[(u16, u16, String)]| -> (u16, u16) {
        let mut gaps = Vec::new();
        let mut from = plot.x;
        for (a, b, _) in taken {
            gaps.push((from, a.saturating_sub(2)));
            from = *b + 2;
        }
        gaps.push((from, end));
        gaps.into_iter()
            .max_by_key(|(a, b)| b.saturating_sub(*a))
            .unwrap_or((plot.x, plot.x))
    };
    let short_title = "g_T [m/s]".chars().count() as u16;
    let mut count = usize::from((plot.width / 9).max(2));
    let mut taken = layout(count);
    while count > 2 && {
        let (a, b) = widest_gap(&taken);
        b.saturating_sub(a) < short_title
    } {
        count = (count * 2 / 3).max(2);
        taken = layout(count);
    }
    for (start, _, label) in &taken {
        buf.set_string(*start, ly, label, gray);
    }
    // The longest tail of "tangential speed g_T [m/s]" that fits the widest gap, centred; else
    // "g_T →" left of the ticks, under the y axis' "g_N ↑".
    let (gap_start, gap_end) = widest_gap(&taken);
    let room = gap_end.saturating_sub(gap_start);
    let words: Vec<&str> = fig.x.label.split(' ').collect();
    match (0..words.len())
        .map(|k| words[k..].join(" "))
        .take_while(|t| t.contains("g_T"))
        .find(|t| t.chars().count() as u16 <= room)
    {
        Some(tail) => {
            let w = tail.chars().count() as u16;
            buf.set_string(gap_start + (room - w) / 2, ly, &tail, gray);
        }
        None => {
            buf.set_stringn(labels.left, ly, "g_T →", (labels.width - 1) as usize, gray);
        }
    }
}
