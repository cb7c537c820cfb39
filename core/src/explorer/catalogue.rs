//! What the page lists, each a derived record read by key (snake_case, as every file record): the
//! parameter registry, the presets, the overlays of the ε_N chart, the stick classes, the status
//! names, the experimental context and the page's words. From the core's own tables, packed only.

use super::help::{
    ARTIFACT_NOTE, GLOSSARY, PAPER, class_is_artifact, option_label, parameter_help, slider_range,
};
use crate::applications::tidal::TidalInput;
use crate::scene::params::{Kind, PARAMETERS};
use crate::{Accuracy, Preset, Scene, Status, StickClass};
use alloc::collections::BTreeMap;
use alloc::format;
use alloc::string::String;
use alloc::vec::Vec;
use serde::Serialize;

/// One entry of the parameter registry: `{path, label, unit, kind, ...}` with `min`, `max`, `log`
/// for numbers and `options` for choices.
#[derive(Debug, Clone, Serialize)]
pub struct ParameterEntry {
    /// Parameter path.
    pub path: &'static str,
    /// Label.
    pub label: &'static str,
    /// SI unit.
    pub unit: &'static str,
    /// Its kind and range.
    #[serde(flatten)]
    pub kind: KindEntry,
}

/// A parameter's kind: `"kind": "number"` with its range, `"choice"` with its options, `"toggle"`.
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum KindEntry {
    /// A number in `[min, max]`, on a log scale or not.
    Number {
        /// Lowest value.
        min: f64,
        /// Highest value.
        max: f64,
        /// Whether the slider is logarithmic.
        log: bool,
    },
    /// One of `options`.
    Choice {
        /// The options by name.
        options: &'static [&'static str],
    },
    /// On or off.
    Toggle,
}

/// The parameter registry.
pub fn parameters() -> Vec<ParameterEntry> {
    PARAMETERS
        .iter()
        .map(|p| ParameterEntry {
            path: p.path,
            label: p.label,
            unit: p.unit,
            kind: match p.kind {
                Kind::Number { min, max, log } => KindEntry::Number { min, max, log },
                Kind::Choice(options) => KindEntry::Choice { options },
                Kind::Toggle => KindEntry::Toggle,
            },
        })
        .collect()
}

/// A preset: `{name, description, scene}` (the scene, so that the page can say which preset the
/// scene it shows is).
#[derive(Debug, Clone, Serialize)]
pub struct PresetEntry {
    /// Name.
    pub name: &'static str,
    /// What it is.
    pub description: &'static str,
    /// Its scene.
    pub scene: Scene,
}

/// The presets.
pub fn presets() -> Vec<PresetEntry> {
    Preset::ALL
        .iter()
        .map(|p| PresetEntry {
            name: p.name(),
            description: p.description(),
            scene: p.scene(),
        })
        .collect()
}

/// What can be drawn over the ε_N chart: a measured law or range of the atlas, or another model.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum OverlayEntry {
    /// A law or range of the atlas.
    Atlas {
        /// `atlas:<id>`.
        key: String,
        /// Source and material.
        label: String,
        /// `law` or `range`.
        kind: &'static str,
        /// The speeds it was measured at \[m/s\].
        valid: [f64; 2],
        /// The temperatures \[K\].
        temperature: [f64; 2],
        /// The grains' geometry.
        geometry: &'static str,
    },
    /// Another model.
    Model {
        /// `model:<name>`.
        key: String,
        /// Its citation.
        label: &'static str,
        /// `model`.
        kind: &'static str,
        /// The scene section it needs, if any.
        needs: Option<&'static str>,
    },
}

/// The overlays: the measured laws and ranges of the atlas, then the other models.
pub fn overlays() -> Vec<OverlayEntry> {
    use crate::data::atlas::{ENTRIES, Kind as EntryKind};
    use crate::models::Model;
    let mut list: Vec<OverlayEntry> = ENTRIES
        .iter()
        .filter(|e| e.kind != EntryKind::Threshold)
        .map(|e| OverlayEntry::Atlas {
            key: format!("atlas:{}", e.id),
            label: format!("{} {}: {}", e.citation.authors, e.citation.year, e.material),
            kind: e.kind.name(),
            valid: e.valid_speed,
            temperature: e.temperature,
            geometry: e.geometry.name(),
        })
        .collect();
    list.extend(
        Model::ALL
            .iter()
            .filter(|m| **m != Model::Hertzsch2002)
            .map(|m| OverlayEntry::Model {
                key: format!("model:{}", m.name()),
                label: m.citation(),
                kind: "model",
                needs: m.needs_section(),
            }),
    );
    list
}

