//! The host-testable part of the binding: a [`Explorer`] holding a scene, with every operation the
//! page needs as a plain Rust method returning `Result<_, String>` (the string names the field).
//!
//! No physics here: every number comes from `rime-core`; this module only validates arguments,
//! converts between JSON/text and core types, and packs results into flat arrays.

use rime_core::params::{Kind, PARAMETERS, Value};
use rime_core::sweep::log_space;
use rime_core::tidal::TidalInput;
use rime_core::{Accuracy, Contact, Preset, Scene, Status, StickClass};
use serde_json::Value as Json;
use std::collections::BTreeMap;

pub use rime_core::explorer::limits::{MAX_CURVE_POINTS, MAX_MAP_SIDE, MAX_SCENE_BYTES};

/// The collision record the page's collision card reads: the core's trajectory (its serde form:
/// `t`, `xi`, `xi_dot`, `force`, `phases`, `t_c` — `null` when unresolved —, `xi_max`, `eps_n`,
/// `status`, `ledger`, `resolved`, `rhs_evaluations`) with the impact speed, the radii and, with
/// adhesion, the dynamic JKR model's loop.
#[derive(serde::Serialize)]
struct CollisionRecord<'a> {
    g: f64,
    #[serde(flatten)]
    trajectory: &'a rime_core::collision::Trajectory,
    radius_1: f64,
    radius_2: f64,
    dynamic: Option<ForceLoop>,
}

/// The dynamic JKR model's force loop (`Dynamic::force_loop`) as two arrays.
#[derive(serde::Serialize)]
struct ForceLoop {
    xi: Vec<f64>,
    force: Vec<f64>,
}

