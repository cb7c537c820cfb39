//! `rime ring`: what the scene's collision law does to a ring — equilibrium velocity dispersion,
//! thickness and verdict (docs/physics.md#ring).

use crate::args::{Common, Format};
use crate::output;
use crate::scene_io::{CliError, CliResult, err};
use rime_core::ring::{Orbit, Prediction, RingPatch, equilibrium};
use rime_core::ring_sizes::{DampingRule, SizeDistribution, SizeRingInput, SizeRingRecord};

/// Parsed arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct Args {
    /// Optical depth τ.
    pub tau: f64,
    /// Ω, or a planet and a distance.
    pub orbit: Orbit,
    /// `--radius`: both grains' radius \[m\].
    pub radius: Option<f64>,
    /// `--scale-damping`: replace A by A′ = A·R′/R (a different material).
    pub scale_damping: bool,
    /// A was given in this command (`--set bulk.damping…`) without the grains' radius: it was
    /// given for the `--radius` grains, not for the scene's.
    pub damping_given_here: bool,
    /// `--radii …`: a ring of many sizes (issue 38), with the A rule.
    pub sizes: Option<(SizeDistribution, DampingRule)>,
}

/// Reads `--radii`, `--q`, `--bins`, `--fractions`, `--damping-rule` (None without `--radii`).
fn parse_sizes(
    get: &dyn Fn(&str) -> Option<String>,
) -> CliResult<Option<(SizeDistribution, DampingRule)>> {
    let Some(radii) = get("--radii") else {
        for flag in ["--q", "--bins", "--fractions", "--damping-rule"] {
            if get(flag).is_some() {
                return err(format!("{flag}: only with --radii (a ring of many sizes)"));
            }
        }
        return Ok(None);
    };
    if get("--radius").is_some() {
        return err("--radii: cannot be combined with --radius (one size)");
    }
    if get("--scale-damping").is_some() {
        return err(
            "--scale-damping: not with --radii; choose how A follows the sizes with --damping-rule",
        );
    }
    let rule = match get("--damping-rule").as_deref() {
        None | Some("same") => DampingRule::Same,
        Some("keep_epsilon") => DampingRule::KeepEpsilon,
        Some(other) => {
            return err(format!(
                "--damping-rule: expected same or keep_epsilon, got {other:?}"
            ));
        }
    };
    let quantity = |text: &str| -> CliResult<f64> {
        rime_core::units::parse_quantity("--radii", text, "m").map_err(CliError::from)
    };
    let sizes = if let Some((lo, hi)) = radii.split_once("..") {
        if get("--fractions").is_some() {
            return err("--fractions: only with a list of --radii (a range takes --q)");
        }
        let q = get("--q").ok_or_else(|| {
            CliError::input("--q: required with a range of --radii (dN/dR ∝ R^−q)")
        })?;
        let q = rime_core::units::parse_quantity("--q", &q, "1").map_err(CliError::from)?;
        let bins = match get("--bins") {
            None => 3,
            Some(b) => b.trim().parse::<usize>().map_err(|_| {
                CliError::input(format!(
                    "--bins: expected a whole number of bins, got {b:?}"
                ))
            })?,
        };
        SizeDistribution::PowerLaw {
            q,
            radius_min: quantity(lo)?,
            radius_max: quantity(hi)?,
            bins,
        }
    } else {
        for flag in ["--q", "--bins"] {
            if get(flag).is_some() {
                return err(format!("{flag}: only with a range of --radii (R1..R2)"));
            }
        }
        let radii: Vec<f64> = radii.split(',').map(quantity).collect::<CliResult<_>>()?;
        let fractions: Vec<f64> = match get("--fractions") {
            Some(f) => f
                .split(',')
                .map(|x| {
                    rime_core::units::parse_quantity("--fractions", x, "1").map_err(CliError::from)
                })
                .collect::<CliResult<_>>()?,
            None if radii.len() == 1 => vec![1.0],
            None => return err("--fractions: required with a list of --radii"),
        };
        SizeDistribution::List { radii, fractions }
    };
    Ok(Some((sizes, rule)))
}

