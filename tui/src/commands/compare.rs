//! `rime compare`: several models of the same collision side by side (docs/cli.md#compare).

use crate::args::{Common, Format};
use crate::output::{num, table};
use crate::scene_io::{CliError, CliResult, err};
use rime_core::Accuracy;
use rime_core::error::Number;
use rime_core::models::{Evaluator, Model, SpeedStatus};
use serde::Serialize;

/// What `--models` may name: a collision model, or a measured law of the data atlas
/// (`atlas:ID`, docs/physics.md#data-atlas), evaluated with the scene's reduced radius where the law
/// needs one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Subject {
    /// A collision model on the scene's grains.
    Model(Model),
    /// An empirical law of the atlas.
    Law(&'static rime_core::atlas::Entry),
}

/// The options of `rime compare`.
#[derive(Debug, Clone, Default)]
pub struct Args {
    /// `--models`; empty: every model the scene supports.
    pub models: Vec<Model>,
    /// The atlas laws named in `--models` (`atlas:ID`).
    pub laws: Vec<&'static rime_core::atlas::Entry>,
    /// `--g`.
    pub g: Vec<f64>,
    /// `--list`: name every model with its citation.
    pub list: bool,
    /// `--bench`: the cost per ε_N of each model at each accuracy level.
    pub bench: bool,
}

fn law_ids() -> impl Iterator<Item = &'static rime_core::atlas::Entry> {
    rime_core::atlas::ENTRIES
        .iter()
        .filter(|e| e.kind == rime_core::atlas::Kind::Law)
}

