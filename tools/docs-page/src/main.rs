//! Renders a Markdown file of `docs/` into a standalone HTML page for the web explorer's folder, so
//! the page's "Eq. (N)" and "decision N" links resolve on any static server (`make www`):
//!
//! ```text
//! docs-page docs/physics.md www/physics.html
//! ```
//!
//! Links to other files of the repository do not exist on a served page: they become their path as
//! code (the reader knows where to look); links within the file and to the web stay links. Every
//! heading gets the id GitHub gives it (`## Equations used` → `#equations-used`), so an anchor that
//! works on the repository's rendering works on the page too.

use pulldown_cmark::{CowStr, Event, Options, Parser, Tag, TagEnd, html};
use std::process::ExitCode;

/// What a link becomes on the served page.
#[derive(Debug, PartialEq)]
enum Target {
    /// Keep it, with this destination.
    Link(String),
    /// A file of the repository that is not served: show its path instead.
    Text(String),
}

/// Where a link of `source_name` (e.g. `physics.md`) points on the served page.
fn target(dest: &str, source_name: &str) -> Target {
    if dest.starts_with('#') || dest.contains("://") || dest.starts_with("mailto:") {
        return Target::Link(dest.to_string());
    }
    // A link to this very file (`physics.md#decision-2`) is an anchor of the page.
    if let Some(anchor) = dest.strip_prefix(source_name)
        && (anchor.is_empty() || anchor.starts_with('#'))
    {
        return Target::Link(if anchor.is_empty() {
            "#".into()
        } else {
            anchor.into()
        });
    }
    Target::Text(dest.trim_start_matches("../").to_string())
}