/// Reads `--tau`, `--omega | --planet-mass --distance`, `--radius`, `--scale-damping`; `sets` are
/// the command's `--set KEY=VALUE` (A set here without `grains.radius_*` is A of the `--radius`
/// grains).
pub fn parse(get: &dyn Fn(&str) -> Option<String>, sets: &[String]) -> CliResult<Args> {
    let q = |name: &'static str, unit: &str| -> CliResult<Option<f64>> {
        get(name)
            .map(|v| rime_core::units::parse_quantity(name, &v, unit).map_err(CliError::from))
            .transpose()
    };
    let tau = q("--tau", "1")?.ok_or_else(|| CliError::input("--tau: required (optical depth)"))?;
    let orbit = match (
        q("--omega", "1/s")?,
        q("--planet-mass", "kg")?,
        q("--distance", "m")?,
    ) {
        (Some(o), None, None) => Orbit::Omega(o),
        (None, Some(m), Some(d)) => Orbit::Planet {
            planet_mass: m,
            distance: d,
        },
        (Some(_), _, _) => return err("--omega: cannot be combined with --planet-mass/--distance"),
        (None, Some(_), None) => return err("--distance: required with --planet-mass"),
        (None, None, Some(_)) => return err("--planet-mass: required with --distance"),
        (None, None, None) => {
            return err("--omega: required (or --planet-mass and --distance)");
        }
    };
    Ok(Args {
        tau,
        orbit,
        radius: q("--radius", "m")?,
        scale_damping: get("--scale-damping").as_deref() == Some("true"),
        damping_given_here: sets.iter().any(|s| set_key(s).starts_with("bulk.damping"))
            && !sets.iter().any(|s| set_key(s).starts_with("grains.radius")),
        sizes: parse_sizes(get)?,
    })
}

fn set_key(set: &str) -> &str {
    set.split_once('=').map_or(set, |(k, _)| k).trim()
}

/// The ring's record in the chosen format.
// Long by design: one record's three outputs (JSON, CSV, table) side by side so that their fields
// stay in step.
pub fn run(common: &Common, args: &Args) -> CliResult<String> {
    if let Some((sizes, rule)) = &args.sizes {
        return run_sizes(common, args, sizes, *rule);
    }
    if args.scale_damping
        && args
            .radius
            .is_none_or(|r| r == common.scene.grains.radius_1)
    {
        return err("--scale-damping: only with a --radius other than the scene's");
    }
    // A set in this command (and no grain radius) describes the grains of this ring.
    let set_for = match args.radius {
        Some(r) if args.damping_given_here => {
            if args.scale_damping {
                return err(format!(
                    "--scale-damping: A was given here (--set bulk.damping…) for the {} m grains \
                     of --radius; nothing to scale (set grains.radius_1/2 to the grains A was \
                     measured for to scale it from them)",
                    output::num(r)
                ));
            }
            r
        }
        _ => common.scene.grains.radius_1,
    };
    let patch = RingPatch::with_damping_set_for(
        &common.scene,
        args.tau,
        args.orbit,
        args.radius,
        args.scale_damping,
        set_for,
    )?;
    let rec = equilibrium(&patch.scene, &patch.input)?;
    let p = rec.prediction();
    let note = patch.damping_note(&rec, "--scale-damping");
    // The core's record of this ring (field names are a contract, docs/cli.md).
    // ν of this one-size ring (issue 38): the one-bin ring of many sizes, the same c to the digit.
    let viscosity = rime_core::ring_sizes::one_size_viscosity(&patch.scene, &patch.input)?;
    let out =
        rime_core::explorer::records::RingOutput::new(&rec, note.clone()).with_viscosity(viscosity);
    let (values, verdicts) = (&out.values, out.verdicts);
    Ok(match common.format {
        Format::Json => {
            // The keys in the order docs/cli.md lists them (issue 37 C5: they were sorted).
            let v = serde_json::to_value(&out).map_err(|e| CliError::input(e.to_string()))?;
            crate::output::json_in_order(&v, &RING_KEYS)
        }
        Format::Csv => {
            let mut s = String::from("name,value,unit\n");
            for (k, v) in verdicts {
                s.push_str(&format!("{k},{v},\n"));
            }
            s.push_str(&format!(
                "equilibrium,{},\nverdict_words,{},\n",
                p.verdict.is_equilibrium(),
                p.verdict.words()
            ));
            for (k, v, u) in values {
                s.push_str(&format!(
                    "{k},{},{u}\n",
                    v.map(output::num).unwrap_or_default()
                ));
            }
            s.push_str(&format!(
                "viscosity.overstability,{},\n",
                viscosity.overstability
            ));
            if let Some(n) = &note {
                s.push_str(&format!("damping_note,\"{}\",\n", n.replace('"', "'")));
            }
            s
        }
        Format::Table => {
            let mut rows: Vec<Vec<String>> = verdicts
                .iter()
                .map(|(k, v)| vec![k.to_string(), v.to_string(), String::new()])
                .collect();
            rows.push(vec![
                "equilibrium".into(),
                if p.verdict.is_equilibrium() {
                    "yes"
                } else {
                    "no"
                }
                .into(),
                String::new(),
            ]);
            // ν in one area unit for all three (as the many-sizes table writes it).
            let (area_scale, area) = rime_core::format::area_per_time_unit(viscosity.total);
            rows.extend(values.iter().map(|(k, v, u)| match (*u, v) {
                ("m²/s", Some(x)) => {
                    vec![k.clone(), output::num(x / area_scale), area.to_string()]
                }
                _ => vec![
                    k.clone(),
                    v.map(output::num).unwrap_or_else(|| "none".into()),
                    u.to_string(),
                ],
            }));
            rows.push(vec![
                "viscosity.overstability".into(),
                viscosity.overstability.into(),
                String::new(),
            ]);
            let mut s = output::table(&["name", "value", "unit"], &output::human_value_rows(rows));
            if let Some(n) = note {
                s.push_str(&format!("note: {n}\n"));
            }
            s.push_str(&summary(p, rec.radius * rec.omega));
            s
        }
    })
}