/// A stick class: `{name, letter, label, description, meaning}`.
#[derive(Debug, Clone, Serialize)]
pub struct ClassEntry {
    /// Name.
    pub name: &'static str,
    /// The map's letter.
    pub letter: char,
    /// Label.
    pub label: &'static str,
    /// One line.
    pub description: &'static str,
    /// What it means physically.
    pub meaning: &'static str,
}

/// The stick classes in code order.
pub fn classes() -> Vec<ClassEntry> {
    StickClass::ALL
        .iter()
        .map(|c| ClassEntry {
            name: c.name(),
            letter: c.letter(),
            label: c.label(),
            description: c.description(),
            meaning: c.meaning(),
        })
        .collect()
}

/// The status names in code order.
pub fn statuses() -> [&'static str; 4] {
    Status::ALL.map(Status::name)
}

/// The experimental context of the ε_N chart: the Bridges et al. (1984) law and the microgravity
/// ice experiments' ranges.
#[derive(Debug, Clone, Serialize)]
pub struct Experiments {
    /// ε = a (g/g0)^b with its legend entry.
    pub bridges: Bridges,
    /// The experiments' ranges.
    pub bands: Vec<BandEntry>,
}

/// The Bridges et al. (1984) law ε = a (g/g0)^b with its legend entry.
#[derive(Debug, Clone, Serialize)]
pub struct Bridges {
    /// a.
    pub a: f64,
    /// b.
    pub b: f64,
    /// g0 \[m/s\].
    pub g0: f64,
    /// Legend text.
    pub label: &'static str,
}

/// An experiment's range as two intervals.
#[derive(Debug, Clone, Serialize)]
pub struct BandEntry {
    /// Speeds \[m/s\].
    pub x: [f64; 2],
    /// ε_N.
    pub y: [f64; 2],
    /// Legend text.
    pub label: String,
}

/// The experimental context.
pub fn experiments() -> Experiments {
    let b = crate::fit::BRIDGES_1984;
    Experiments {
        bridges: Bridges {
            a: b.a,
            b: b.b,
            g0: b.g0,
            label: crate::fit::BRIDGES_1984_LABEL,
        },
        bands: crate::figure::experiments::bands(0)
            .into_iter()
            .map(|band| BandEntry {
                x: [band.x.0, band.x.1],
                y: [band.y.0, band.y.1],
                label: band.label,
            })
            .collect(),
    }
}

/// Everything the page says in words: the paper's citation, the glossary, per-parameter help and
/// human option names, the stick classes' meaning (with artifacts marked), the artifact note, the
/// appendix's example, the accuracy levels and the speeds the page accepts.
#[derive(Debug, Clone, Serialize)]
pub struct Help {
    /// The paper.
    pub paper: crate::figure::words::Citation,
    /// The glossary.
    pub glossary: Vec<GlossaryEntry>,
    /// Each parameter's help by path.
    pub parameters: BTreeMap<&'static str, ParameterHelp>,
    /// Each class, artifact or not.
    pub classes: Vec<ClassArtifact>,
    /// Why the grey cells are an artifact.
    pub artifact_note: &'static str,
    /// The appendix's example (the paper's planet and grain).
    pub tidal_paper: TidalInput,
    /// The accuracy levels.
    pub levels: Vec<Level>,
    /// The speeds the page accepts.
    pub limits: SpeedLimits,
}

/// One glossary entry.
#[derive(Debug, Clone, Serialize)]
pub struct GlossaryEntry {
    /// The term.
    pub term: &'static str,
    /// What it means.
    pub meaning: &'static str,
}

/// One parameter's help: the sentence, human option names, the slider's range.
#[derive(Debug, Clone, Serialize)]
pub struct ParameterHelp {
    /// The sentence.
    pub help: &'static str,
    /// Human names of the options.
    pub options: BTreeMap<&'static str, &'static str>,
    /// The slider's range.
    pub slider: Option<[f64; 2]>,
}