/// GitHub's anchor for a heading: lower case, punctuation dropped (but `-` and `_`), spaces → `-`.
fn slug(text: &str) -> String {
    text.trim()
        .chars()
        .flat_map(char::to_lowercase)
        .filter(|c| c.is_alphanumeric() || matches!(c, ' ' | '-' | '_'))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// `slug`, or `slug-1`, `slug-2`… when an earlier heading has it (as GitHub numbers them).
fn unique(slug: String, seen: &mut Vec<String>) -> String {
    let mut candidate = slug.clone();
    let mut n = 0;
    while seen.contains(&candidate) {
        n += 1;
        candidate = format!("{slug}-{n}");
    }
    seen.push(candidate.clone());
    candidate
}

/// The page: the rendered notes between a header (back to the explorer) and the page's stylesheet.
fn page(markdown: &str, source_name: &str, title: &str) -> String {
    let mut opts = Options::empty();
    opts.insert(Options::ENABLE_TABLES);
    opts.insert(Options::ENABLE_STRIKETHROUGH);
    let mut events = Vec::new();
    // Inside a link that became text: its text is kept, followed by its path.
    let mut unlinked: Vec<Option<String>> = Vec::new();
    // Where the current heading starts in `events`, and its text so far.
    let mut heading: Option<(usize, String)> = None;
    let mut slugs: Vec<String> = Vec::new();
    for event in Parser::new_ext(markdown, opts) {
        if let Some((_, text)) = heading.as_mut()
            && let Event::Text(t) | Event::Code(t) = &event
        {
            text.push_str(t);
        }
        match event {
            Event::Start(Tag::Heading { .. }) => {
                heading = Some((events.len(), String::new()));
                events.push(event);
            }
            Event::End(TagEnd::Heading(level)) => {
                if let Some((start, text)) = heading.take() {
                    let slug = unique(slug(&text), &mut slugs);
                    if let Some(Event::Start(Tag::Heading { id, .. })) = events.get_mut(start)
                        && id.is_none()
                    {
                        *id = Some(CowStr::from(slug));
                    }
                }
                events.push(Event::End(TagEnd::Heading(level)));
            }
            Event::Start(Tag::Link {
                link_type,
                dest_url,
                title,
                id,
            }) => match target(&dest_url, source_name) {
                Target::Link(dest) => {
                    unlinked.push(None);
                    events.push(Event::Start(Tag::Link {
                        link_type,
                        dest_url: CowStr::from(dest),
                        title,
                        id,
                    }));
                }
                Target::Text(path) => unlinked.push(Some(path)),
            },
            Event::End(TagEnd::Link) => match unlinked.pop().flatten() {
                Some(path) => {
                    events.push(Event::Text(" (".into()));
                    events.push(Event::Code(CowStr::from(path)));
                    events.push(Event::Text(")".into()));
                }
                None => events.push(Event::End(TagEnd::Link)),
            },
            other => events.push(other),
        }
    }
    let mut body = String::new();
    html::push_html(&mut body, events.into_iter());
    format!(
        "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title}</title>\n<link rel=\"icon\" href=\"data:,\">\n\
         <link rel=\"stylesheet\" href=\"style.css\">\n</head>\n<body class=\"notes\">\n\
         <header class=\"notes-header\"><a href=\"index.html\">← the explorer</a> · \
         rendered from <code>docs/{source_name}</code> by <code>make www</code></header>\n\
         <main class=\"notes-body\">\n{body}</main>\n</body>\n</html>\n"
    )
}

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [input, output] = args.as_slice() else {
        return Err("usage: docs-page INPUT.md OUTPUT.html".into());
    };
    let text = std::fs::read_to_string(input).map_err(|e| format!("cannot read {input}: {e}"))?;
    let name = std::path::Path::new(input)
        .file_name()
        .and_then(|n| n.to_str())
        .ok_or_else(|| format!("{input}: not a file name"))?;
    let title = text
        .lines()
        .find_map(|l| l.strip_prefix("# "))
        .unwrap_or(name)
        .replace('<', "&lt;");
    std::fs::write(output, page(&text, name, &title))
        .map_err(|e| format!("cannot write {output}: {e}"))
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("docs-page: {e}");
            ExitCode::from(2)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_to_this_file_become_anchors_and_other_files_their_path() {
        let link = |d: &str| Target::Link(d.into());
        let text = |d: &str| Target::Text(d.into());
        for (dest, want) in [
            ("physics.md#decision-2", link("#decision-2")),
            ("#models", link("#models")),
            ("https://doi.org/x", link("https://doi.org/x")),
            ("../core/src/fit/mod.rs", text("core/src/fit/mod.rs")),
            ("cli.md#records", text("cli.md#records")),
        ] {
            assert_eq!(target(dest, "physics.md"), want, "{dest}");
        }
    }

    #[test]
    fn headings_get_githubs_anchors() {
        let html = page(
            "## Equations used\n\n### 2. End of contact (`force_zero`)\n\n## Equations used\n",
            "physics.md",
            "t",
        );
        assert!(html.contains("<h2 id=\"equations-used\">"), "{html}");
        assert!(
            html.contains("<h3 id=\"2-end-of-contact-force_zero\">"),
            "{html}"
        );
        assert!(html.contains("<h2 id=\"equations-used-1\">"), "{html}");
    }

    #[test]
    fn anchors_survive_and_repository_links_do_not_dangle() {
        let md = "<a id=\"decision-2\"></a>\n\n### 2. End\n\nSee [the fit](../core/src/fit/mod.rs) and [two](physics.md#decision-2); η* stays η*.\n";
        let html = page(md, "physics.md", "t");
        assert!(html.contains("<a id=\"decision-2\"></a>"), "{html}");
        assert!(
            html.contains("the fit (<code>core/src/fit/mod.rs</code>)"),
            "{html}"
        );
        assert!(html.contains("<a href=\"#decision-2\">two</a>"), "{html}");
        assert!(!html.contains("href=\"../"), "{html}");
        assert!(html.contains("η* stays η*"), "{html}");
    }

    /// Issue 37: the page's physics notes read "(g_s/g'{N,v})²) *with g'*{N,v}": two subscripts
    /// `_{…}` of a formula paired as emphasis and lost their underscores. No emphasis of the real
    /// notes holds a formula's brace, and every row of "Equations used" is an anchor the page's
    /// equation links land on.
    #[test]
    fn issue_37_the_notes_keep_formula_underscores_and_anchor_each_equation_row() {
        let md = include_str!("../../../docs/physics.md");
        let html = page(md, "physics.md", "t");
        assert!(
            html.contains("g'_{N,v}"),
            "the adhesion formula lost its subscript"
        );
        for em in html.split("<em>").skip(1) {
            let inside = em.split("</em>").next().unwrap_or_default();
            assert!(
                !inside.contains('{') && !inside.contains('}'),
                "a formula read as emphasis: <em>{inside}</em>"
            );
        }
        let rows = md
            .lines()
            .filter(|l| l.starts_with("| ") && l.contains("Eq. ("))
            .filter(|l| l.split('|').nth(1).is_some_and(|c| c.contains("Eq. (")));
        let mut n = 0;
        for row in rows {
            n += 1;
            assert!(
                row.starts_with("| <a id=\"eq-"),
                "a row without its anchor: {row}"
            );
        }
        assert!(n >= 19, "{n} equation rows");
        for id in ["eq-4", "eq-13", "eq-a1"] {
            assert!(html.contains(&format!("<a id=\"{id}\"></a>")), "{id}");
        }
    }
}