/// The table's last line, for people (issue 37): the verdict, c, H and the mean impact speed in
/// 4 significant digits with prefixed units. For `heats` the numbers are the balance outside the
/// slow-collision regime (docs/physics.md#ring), which the line says, with the reason.
fn summary(p: &Prediction, r_omega: f64) -> String {
    use rime_core::explorer::format::{qty, sig};
    use rime_core::ring::{HOT_IN_R_OMEGA, SLOW_EQUILIBRATION_ORBITS, SLOW_REGIME_LIMIT, Verdict};
    let numbers = format!(
        "c = {} ({} RΩ), H = {}, mean impact speed {}",
        qty(p.velocity_dispersion, "m/s"),
        sig(p.velocity_dispersion / r_omega, 4),
        qty(p.thickness, "m"),
        qty(p.mean_impact_speed, "m/s")
    );
    if p.verdict != Verdict::Heats {
        return format!("{}: {numbers}\n", p.verdict.words());
    }
    let why = if p.mean_impact_speed > SLOW_REGIME_LIMIT {
        format!(
            "its mean impact speed is above the slow-collision regime's {}",
            qty(SLOW_REGIME_LIMIT, "m/s")
        )
    } else {
        format!(
            "c > {} RΩ is reached only after {} orbits (over {})",
            sig(HOT_IN_R_OMEGA, 3),
            sig(p.equilibration_orbits, 4),
            sig(SLOW_EQUILIBRATION_ORBITS, 3)
        )
    };
    format!(
        "heats: no balance in the slow-collision regime; the balance the law gives, {numbers}, lies \
         outside it ({why}): beyond what the model covers, not a prediction\n"
    )
}