/// The stick map's records (`rime map --format csv`) from the frame's arrays: `g` (n speeds),
/// `eps_t` and class codes (n² each, row-major). Formatted only when the page downloads them:
/// 14 400 rows cost ~40 ms, too much for every frame.
pub fn map_records(g: &[f64], eps_t: &[f64], codes: &[u8]) -> Result<String, String> {
    let n = g.len();
    if eps_t.len() != n * n || codes.len() != n * n {
        return Err(format!(
            "mapRecords: epsT and class must hold n² = {} values (got {} and {})",
            n * n,
            eps_t.len(),
            codes.len()
        ));
    }
    let class = codes
        .iter()
        .map(|&c| {
            StickClass::ALL
                .get(usize::from(c))
                .copied()
                .ok_or_else(|| format!("mapRecords: unknown class code {c}"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let map = rime_core::sweep::StickMap {
        g: g.to_vec(),
        eps_n: Vec::new(),
        class,
        eps_t: eps_t.to_vec(),
        rhs_evaluations: 0,
    };
    Ok(rime_core::explorer::records::map_csv(&map))
}

/// The appendix as JSON (`{input, result, paper}`) for `input`, or without one the paper's planet
/// and distance with the scene's grain 1 radius, density and surface energy (the paper's 0.1 J/m²
/// without adhesion). One builder for the frame and [`Explorer::tidal`].
pub fn tidal_json(scene: &Scene, input: Option<TidalInput>) -> Result<Json, String> {
    use rime_core::explorer::tidal::{card, input_for};
    let (input, gamma_from_paper) = match input {
        Some(typed) => (typed, false),
        None => input_for(scene, 1.0),
    };
    let card = card(input, gamma_from_paper).map_err(|e| format!("tidal.{e}"))?;
    serde_json::to_value(&card).map_err(|e| format!("tidal: {e}"))
}

/// What the page's ring card sends (issue 24): τ, Ω or a planet and a distance, and the ε_N
/// chart's speed range `[from, to]` \[m/s\] for the ε_cr line.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RingRequest {
    tau: f64,
    omega: Option<f64>,
    planet_mass: Option<f64>,
    distance: Option<f64>,
    chart: (f64, f64),
}

/// The ring card for `scene` (JSON) and `input` (JSON `{tau, omega | planet_mass + distance,
/// chart: [from, to]}`), built by `rime_core::explorer::ring::ring_card`: `{verdict, equilibrium,
/// sentence, rows: [{label, text}], eps_cr_line: {name, short, points, color, stroke}, meeting:
/// [g, ε] | null, impact_marker: {x, label, short, color}, record}` (`record` is `rime ring`'s
/// prediction record; colours are indices into the palette's `series`). Errors name the field
/// (`ring.tau: …`).
pub fn ring_card_json(scene: &str, input: &str) -> Result<String, String> {
    use rime_core::ring::{Orbit, RingInput};
    let scene = parse_scene(scene)?;
    let de = &mut serde_json::Deserializer::from_str(input);
    let req: RingRequest = serde_path_to_error::deserialize(de).map_err(|e| {
        let path = e.path().to_string();
        let path = if path == "." || path.is_empty() {
            "ring".to_string()
        } else {
            format!("ring.{path}")
        };
        format!("{path}: {}", e.into_inner())
    })?;
    let orbit = match (req.omega, req.planet_mass, req.distance) {
        (Some(o), None, None) => Orbit::Omega(o),
        (None, Some(m), Some(d)) => Orbit::Planet {
            planet_mass: m,
            distance: d,
        },
        _ => return Err("ring.omega: give omega, or planet_mass and distance".into()),
    };
    let input = RingInput {
        tau: req.tau,
        orbit,
        damping_set_for_radius: None,
    };
    let card = rime_core::explorer::ring::ring_card(&scene, &input, req.chart)
        .map_err(|e| format!("ring.{e}"))?;
    let line = &card.eps_cr_line;
    let page = RingCardJson {
        verdict: card.verdict,
        equilibrium: card.equilibrium,
        sentence: &card.sentence,
        rows: &card.rows,
        eps_cr_line: LineJson {
            name: &line.name,
            short: &line.short,
            points: &line.points,
            color: line.color,
            stroke: line.stroke.name(),
        },
        meeting: card.meeting.map(|(g, e)| [g, e]),
        impact_marker: &card.impact_marker,
        record: &card.record,
    };
    serde_json::to_string(&page).map_err(|e| format!("ring: {e}"))
}

fn core_err(e: rime_core::Error) -> String {
    e.to_string()
}

fn check_speed(field: &str, g: f64) -> Result<f64, String> {
    if rime_core::limits::speed_is_valid(g) {
        Ok(g)
    } else {
        let domain = rime_core::limits::SPEED_DOMAIN;
        Err(format!("{field}: speed must lie in {domain} m/s (got {g})"))
    }
}

fn check_count(field: &str, n: usize, lo: usize, hi: usize) -> Result<usize, String> {
    if (lo..=hi).contains(&n) {
        Ok(n)
    } else {
        Err(format!("{field}: must lie in [{lo}, {hi}] (got {n})"))
    }
}

/// Parses an accuracy level (`fast`, `balanced`, `precise` or a tolerance).
pub fn parse_accuracy(text: &str) -> Result<Accuracy, String> {
    Accuracy::parse(text).map_err(core_err)
}

/// Parses scene JSON; errors name the JSON path (`layer.viscosity: ...`).
pub fn parse_scene(text: &str) -> Result<Scene, String> {
    if text.len() > MAX_SCENE_BYTES {
        return Err(format!(
            "scene: {} bytes; a scene is at most {MAX_SCENE_BYTES} bytes",
            text.len()
        ));
    }
    let de = &mut serde_json::Deserializer::from_str(text);
    let scene: Scene = serde_path_to_error::deserialize(de).map_err(|e| {
        let path = e.path().to_string();
        let path = if path == "." || path.is_empty() {
            "scene".to_string()
        } else {
            path
        };
        format!("{path}: {}", e.into_inner())
    })?;
    scene.validate().map_err(core_err)?;
    Ok(scene)
}

/// Log-spaced speeds from `from` to `to` inclusive (validated).
pub fn speeds(from: f64, to: f64, n: usize) -> Result<Vec<f64>, String> {
    let from = check_speed("from", from)?;
    let to = check_speed("to", to)?;
    if from >= to {
        return Err(format!("to: must be greater than from ({to} <= {from})"));
    }
    let n = check_count("n", n, 2, MAX_CURVE_POINTS)?;
    let mut g = vec![0.0; n];
    log_space(from, to, &mut g);
    Ok(g)
}

/// A scene being explored.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Explorer {
    /// The current scene (always valid).
    pub scene: Scene,
}

impl Explorer {
    /// The default (`ice`) scene.
    pub fn new() -> Explorer {
        Explorer::default()
    }

    /// A scene from JSON.
    pub fn from_json(text: &str) -> Result<Explorer, String> {
        Ok(Explorer {
            scene: parse_scene(text)?,
        })
    }

    /// Replaces the scene from JSON; on error the scene is unchanged.
    pub fn set_json(&mut self, text: &str) -> Result<(), String> {
        self.scene = parse_scene(text)?;
        Ok(())
    }

    /// The scene as compact JSON (numbers round-trip exactly).
    pub fn to_json(&self) -> Result<String, String> {
        serde_json::to_string(&self.scene).map_err(|e| format!("scene: {e}"))
    }

    /// Sets a parameter from text (number with optional unit, choice, `on`/`off`); on error the
    /// scene is unchanged and the message names the field.
    pub fn set(&mut self, path: &str, text: &str) -> Result<(), String> {
        let before = self.scene;
        self.scene.set(path, text).map_err(|e| match e {
            rime_core::Error::UnknownParameter => format!("{path}: unknown parameter"),
            e => core_err(e),
        })?;
        self.check(path, before)
    }

    /// The core's full check of the scene after a change of `path` (`Contact::new`, which also
    /// checks derived quantities); on error the scene goes back to `before`.
    fn check(&mut self, path: &str, before: Scene) -> Result<(), String> {
        match Contact::new(&self.scene) {
            Ok(_) => Ok(()),
            Err(e) => {
                self.scene = before;
                let msg = core_err(e);
                Err(if msg.contains(path) {
                    msg
                } else {
                    format!("{path}: {msg}")
                })
            }
        }
    }

    /// Sets a numeric parameter directly; same rules as [`Explorer::set`].
    pub fn set_number(&mut self, path: &str, value: f64) -> Result<(), String> {
        let before = self.scene;
        self.scene.set_number(path, value).map_err(|e| match e {
            rime_core::Error::UnknownParameter => format!("{path}: unknown parameter"),
            e => core_err(e),
        })?;
        self.check(path, before)
    }

    /// The preset whose scene this is, if any (the page's preset menu names it on every edit
    /// without reading the scene's text back).
    pub fn preset(&self) -> Option<&'static str> {
        Preset::ALL
            .into_iter()
            .find(|p| p.scene() == self.scene)
            .map(Preset::name)
    }

    /// A parameter's value as JSON: a number, a choice name, a boolean for effects, `null` when
    /// inactive.
    pub fn get(&self, path: &str) -> Result<String, String> {
        let v = self.scene.get(path).map_err(|e| match e {
            rime_core::Error::UnknownParameter => format!("{path}: unknown parameter"),
            e => core_err(e),
        })?;
        Ok(match v {
            Value::Number(x) => Json::from(x),
            Value::Choice(c) => Json::from(c),
            Value::Enabled(b) => Json::from(b),
            Value::Inactive => Json::Null,
        }
        .to_string())
    }

    /// The damping time `A` \[s\] the scene gives (directly or from viscosities).
    pub fn damping_time(&self) -> Result<f64, String> {
        Ok(Contact::new(&self.scene).map_err(core_err)?.damping_time)
    }

    /// Loads a named preset.
    pub fn load_preset(&mut self, name: &str) -> Result<(), String> {
        let p = Preset::from_name(name).ok_or_else(|| {
            format!(
                "preset: unknown preset {name:?} (one of {})",
                Preset::ALL.map(Preset::name).join(", ")
            )
        })?;
        self.scene = p.scene();
        Ok(())
    }

    /// The full normal result at one speed, as JSON (`g_n`, `eps_n`, `status`, `t_c`, `xi_max`,
    /// `error_estimate`; infinities as `null`).
    pub fn normal(&self, g: f64, accuracy: &str) -> Result<String, String> {
        let g = check_speed("g_n", g)?;
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let r = contact
            .normal(g, parse_accuracy(accuracy)?)
            .map_err(core_err)?;
        let page = NormalJson {
            g_n: g,
            eps_n: r.eps,
            status: r.status.name(),
            t_c: r.t_c,
            xi_max: r.xi_max,
            error_estimate: r.error_estimate,
        };
        serde_json::to_string(&page).map_err(|e| format!("normal: {e}"))
    }

    /// One collision from the inside at impact speed `g` (docs/physics.md#collision), as JSON:
    /// `t`, `xi`, `xi_dot`, `force` (SI arrays of `points` samples plus the phase instants),
    /// `phases` (`{name, t}`), `t_c` (`null` when unresolved), `xi_max`, `eps_n`, `status`,
    /// `ledger` (joules and `closure`), `resolved`, the grains' radii, and with adhesion the dynamic
    /// JKR model's loop `dynamic` (`{xi, force}`).
    pub fn collision(&self, g: f64, points: usize, accuracy: &str) -> Result<String, String> {
        let g = check_speed("g_n", g)?;
        let points = check_count("points", points, 2, MAX_CURVE_POINTS)?;
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let t = contact
            .collision(g, points, parse_accuracy(accuracy)?)
            .map_err(core_err)?;
        // The dynamic JKR model's loop, as two arrays.
        let dynamic = self.scene.adhesion.and_then(|a| {
            rime_core::models::brilliantov2007::Dynamic::new(&contact, a.surface_energy, a.jkr_end)
                .and_then(|d| d.force_loop(g, 1e-9))
                .ok()
                .map(|p| ForceLoop {
                    xi: p.iter().map(|q| q.xi).collect(),
                    force: p.iter().map(|q| q.force).collect(),
                })
        });
        let record = CollisionRecord {
            g,
            trajectory: &t,
            radius_1: self.scene.grains.radius_1,
            radius_2: self.scene.grains.radius_2,
            dynamic,
        };
        serde_json::to_string(&record).map_err(|e| format!("collision: {e}"))
    }

    /// Fits the damping time A of the current scene to a measured law of the atlas (`id`) over the
    /// speeds it was measured at and, on success, makes the fitted scene current. JSON: `value`,
    /// `standard_error` (or `null`), `rms_error`, `warnings`, `scene`. On error the scene is unchanged.
    pub fn fit_to_entry(&mut self, id: &str, accuracy: &str) -> Result<String, String> {
        let entry =
            rime_core::atlas::find(id).ok_or_else(|| format!("overlays: unknown entry {id:?}"))?;
        let f = rime_core::fit_scene::fit_to_entry(
            &self.scene,
            entry,
            &["bulk.damping.time"],
            parse_accuracy(accuracy)?,
        )
        .map_err(|e| format!("fit A to {id}: {e}"))?;
        self.scene = f.scene;
        let p = &f.params[0];
        let page = FitJson {
            id,
            value: p.value,
            standard_error: p.standard_error,
            rms_error: f.rms_error,
            warnings: &f.warnings,
            scene: serde_json::to_string(&f.scene).map_err(|e| e.to_string())?,
        };
        serde_json::to_string(&page).map_err(|e| format!("fit A to {id}: {e}"))
    }

    /// Tangential restitution at one point, as JSON (`g_n`, `g_t`, `eps_t`, `eps_n`, `class`).
    pub fn tangential(&self, g_n: f64, g_t: f64, accuracy: &str) -> Result<String, String> {
        let (g_n, g_t) = (check_map_speed("g_n", g_n)?, check_map_speed("g_t", g_t)?);
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let t = contact
            .tangential(g_n, g_t, parse_accuracy(accuracy)?)
            .map_err(core_err)?;
        let page = TangentialJson {
            g_n,
            g_t,
            eps_t: t.eps_t,
            eps_n: t.eps_n,
            class: t.class.name(),
        };
        serde_json::to_string(&page).map_err(|e| format!("tangential: {e}"))
    }

    /// The appendix (Eq. (A.1)–(A.7)) as JSON: the core's tidal card (`rime_core::explorer::tidal`). `input_json` is a
    /// `TidalInput`; empty means the paper's planet and distance with the scene's grain 1 radius,
    /// density and surface energy (the paper's 0.1 J/m² without adhesion).
    pub fn tidal(&self, input_json: &str) -> Result<String, String> {
        let input: Option<TidalInput> = if input_json.trim().is_empty() {
            None
        } else {
            let de = &mut serde_json::Deserializer::from_str(input_json);
            Some(serde_path_to_error::deserialize(de).map_err(|e| {
                let path = e.path().to_string();
                format!("tidal.{path}: {}", e.into_inner())
            })?)
        };
        Ok(tidal_json(&self.scene, input)?.to_string())
    }
}

fn check_map_speed(field: &str, g: f64) -> Result<f64, String> {
    if rime_core::limits::speed_or_zero_is_valid(g) {
        Ok(g)
    } else {
        let domain = rime_core::limits::SPEED_OR_ZERO_DOMAIN;
        Err(format!("{field}: speed must lie in {domain} m/s (got {g})"))
    }
}

/// A catalogue as JSON. `serde_json` fails only on a map with non-string keys or a `Serialize`
/// impl that errors; the catalogues have neither, so the fallback `null` is never sent.
fn catalogue_json<T: serde::Serialize>(value: &T) -> String {
    serde_json::to_string(value).unwrap_or_else(|_| "null".to_string())
}

/// The parameter registry as JSON: a list of `{path, label, unit, kind, ...}` with `min`, `max`,
/// `log` for numbers and `options` for choices.
pub fn parameters_json() -> String {
    let list: Vec<ParameterJson> = PARAMETERS
        .iter()
        .map(|p| ParameterJson {
            path: p.path,
            label: p.label,
            unit: p.unit,
            kind: match p.kind {
                Kind::Number { min, max, log } => KindJson::Number { min, max, log },
                Kind::Choice(options) => KindJson::Choice { options },
                Kind::Toggle => KindJson::Toggle,
            },
        })
        .collect();
    catalogue_json(&list)
}

/// The presets as JSON: a list of `{name, description, scene}` (the scene, so that the page can
/// say which preset the scene it shows is).
pub fn presets_json() -> String {
    let list: Vec<PresetJson> = Preset::ALL
        .iter()
        .map(|p| PresetJson {
            name: p.name(),
            description: p.description(),
            scene: p.scene(),
        })
        .collect();
    catalogue_json(&list)
}

/// What can be drawn over the ε_N chart, as JSON: a list of `{key, label, kind, valid, temperature,
/// geometry}` (measured laws and ranges of the atlas, then the other models with `needs`).
pub fn overlays_json() -> String {
    use rime_core::atlas::{ENTRIES, Kind as EntryKind};
    use rime_core::models::Model;
    let mut list: Vec<OverlayJson> = ENTRIES
        .iter()
        .filter(|e| e.kind != EntryKind::Threshold)
        .map(|e| OverlayJson::Atlas {
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
            .map(|m| OverlayJson::Model {
                key: format!("model:{}", m.name()),
                label: m.citation(),
                kind: "model",
                needs: m.needs_section(),
            }),
    );
    catalogue_json(&list)
}

/// The stick classes in code order as JSON: a list of `{name, letter, label, description, meaning}`.
pub fn classes_json() -> String {
    let list: Vec<ClassJson> = StickClass::ALL
        .iter()
        .map(|c| ClassJson {
            name: c.name(),
            letter: c.letter(),
            label: c.label(),
            description: c.description(),
            meaning: c.meaning(),
        })
        .collect();
    catalogue_json(&list)
}

/// The status names in code order as JSON.
pub fn statuses_json() -> String {
    catalogue_json(&Status::ALL.map(Status::name))
}

/// The experimental context of the ε_N chart as JSON: the Bridges et al. (1984) law
/// (`{a, b, g0, label}`, ε = a (g/g0)^b) and the microgravity ice experiments' ranges
/// (`[{x: [lo, hi], y: [lo, hi], label}]`): numbers and words from `rime_core::fit` and
/// `rime_core::figure`, packed only.
pub fn experiments_json() -> String {
    let b = rime_core::fit::BRIDGES_1984;
    let bands = rime_core::figure::experiments::bands(0);
    let page = ExperimentsJson {
        bridges: BridgesJson {
            a: b.a,
            b: b.b,
            g0: b.g0,
            label: rime_core::fit::BRIDGES_1984_LABEL,
        },
        bands: bands
            .iter()
            .map(|band| BandJson {
                x: [band.x.0, band.x.1],
                y: [band.y.0, band.y.1],
                label: &band.label,
            })
            .collect(),
    };
    catalogue_json(&page)
}

/// Everything the page says in words, as JSON: the paper's citation, the glossary,
/// per-parameter help and human option names, the stick classes' meaning (with artifacts marked)
/// and the artifact note. From `rime_core::explorer::help`, shared with the other surfaces.
pub fn help_json() -> String {
    use rime_core::explorer::help::{
        ARTIFACT_NOTE, GLOSSARY, PAPER, class_is_artifact, option_label, parameter_help,
        slider_range,
    };
    let parameters: BTreeMap<&str, ParameterHelpJson> = PARAMETERS
        .iter()
        .map(|p| {
            let options = match p.kind {
                Kind::Choice(options) => options
                    .iter()
                    .map(|o| (*o, option_label(p.path, o).unwrap_or(o)))
                    .collect(),
                _ => BTreeMap::new(),
            };
            let help = ParameterHelpJson {
                help: parameter_help(p.path).unwrap_or(""),
                options,
                slider: slider_range(p.path).map(|(lo, hi)| [lo, hi]),
            };
            (p.path, help)
        })
        .collect();
    let page = HelpJson {
        paper: PAPER,
        glossary: GLOSSARY
            .iter()
            .map(|(term, meaning)| GlossaryJson { term, meaning })
            .collect(),
        parameters,
        classes: StickClass::ALL
            .iter()
            .map(|c| ClassArtifactJson {
                name: c.name(),
                artifact: class_is_artifact(*c),
            })
            .collect(),
        artifact_note: ARTIFACT_NOTE,
        tidal_paper: TidalInput::default(),
        levels: Accuracy::LEVELS
            .iter()
            .map(|l| LevelJson {
                name: l.name(),
                trade: l.trade(),
                bound: l.error_bound(),
            })
            .collect(),
        limits: LimitsJson {
            speed_min: rime_core::explorer::limits::SPEED_MIN,
            speed_max: rime_core::explorer::limits::SPEED_MAX,
        },
    };
    catalogue_json(&page)
}

/// Parses a typed speed (`"1 um/s"`, `"0.02"`, `"5 cm/s"`) for the view field `field`; the value
/// must be a speed the models accept (`(0, 1e6]` m/s). Errors name the field and show the value
/// short (a 309-digit number reads `1e308`).
pub fn parse_speed(field: &str, text: &str) -> Result<f64, String> {
    speed_within(
        field,
        text,
        rime_core::explorer::limits::speed_is_valid,
        rime_core::limits::SPEED_DOMAIN,
    )
}

/// Parses a typed end of the chart's speed range: as [`parse_speed`], within the core's chart
/// limits `[1e-12, 1e6]` m/s (a link with `view.from = 1e-300` drew 301 decades).
pub fn parse_chart_speed(field: &str, text: &str) -> Result<f64, String> {
    speed_within(
        field,
        text,
        rime_core::explorer::limits::chart_speed_is_valid,
        rime_core::explorer::limits::CHART_SPEED_DOMAIN,
    )
}

/// A typed speed that `valid` accepts; the error names the field and the `domain`.
fn speed_within(
    field: &str,
    text: &str,
    valid: fn(f64) -> bool,
    domain: &str,
) -> Result<f64, String> {
    let v = parse_quantity(field, text, "m/s")?;
    if valid(v) {
        Ok(v)
    } else {
        Err(format!(
            "{field}: must be a speed in {domain} m/s (got {})",
            rime_core::explorer::format::sig(v, 4)
        ))
    }
}

/// Parses a typed quantity with optional units compatible with `unit` (the core's unit parser);
/// errors name `field` and never carry the typed text at full length.
pub fn parse_quantity(field: &str, text: &str, unit: &str) -> Result<f64, String> {
    let shown: String = if text.chars().count() > 24 {
        format!("{}…", text.chars().take(24).collect::<String>())
    } else {
        text.to_string()
    };
    let v = rime_core::units::parse_quantity("value", text, unit).map_err(|e| {
        let msg = e.to_string();
        let msg = msg.strip_prefix("value: ").unwrap_or(&msg).to_string();
        let msg = if msg.chars().count() > 160 {
            format!("{}…", msg.chars().take(160).collect::<String>())
        } else {
            msg
        };
        format!("{field}: {msg} (typed \"{shown}\")")
    })?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("{field}: not a finite number (typed \"{shown}\")"))
    }
}