/// Parses `--models a,b,…` (model names, or `atlas:ID` for a measured law); an unknown name is an
/// error naming `--models` and the valid names.
pub fn parse_subjects(text: &str) -> CliResult<Vec<Subject>> {
    let names = || {
        Model::ALL
            .iter()
            .map(|m| m.name().to_string())
            .chain(law_ids().map(|e| format!("atlas:{}", e.id)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut out = Vec::new();
    for name in text.split(',').map(str::trim) {
        let subject = match name.strip_prefix("atlas:") {
            Some(id) => law_ids().find(|e| e.id == id).map(Subject::Law),
            None => Model::from_name(name).map(Subject::Model),
        };
        match subject {
            Some(s) if !out.contains(&s) => out.push(s),
            Some(_) => {}
            None => {
                let all = names();
                return match crate::suggest::closest(name, all.split(", ")) {
                    Some(close) => err(format!(
                        "--models: unknown model '{name}' (did you mean `{close}`?)"
                    )),
                    None => err(format!("--models: unknown model '{name}' (valid: {all})")),
                };
            }
        }
    }
    Ok(out)
}

/// [`parse_subjects`] split into models and atlas laws.
pub fn parse_models(text: &str) -> CliResult<(Vec<Model>, Vec<&'static rime_core::atlas::Entry>)> {
    let mut models = Vec::new();
    let mut laws = Vec::new();
    for s in parse_subjects(text)? {
        match s {
            Subject::Model(m) => models.push(m),
            Subject::Law(e) => laws.push(e),
        }
    }
    Ok((models, laws))
}

use rime_core::explorer::records::{
    COMPARE_HEADER, CompareOutput, CompareRecord as Record, SpeedRecord as Speed,
};

#[derive(Serialize)]
struct Listing {
    model: &'static str,
    citation: String,
}

fn evaluators(common: &Common, args: &Args) -> CliResult<Vec<Evaluator>> {
    if args.models.is_empty() {
        // Every model this scene can run (the plastic one needs a plasticity section).
        return Ok(Model::ALL
            .into_iter()
            .filter_map(|m| Evaluator::new(m, &common.scene).ok())
            .collect());
    }
    args.models
        .iter()
        .map(|&m| Evaluator::new(m, &common.scene).map_err(|e| CliError::from(e).context(m.name())))
        .collect()
}

/// Width of `compare --list`'s table: an 80-column terminal.
pub const LIST_WIDTH: usize = 80;

/// The models and laws, names left, citations wrapped at word boundaries to `width` columns.
fn list_table(rows: &[Listing], width: usize) -> String {
    let name = rows
        .iter()
        .map(|r| r.model.chars().count())
        .max()
        .unwrap_or(5)
        .max(5);
    let text_width = width.saturating_sub(name + 2).max(20);
    let mut s = format!("{:<name$}  citation\n", "model");
    for r in rows {
        let mut line = String::new();
        let mut first = true;
        let flush = |line: &mut String, first: &mut bool, s: &mut String| {
            let label = if *first { r.model } else { "" };
            s.push_str(&format!("{label:<name$}  {line}\n"));
            line.clear();
            *first = false;
        };
        for word in r.citation.split_whitespace() {
            if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > text_width {
                flush(&mut line, &mut first, &mut s);
            }
            if !line.is_empty() {
                line.push(' ');
            }
            line.push_str(word);
        }
        flush(&mut line, &mut first, &mut s);
    }
    s
}

/// Runs `rime compare`.
// Long by design: one command's modes (list, bench, evaluate) and its three output formats kept
// together so the fields stay in step.
pub fn run(common: &Common, args: &Args) -> CliResult<String> {
    if args.list {
        let mut rows: Vec<Listing> = Model::ALL
            .iter()
            .map(|m| Listing {
                model: m.name(),
                citation: m.citation().to_string(),
            })
            .collect();
        rows.extend(law_ids().map(|e| Listing {
            model: e.id,
            citation: format!(
                "{} ({}), {} {}: measured law {} (use as atlas:{})",
                e.citation.authors,
                e.citation.year,
                e.citation.journal,
                e.citation.volume,
                e.formula,
                e.id
            ),
        }));
        return Ok(match common.format {
            Format::Json => to_json(&rows)?,
            Format::Csv => {
                let mut s = String::from("model,citation\n");
                for r in &rows {
                    s.push_str(&format!(
                        "{},\"{}\"\n",
                        r.model,
                        r.citation.replace('"', "'")
                    ));
                }
                s
            }
            Format::Table => list_table(&rows, LIST_WIDTH),
        });
    }
    let evaluators = if args.models.is_empty() && !args.laws.is_empty() {
        Vec::new()
    } else {
        evaluators(common, args)?
    };
    if args.bench {
        return bench(common, &evaluators, &args.g);
    }
    if args.g.is_empty() {
        return err("--g: required (or --list, --bench)");
    }
    let mut records = Vec::new();
    let mut speeds = Vec::new();
    // Every model's ε_N at every speed and its characteristic speeds, on every core; then read in
    // the sequential order (model by model, speeds first), so the output and the first error are
    // the sequential ones.
    let threads = crate::parallel::threads();
    let n = args.g.len();
    let results = crate::parallel::each(evaluators.len() * n, threads, 1, |k| {
        evaluators[k / n].eps(args.g[k % n], common.accuracy)
    });
    let characteristic = crate::parallel::each(evaluators.len(), threads, 1, |m| {
        evaluators[m].characteristic_speeds(common.accuracy)
    });
    let mut results = results.into_iter();
    for (e, cs) in evaluators.iter().zip(characteristic) {
        let name = e.model().name();
        for (&g, r) in args.g.iter().zip(results.by_ref()) {
            let r =
                r.map_err(|x| CliError::from(x).context(format!("{name}, g_n = {}", Number(g))))?;
            records.push(Record {
                model: name,
                g_n: g,
                eps_n: r.eps,
                status: r.status.name(),
            });
        }
        let cs = cs.map_err(|x| CliError::from(x).context(name))?;
        for s in cs.iter() {
            speeds.push(Speed {
                model: name,
                name: s.name,
                value: (s.status == SpeedStatus::Value).then_some(s.value),
                status: s.status.name(),
            });
        }
    }
    // The empirical laws: evaluated at the same speeds (status `measured`, or `extrapolated` outside
    // the speeds they were measured at), with their measured range as characteristic speeds.
    let r_eff = rime_core::Contact::new(&common.scene)?.r_eff;
    for law in &args.laws {
        let radius = law.needs_radius().then_some(r_eff);
        for &g in &args.g {
            let v = law.eval(g, radius).map_err(|x| {
                CliError::from(x).context(format!("atlas:{}, g_n = {}", law.id, Number(g)))
            })?;
            records.push(Record {
                model: law.id,
                g_n: g,
                eps_n: v.eps,
                status: if v.extrapolated {
                    "extrapolated"
                } else {
                    "measured"
                },
            });
        }
        for (name, value) in [
            ("valid_from", law.valid_speed[0]),
            ("valid_to", law.valid_speed[1]),
        ] {
            speeds.push(Speed {
                model: law.id,
                name,
                value: Some(value),
                status: SpeedStatus::Value.name(),
            });
        }
    }
    Ok(match common.format {
        // The record's own order, the documented one: `records`, then `characteristic_speeds`
        // (issue 37 C5: the keys were sorted).
        Format::Json => to_json(&CompareOutput {
            records,
            characteristic_speeds: speeds,
        })?,
        Format::Csv => CompareOutput {
            records,
            characteristic_speeds: speeds,
        }
        .csv(),
        Format::Table => {
            let mut s = table(
                &COMPARE_HEADER,
                &records
                    .iter()
                    .map(|r| r.cells().to_vec())
                    .collect::<Vec<_>>(),
            );
            s.push('\n');
            s.push_str(&table(
                &["model", "speed", "value [m/s]"],
                &speeds
                    .iter()
                    .map(|c| {
                        let value = c.value.map_or_else(|| c.status.replace('_', " "), num);
                        vec![c.model.into(), c.name.into(), value]
                    })
                    .collect::<Vec<_>>(),
            ));
            s
        }
    })
}

fn to_json<T: Serialize>(v: &T) -> CliResult<String> {
    serde_json::to_string_pretty(v)
        .map(|s| s + "\n")
        .map_err(|e| CliError::input(e.to_string()))
}

#[derive(Serialize)]
struct Cost {
    model: &'static str,
    accuracy: &'static str,
    ns_per_eps: f64,
    evaluations: usize,
}

/// The cost per ε_N of each model at each accuracy level, measured in one run: every speed of
/// `g` (default 60 log-spaced speeds 1e-6…1 m/s) evaluated repeatedly for at least 0.2 s.
fn bench(common: &Common, evaluators: &[Evaluator], g: &[f64]) -> CliResult<String> {
    let default: Vec<f64> = (0..60)
        .map(|i| 10f64.powf(-6.0 + 6.0 * i as f64 / 59.0))
        .collect();
    let g = if g.is_empty() { &default[..] } else { g };
    let mut rows = Vec::new();
    for e in evaluators {
        for level in Accuracy::LEVELS {
            let start = std::time::Instant::now();
            let mut n = 0usize;
            let mut sink = 0.0;
            while n == 0 || start.elapsed().as_secs_f64() < 0.2 {
                for &x in g {
                    sink += e
                        .eps(x, level)
                        .map_err(|err| CliError::from(err).context(e.model().name()))?
                        .eps;
                }
                n += g.len();
            }
            let ns = start.elapsed().as_secs_f64() * 1e9 / n as f64;
            std::hint::black_box(sink);
            rows.push(Cost {
                model: e.model().name(),
                accuracy: level.name(),
                ns_per_eps: ns,
                evaluations: n,
            });
        }
    }
    Ok(match common.format {
        Format::Json => to_json(&rows)?,
        _ => table(
            &["model", "accuracy", "ns/eps", "evaluations"],
            &rows
                .iter()
                .map(|r| {
                    vec![
                        r.model.into(),
                        r.accuracy.into(),
                        format!("{:.1}", r.ns_per_eps),
                        r.evaluations.to_string(),
                    ]
                })
                .collect::<Vec<_>>(),
        ),
    })
}