/// `rime ring --radii …`: a ring of many sizes (issue 38, docs/physics.md#ring-sizes).
fn run_sizes(
    common: &Common,
    args: &Args,
    sizes: &SizeDistribution,
    rule: DampingRule,
) -> CliResult<String> {
    use rime_core::explorer::format::{qty, sig};
    let input = SizeRingInput {
        tau: args.tau,
        orbit: args.orbit,
        sizes: sizes.clone(),
        damping_rule: rule,
    };
    let rec = rime_core::ring_sizes::equilibrium(&common.scene, &input).map_err(|e| {
        // The core names its fields; on the command line they are flags.
        let text = e.to_string();
        let text = ["radius_min", "radius_max", "radii"]
            .iter()
            .fold(text, |t, f| {
                t.replacen(&format!("{f}:"), &format!("--radii ({f}):"), 1)
            });
        let text = ["q:", "bins:", "fractions:"].iter().fold(text, |t, f| {
            if t.starts_with(f) {
                format!("--{t}")
            } else {
                t
            }
        });
        CliError::input(text)
    })?;
    let prediction = if rec.friction { "rough" } else { "smooth" };
    Ok(match common.format {
        Format::Json => {
            let mut v = serde_json::to_value(&rec).map_err(|e| CliError::input(e.to_string()))?;
            if let Some(map) = v.as_object_mut() {
                map.insert("equilibrium".into(), rec.verdict.is_equilibrium().into());
                map.insert("verdict_words".into(), rec.verdict.words().into());
                map.insert("prediction".into(), prediction.into());
            }
            // The keys in the order docs/cli.md lists them (issue 37 C5: they were sorted).
            crate::output::json_in_order(&v, &RING_SIZES_KEYS)
        }
        Format::Csv => {
            let mut s = String::from("name,value,unit\n");
            for (k, v) in ring_values(&rec) {
                s.push_str(&format!("{k},{v}\n"));
            }
            for (i, b) in rec.size_bins.iter().enumerate() {
                for (k, v, u) in bin_values(b) {
                    s.push_str(&format!("bin{}.{k},{},{u}\n", i + 1, output::num(v)));
                }
            }
            s
        }
        Format::Table => {
            let rows: Vec<Vec<String>> = ring_values(&rec)
                .into_iter()
                .map(|(k, v)| {
                    let (v, u) = v.split_once(',').unwrap_or((&v, ""));
                    match (u, v.parse::<f64>()) {
                        ("m²/s", Ok(x)) => {
                            let (scale, u) =
                                rime_core::format::area_per_time_unit(rec.viscosity.total);
                            vec![k.to_string(), output::num(x / scale), u.to_string()]
                        }
                        _ => vec![k.to_string(), v.to_string(), u.to_string()],
                    }
                })
                .collect();
            let mut s = output::table(&["name", "value", "unit"], &output::human_value_rows(rows));
            s.push('\n');
            let bins: Vec<Vec<String>> = rec
                .size_bins
                .iter()
                .enumerate()
                .map(|(i, b)| {
                    let radii = if b.radius_min == b.radius_max {
                        qty(b.radius, "m")
                    } else {
                        format!("{}–{}", qty(b.radius_min, "m"), qty(b.radius_max, "m"))
                    };
                    vec![
                        (i + 1).to_string(),
                        radii,
                        sig(b.number_fraction, 4),
                        qty(b.velocity_dispersion, "m/s"),
                        qty(b.thickness, "m"),
                        if b.at_floor { "floor" } else { "" }.to_string(),
                    ]
                })
                .collect();
            s.push_str(&output::table(
                &["bin", "radii", "fraction", "c", "H", ""],
                &bins,
            ));
            let nu = |x: f64| {
                let (scale, u) = rime_core::format::area_per_time_unit(rec.viscosity.total);
                format!("{} {u}", sig(x / scale, 4))
            };
            s.push_str(&format!(
                "{}\nall grains (number-weighted): c = {}, H = {}\n\
                 ν = {} (translational {}, collisional {})\n\
                 d ln ν/d ln τ = {}\n\
                 A: {}\n",
                rec.verdict.words(),
                qty(rec.velocity_dispersion, "m/s"),
                qty(rec.thickness, "m"),
                nu(rec.viscosity.total),
                nu(rec.viscosity.translational),
                nu(rec.viscosity.collisional),
                sig(rec.viscosity.dlnnu_dlntau, 4),
                match rule {
                    DampingRule::Same => "the scene's for every pair (a material constant)",
                    DampingRule::KeepEpsilon =>
                        "scaled so every pair keeps the scene's ε_N(g) (a different material)",
                },
            ));
            s.push_str(
                "overstability: not assessed (no published criterion checked for this closure)\n",
            );
            s
        }
    })
}

