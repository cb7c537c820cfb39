//! What the subcommands take: the options every subcommand shares, the output format and the
//! parsers of flag values (numbers, quantities with units, speeds, counts), so that the parser
//! (`crate::cli`) and the subcommands (`crate::commands`) both import from here and not from each
//! other.

use crate::scene_io::{CliError, CliResult, err, scene_json};
use rime_core::{Accuracy, Contact, Scene};

/// Output format of a subcommand.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// JSON (default when stdout is not a terminal).
    Json,
    /// CSV with one header line.
    Csv,
    /// An aligned text table (default on a terminal).
    Table,
}

/// Options shared by every subcommand.
#[derive(Debug, Clone)]
pub struct Common {
    /// The scene after `--scene`/`--preset` and every `--set`.
    pub scene: Scene,
    /// Accuracy level.
    pub accuracy: Accuracy,
    /// Output format.
    pub format: Format,
}

/// `rime figures --explorer`: the explorer's figures and records of a scene, as the terminal's `x`
/// and the page's downloads draw them.
#[derive(Debug, Clone)]
pub struct ExplorerFigures {
    /// The core's request: scene, level, speeds, points, map (validated by the core, so the flags
    /// refuse exactly what the terminal and the page refuse).
    pub request: rime_core::explorer::request::Request,
    /// ε_N on a log axis.
    pub y_log: bool,
    /// Leave out the experimental context.
    pub no_experiments: bool,
}

/// The flag that sets a field of the core's [`Request`](rime_core::explorer::request::Request).
pub(crate) fn request_flag(field: &str) -> &str {
    match field {
        "from" => "--from",
        "to" => "--to",
        "points" => "--points",
        "map_n" => "--n",
        "map_max" => "--max",
        "overlays" => "--overlays",
        other => other,
    }
}

/// The core's request of `rime figures --explorer`, checked by the core; errors name the flag.
pub(crate) fn explorer_request(
    common: &Common,
    get: &dyn Fn(&str) -> Option<String>,
) -> CliResult<rime_core::explorer::request::Request> {
    use rime_core::explorer::frame::Overlay;
    use rime_core::explorer::request::Request;
    let mut request = Request::new(common.scene, common.accuracy);
    request.speeds = match (get("--from"), get("--to")) {
        (None, None) => None,
        (Some(a), Some(b)) => Some((speed("--from", &a, false)?, speed("--to", &b, false)?)),
        (Some(_), None) => return err("--to: required with --from"),
        (None, Some(_)) => return err("--from: required with --to"),
    };
    let whole = |flag: &str, default: usize| -> CliResult<usize> {
        match get(flag) {
            None => Ok(default),
            Some(t) => t
                .trim()
                .parse::<usize>()
                .map_err(|_| CliError::input(format!("{flag}: '{t}' is not a whole number"))),
        }
    };
    request.points = whole("--points", Request::POINTS)?;
    request.map_n = whole("--n", Request::MAP_N)?;
    request.map_max = get("--max")
        .map(|m| speed("--max", &m, false))
        .transpose()?;
    if let Some(list) = get("--overlays") {
        request.overlays = list
            .split(',')
            .map(str::trim)
            .map(|o| Overlay::parse(o).map_err(|e| CliError::input(format!("--overlays {o}: {e}"))))
            .collect::<CliResult<_>>()?;
    }
    request.validate().map_err(|e| {
        let text = e.to_string();
        let (field, rest) = text.split_once(':').unwrap_or(("", &text));
        CliError::input(format!("{}:{rest}", request_flag(field)))
    })?;
    Ok(request)
}

pub(crate) fn number(flag: &str, text: &str) -> CliResult<f64> {
    match text.trim().parse::<f64>() {
        Ok(v) if rime_core::units::underflows(text.trim(), v) => err(format!(
            "{flag} {}: expected {}",
            text.trim(),
            rime_core::units::UNDERFLOW
        )),
        Ok(v) if v.is_finite() => Ok(v),
        Ok(v) => err(format!("{flag}: {v} is not a finite number")),
        Err(_) => err(format!("{flag}: '{text}' is not a number")),
    }
}

/// A value in the SI unit `unit`, with an optional unit (`1e-6`, `"1 um"`, `200 K`), parsed by
/// [`rime_core::units::parse_quantity`] like `--set`.
pub(crate) fn quantity(flag: &str, text: &str, unit: &str) -> CliResult<f64> {
    rime_core::units::parse_quantity("", text, unit).map_err(|e| {
        let shown: String = text.trim().chars().take(40).collect();
        CliError::input(format!("{flag} {shown}{e}"))
    })
}

/// A speed in m/s, with an optional unit (`0.01`, `"2 mm/s"`, `5cm/s`), parsed by
/// [`rime_core::units::parse_quantity`] like `--set`.
pub(crate) fn speed(flag: &str, text: &str, allow_zero: bool) -> CliResult<f64> {
    // The core names the field in front of its message; the flag goes there instead.
    let v = rime_core::units::parse_quantity("", text, "m/s").map_err(|e| {
        let shown: String = text.trim().chars().take(40).collect();
        CliError::input(format!("{flag} {shown}{e}"))
    })?;
    use rime_core::limits::{
        SPEED_DOMAIN, SPEED_OR_ZERO_DOMAIN, speed_is_valid, speed_or_zero_is_valid,
    };
    let (ok, range) = if allow_zero {
        (speed_or_zero_is_valid(v), SPEED_OR_ZERO_DOMAIN)
    } else {
        (speed_is_valid(v), SPEED_DOMAIN)
    };
    if !ok {
        return err(format!(
            "{flag}: speed {} must lie in {range} m/s",
            rime_core::error::Number(v)
        ));
    }
    Ok(v)
}

pub(crate) fn speed_list(flag: &str, text: &str, allow_zero: bool) -> CliResult<Vec<f64>> {
    let items: Vec<&str> = text.split(',').map(str::trim).collect();
    if items.iter().all(|s| s.is_empty()) {
        return err(format!("{flag}: empty list"));
    }
    if items.len() > 1_000_000 {
        return err(format!("{flag}: at most 1000000 values"));
    }
    items.iter().map(|s| speed(flag, s, allow_zero)).collect()
}

/// Most points of any curve or table the CLI computes: the core's limit.
pub(crate) const MAX_POINTS: usize = rime_core::explorer::request::Request::MAX_POINTS;
/// Largest stick map the CLI computes: the core's limit.
pub(crate) const MAX_MAP_N: usize = rime_core::explorer::request::Request::MAX_MAP_N;

pub(crate) fn count(flag: &str, text: &str, min: usize, max: usize) -> CliResult<usize> {
    match text.trim().parse::<usize>() {
        Ok(n) if (min..=max).contains(&n) => Ok(n),
        _ => err(format!(
            "{flag}: '{text}' must be a whole number in [{min}, {max}]"
        )),
    }
}

/// Builds the contact constants for a command.
pub fn contact(common: &Common) -> CliResult<Contact> {
    Ok(Contact::new(&common.scene)?)
}

/// Renders the scene JSON for `rime scene`.
pub fn scene_text(common: &Common) -> CliResult<String> {
    scene_json(&common.scene).map(|mut s| {
        s.push('\n');
        s
    })
}