// The page's own shapes (www/app.js reads them by key): derived, so a key is spelled once.

/// `ring_card_json`: the core's ring card with the line's stroke by name.
#[derive(serde::Serialize)]
struct RingCardJson<'a> {
    verdict: &'a str,
    equilibrium: bool,
    sentence: &'a str,
    rows: &'a [rime_core::explorer::ring::RingRow],
    eps_cr_line: LineJson<'a>,
    meeting: Option<[f64; 2]>,
    impact_marker: &'a rime_core::figure::Marker,
    record: &'a rime_core::ring::RingRecord,
}

/// A chart line as the page draws it (`stroke` by name).
#[derive(serde::Serialize)]
struct LineJson<'a> {
    name: &'a str,
    short: &'a str,
    points: &'a [(f64, f64)],
    color: usize,
    stroke: &'static str,
}

/// [`Explorer::normal`]: the core's `Normal` under the page's names (`eps_n`, status by name).
#[derive(serde::Serialize)]
struct NormalJson {
    g_n: f64,
    eps_n: f64,
    status: &'static str,
    t_c: f64,
    xi_max: f64,
    error_estimate: f64,
}

/// [`Explorer::fit_to_entry`]: the fitted damping time and the fitted scene (as scene JSON text).
#[derive(serde::Serialize)]
struct FitJson<'a> {
    id: &'a str,
    value: f64,
    standard_error: Option<f64>,
    rms_error: f64,
    warnings: &'a [String],
    scene: String,
}

