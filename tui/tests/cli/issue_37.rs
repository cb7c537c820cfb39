//! Issue 37, the command line: tables for people (4–6 significant digits with prefixed units,
//! JSON and CSV with every digit), `ring`'s "heats" line, units on `collision`'s tangential rows,
//! `tidal`'s verdict, did-you-mean, `--set` on an absent section, underflow, help width, exit codes.

use crate::bin::rime;
use std::process::Command;

fn ok(args: &[&str]) -> String {
    let (code, out, err) = rime(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

/// A table cell `605.2 µs` (or `605.2` with `µs` in a unit column) back in SI: the number times
/// its prefix. Written here, independent of the formatter, from the SI prefixes.
fn si(value: &str, unit: &str) -> Option<f64> {
    let v: f64 = value.parse().ok()?;
    let prefixes = [
        ("T", 1e12),
        ("G", 1e9),
        ("M", 1e6),
        ("k", 1e3),
        ("m", 1e-3),
        ("µ", 1e-6),
        ("n", 1e-9),
        ("p", 1e-12),
    ];
    for base in ["m/s", "Pa s", "Pa", "s", "m", "J", "N", "g"] {
        if let Some(p) = unit.strip_suffix(base) {
            let scale = if p.is_empty() {
                1.0
            } else {
                prefixes.iter().find(|(s, _)| *s == p)?.1
            };
            // Masses are printed in g, kg and below; the records are in kg.
            let to_si = if base == "g" { 1e-3 } else { 1.0 };
            return Some(v * scale * to_si);
        }
    }
    Some(v)
}

/// Significant digits of a printed number (`605.2` → 4, `1e-10` → 1, `0.4954` → 4).
fn digits(value: &str) -> usize {
    let mantissa = value.split(['e', 'E']).next().unwrap_or(value);
    mantissa
        .chars()
        .filter(char::is_ascii_digit)
        .collect::<String>()
        .trim_start_matches('0')
        .len()
}

/// Issue 37 item 11: `rime eps --format table` prints each number to at most 6 significant digits
/// with a prefixed unit, within 80 columns, and agrees with the JSON to those digits; the CSV keeps
/// every digit of the JSON.
#[test]
fn issue_37_the_eps_table_is_for_people_and_the_csv_keeps_every_digit() {
    let g = "1 mm/s,1 cm/s,0.1";
    let json: serde_json::Value =
        serde_json::from_str(&ok(&["eps", "--g", g, "--format", "json"])).unwrap();
    let table = ok(&["eps", "--g", g, "--format", "table"]);
    let csv = ok(&["eps", "--g", g, "--format", "csv"]);
    for line in table.lines() {
        assert!(line.chars().count() <= 80, "wider than 80 columns: {line}");
    }
    let rows: Vec<&str> = table.lines().skip(1).collect();
    let records = json.as_array().unwrap();
    assert_eq!(rows.len(), records.len());
    for (row, rec) in rows.iter().zip(records) {
        // Cells: g (value unit), eps_n, status, t_c (value unit), xi_max (value unit), error.
        let cells: Vec<&str> = row.split_whitespace().collect();
        assert_eq!(cells.len(), 9, "{row}");
        let checks = [
            (cells[0], cells[1], "g_n"),
            (cells[2], "", "eps_n"),
            (cells[4], cells[5], "t_c"),
            (cells[6], cells[7], "xi_max"),
        ];
        for (value, unit, key) in checks {
            let exact = rec[key].as_f64().unwrap();
            let shown = si(value, unit).unwrap_or_else(|| panic!("{value} {unit}"));
            assert!(digits(value) <= 6, "{key}: {value} has more than 6 digits");
            assert!(
                (shown - exact).abs() <= 5e-4 * exact.abs(),
                "{key}: table {value} {unit} vs {exact}"
            );
        }
    }
    // The CSV: every digit (it reads back as the JSON's very numbers).
    for (line, rec) in csv.lines().skip(1).zip(records) {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(
            cells[1].parse::<f64>().unwrap(),
            rec["eps_n"].as_f64().unwrap()
        );
        assert_eq!(
            cells[3].parse::<f64>().unwrap(),
            rec["t_c"].as_f64().unwrap()
        );
    }
}

/// Issue 37 item 11: the `name value unit` tables (`tidal`, `ring`, `collision`) and
/// `tangential` print at most 6 significant digits; every value agrees with the JSON to them.
#[test]
fn issue_37_name_value_tables_are_for_people() {
    let cases: [&[&str]; 3] = [
        &["tidal"],
        &[
            "ring",
            "--preset",
            "ice",
            "--tau",
            "0.5",
            "--omega",
            "1.3143527e-4",
        ],
        &["collision", "--g", "0.01"],
    ];
    for args in cases {
        let table = ok(&[args, &["--format", "table"]].concat());
        let mut numbers = 0;
        for line in table.lines().skip(1) {
            let cells: Vec<&str> = line.split_whitespace().collect();
            if cells.len() >= 2 && cells[1].parse::<f64>().is_ok() {
                numbers += 1;
                assert!(digits(cells[1]) <= 6, "{args:?}: {line}");
            }
        }
        assert!(numbers > 3, "{args:?}\n{table}");
    }
    let tangential = ok(&[
        "tangential",
        "--gn",
        "0.01",
        "--gt",
        "0.01",
        "--format",
        "table",
    ]);
    for cell in tangential.lines().skip(1).flat_map(str::split_whitespace) {
        if cell.parse::<f64>().is_ok() {
            assert!(digits(cell) <= 6, "{cell}\n{tangential}");
        }
    }
}

/// Issue 37 item 11: `ring`'s summary line carries 4 digits and prefixed units (was
/// `c = 5.257410800000001e-6 m/s`, `H = 0.03563071337723164 m`), the same numbers as the JSON.
#[test]
fn issue_37_the_ring_summary_line_is_for_people() {
    let args = [
        "ring",
        "--preset",
        "ice",
        "--tau",
        "0.5",
        "--omega",
        "1.3143527e-4",
    ];
    let table = ok(&[&args[..], &["--format", "table"]].concat());
    let json: serde_json::Value =
        serde_json::from_str(&ok(&[&args[..], &["--format", "json"]].concat())).unwrap();
    let last = table.lines().last().unwrap();
    let c = json["values"]["velocity_dispersion"].as_f64();
    let c = c.or_else(|| json["rough"]["velocity_dispersion"].as_f64());
    let text = |key: &str| -> (String, String) {
        let (_, rest) = last
            .split_once(key)
            .unwrap_or_else(|| panic!("{key} in {last}"));
        let mut words = rest.split_whitespace();
        let v = words.next().unwrap().to_string();
        let u = words.next().unwrap().trim_end_matches(',').to_string();
        (v, u)
    };
    let (cv, cu) = text("c = ");
    assert!(digits(&cv) <= 4, "{last}");
    assert_eq!(cu, "µm/s", "{last}");
    let (hv, hu) = text("H = ");
    assert!(digits(&hv) <= 4 && hu == "mm", "{last}");
    if let Some(c) = c {
        let shown = si(&cv, &cu).unwrap();
        assert!((shown - c).abs() <= 5e-4 * c, "{shown} vs {c}");
    }
}

/// Issue 37 item 12: a ring that `heats` says what its c and H are (the balance outside the
/// slow-collision regime, and why), not a bare "heats" beside finite numbers.
#[test]
fn issue_37_heats_says_what_the_numbers_are() {
    let table = ok(&[
        "ring",
        "--preset",
        "ice",
        "--tau",
        "0.5",
        "--radius",
        "1",
        "--omega",
        "1.3143527e-4",
        "--format",
        "table",
    ]);
    let last = table.lines().last().unwrap();
    assert!(last.starts_with("heats: "), "{last}");
    assert!(last.contains("outside"), "{last}");
    assert!(last.contains("slow-collision regime"), "{last}");
    assert!(last.contains("not a prediction"), "{last}");
}

/// Issue 37 item 14: `collision --format table`'s tangential rows have units (J, rad/s), as
/// docs/cli.md gives them; the CSV's comment lines too.
#[test]
fn issue_37_collision_tangential_rows_have_units() {
    let args = [
        "collision",
        "--g",
        "0.01",
        "--gt",
        "0.01",
        "--set",
        "friction=on",
    ];
    let table = ok(&[&args[..], &["--format", "table"]].concat());
    let unit = |name: &str| -> String {
        let line = table
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("{name}\n{table}"));
        line.split_whitespace().nth(2).unwrap_or("").to_string()
    };
    for name in ["energy_before", "energy_after", "friction_work"] {
        assert!(unit(name).ends_with('J'), "{name}: {}\n{table}", unit(name));
    }
    for name in ["spin_change_1", "spin_change_2"] {
        assert_eq!(unit(name), "rad/s", "{table}");
    }
    let csv = ok(&[&args[..], &["--format", "csv"]].concat());
    assert!(
        csv.contains("# tangential.friction_work,") && csv.contains(",J\n"),
        "{csv}"
    );
    assert!(
        csv.lines()
            .any(|l| l.starts_with("# tangential.spin_change_1,") && l.ends_with(",rad/s"))
    );
}

/// Issue 37 item 14: `tidal --format table` ends with the core's verdict (it was only in JSON).
#[test]
fn issue_37_the_tidal_table_has_the_verdict() {
    let json: serde_json::Value =
        serde_json::from_str(&ok(&["tidal", "--format", "json"])).unwrap();
    let verdict = json["verdict"].as_str().unwrap();
    let table = ok(&["tidal", "--format", "table"]);
    assert_eq!(table.lines().last().unwrap(), verdict);
}

/// Issue 37 item 13: a mistyped subcommand, flag, `--set` path, model or preset gets "did you
/// mean" (exit 2, one line); a path with nothing close lists its section's paths or the sections,
/// never all 24 paths on one line.
#[test]
fn issue_37_did_you_mean() {
    let cases: [(&[&str], &str); 6] = [
        (&["esp", "--g", "0.1"], "did you mean `eps`?"),
        (&["eps", "--gg", "0.1"], "did you mean `--g`?"),
        (
            &["eps", "--set", "bulk.dampin.time=1e-3"],
            "did you mean `bulk.damping.time`?",
        ),
        (
            &["compare", "--models", "brilianov2007"],
            "did you mean `brilliantov2007`?",
        ),
        (
            &["eps", "--preset", "ice-frots"],
            "did you mean `ice-frost`?",
        ),
        (&["help", "rign"], "did you mean `ring`?"),
    ];
    for (args, expected) in cases {
        let (code, out, err) = rime(args);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert!(err.contains(expected), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    }
    // Nothing close: the section's paths (friction.mu → friction.coefficient), else the sections.
    let (code, _, err) = rime(&["eps", "--set", "friction.mu=0.3"]);
    assert_eq!(code, 2);
    assert!(err.contains("friction.coefficient"), "{err}");
    assert!(!err.contains("grains.radius_1"), "the whole list: {err}");
    let (code, _, err) = rime(&["eps", "--set", "nothing.like.it=1"]);
    assert_eq!(code, 2);
    assert!(
        err.chars().count() < 200,
        "{} characters: {err}",
        err.chars().count()
    );
    assert!(err.contains("grains") && err.contains("friction"), "{err}");
    // Far from every name: no suggestion.
    let (_, _, err) = rime(&["zzzzzz"]);
    assert!(!err.contains("did you mean"), "{err}");
}

/// Issue 37 item 13: bash completes parameter paths after `--set` (it offered flags), in a real
/// bash with the generated script; zsh and fish list them too.
#[test]
fn issue_37_completion_offers_parameter_paths_after_set() {
    let script = ok(&["completions", "bash"]);
    let probe = format!(
        "{script}\nCOMP_WORDS=(rime eps --set bulk.damping.t); COMP_CWORD=3; _rime; echo \"${{COMPREPLY[*]}}\"\n\
         COMP_WORDS=(rime --set lay); COMP_CWORD=2; _rime; echo \"${{COMPREPLY[*]}}\"\n"
    );
    let out = Command::new("bash")
        .arg("-c")
        .arg(&probe)
        .output()
        .expect("bash is needed for this test");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "bulk.damping.time=", "{text}");
    let layer: Vec<&str> = rime_core::params::PARAMETERS
        .iter()
        .map(|p| p.path)
        .filter(|p| p.starts_with("lay"))
        .collect();
    assert!(!layer.is_empty());
    for p in &layer {
        assert!(
            lines[1].split(' ').any(|w| w == format!("{p}=")),
            "{p}: {text}"
        );
    }
    assert!(
        !lines[1].contains("--"),
        "flags offered after --set: {text}"
    );
    for sh in ["zsh", "fish"] {
        assert!(
            ok(&["completions", sh]).contains("bulk.damping.time="),
            "{sh}"
        );
    }
}

/// Issue 37 item 14: `--set layer.thickness=2um` on a scene without a layer says on stderr that
/// the layer is switched on and which defaults the other fields took; with every field given, or a
/// scene that has a layer, nothing is said.
#[test]
fn issue_37_setting_a_field_of_an_absent_effect_says_so() {
    let (code, _, err) = rime(&[
        "eps",
        "--g",
        "0.01",
        "--set",
        "layer.thickness=2um",
        "--format",
        "csv",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("no layer") && err.contains("switched on"),
        "{err}"
    );
    assert!(err.contains("layer.viscosity = 1 kPa s"), "{err}");
    assert!(err.contains("--set layer=off"), "{err}");
    for quiet in [
        &[
            "--set",
            "layer.thickness=2um",
            "--set",
            "layer.viscosity=500",
            "--set",
            "layer.reading=offset",
        ][..],
        &["--preset", "ice-frost", "--set", "layer.thickness=2um"][..],
        &["--set", "layer=on", "--set", "layer.thickness=2um"][..],
    ] {
        let (code, _, err) =
            rime(&[&["eps", "--g", "0.01", "--format", "csv"][..], quiet].concat());
        assert_eq!(code, 0, "{err}");
        assert!(err.is_empty(), "{quiet:?}: {err}");
    }
}

/// Issue 37 item 14: a number below a double's range is refused as such (it was read as 0 and
/// refused as "speed 0"), for speeds and `--set` alike; a true zero keeps its own message.
#[test]
fn issue_37_an_underflowing_number_says_so() {
    for args in [
        &["eps", "--g", "1e-400"][..],
        &["eps", "--g", "0.01", "--set", "grains.radius_1=1e-400"][..],
        &["eps", "--g", "2.5e-999 m/s"][..],
    ] {
        let (code, _, err) = rime(args);
        assert_eq!(code, 2, "{args:?}");
        assert!(err.contains("underflows to 0"), "{args:?}: {err}");
    }
    let (code, _, err) = rime(&["eps", "--g", "0e-400"]);
    assert_eq!(code, 2);
    assert!(!err.contains("underflows"), "{err}");
    // The smallest subnormal is a number like any other.
    let (code, _, err) = rime(&["eps", "--g", "5e-324"]);
    assert!(!err.contains("underflows"), "{code} {err}");
}

/// Issue 37 item 14: `tangential`'s ε_N takes the stick maps' path and `eps` its own (docs/cli.md):
/// they agree to the documented 1e-14 relative at `fast` and `precise`, bit for bit at
/// `integrated`.
#[test]
fn issue_37_eps_and_tangential_agree_to_the_documented_digits() {
    let g = "1e-5,3e-4,0.01,0.3,10";
    for (level, bound) in [("fast", 1e-14), ("precise", 1e-14), ("integrated", 0.0)] {
        let eps: serde_json::Value = serde_json::from_str(&ok(&[
            "eps",
            "--g",
            g,
            "--accuracy",
            level,
            "--format",
            "json",
        ]))
        .unwrap();
        let tan: serde_json::Value = serde_json::from_str(&ok(&[
            "tangential",
            "--gn",
            g,
            "--gt",
            "0.001",
            "--set",
            "friction=on",
            "--accuracy",
            level,
            "--format",
            "json",
        ]))
        .unwrap();
        for (a, b) in eps.as_array().unwrap().iter().zip(tan.as_array().unwrap()) {
            let (x, y) = (a["eps_n"].as_f64().unwrap(), b["eps_n"].as_f64().unwrap());
            assert!((x - y).abs() <= bound * x.abs(), "{level}: {x} vs {y}");
        }
    }
}

/// Issue 37 item 14: every help page fits 80 columns, and says what the exit codes are (2 bad
/// input, 1 a failed computation), as docs/cli.md does.
#[test]
fn issue_37_help_fits_80_columns_and_tells_the_exit_codes() {
    let overview = ok(&["--help"]);
    let subs: Vec<String> = overview
        .lines()
        .skip_while(|l| !l.starts_with("SUBCOMMANDS"))
        .skip(1)
        .take_while(|l| !l.is_empty())
        .filter(|l| l.starts_with("  ") && !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next().map(String::from))
        .collect();
    assert!(subs.len() > 10, "{overview}");
    let mut pages = vec![("rime".to_string(), overview)];
    for s in &subs {
        pages.push((s.clone(), ok(&[s.as_str(), "--help"])));
    }
    for (name, page) in &pages {
        for line in page.lines() {
            assert!(
                line.chars().count() <= 80,
                "{name}: {} columns: {line}",
                line.chars().count()
            );
        }
        let flat = page.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(flat.contains("2 bad input"), "{name}: {flat}");
        assert!(flat.contains("1 a computation that failed"), "{name}");
    }
    // fit names its own formats only.
    let fit = ok(&["fit", "--help"]);
    assert!(!fit.contains("json | csv | table"), "{fit}");
}

/// Issue 37 (review F12, C1): `--accuracy` errors name the field once and suggest the level;
/// a second, different `--format` is refused (the last one won silently); `fit --law` says its speeds are the
/// law's, not "from the header" (a law has none).
#[test]
fn issue_37_small_error_texts() {
    let (code, _, err) = rime(&["eps", "--g", "0.1", "--accuracy", "precse"]);
    assert_eq!(code, 2);
    assert_eq!(err.matches("accuracy").count(), 1, "{err}");
    assert!(err.contains("did you mean `precise`?"), "{err}");
    let (code, out, err) = rime(&["eps", "--g", "0.1", "--format", "json", "--format", "csv"]);
    assert_eq!(code, 2, "{out}");
    assert!(
        err.contains("--format") && err.contains("different"),
        "{err}"
    );
    ok(&["eps", "--g", "0.1", "--format", "json", "--format", "json"]);
    let fit = ok(&["fit", "--law", "bridges1984", "--format", "table"]);
    assert!(!fit.contains("from the header"), "{fit}");
    assert!(fit.contains("the law's measured speeds"), "{fit}");
}

/// Every object's keys of a JSON text in the order they are written, by path (`""` for the top,
/// `"ledger"`, `"size_bins"` for an array's elements): read from the text itself, as a person
/// reads it (a parsed `serde_json::Value` would sort them).
fn key_order(text: &str) -> Vec<(String, Vec<String>)> {
    enum Ctx {
        Object(String),
        Array(String),
    }
    let mut out: Vec<(String, Vec<String>)> = Vec::new();
    let mut stack: Vec<Ctx> = Vec::new();
    let mut last_string = String::new();
    let mut pending_key: Option<String> = None;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' => {
                last_string.clear();
                while let Some(c) = chars.next() {
                    match c {
                        '\\' => {
                            chars.next();
                        }
                        '"' => break,
                        c => last_string.push(c),
                    }
                }
            }
            ':' => {
                let Some(Ctx::Object(path)) = stack.last() else {
                    panic!("a key outside an object")
                };
                let path = path.clone();
                match out.iter_mut().find(|(p, _)| *p == path) {
                    Some((_, keys)) if !keys.contains(&last_string) => {
                        keys.push(last_string.clone())
                    }
                    Some(_) => {}
                    None => out.push((path.clone(), vec![last_string.clone()])),
                }
                pending_key = Some(if path.is_empty() {
                    last_string.clone()
                } else {
                    format!("{path}.{last_string}")
                });
            }
            '{' | '[' => {
                // An object or array is the value of the pending key, or an element of an array.
                let path = match (pending_key.take(), stack.last()) {
                    (Some(k), _) => k,
                    (None, Some(Ctx::Array(p))) | (None, Some(Ctx::Object(p))) => p.clone(),
                    (None, None) => String::new(),
                };
                stack.push(if c == '{' {
                    Ctx::Object(path)
                } else {
                    Ctx::Array(path)
                });
            }
            '}' | ']' => {
                stack.pop();
            }
            ',' => pending_key = None,
            _ => {}
        }
    }
    out
}