/// Whether a stick class is an artifact of the printed law.
#[derive(Debug, Clone, Serialize)]
pub struct ClassArtifact {
    /// The class.
    pub name: &'static str,
    /// Whether it is an artifact.
    pub artifact: bool,
}

/// An accuracy level: its name, trade-off and error bound (`null` for none).
#[derive(Debug, Clone, Serialize)]
pub struct Level {
    /// Name.
    pub name: &'static str,
    /// Its trade-off in words.
    pub trade: &'static str,
    /// Its error bound.
    pub bound: f64,
}

/// The speeds the page accepts \[m/s\].
#[derive(Debug, Clone, Serialize)]
pub struct SpeedLimits {
    /// Lowest.
    pub speed_min: f64,
    /// Highest.
    pub speed_max: f64,
}

/// The page's words.
pub fn help() -> Help {
    let parameters = PARAMETERS
        .iter()
        .map(|p| {
            let options = match p.kind {
                Kind::Choice(options) => options
                    .iter()
                    .map(|o| (*o, option_label(p.path, o).unwrap_or(o)))
                    .collect(),
                _ => BTreeMap::new(),
            };
            let help = ParameterHelp {
                help: parameter_help(p.path).unwrap_or(""),
                options,
                slider: slider_range(p.path).map(|(lo, hi)| [lo, hi]),
            };
            (p.path, help)
        })
        .collect();
    Help {
        paper: PAPER,
        glossary: GLOSSARY
            .iter()
            .map(|(term, meaning)| GlossaryEntry { term, meaning })
            .collect(),
        parameters,
        classes: StickClass::ALL
            .iter()
            .map(|c| ClassArtifact {
                name: c.name(),
                artifact: class_is_artifact(*c),
            })
            .collect(),
        artifact_note: ARTIFACT_NOTE,
        tidal_paper: TidalInput::default(),
        levels: Accuracy::LEVELS
            .iter()
            .map(|l| Level {
                name: l.name(),
                trade: l.trade(),
                bound: l.error_bound(),
            })
            .collect(),
        limits: SpeedLimits {
            speed_min: super::limits::SPEED_MIN,
            speed_max: super::limits::SPEED_MAX,
        },
    }
}

/// One of the ring card's size choices as the page offers it.
#[derive(Debug, Clone, Serialize)]
pub struct RingSizeChoice {
    /// The name a request sends (`one`, `to_5r`, `to_10r`).
    pub name: &'static str,
    /// What the page shows (`one size`, `R–5R, q = 3`).
    pub label: &'static str,
}

