//! `rime collision`: one collision's time course, phases and energy ledger (docs/cli.md,
//! docs/physics.md#collision).

use crate::args::{Common, Format, number, speed};
use crate::output::table;
use crate::scene_io::{CliError, CliResult, err};

/// Arguments of `rime collision`.
#[derive(Debug, Clone)]
pub struct Args {
    /// Normal impact speed \[m/s\].
    pub g: f64,
    /// Tangential speed \[m/s\], for an oblique impact.
    pub gt: Option<f64>,
    /// Evenly spaced samples over the contact.
    pub points: usize,
}

/// Parses the flags of `rime collision`.
pub fn parse(get: &dyn Fn(&str) -> Option<String>) -> CliResult<Args> {
    let g = speed(
        "--g",
        &get("--g").ok_or_else(|| CliError::input("--g: required (m/s)"))?,
        false,
    )?;
    let gt = get("--gt").map(|t| speed("--gt", &t, true)).transpose()?;
    let points = match get("--points") {
        None => 400,
        Some(p) => {
            let n = number("--points", &p)?;
            if !(n.fract() == 0.0 && (2.0..=1e6).contains(&n)) {
                return err(format!("--points: {p} must be an integer in [2, 1000000]"));
            }
            n as usize
        }
    };
    Ok(Args { g, gt, points })
}

/// Runs `rime collision`.
pub fn run(common: &Common, args: &Args) -> CliResult<String> {
    let contact = crate::args::contact(common)?;
    let tr = contact
        .collision(args.g, args.points, common.accuracy)
        .map_err(|e| CliError::input(format!("--g {}: {e}", args.g)))?;
    let oblique = match args.gt {
        None => None,
        Some(gt) => {
            if contact.friction.is_none() {
                return err("--gt: the scene has no friction (--set friction=on)");
            }
            let grains = &common.scene.grains;
            Some(
                contact
                    .oblique(
                        grains.radius_1,
                        grains.radius_2,
                        args.g,
                        gt,
                        common.accuracy,
                    )
                    .map_err(|e| CliError::input(format!("--gt {gt}: {e}")))?,
            )
        }
    };
    // The core's record of this collision, in its three forms (field names, order and units are
    // the core's: docs/cli.md); this command only prints them.
    let record = rime_core::explorer::records::CollisionRecord::new(args.g, &tr, oblique.as_ref());
    Ok(match common.format {
        Format::Json => {
            let v = serde_json::to_value(&record).map_err(|e| CliError::input(e.to_string()))?;
            crate::output::pretty_json(&v, &COLLISION_KEYS)
        }
        Format::Csv => record.csv(),
        Format::Table => table(
            &["quantity", "value", "unit"],
            &crate::output::human_value_rows(record.table_rows()),
        ),
    })
}

/// The JSON keys in the order docs/cli.md lists them (issue 37 C5: they were sorted): the impact
/// speed, the series, the phases, the four values of `rime eps`, the ledger, the tangential part.
const COLLISION_KEYS: [(&str, &[&str]); 4] = [
    (
        "",
        &[
            "g",
            "t",
            "xi",
            "xi_dot",
            "force",
            "phases",
            "t_c",
            "xi_max",
            "eps_n",
            "status",
            "resolved",
            "ledger",
            "tangential",
        ],
    ),
    ("phases", &["name", "t"]),
    (
        "ledger",
        &[
            "kinetic_in",
            "kinetic_out",
            "dissipated_bulk",
            "dissipated_layer",
            "elastic_retained",
            "adhesion",
            "closure",
        ],
    ),
    (
        "tangential",
        &[
            "eps_t",
            "class",
            "energy_before",
            "energy_after",
            "friction_work",
            "spin_change",
        ],
    ),
];