/// [`Explorer::tangential`]: one point of the stick map.
#[derive(serde::Serialize)]
struct TangentialJson {
    g_n: f64,
    g_t: f64,
    eps_t: f64,
    eps_n: f64,
    class: &'static str,
}

/// One entry of [`parameters_json`].
#[derive(serde::Serialize)]
struct ParameterJson {
    path: &'static str,
    label: &'static str,
    unit: &'static str,
    #[serde(flatten)]
    kind: KindJson,
}

/// A parameter's kind: `"kind": "number"` with its range, `"choice"` with its options, `"toggle"`.
#[derive(serde::Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
enum KindJson {
    Number { min: f64, max: f64, log: bool },
    Choice { options: &'static [&'static str] },
    Toggle,
}

/// One entry of [`presets_json`].
#[derive(serde::Serialize)]
struct PresetJson {
    name: &'static str,
    description: &'static str,
    scene: Scene,
}

/// One entry of [`overlays_json`]: a measured law or range of the atlas, or another model.
#[derive(serde::Serialize)]
#[serde(untagged)]
enum OverlayJson {
    Atlas {
        key: String,
        label: String,
        kind: &'static str,
        valid: [f64; 2],
        temperature: [f64; 2],
        geometry: &'static str,
    },
    Model {
        key: String,
        label: &'static str,
        kind: &'static str,
        needs: Option<&'static str>,
    },
}

