//! `rime ring`: what the scene's collision law does to a ring — equilibrium velocity dispersion,
//! thickness and verdict (docs/physics.md#ring).

use crate::args::{Common, Format};
use crate::output;
use crate::scene_io::{CliError, CliResult, err};
use rime_core::ring::{Orbit, Prediction, RingPatch, equilibrium};

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
    })
}

fn set_key(set: &str) -> &str {
    set.split_once('=').map_or(set, |(k, _)| k).trim()
}

/// The ring's record in the chosen format.
// Long by design: one record's three outputs (JSON, CSV, table) side by side so that their fields
// stay in step.
pub fn run(common: &Common, args: &Args) -> CliResult<String> {
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
    let out = rime_core::explorer::records::RingOutput::new(&rec, note.clone());
    let (values, verdicts) = (&out.values, out.verdicts);
    Ok(match common.format {
        Format::Json => {
            // Through a value: the keys sorted, as this output has always printed them.
            let v = serde_json::to_value(&out).map_err(|e| CliError::input(e.to_string()))?;
            serde_json::to_string_pretty(&v).map_err(|e| CliError::input(e.to_string()))? + "\n"
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
            rows.extend(values.iter().map(|(k, v, u)| {
                vec![
                    k.clone(),
                    v.map(output::num).unwrap_or_else(|| "none".into()),
                    u.to_string(),
                ]
            }));
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
