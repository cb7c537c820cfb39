//! The terminal's colours: how many it shows (24-bit, the 16 ANSI colours, none with
//! `NO_COLOR`) and the one mapping of the palette ([`rime_core::explorer::palette`]) to them. The
//! figure adapter ([`super::view::plot`]) and every view take their colours from here.

use ratatui::style::{Color, Modifier, Style};
use rime_core::explorer::palette::{self, Rgb};

/// How many colours the terminal shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Colors {
    /// 24-bit colour: the palette as it is.
    #[default]
    Rgb,
    /// The 16 ANSI colours: each palette colour mapped to a fixed one.
    Ansi16,
    /// No colour (`NO_COLOR`, <https://no-color.org>): strokes and marks carry the differences.
    None,
}

impl Colors {
    /// What the environment asks for: none when `NO_COLOR` is set (and not empty), 24-bit when
    /// `COLORTERM` says `truecolor`/`24bit` or `TERM` names a 256-colour or direct-colour terminal
    /// (tmux and the common terminals map 24-bit colour there), else the 16 ANSI colours.
    pub fn from_env() -> Colors {
        let var = |k: &str| std::env::var(k).unwrap_or_default();
        Colors::from_vars(&var("NO_COLOR"), &var("COLORTERM"), &var("TERM"))
    }

    /// [`Colors::from_env`] on given values (for tests).
    pub fn from_vars(no_color: &str, colorterm: &str, term: &str) -> Colors {
        if !no_color.is_empty() {
            Colors::None
        } else if matches!(colorterm, "truecolor" | "24bit")
            || term.contains("256color")
            || term.contains("direct")
        {
            Colors::Rgb
        } else {
            Colors::Ansi16
        }
    }

    /// A palette colour on this terminal (`Color::Reset`, the terminal's own, without colour).
    pub fn color(self, c: Rgb) -> Color {
        match self {
            Colors::Rgb => Color::Rgb(c.r, c.g, c.b),
            Colors::None => Color::Reset,
            Colors::Ansi16 => ansi16(c),
        }
    }

    /// A style in palette colour `c`.
    pub fn fg(self, c: Rgb) -> Style {
        Style::new().fg(self.color(c))
    }

    /// A palette colour as a background, with the letter colour that reads on it.
    pub fn cell(self, bg: Rgb) -> Style {
        match self {
            Colors::None => Style::new().add_modifier(Modifier::REVERSED),
            _ => Style::new().fg(self.color(bg.text_on())).bg(self.color(bg)),
        }
    }
}

/// The 16-colour stand-in of each palette colour: fixed for the palette's hues (each hue its own
/// ANSI colour), the nearest of the xterm defaults for any other.
fn ansi16(c: Rgb) -> Color {
    let fixed = [
        (palette::ORANGE, Color::Yellow),
        (palette::YELLOW, Color::LightYellow),
        (palette::SKY_BLUE, Color::LightCyan),
        (palette::BLUISH_GREEN, Color::Green),
        (palette::BLUE, Color::Blue),
        (palette::VERMILLION, Color::Red),
        (palette::REDDISH_PURPLE, Color::Magenta),
        (palette::GREY_LIGHT, Color::Gray),
        (palette::GREY_DARK, Color::DarkGray),
        (palette::WHITE, Color::White),
        (palette::BLACK, Color::Black),
    ];
    if let Some((_, a)) = fixed.iter().find(|(p, _)| *p == c) {
        return *a;
    }
    let xterm = [
        (Rgb::hex(0x000000), Color::Black),
        (Rgb::hex(0xCD0000), Color::Red),
        (Rgb::hex(0x00CD00), Color::Green),
        (Rgb::hex(0xCDCD00), Color::Yellow),
        (Rgb::hex(0x0000EE), Color::Blue),
        (Rgb::hex(0xCD00CD), Color::Magenta),
        (Rgb::hex(0x00CDCD), Color::Cyan),
        (Rgb::hex(0xE5E5E5), Color::Gray),
        (Rgb::hex(0x7F7F7F), Color::DarkGray),
        (Rgb::hex(0xFF0000), Color::LightRed),
        (Rgb::hex(0x00FF00), Color::LightGreen),
        (Rgb::hex(0xFFFF00), Color::LightYellow),
        (Rgb::hex(0x5C5CFF), Color::LightBlue),
        (Rgb::hex(0xFF00FF), Color::LightMagenta),
        (Rgb::hex(0x00FFFF), Color::LightCyan),
        (Rgb::hex(0xFFFFFF), Color::White),
    ];
    let d = |a: Rgb| {
        let s = |x: u8, y: u8| (i32::from(x) - i32::from(y)).pow(2);
        s(a.r, c.r) + s(a.g, c.g) + s(a.b, c.b)
    };
    xterm
        .iter()
        .min_by_key(|(p, _)| d(*p))
        .map_or(Color::Reset, |(_, a)| *a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_color_and_16_colours_follow_the_environment() {
        assert_eq!(
            Colors::from_vars("1", "truecolor", "xterm-256color"),
            Colors::None
        );
        assert_eq!(Colors::from_vars("", "truecolor", "xterm"), Colors::Rgb);
        assert_eq!(Colors::from_vars("", "", "tmux-256color"), Colors::Rgb);
        assert_eq!(Colors::from_vars("", "", "xterm"), Colors::Ansi16);
        assert_eq!(Colors::from_vars("", "", "linux"), Colors::Ansi16);
    }

    #[test]
    fn every_palette_hue_keeps_its_own_ansi_colour() {
        let hues = [
            palette::ORANGE,
            palette::YELLOW,
            palette::SKY_BLUE,
            palette::BLUISH_GREEN,
            palette::BLUE,
            palette::VERMILLION,
            palette::REDDISH_PURPLE,
            palette::GREY_LIGHT,
            palette::GREY_DARK,
        ];
        for (i, a) in hues.iter().enumerate() {
            for b in &hues[i + 1..] {
                assert_ne!(ansi16(*a), ansi16(*b), "{a:?} and {b:?}");
            }
        }
        assert_eq!(Colors::None.color(palette::ORANGE), Color::Reset);
    }
}