/// One entry of [`classes_json`].
#[derive(serde::Serialize)]
struct ClassJson {
    name: &'static str,
    letter: char,
    label: &'static str,
    description: &'static str,
    meaning: &'static str,
}

/// [`experiments_json`].
#[derive(serde::Serialize)]
struct ExperimentsJson<'a> {
    bridges: BridgesJson,
    bands: Vec<BandJson<'a>>,
}

/// The Bridges et al. (1984) law ε = a (g/g0)^b with its legend entry.
#[derive(serde::Serialize)]
struct BridgesJson {
    a: f64,
    b: f64,
    g0: f64,
    label: &'static str,
}

/// An experiment's range as two intervals.
#[derive(serde::Serialize)]
struct BandJson<'a> {
    x: [f64; 2],
    y: [f64; 2],
    label: &'a str,
}

/// [`help_json`].
#[derive(serde::Serialize)]
struct HelpJson {
    paper: rime_core::figure::words::Citation,
    glossary: Vec<GlossaryJson>,
    parameters: BTreeMap<&'static str, ParameterHelpJson>,
    classes: Vec<ClassArtifactJson>,
    #[serde(rename = "artifactNote")]
    artifact_note: &'static str,
    #[serde(rename = "tidalPaper")]
    tidal_paper: TidalInput,
    levels: Vec<LevelJson>,
    limits: LimitsJson,
}

/// One glossary entry.
#[derive(serde::Serialize)]
struct GlossaryJson {
    term: &'static str,
    meaning: &'static str,
}