/// The ring-wide rows `name → "value,unit"` (CSV with every digit).
fn ring_values(rec: &SizeRingRecord) -> Vec<(&'static str, String)> {
    let n = |v: f64, u: &str| format!("{},{u}", output::num(v));
    vec![
        ("verdict", format!("{},", rec.verdict.name())),
        ("equilibrium", format!("{},", rec.verdict.is_equilibrium())),
        ("verdict_words", format!("{},", rec.verdict.words())),
        ("damping_rule", format!("{},", rec.damping_rule.name())),
        ("tau", n(rec.tau, "")),
        ("omega", n(rec.omega, "1/s")),
        ("damping_time", n(rec.damping_time, "s")),
        (
            "damping_reference_radius",
            n(rec.damping_reference_radius, "m"),
        ),
        ("velocity_dispersion", n(rec.velocity_dispersion, "m/s")),
        ("thickness", n(rec.thickness, "m")),
        ("mean_impact_speed", n(rec.mean_impact_speed, "m/s")),
        ("sticking_fraction", n(rec.sticking_fraction, "")),
        ("filling_factor", n(rec.filling_factor, "")),
        (
            "viscosity.translational",
            n(rec.viscosity.translational, "m²/s"),
        ),
        (
            "viscosity.collisional",
            n(rec.viscosity.collisional, "m²/s"),
        ),
        ("viscosity.total", n(rec.viscosity.total, "m²/s")),
        ("viscosity.dlnnu_dlntau", n(rec.viscosity.dlnnu_dlntau, "")),
        (
            "viscosity.overstability",
            format!("{},", rec.viscosity.overstability),
        ),
    ]
}

fn bin_values(b: &rime_core::ring_sizes::BinPrediction) -> Vec<(&'static str, f64, &'static str)> {
    vec![
        ("radius_min", b.radius_min, "m"),
        ("radius_max", b.radius_max, "m"),
        ("radius", b.radius, "m"),
        ("number_fraction", b.number_fraction, ""),
        ("tau", b.tau, ""),
        ("velocity_dispersion", b.velocity_dispersion, "m/s"),
        ("thickness", b.thickness, "m"),
        ("floor_dispersion", b.floor_dispersion, "m/s"),
        ("mean_impact_speed", b.mean_impact_speed, "m/s"),
        ("sticking_fraction", b.sticking_fraction, ""),
        ("collision_frequency", b.collision_frequency, ""),
        ("viscosity_translational", b.viscosity_translational, "m²/s"),
    ]
}

/// One size's JSON keys in the order docs/cli.md lists them (issue 37 C5: they were sorted): the
/// verdicts, what the ring does, the inputs, then each prediction.
const RING_KEYS: [(&str, &[&str]); 4] = [
    (
        "",
        &[
            "verdict",
            "equilibrium",
            "verdict_words",
            "prediction",
            "velocity_dispersion",
            "velocity_dispersion_r_omega",
            "thickness",
            "mean_impact_speed",
            "eps_cr",
            "eps_cr_dilute",
            "eps_effective",
            "equilibration_orbits",
            "floor_dispersion",
            "tau",
            "omega",
            "radius",
            "damping_time",
            "scaled_damping_time",
            "damping_note",
            "smooth",
            "rough",
            "viscosity",
        ],
    ),
    ("smooth", &PREDICTION_KEYS),
    ("rough", &PREDICTION_KEYS),
    ("viscosity", &VISCOSITY_KEYS),
];

const VISCOSITY_KEYS: [&str; 5] = [
    "translational",
    "collisional",
    "total",
    "dlnnu_dlntau",
    "overstability",
];

const PREDICTION_KEYS: [&str; 8] = [
    "velocity_dispersion",
    "thickness",
    "mean_impact_speed",
    "eps_effective",
    "eps_cr",
    "sticking_fraction",
    "equilibration_orbits",
    "verdict",
];

/// Many sizes' JSON keys in the order docs/cli.md lists them (issue 37 C5: they were sorted).
const RING_SIZES_KEYS: [(&str, &[&str]); 3] = [
    (
        "",
        &[
            "verdict",
            "equilibrium",
            "verdict_words",
            "prediction",
            "velocity_dispersion",
            "thickness",
            "mean_impact_speed",
            "sticking_fraction",
            "filling_factor",
            "tau",
            "omega",
            "damping_time",
            "damping_reference_radius",
            "damping_rule",
            "friction",
            "size_bins",
            "viscosity",
        ],
    ),
    (
        "size_bins",
        &[
            "radius_min",
            "radius_max",
            "radius",
            "number_fraction",
            "tau",
            "velocity_dispersion",
            "thickness",
            "floor_dispersion",
            "at_floor",
            "mean_impact_speed",
            "sticking_fraction",
            "collision_frequency",
            "viscosity_translational",
        ],
    ),
    (
        "viscosity",
        &[
            "translational",
            "collisional",
            "total",
            "dlnnu_dlntau",
            "overstability",
        ],
    ),
];