/// Issue 37 (review C5): every JSON output writes its keys in the order docs/cli.md lists them
/// (`tidal`, `ring`, `compare`, `collision`, `map` and `fit` printed them sorted). The expected
/// orders are docs/cli.md's, copied here section by section.
#[test]
fn issue_37_json_keys_come_in_the_documented_order() {
    let ring_prediction = [
        "velocity_dispersion",
        "thickness",
        "mean_impact_speed",
        "eps_effective",
        "eps_cr",
        "sticking_fraction",
        "equilibration_orbits",
        "verdict",
    ];
    // `rime tidal`: the named values as the CSV lists them, then `stays_in_contact`, `verdict`.
    let tidal_csv = ok(&["tidal", "--format", "csv"]);
    let mut tidal: Vec<&str> = tidal_csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap())
        .collect();
    tidal.extend(["stays_in_contact", "verdict"]);
    let scene_keys = key_order(&ok(&["scene"]));
    // (arguments, [(object path, its keys in order)])
    type Case<'a> = (Vec<&'a str>, Vec<(&'a str, Vec<&'a str>)>);
    let cases: Vec<Case> = vec![
        (vec!["tidal"], vec![("", tidal)]),
        (
            vec!["ring", "--tau", "0.1", "--omega", "1.3143527e-4"],
            vec![
                (
                    "",
                    vec![
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
                ("smooth", ring_prediction.to_vec()),
                ("rough", ring_prediction.to_vec()),
            ],
        ),
        (
            vec![
                "ring",
                "--tau",
                "0.1",
                "--omega",
                "1.3143527e-4",
                "--radii",
                "1cm..5cm",
                "--q",
                "3",
                "--bins",
                "2",
            ],
            vec![
                (
                    "",
                    vec![
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
                    vec![
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
                    vec![
                        "translational",
                        "collisional",
                        "total",
                        "dlnnu_dlntau",
                        "overstability",
                    ],
                ),
            ],
        ),
        (
            vec![
                "compare",
                "--models",
                "hertzsch2002,atlas:bridges1984",
                "--g",
                "0.01",
            ],
            vec![
                ("", vec!["records", "characteristic_speeds"]),
                ("records", vec!["model", "g_n", "eps_n", "status"]),
                (
                    "characteristic_speeds",
                    vec!["model", "name", "value", "status"],
                ),
            ],
        ),
        (
            vec![
                "collision",
                "--g",
                "0.01",
                "--gt",
                "0.01",
                "--points",
                "3",
                "--set",
                "friction.coefficient=0.3",
            ],
            vec![
                (
                    "",
                    vec![
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
                ("phases", vec!["name", "t"]),
                (
                    "ledger",
                    vec![
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
                    vec![
                        "eps_t",
                        "class",
                        "energy_before",
                        "energy_after",
                        "friction_work",
                        "spin_change",
                    ],
                ),
            ],
        ),
        (
            vec!["map", "--max", "0.1", "--n", "3"],
            vec![("", vec!["g", "class", "eps_t", "eps_n"])],
        ),
        (
            vec!["fit", "--law", "bridges1984"],
            vec![
                (
                    "",
                    vec![
                        "source",
                        "params",
                        "correlation",
                        "rms_error",
                        "reduced_chi2",
                        "dof",
                        "points",
                        "weighted",
                        "header",
                        "g_unit",
                        "g_unit_assumed",
                        "warnings",
                        "residuals",
                        "runs_test",
                        "chi2_scaled",
                        "scene",
                        "param",
                        "value",
                        "unit",
                        "standard_error",
                    ],
                ),
                ("params", vec!["param", "value", "unit", "standard_error"]),
                (
                    "runs_test",
                    vec!["runs", "expected", "positive", "negative", "p"],
                ),
                // The scene as `rime scene` writes it (docs/cli.md, Scene JSON).
                (
                    "scene",
                    scene_keys[0].1.iter().map(String::as_str).collect(),
                ),
            ],
        ),
        (
            vec!["tangential", "--gn", "0.01", "--gt", "0.01"],
            vec![("", vec!["g_n", "g_t", "eps_t", "eps_n", "class"])],
        ),
        (
            vec!["eps", "--g", "0.01"],
            vec![(
                "",
                vec!["g_n", "eps_n", "status", "t_c", "xi_max", "error_estimate"],
            )],
        ),
    ];
    for (args, expected) in cases {
        let mut full = args.clone();
        full.extend(["--format", "json"]);
        let text = ok(&full);
        let got = key_order(&text);
        for (path, keys) in expected {
            let written = got
                .iter()
                .find(|(p, _)| p == path)
                .unwrap_or_else(|| panic!("{args:?}: no object at {path:?}: {got:?}"));
            assert_eq!(written.1, keys, "{args:?}: the keys of {path:?}");
        }
    }
}

/// Issue 37 (review F6): `rime tidal`'s table and CSV write the density's and surface energy's
/// units as a person reads them (`kg/m³`, `J/m²`, as the explorer and the page write them), not
/// `kg/m3`, `J/m2`; the JSON keys stay.
#[test]
fn issue_37_tidal_units_read_as_written_elsewhere() {
    for format in ["table", "csv"] {
        let text = ok(&["tidal", "--format", format]);
        let unit_of = |name: &str| {
            let line = text
                .lines()
                .find(|l| l.trim_start().starts_with(name))
                .unwrap_or_else(|| panic!("{format}: no {name}: {text}"));
            line.split([',', ' '])
                .rfind(|c| !c.is_empty())
                .unwrap()
                .to_string()
        };
        assert_eq!(unit_of("density"), "kg/m³", "{format}: {text}");
        assert_eq!(unit_of("surface_energy"), "J/m²", "{format}: {text}");
    }
    let json: serde_json::Value =
        serde_json::from_str(&ok(&["tidal", "--format", "json"])).unwrap();
    assert_eq!(json["density"].as_f64(), Some(900.0));
    assert_eq!(json["surface_energy"].as_f64(), Some(0.1));
}

/// Issue 37 (review C6): `rime data --format table` fits 80 columns (it was 165, the formula
/// right-aligned to 130) with every entry, its formula whole and the units of its symbols
/// (`hatzes1988_frost`'s v is in cm/s); a law's values at speeds read with 4 significant digits.
#[test]
fn issue_37_the_atlas_table_fits_80_columns_and_says_the_units() {
    let table = ok(&["data", "--format", "table"]);
    for line in table.lines() {
        assert!(
            line.chars().count() <= 80,
            "{} columns: {line}",
            line.chars().count()
        );
    }
    let json: serde_json::Value = serde_json::from_str(&ok(&["data", "--format", "json"])).unwrap();
    let flat = table.split_whitespace().collect::<Vec<_>>().join(" ");
    for e in json.as_array().unwrap() {
        let id = e["id"].as_str().unwrap();
        assert!(
            table
                .lines()
                .any(|l| l.split_whitespace().next() == Some(id)),
            "{id}: {table}"
        );
        let formula = e["formula"].as_str().unwrap();
        let formula = formula.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(flat.contains(&formula), "{id}: {formula}");
        let units = e["units"].as_str().unwrap();
        if !units.is_empty() {
            assert!(
                flat.contains(&format!("{formula} [{units}]")),
                "{id}: {units}"
            );
        }
    }
    assert!(flat.contains("eps = 0.48 v^-0.20 [v in cm/s]"), "{flat}");
    let law = ok(&[
        "data",
        "--law",
        "bridges1984",
        "--g",
        "0.01",
        "--format",
        "table",
    ]);
    let row: Vec<&str> = law.lines().nth(1).unwrap().split_whitespace().collect();
    // (v / v_c)^-0.234 at v = 1 cm/s, v_c = 0.0077 cm/s: computed here from the law's formula.
    let eps = (1.0f64 / 0.0077).powf(-0.234);
    assert_eq!(row[..2], ["10", "mm/s"], "{law}");
    assert!(digits(row[2]) <= 6, "{law}");
    assert!((row[2].parse::<f64>().unwrap() - eps).abs() < 1e-3, "{law}");
}

/// Issue 37 (review X1): `rime figures` writes captions.txt beside the figures (the README
/// points at docs/figures/captions.txt; it was never written), its text the captions printed;
/// a stick map's SVG draws a rectangle per run of equal cells, not per cell (2.2 MB each).
#[test]
fn issue_37_figures_write_their_captions_and_compact_maps() {
    let dir = std::env::temp_dir().join(format!("rime-issue-37-x1-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = ok(&["figures", "--out", dir.to_str().unwrap()]);
    let captions = std::fs::read_to_string(dir.join("captions.txt")).expect("captions.txt");
    let printed: String = out
        .lines()
        .filter(|l| !l.starts_with("wrote "))
        .map(|l| format!("{l}\n"))
        .collect();
    assert_eq!(captions, printed);
    assert!(captions.contains("fig4-hard: Fig. 4"), "{captions}");
    for map in ["fig4-hard", "fig4-layer", "fig4-adhesion-zoom"] {
        let svg = std::fs::read_to_string(dir.join(format!("{map}.svg"))).expect("svg");
        let rects = svg.matches("<rect").count();
        // The maps are grids of thousands of cells in a few regions (rolling, sliding, …).
        assert!(rects < 2000, "{map}: {rects} rectangles");
        assert!(rects > 100, "{map}: {rects} rectangles: no map drawn?");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