/// One parameter's help: the sentence, human option names, the slider's range.
#[derive(serde::Serialize)]
struct ParameterHelpJson {
    help: &'static str,
    options: BTreeMap<&'static str, &'static str>,
    slider: Option<[f64; 2]>,
}

/// Whether a stick class is an artifact of the printed law.
#[derive(serde::Serialize)]
struct ClassArtifactJson {
    name: &'static str,
    artifact: bool,
}

/// An accuracy level: its name, trade-off and error bound (`null` for none).
#[derive(serde::Serialize)]
struct LevelJson {
    name: &'static str,
    trade: &'static str,
    bound: f64,
}

/// The speeds the page accepts.
#[derive(serde::Serialize)]
struct LimitsJson {
    #[serde(rename = "speedMin")]
    speed_min: f64,
    #[serde(rename = "speedMax")]
    speed_max: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn issue_36_the_preset_is_named_by_the_scene_not_its_text() {
        let mut e = Explorer::new();
        for p in Preset::ALL {
            e.load_preset(p.name()).unwrap();
            assert_eq!(e.preset(), Some(p.name()));
        }
        // Back from its text (as a link brings it), still that preset.
        let text = e.to_json().unwrap();
        let e2 = Explorer::from_json(&text).unwrap();
        assert_eq!(e2.preset(), e.preset());
        // One parameter changed: no preset; changed back: the preset again.
        e.load_preset("ice-frost").unwrap();
        let eta = e.get("layer.viscosity").unwrap();
        e.set("layer.viscosity", "2500").unwrap();
        assert_eq!(e.preset(), None);
        e.set("layer.viscosity", &eta).unwrap();
        assert_eq!(e.preset(), Some("ice-frost"));
        // The Compare list asks whether a section is there the same way (`get` of its toggle).
        assert_eq!(e.get("plasticity").unwrap(), "false");
        e.set("plasticity", "true").unwrap();
        assert_eq!(e.get("plasticity").unwrap(), "true");
    }