/// The ring card's grain-size choices in the order a key cycles them (issue 38).
pub fn ring_sizes() -> Vec<RingSizeChoice> {
    super::ring::CardSizeChoice::ALL
        .iter()
        .map(|c| RingSizeChoice {
            name: c.name(),
            label: c.label(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::string::ToString;
    use serde_json::Value as Json;

    fn parse<T: Serialize>(v: &T) -> Json {
        serde_json::to_value(v).expect("JSON")
    }

    /// The keys of a JSON object, sorted (the page reads by key; order is not part of the contract).
    fn keys(v: &Json) -> Vec<&str> {
        let mut k: Vec<&str> = v
            .as_object()
            .expect("an object")
            .keys()
            .map(String::as_str)
            .collect();
        k.sort_unstable();
        k
    }

    /// Whether a JSON number carries `x` (a non-finite one crosses as `null`).
    fn carries(j: &Json, x: f64) -> bool {
        if x.is_finite() {
            j.as_f64() == Some(x)
        } else {
            j.is_null()
        }
    }

    #[test]
    fn issue_36_the_parameter_catalogue_keeps_its_keys() {
        let list = parse(&parameters());
        let list = list.as_array().expect("a list");
        assert_eq!(list.len(), PARAMETERS.len());
        for (j, p) in list.iter().zip(PARAMETERS.iter()) {
            assert_eq!(j["path"], p.path);
            assert_eq!(j["label"], p.label);
            assert_eq!(j["unit"], p.unit);
            match p.kind {
                Kind::Number { min, max, log } => {
                    assert_eq!(
                        keys(j),
                        ["kind", "label", "log", "max", "min", "path", "unit"]
                    );
                    assert_eq!(j["kind"], "number");
                    assert_eq!(
                        (j["min"].as_f64(), j["max"].as_f64()),
                        (Some(min), Some(max))
                    );
                    assert_eq!(j["log"], log);
                }
                Kind::Choice(options) => {
                    assert_eq!(keys(j), ["kind", "label", "options", "path", "unit"]);
                    assert_eq!(j["kind"], "choice");
                    assert_eq!(j["options"], Json::from(options.to_vec()));
                }
                Kind::Toggle => {
                    assert_eq!(keys(j), ["kind", "label", "path", "unit"]);
                    assert_eq!(j["kind"], "toggle");
                }
            }
        }
        // Every kind is present, so each arm above ran.
        for kind in ["number", "choice", "toggle"] {
            assert!(list.iter().any(|j| j["kind"] == kind), "{kind}");
        }
    }

    #[test]
    fn issue_36_presets_classes_statuses_keep_their_keys() {
        let list = parse(&presets());
        let list = list.as_array().expect("a list");
        assert_eq!(list.len(), Preset::ALL.len());
        for (j, p) in list.iter().zip(Preset::ALL.iter()) {
            assert_eq!(keys(j), ["description", "name", "scene"]);
            assert_eq!(j["name"], p.name());
            assert_eq!(j["description"], p.description());
            let scene: Scene = serde_json::from_value(j["scene"].clone()).expect("a scene");
            assert_eq!(scene, p.scene());
        }
        let list = parse(&classes());
        let list = list.as_array().expect("a list");
        assert_eq!(list.len(), StickClass::ALL.len());
        for (j, c) in list.iter().zip(StickClass::ALL.iter()) {
            assert_eq!(
                keys(j),
                ["description", "label", "letter", "meaning", "name"]
            );
            assert_eq!(j["name"], c.name());
            // The letter is a one-character string, not a number.
            assert_eq!(j["letter"], c.letter().to_string());
            assert_eq!(j["label"], c.label());
            assert_eq!(j["description"], c.description());
            assert_eq!(j["meaning"], c.meaning());
        }
        // The status codes' order is the core's (a frame's status arrays index it).
        let names = parse(&statuses());
        assert_eq!(
            names,
            Json::from(
                [
                    "rebound",
                    "stuck_in_layer",
                    "stuck_by_adhesion",
                    "overdamped"
                ]
                .to_vec()
            )
        );
        for (i, s) in Status::ALL.iter().enumerate() {
            assert_eq!(names[usize::from(s.code())], s.name(), "{i}");
        }
    }

    #[test]
    fn issue_36_overlays_and_experiments_keep_their_keys() {
        use crate::data::atlas::{ENTRIES, Kind as EntryKind};
        use crate::models::Model;
        let list = parse(&overlays());
        let list = list.as_array().expect("a list");
        let entries: Vec<_> = ENTRIES
            .iter()
            .filter(|e| e.kind != EntryKind::Threshold)
            .collect();
        let models: Vec<_> = Model::ALL
            .iter()
            .filter(|m| **m != Model::Hertzsch2002)
            .collect();
        assert_eq!(list.len(), entries.len() + models.len());
        for (j, e) in list.iter().zip(&entries) {
            assert_eq!(
                keys(j),
                ["geometry", "key", "kind", "label", "temperature", "valid"]
            );
            assert_eq!(j["key"], format!("atlas:{}", e.id));
            assert!(j["label"].as_str().expect("label").contains(e.material));
            assert_eq!(j["kind"], e.kind.name());
            assert!(carries(&j["valid"][0], e.valid_speed[0]));
            assert!(carries(&j["valid"][1], e.valid_speed[1]));
            assert!(carries(&j["temperature"][0], e.temperature[0]));
            assert!(carries(&j["temperature"][1], e.temperature[1]));
            assert_eq!(j["geometry"], e.geometry.name());
        }
        for (j, m) in list[entries.len()..].iter().zip(&models) {
            assert_eq!(keys(j), ["key", "kind", "label", "needs"]);
            assert_eq!(j["key"], format!("model:{}", m.name()));
            assert_eq!(j["kind"], "model");
            assert_eq!(j["label"], m.citation());
            assert_eq!(j["needs"].as_str(), m.needs_section());
        }
        let x = parse(&experiments());
        assert_eq!(keys(&x), ["bands", "bridges"]);
        assert_eq!(keys(&x["bridges"]), ["a", "b", "g0", "label"]);
        let b = crate::fit::BRIDGES_1984;
        // Bridges et al. (1984): ε = 0.32 (v / 1 cm/s)^−0.234.
        assert_eq!(x["bridges"]["a"], 0.32);
        assert_eq!(x["bridges"]["b"].as_f64(), Some(b.b));
        assert_eq!(x["bridges"]["g0"].as_f64(), Some(b.g0));
        let bands = crate::figure::experiments::bands(0);
        assert_eq!(bands.len(), 2);
        assert_eq!(x["bands"].as_array().map(Vec::len), Some(bands.len()));
        for (j, band) in x["bands"].as_array().expect("bands").iter().zip(&bands) {
            assert_eq!(keys(j), ["label", "x", "y"]);
            assert_eq!(j["x"][0].as_f64(), Some(band.x.0));
            assert_eq!(j["x"][1].as_f64(), Some(band.x.1));
            assert_eq!(j["y"][0].as_f64(), Some(band.y.0));
            assert_eq!(j["y"][1].as_f64(), Some(band.y.1));
            assert_eq!(j["label"], band.label);
        }
    }

    #[test]
    fn issue_36_help_keeps_its_keys_in_snake_case() {
        let h = parse(&help());
        assert_eq!(
            keys(&h),
            [
                "artifact_note",
                "classes",
                "glossary",
                "levels",
                "limits",
                "paper",
                "parameters",
                "tidal_paper"
            ]
        );
        assert_eq!(
            keys(&h["paper"]),
            ["authors", "journal", "pages", "title", "volume", "year"]
        );
        assert_eq!(h["paper"]["authors"], "J.-M. Hertzsch");
        assert_eq!(h["paper"]["year"], 2002);
        assert_eq!(h["paper"]["pages"], PAPER.pages);
        assert_eq!(h["glossary"].as_array().map(Vec::len), Some(GLOSSARY.len()));
        assert_eq!(keys(&h["glossary"][0]), ["meaning", "term"]);
        assert_eq!(h["glossary"][0]["term"], GLOSSARY[0].0);
        assert_eq!(h["glossary"][0]["meaning"], GLOSSARY[0].1);
        assert_eq!(
            h["parameters"]["contact_end"]["options"]["force_zero"],
            "when the force returns to zero"
        );
        let params = h["parameters"].as_object().expect("parameters");
        assert_eq!(params.len(), PARAMETERS.len());
        for p in PARAMETERS.iter() {
            let j = &params[p.path];
            assert_eq!(keys(j), ["help", "options", "slider"], "{}", p.path);
            assert_eq!(j["help"], parameter_help(p.path).unwrap_or(""));
            match p.kind {
                Kind::Choice(options) => {
                    assert_eq!(keys(&j["options"]).len(), options.len());
                    for o in options {
                        assert_eq!(j["options"][*o], option_label(p.path, o).unwrap_or(o));
                    }
                }
                _ => assert_eq!(j["options"], Json::Object(Default::default())),
            }
            match slider_range(p.path) {
                Some((lo, hi)) => {
                    assert_eq!(j["slider"][0].as_f64(), Some(lo));
                    assert_eq!(j["slider"][1].as_f64(), Some(hi));
                }
                None => assert!(j["slider"].is_null()),
            }
        }
        assert_eq!(keys(&h["classes"][0]), ["artifact", "name"]);
        let artifacts: Vec<&str> = h["classes"]
            .as_array()
            .expect("classes")
            .iter()
            .filter(|c| c["artifact"] == true)
            .map(|c| c["name"].as_str().expect("name"))
            .collect();
        assert_eq!(artifacts, ["sliding_gap"]);
        assert_eq!(keys(&h["levels"][0]), ["bound", "name", "trade"]);
        let levels: Vec<&str> = h["levels"]
            .as_array()
            .expect("levels")
            .iter()
            .map(|l| l["name"].as_str().expect("name"))
            .collect();
        assert_eq!(levels, ["fast", "precise", "integrated"]);
        assert_eq!(keys(&h["limits"]), ["speed_max", "speed_min"]);
        assert_eq!(
            h["limits"]["speed_max"].as_f64(),
            Some(super::super::limits::SPEED_MAX)
        );
        assert_eq!(
            h["tidal_paper"],
            serde_json::to_value(TidalInput::default()).expect("tidal input")
        );
    }
}
