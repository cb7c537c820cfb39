//! Drawing: [`render`] composes the screen from views, each a pure function of the data it shows
//! (not of the whole [`App`]): [`panel`] the parameters, [`chart`] the ε_N chart, [`map`] the stick
//! map, [`plot`] the one adapter that draws the core's figures (and maps the palette to terminal
//! colours), [`lines`] the derived, status and message lines, [`help`] the `?` overlay and [`tidal`] the
//! appendix calculator. Where each goes is [`super::layout`].

pub mod chart;
pub mod collision;
pub mod help;
pub mod lines;
pub mod map;
pub mod panel;
pub mod plot;
pub mod ring;
pub mod stick;
pub mod tidal;

use super::layout::{MIN_SIZE, layout};
use super::state::{App, Focus};
use ratatui::Frame;
use ratatui::layout::{Alignment, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{BorderType, Paragraph, Wrap};

/// The focused pane's border: thick and highlighted; the others thin and dim.
pub(super) fn pane_border(focused: bool) -> (BorderType, Style) {
    if focused {
        (
            BorderType::Thick,
            Style::new().fg(Color::Cyan).add_modifier(Modifier::BOLD),
        )
    } else {
        (BorderType::Plain, Style::new().fg(Color::DarkGray))
    }
}

/// An overlay panel over `area` (the tidal appendix, the sticking thresholds, the ring card): the
/// area cleared, a white border with the bold `title` and the panel's keys on the bottom edge.
/// Returns the area inside the border.
pub(super) fn overlay_panel(frame: &mut Frame, area: Rect, title: &str, keys: &str) -> Rect {
    frame.render_widget(ratatui::widgets::Clear, area);
    let block = ratatui::widgets::Block::bordered()
        .border_style(Style::new().fg(Color::White))
        .title(Span::styled(
            format!(" {title} "),
            Style::new().add_modifier(Modifier::BOLD),
        ))
        .title_bottom(format!(" {keys} "));
    let inner = block.inner(area);
    frame.render_widget(block, area);
    inner
}

/// Draws the whole screen: the one place that reads the whole [`App`] and hands each view its data.
// Long by design: the screen's panes and overlays in drawing order, the one place that decides
// what covers what.
pub fn render(app: &App, frame: &mut Frame) {
    let area = frame.area();
    let Some(l) = layout(area.width, area.height) else {
        too_small(frame, area);
        return;
    };
    let panel_rows = panel::panel(
        frame,
        l.panel,
        &panel::PanelView {
            scene: &app.scene,
            preset: app.preset,
            selected: app.selected,
            focused: app.focus == Focus::Panel,
        },
    );
    let mut drawn = super::state::Drawn {
        panel_rows,
        ..Default::default()
    };
    let data = app.data.as_ref();
    let show_map = !l.shared || app.map_shown;
    let show_chart = !l.shared || !app.map_shown;
    if show_chart {
        drawn.chart_axis = chart::chart(
            frame,
            l.chart,
            &chart::ChartView {
                data,
                sweep: app.sweep_def(),
                cursor: app.cursor,
                experiments: app.experiments,
                focused: app.focus == Focus::Chart,
                y_log: app.y_log,
                pinned: app.pinned.as_ref(),
                shared: l.shared,
                colors: app.colors,
                ring: app.ring_on_chart(),
            },
        );
    }
    if show_map {
        drawn.map_plot = map::map(
            frame.buffer_mut(),
            l.map,
            data,
            app.map_cursor,
            app.focus == Focus::Map,
            l.shared,
            app.colors,
        );
    }
    frame.render_widget(
        Paragraph::new(lines::derived_line(data, app.cursor, l.derived.width)),
        l.derived,
    );
    app.drawn.set(drawn);
    let status = lines::StatusView {
        accuracy: app.accuracy,
        data,
        elapsed: app.fixed_elapsed,
        computing: app.computing(),
        cursor: app.cursor,
    };
    let view_to_lose = app.view_to_lose();
    let message = lines::message_line(&lines::MessageView {
        confirm: app.confirm,
        open: app.open.as_ref(),
        input: app.input.as_ref(),
        selected: app.selected,
        message: app.message.as_ref(),
        view_to_lose: &view_to_lose,
    });
    match l.message {
        Some(r) => {
            frame.render_widget(
                Paragraph::new(lines::status_line(&status, l.status.width)),
                l.status,
            );
            // A long message ends in … rather than being cut silently; the input lines keep
            // their cursor (they scroll with it).
            let message = if app.input.is_some() || app.open.is_some() {
                message
            } else {
                lines::fit(message.spans, r.width as usize, "…")
            };
            frame.render_widget(Paragraph::new(message), r);
        }
        None => {
            let mut spans = if app.input.is_some() || app.open.is_some() || app.confirm.is_some() {
                Vec::new()
            } else {
                lines::status_spans(&status, l.status.width)
            };
            if !spans.is_empty() {
                spans.push(Span::raw(" │ "));
            }
            spans.extend(message.spans);
            // One fit of the shared line (the input lines keep their cursor: they scroll with it).
            let line = if app.input.is_some() || app.open.is_some() {
                Line::from(spans)
            } else {
                lines::fit(spans, l.status.width as usize, lines::STATUS_CUT)
            };
            frame.render_widget(Paragraph::new(line), l.status);
        }
    }
    if app.ring {
        ring::render_over(frame, l.map, l.views(), l.shared, app.ring_card.as_ref());
    }
    if app.tidal {
        let view = super::tidal::view(&app.scene, app.tidal_factor);
        tidal::render(frame, l.views(), &view);
    }
    if let Some(rows) = &app.stick {
        stick::render(frame, l.views(), rows, app.colors);
    }
    if let Some((g, result)) = &app.inside {
        let view = collision::CollisionView {
            g: *g,
            trajectory: result.as_ref().map_err(String::as_str),
            dynamic_loop: &app.inside_dynamic,
            colors: app.colors,
        };
        collision::render(frame, l.views(), &view);
    }
    if app.help {
        help::help(frame, area, app.help_scroll);
    }
}

fn too_small(frame: &mut Frame, area: Rect) {
    let text = vec![
        Line::from(Span::styled(
            format!("terminal too small (need {}×{})", MIN_SIZE.0, MIN_SIZE.1),
            Style::new().add_modifier(Modifier::BOLD),
        )),
        Line::from(format!("now {}×{}", area.width, area.height)),
        Line::from("enlarge the window, or q to quit"),
    ];
    let h = (text.len() as u16).min(area.height);
    let y = area.y + area.height.saturating_sub(h) / 2;
    frame.render_widget(
        Paragraph::new(text)
            .alignment(Alignment::Center)
            .wrap(Wrap { trim: true }),
        Rect::new(area.x, y, area.width, h),
    );
}