    #[test]
    fn json_round_trips_and_errors_name_the_field() {
        let mut e = Explorer::new();
        e.load_preset("ice-frost").unwrap();
        let text = e.to_json().unwrap();
        assert_eq!(Explorer::from_json(&text).unwrap(), e);
        let bad = text.replace("1000.0", "-5.0");
        let err = Explorer::from_json(&bad).unwrap_err();
        assert!(err.starts_with("layer.viscosity:"), "{err}");
        let err = Explorer::from_json(r#"{"grains": {"radius_1": "x"}}"#).unwrap_err();
        assert!(err.starts_with("grains.radius_1:"), "{err}");
        let err = Explorer::from_json(&text.replace("\"layer\"", "\"layr\"")).unwrap_err();
        assert!(err.contains("layr"), "{err}");
        assert!(Explorer::from_json("garbage").is_err());
    }

    #[test]
    fn issue_24_the_ring_card_is_the_cores_and_bad_input_names_the_field() {
        let scene = serde_json::to_string(&Preset::Ice.scene()).unwrap();
        let input = r#"{"tau": 0.5, "omega": 1.3143527e-4, "chart": [1e-7, 1.0]}"#;
        let card: Json = serde_json::from_str(&ring_card_json(&scene, input).unwrap()).unwrap();
        let core = rime_core::explorer::ring::ring_card(
            &Preset::Ice.scene(),
            &rime_core::ring::RingInput {
                tau: 0.5,
                orbit: rime_core::ring::Orbit::Omega(1.3143527e-4),
                damping_set_for_radius: None,
            },
            (1e-7, 1.0),
        )
        .unwrap();
        assert_eq!(card["sentence"], core.sentence);
        assert_eq!(card["verdict"], "equilibrium at the monolayer floor");
        assert_eq!(card["equilibrium"], true);
        assert_eq!(card["rows"][0]["text"], core.rows[0].text);
        assert_eq!(
            card["record"]["rough"]["velocity_dispersion"],
            core.record.rough.velocity_dispersion
        );
        assert_eq!(card["eps_cr_line"]["stroke"], "dashed");
        for (bad, field) in [
            (
                r#"{"tau": 0, "omega": 1e-4, "chart": [1e-7, 1]}"#,
                "ring.tau:",
            ),
            (r#"{"tau": 0.5, "chart": [1e-7, 1]}"#, "ring.omega:"),
            (
                r#"{"tau": 0.5, "omega": 1e-4, "chart": [1, 0.1]}"#,
                "ring.chart:",
            ),
            (r#"{"tau": 0.5, "omega": 1e-4}"#, "ring:"),
            (
                r#"{"tau": "x", "omega": 1e-4, "chart": [1e-7, 1]}"#,
                "ring.tau:",
            ),
        ] {
            let e = ring_card_json(&scene, bad).unwrap_err();
            assert!(e.starts_with(field), "{bad}: {e}");
        }
    }

    #[test]
    fn set_validates_and_keeps_the_scene() {
        let mut e = Explorer::new();
        let before = e.clone();
        let err = e.set("layer.viscosity", "-3").unwrap_err();
        assert!(err.starts_with("layer.viscosity:"), "{err}");
        assert_eq!(e, before);
        assert!(e.set("no.such", "1").unwrap_err().starts_with("no.such:"));
        assert!(e.set_number("grains.density", f64::NAN).is_err());
        assert_eq!(e, before);
        e.set("layer.viscosity", "2 kPa s").unwrap();
        assert_eq!(e.get("layer.viscosity").unwrap(), "2000.0");
        assert_eq!(e.get("layer").unwrap(), "true");
        assert_eq!(e.get("bulk.damping.viscosities.shear").unwrap(), "null");
        assert_eq!(e.get("contact_end").unwrap(), "\"force_zero\"");
        assert_eq!(Explorer::new().damping_time().unwrap(), 1e-4);
        assert!(e.load_preset("nope").unwrap_err().starts_with("preset:"));
    }

    #[test]
    fn metadata_is_json() {
        let p: Vec<Json> = serde_json::from_str(&parameters_json()).unwrap();
        assert_eq!(p.len(), PARAMETERS.len());
        let c: Vec<Json> = serde_json::from_str(&classes_json()).unwrap();
        assert_eq!(c.len(), 7);
        let s: Vec<String> = serde_json::from_str(&statuses_json()).unwrap();
        assert_eq!(s[3], "overdamped");
        let pr: Vec<Json> = serde_json::from_str(&presets_json()).unwrap();
        assert_eq!(pr.len(), 4);
        let x: Json = serde_json::from_str(&experiments_json()).unwrap();
        assert_eq!(x["bridges"]["a"], 0.32);
        assert_eq!(x["bands"].as_array().unwrap().len(), 2);
        let t: Json = serde_json::from_str(&Explorer::new().tidal("").unwrap()).unwrap();
        assert!(t["result"]["d_roche"].as_f64().unwrap() > 1e8);
        // Issue 36: the page receives the core's card itself, so its marks are the terminal's.
        let (input, from_paper) = rime_core::explorer::tidal::input_for(&Scene::default(), 1.0);
        let card = rime_core::explorer::tidal::card(input, from_paper).unwrap();
        assert_eq!(t, serde_json::to_value(&card).unwrap());
        let n: Json = serde_json::from_str(&Explorer::new().normal(0.01, "fast").unwrap()).unwrap();
        assert_eq!(n["status"], "rebound");
    }

    #[test]
    fn typed_speeds_take_units_and_bad_ones_name_the_field_issue_12() {
        assert_eq!(parse_speed("g from", "1 um/s").unwrap(), 1e-6);
        assert_eq!(parse_speed("g from", "5 cm/s").unwrap(), 0.05);
        assert_eq!(parse_speed("g to", "0.3").unwrap(), 0.3);
        let e = parse_speed("g to", "2e6 m/s").unwrap_err();
        assert!(e.starts_with("g to:") && e.contains("2e6"), "{e}");
        let huge = format!("1{}", "0".repeat(308));
        let e = parse_speed("g to", &huge).unwrap_err();
        assert!(e.starts_with("g to:") && e.len() < 200, "{e}");
        let e = parse_speed("g from", "fast").unwrap_err();
        assert!(e.starts_with("g from:"), "{e}");
        assert!(parse_speed("g from", "-1 m/s").is_err());
        assert!(parse_speed("g from", "3 kg").is_err());
        assert_eq!(
            parse_quantity("tidal.distance", "1.5e5 km", "m").unwrap(),
            1.5e8
        );
    }

    #[test]
    fn help_names_every_parameter_and_marks_the_artifact() {
        let h: Json = serde_json::from_str(&help_json()).unwrap();
        assert_eq!(h["paper"]["year"], 2002);
        assert_eq!(
            h["parameters"]["contact_end"]["options"]["force_zero"],
            "when the force returns to zero"
        );
        let artifacts: Vec<&str> = h["classes"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["artifact"] == true)
            .map(|c| c["name"].as_str().unwrap())
            .collect();
        assert_eq!(artifacts, ["sliding_gap"]);
        let levels: Vec<&str> = h["levels"]
            .as_array()
            .unwrap()
            .iter()
            .map(|l| l["name"].as_str().unwrap())
            .collect();
        assert_eq!(levels, ["fast", "precise", "integrated"]);
    }

    #[test]
    fn one_collision_as_the_core_computes_it_issue_13() {
        let mut e = Explorer::new();
        e.load_preset("ice-sticky").unwrap();
        let c: Json = serde_json::from_str(&e.collision(1e-3, 50, "precise").unwrap()).unwrap();
        let contact = Contact::new(&e.scene).unwrap();
        let n = contact.normal(1e-3, Accuracy::Precise).unwrap();
        assert_eq!(c["eps_n"].as_f64().unwrap(), n.eps);
        assert_eq!(c["t_c"].as_f64().unwrap(), n.t_c);
        assert!(
            c["ledger"]["closure"].as_f64().unwrap().abs() < 1e-9,
            "{}",
            c["ledger"]
        );
        assert!(c["t"].as_array().unwrap().len() >= 50);
        assert!(c["dynamic"]["xi"].as_array().unwrap().len() > 10);
        let err = e.collision(-1.0, 50, "fast").unwrap_err();
        assert!(err.starts_with("g_n"), "{err}");
        assert!(
            e.collision(0.01, 1, "fast")
                .unwrap_err()
                .starts_with("points")
        );
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

    fn parse(text: &str) -> Json {
        serde_json::from_str(text).expect("JSON")
    }

    #[test]
    fn issue_36_the_parameter_catalogue_keeps_its_keys() {
        let list = parse(&parameters_json());
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
        let presets = parse(&presets_json());
        let presets = presets.as_array().expect("a list");
        assert_eq!(presets.len(), Preset::ALL.len());
        for (j, p) in presets.iter().zip(Preset::ALL.iter()) {
            assert_eq!(keys(j), ["description", "name", "scene"]);
            assert_eq!(j["name"], p.name());
            assert_eq!(j["description"], p.description());
            let scene: Scene = serde_json::from_value(j["scene"].clone()).expect("a scene");
            assert_eq!(scene, p.scene());
        }
        let classes = parse(&classes_json());
        let classes = classes.as_array().expect("a list");
        assert_eq!(classes.len(), StickClass::ALL.len());
        for (j, c) in classes.iter().zip(StickClass::ALL.iter()) {
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
        let statuses = parse(&statuses_json());
        let names: Vec<&str> = Status::ALL.iter().map(|s| s.name()).collect();
        assert_eq!(statuses, Json::from(names));
    }

    #[test]
    fn issue_36_overlays_and_experiments_keep_their_keys() {
        use rime_core::atlas::{ENTRIES, Kind as EntryKind};
        use rime_core::models::Model;
        let list = parse(&overlays_json());
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
        let x = parse(&experiments_json());
        assert_eq!(keys(&x), ["bands", "bridges"]);
        assert_eq!(keys(&x["bridges"]), ["a", "b", "g0", "label"]);
        let b = rime_core::fit::BRIDGES_1984;
        assert_eq!(x["bridges"]["a"].as_f64(), Some(b.a));
        assert_eq!(x["bridges"]["b"].as_f64(), Some(b.b));
        assert_eq!(x["bridges"]["g0"].as_f64(), Some(b.g0));
        let bands = rime_core::figure::experiments::bands(0);
        assert!(!bands.is_empty());
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
    fn issue_36_help_keeps_its_keys() {
        use rime_core::explorer::help::{GLOSSARY, PAPER, option_label, parameter_help};
        let h = parse(&help_json());
        assert_eq!(
            keys(&h),
            [
                "artifactNote",
                "classes",
                "glossary",
                "levels",
                "limits",
                "paper",
                "parameters",
                "tidalPaper"
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
            match rime_core::explorer::help::slider_range(p.path) {
                Some((lo, hi)) => {
                    assert_eq!(j["slider"][0].as_f64(), Some(lo));
                    assert_eq!(j["slider"][1].as_f64(), Some(hi));
                }
                None => assert!(j["slider"].is_null()),
            }
        }
        assert_eq!(keys(&h["classes"][0]), ["artifact", "name"]);
        assert!(
            h["classes"]
                .as_array()
                .expect("classes")
                .iter()
                .any(|c| c["artifact"] == true)
        );
        assert_eq!(keys(&h["levels"][0]), ["bound", "name", "trade"]);
        assert_eq!(
            h["levels"].as_array().map(Vec::len),
            Some(Accuracy::LEVELS.len())
        );
        assert_eq!(keys(&h["limits"]), ["speedMax", "speedMin"]);
        assert_eq!(
            h["limits"]["speedMax"].as_f64(),
            Some(rime_core::explorer::limits::SPEED_MAX)
        );
        assert_eq!(
            h["tidalPaper"],
            serde_json::to_value(TidalInput::default()).expect("tidal input")
        );
    }

    #[test]
    fn issue_36_point_results_keep_their_keys() {
        let mut ex = Explorer::new();
        ex.load_preset("ice").expect("preset");
        let contact = Contact::new(&Preset::Ice.scene()).expect("contact");
        let n = parse(&ex.normal(1e-3, "fast").expect("normal"));
        assert_eq!(
            keys(&n),
            ["eps_n", "error_estimate", "g_n", "status", "t_c", "xi_max"]
        );
        let core = contact.normal(1e-3, Accuracy::Fast).expect("core normal");
        assert_eq!(n["g_n"].as_f64(), Some(1e-3));
        assert_eq!(n["eps_n"].as_f64(), Some(core.eps));
        assert_eq!(n["status"], core.status.name());
        assert_eq!(n["t_c"].as_f64(), Some(core.t_c));
        assert_eq!(n["xi_max"].as_f64(), Some(core.xi_max));
        // A grain that sticks comes to rest asymptotically: its infinite t_c is sent as null.
        let stuck = NormalJson {
            g_n: 1e-9,
            eps_n: 0.0,
            status: "stuck",
            t_c: f64::INFINITY,
            xi_max: 1e-12,
            error_estimate: f64::INFINITY,
        };
        let stuck = parse(&serde_json::to_string(&stuck).expect("JSON"));
        assert!(stuck["t_c"].is_null() && stuck["error_estimate"].is_null());
        let t = parse(&ex.tangential(1e-3, 2e-3, "fast").expect("tangential"));
        assert_eq!(keys(&t), ["class", "eps_n", "eps_t", "g_n", "g_t"]);
        let core = contact
            .tangential(1e-3, 2e-3, Accuracy::Fast)
            .expect("core tangential");
        assert_eq!(
            (t["g_n"].as_f64(), t["g_t"].as_f64()),
            (Some(1e-3), Some(2e-3))
        );
        assert_eq!(t["eps_t"].as_f64(), Some(core.eps_t));
        assert_eq!(t["eps_n"].as_f64(), Some(core.eps_n));
        assert_eq!(t["class"], core.class.name());
        let f = parse(&ex.fit_to_entry("bridges1984", "fast").expect("fit"));
        assert_eq!(
            keys(&f),
            [
                "id",
                "rms_error",
                "scene",
                "standard_error",
                "value",
                "warnings"
            ]
        );
        assert_eq!(f["id"], "bridges1984");
        let scene: Scene =
            serde_json::from_str(f["scene"].as_str().expect("scene text")).expect("scene");
        assert_eq!(scene, ex.scene);
        assert!(f["warnings"].is_array());
    }

    #[test]
    fn issue_36_the_ring_card_keeps_its_keys() {
        let scene = serde_json::to_string(&Preset::Ice.scene()).unwrap();
        let input = r#"{"tau": 0.5, "omega": 1.3143527e-4, "chart": [1e-7, 1.0]}"#;
        let card = parse(&ring_card_json(&scene, input).unwrap());
        assert_eq!(
            keys(&card),
            [
                "eps_cr_line",
                "equilibrium",
                "impact_marker",
                "meeting",
                "record",
                "rows",
                "sentence",
                "verdict"
            ]
        );
        assert_eq!(keys(&card["rows"][0]), ["label", "text"]);
        assert_eq!(
            keys(&card["eps_cr_line"]),
            ["color", "name", "points", "short", "stroke"]
        );
        assert_eq!(
            keys(&card["impact_marker"]),
            ["color", "label", "short", "x"]
        );
        // Points are [x, y] pairs.
        assert_eq!(
            card["eps_cr_line"]["points"][0].as_array().map(Vec::len),
            Some(2)
        );
        assert!(card["meeting"].is_null() || card["meeting"].as_array().map(Vec::len) == Some(2));
    }
}
