//! The command line as a new user meets it (issue 12, items 12 and 13): per-subcommand help,
//! bare switches, `--format` refused where it would be ignored, units on speeds, the explorer
//! without a terminal, exact decades, units in CSV headers, completions and man page.

use crate::bin::rime_binary;
use std::path::PathBuf;
use std::process::{Command, Stdio};

fn rime(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(rime_binary()).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).to_string(),
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

fn ok(args: &[&str]) -> String {
    let (code, out, err) = rime(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

fn json(args: &[&str]) -> serde_json::Value {
    let mut all = args.to_vec();
    all.extend(["--format", "json"]);
    serde_json::from_str(&ok(&all)).unwrap()
}

/// Exit 2, empty stdout, one stderr line naming `field`.
fn refused(args: &[&str], field: &str) {
    let (code, out, err) = rime(args);
    assert_eq!(code, 2, "{args:?}: {out} {err}");
    assert!(out.is_empty(), "{args:?}: {out}");
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    assert!(err.contains(field), "{args:?}: {err} (should name {field})");
}

struct Dir(PathBuf);

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn scratch(name: &str) -> Dir {
    let d = std::env::temp_dir().join(format!("rime-usability-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    Dir(d)
}

/// Every subcommand with the flags docs/cli.md gives it (scene options and `--format` included
/// where the subcommand reads a scene or prints a table).
const SCENE: [&str; 4] = ["--scene", "--preset", "--set", "--accuracy"];
fn documented() -> Vec<(&'static str, Vec<&'static str>)> {
    let with = |own: &[&'static str], scene: bool, format: bool| {
        let mut v = own.to_vec();
        if scene {
            v.extend(SCENE);
        }
        if format {
            v.push("--format");
        }
        v
    };
    vec![
        ("eps", with(&["--g", "--g-file"], true, true)),
        ("curve", with(&["--from", "--to", "--points"], true, true)),
        ("tangential", with(&["--gn", "--gt"], true, true)),
        ("map", with(&["--max", "--n"], true, true)),
        (
            "tidal",
            with(
                &[
                    "--planet-mass",
                    "--distance",
                    "--radius",
                    "--density",
                    "--surface-energy",
                ],
                false,
                true,
            ),
        ),
        ("scene", with(&["--out"], true, true)),
        (
            "export",
            with(
                &["--out", "--from", "--to", "--points", "--runtime-params"],
                true,
                false,
            ),
        ),
        (
            "fit",
            with(&["--data", "--law", "--radius", "--param"], true, true),
        ),
        ("data", with(&["--law", "--g", "--radius"], true, true)),
        (
            "stick",
            with(
                &["--radius", "--temperature", "--gamma", "--out"],
                true,
                true,
            ),
        ),
        (
            "ring",
            with(
                &[
                    "--tau",
                    "--omega",
                    "--planet-mass",
                    "--distance",
                    "--radius",
                    "--scale-damping",
                ],
                true,
                true,
            ),
        ),
        ("figures", vec!["--out", "--accuracy"]),
        (
            "compare",
            with(&["--models", "--g", "--list", "--bench"], true, true),
        ),
        ("bench", vec!["--out", "--quick", "--frames"]),
    ]
}

/// Splits an example command line the way a shell would (double quotes only).
fn shell_words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    let (mut cur, mut quoted, mut any) = (String::new(), false, false);
    for c in line.chars() {
        match c {
            '"' => {
                quoted = !quoted;
                any = true;
            }
            ' ' if !quoted => {
                if any {
                    words.push(std::mem::take(&mut cur));
                    any = false;
                }
            }
            c => {
                cur.push(c);
                any = true;
            }
        }
    }
    if any {
        words.push(cur);
    }
    words
}

#[test]
fn every_subcommand_has_its_own_help_with_its_flags_and_a_working_example() {
    let global = ok(&["--help"]);
    for (sub, flags) in documented() {
        let help = ok(&[sub, "--help"]);
        assert_ne!(help, global, "{sub} --help prints the global page");
        assert!(help.starts_with(&format!("rime {sub} ")), "{sub}: {help}");
        assert_eq!(ok(&["help", sub]), help, "rime help {sub}");
        assert_eq!(ok(&[sub, "-h"]), help, "{sub} -h");
        for flag in &flags {
            assert!(
                help.lines().any(|l| l.trim_start().starts_with(flag)),
                "{sub} --help lacks {flag}"
            );
        }
        let example = help
            .split("EXAMPLE:\n")
            .nth(1)
            .and_then(|e| e.lines().next())
            .unwrap_or_else(|| panic!("{sub}: no example"))
            .trim();
        assert!(example.starts_with(&format!("rime {sub} ")), "{example}");
        // The examples that only print (no files, under a second) run as shown.
        if !["export", "figures", "bench", "scene", "fit"].contains(&sub) {
            let words = shell_words(example);
            let args: Vec<&str> = words[1..].iter().map(String::as_str).collect();
            ok(&args);
        }
    }
    refused(&["help", "frobnicate"], "frobnicate");
}

#[test]
fn switches_work_bare_and_with_true() {
    // --quick without a value (and the old `--quick true`).
    let bare = scratch("quick-bare");
    let text = ok(&["bench", "--quick", "--out", bare.0.to_str().unwrap()]);
    assert!(text.contains("bench.json"));
    assert!(bare.0.join("bench.json").is_file());
    // --runtime-params last on the line, bare, equals `--runtime-params true`.
    let (a, b, c) = (scratch("rt-bare"), scratch("rt-true"), scratch("rt-off"));
    let header = |d: &Dir, extra: &[&str]| {
        let mut args = vec!["export", "--points", "8", "--out", d.0.to_str().unwrap()];
        args.extend(extra);
        ok(&args);
        std::fs::read_to_string(d.0.join("rime_eps.h")).unwrap()
    };
    let bare = header(&a, &["--runtime-params"]);
    assert_eq!(bare, header(&b, &["--runtime-params", "true"]));
    assert_ne!(bare, header(&c, &[]));
    // --list and --bench of compare, and a switch before another flag.
    let v = json(&["compare", "--list"]);
    assert!(v.as_array().unwrap().len() >= 2);
    refused(&["bench", "--quick=maybe"], "--quick");
}

/// Issue 26: `bench --frames` writes one record per (scene, level, size) with the documented
/// fields; the times are reported, never asserted (only that they are times, and that the first
/// frame is drawn no later than the final one).
#[test]
fn bench_frames_writes_one_record_per_case_issue_26() {
    let d = scratch("bench-frames");
    let text = ok(&[
        "bench",
        "--frames",
        "--quick",
        "--out",
        d.0.to_str().unwrap(),
    ]);
    assert!(
        text.contains("frames.json") && text.contains("cores"),
        "{text}"
    );
    let records: serde_json::Value =
        serde_json::from_slice(&std::fs::read(d.0.join("frames.json")).unwrap()).unwrap();
    let records = records.as_array().unwrap();
    // --quick: 9 scenes × 3 levels at 80×24.
    assert_eq!(records.len(), 9 * 3, "{records:?}");
    let mut cases = std::collections::BTreeSet::new();
    for r in records {
        assert_eq!(r["surface"], "terminal");
        assert_eq!(r["size"], "80x24");
        assert!(["fast", "precise", "integrated"].contains(&r["level"].as_str().unwrap()));
        let (first, last) = (
            r["first_ms"].as_f64().unwrap(),
            r["final_ms"].as_f64().unwrap(),
        );
        assert!(first > 0.0 && first <= last && last.is_finite(), "{r}");
        assert!(r["cores"].as_u64().unwrap() >= 1);
        assert!(r["edit"].is_string(), "{r}");
        assert!(r["load"].is_number() || r["load"].is_null(), "{r}");
        cases.insert((r["scene"].to_string(), r["level"].to_string()));
    }
    assert_eq!(cases.len(), records.len(), "each case once");
}

#[test]
fn format_is_refused_where_it_would_be_ignored() {
    let d = scratch("format");
    let out = d.0.to_str().unwrap();
    refused(
        &["bench", "--quick", "--out", out, "--format", "json"],
        "--format",
    );
    refused(&["figures", "--out", out, "--format", "csv"], "--format");
    refused(&["export", "--out", out, "--format", "table"], "--format");
    refused(&["scene", "--format", "csv"], "--format");
    refused(
        &["fit", "--law", "bridges1984", "--format", "csv"],
        "--format",
    );
    // Nothing was written by the refused commands.
    assert_eq!(std::fs::read_dir(&d.0).unwrap().count(), 0);
    // scene honours the one format it has.
    assert!(json(&["scene"])["grains"].is_object());
    // Scene options are refused where no scene is read.
    refused(&["bench", "--preset", "ice-frost"], "--preset");
}

#[test]
fn speeds_take_units_like_set() {
    let plain = json(&["eps", "--g", "0.002,0.05"]);
    let units = json(&["eps", "--g", "2 mm/s,5cm/s"]);
    assert_eq!(units, plain);
    assert_eq!(units[0]["g_n"], 0.002);
    let a = json(&[
        "curve", "--from", "1 um/s", "--to", "1 m/s", "--points", "4",
    ]);
    assert_eq!(
        a,
        json(&["curve", "--from", "1e-6", "--to", "1", "--points", "4"])
    );
    let m = json(&["map", "--max", "5cm/s", "--n", "3"]);
    assert_eq!(m["g"][2], 0.05);
    let t = json(&["tangential", "--gn", "1 cm/s", "--gt", "1mm/s"]);
    assert_eq!(t[0]["g_n"], 0.01);
    assert_eq!(t[0]["g_t"], 0.001);
    refused(&["eps", "--g", "2 Pa"], "--g");
    refused(&["map", "--max", "5 cm"], "--max");
    refused(&["curve", "--from", "1 um/s", "--to", "2 Mm/s"], "--to");
}

#[test]
fn the_explorer_without_a_terminal_says_so() {
    let out = Command::new(rime_binary())
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty());
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("needs a terminal"), "{err}");
    assert!(err.contains("rime eps"), "{err}");
    assert!(!err.contains("os error"), "{err}");
}

#[test]
fn decades_are_exact_and_numbers_carry_no_float_noise() {
    let v = json(&["curve", "--from", "1e-6", "--to", "1", "--points", "7"]);
    let g: Vec<f64> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["g_n"].as_f64().unwrap())
        .collect();
    assert_eq!(g, [1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0]);
    let csv = ok(&[
        "curve", "--from", "1e-6", "--to", "1", "--points", "7", "--format", "csv",
    ]);
    let first: Vec<&str> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap())
        .collect();
    // One number rule (issue 21): plain from 1e-4, like error messages.
    assert_eq!(
        first,
        ["1e-6", "1e-5", "0.0001", "0.001", "0.01", "0.1", "1"]
    );
    // Halves of decades too: 10^-5.5 to the double.
    let v = json(&["curve", "--from", "1e-6", "--to", "1e-5", "--points", "3"]);
    assert_eq!(v[1]["g_n"].as_f64().unwrap(), 10f64.powf(-5.5));
    // Zero prints as 0, never 0e0.
    let map = ok(&["map", "--max", "0.01", "--n", "3", "--format", "csv"]);
    let row: Vec<&str> = map.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(row[..3], ["0", "0", "0"]);
    assert!(!map.contains("e0,") && !map.contains("99999999"), "{map}");
}

#[test]
fn csv_headers_carry_units_and_json_names_do_not_change() {
    let csv = ok(&["eps", "--g", "0.01", "--format", "csv"]);
    assert_eq!(
        csv.lines().next().unwrap(),
        "g_n [m/s],eps_n,status,t_c [s],xi_max [m],error_estimate"
    );
    let csv = ok(&[
        "tangential",
        "--gn",
        "0.01",
        "--gt",
        "0.001",
        "--format",
        "csv",
    ]);
    assert_eq!(
        csv.lines().next().unwrap(),
        "g_n [m/s],g_t [m/s],eps_t,eps_n,class"
    );
    let csv = ok(&["map", "--max", "0.01", "--n", "2", "--format", "csv"]);
    assert_eq!(
        csv.lines().next().unwrap(),
        "g_n [m/s],g_t [m/s],eps_t,class"
    );
    let v = json(&["eps", "--g", "0.01"]);
    let mut keys: Vec<&str> = v[0]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    keys.sort_unstable();
    assert_eq!(
        keys,
        ["eps_n", "error_estimate", "g_n", "status", "t_c", "xi_max"]
    );
}

#[test]
fn completions_and_man_page_name_every_flag_the_parser_accepts() {
    let shells: Vec<(&str, String)> = ["bash", "zsh", "fish"]
        .iter()
        .map(|sh| (*sh, ok(&["completions", sh])))
        .collect();
    let man = ok(&["man"]);
    assert!(man.starts_with(".TH RIME 1"), "{man}");
    for (sub, flags) in documented() {
        for (_, text) in &shells {
            assert!(text.contains(sub), "completions lack {sub}");
        }
        assert!(man.contains(&format!("rime {sub}")), "man lacks {sub}");
        for flag in flags.iter().chain(&["--help", "--version"]) {
            // The parser accepts it (with a value, then --help ends the parse).
            let global = ["--help", "--version"].contains(flag);
            let value = match *flag {
                "--accuracy" => "fast",
                "--format" => "json",
                _ => "true",
            };
            let with_value = format!("{flag}={value}");
            if !global {
                let (code, _, err) = rime(&[sub, &with_value, "--help"]);
                assert_eq!(code, 0, "{sub} {flag}: {err}");
            }
            for (sh, text) in &shells {
                let needle = if *sh == "fish" {
                    format!("-l {}", flag.trim_start_matches("--"))
                } else {
                    flag.to_string()
                };
                assert!(text.contains(&needle), "{sh} completions: {sub} {flag}");
            }
            assert!(
                man.contains(&flag.replace('-', "\\-")),
                "man page lacks {flag}"
            );
        }
        // …and refuses what it does not document.
        refused(&[sub, "--zzz=true", "--help"], "--zzz");
    }
    refused(&["completions", "tcsh"], "tcsh");
}

/// Issue 12 item 7: without `--accuracy` the command line uses the best level — the tightest named
/// bound (1e-10) — and the former `balanced` is still accepted under its new name's meaning.
#[test]
fn the_default_level_is_the_tightest_named_bound_issue_12() {
    let rec = json(&["eps", "--g", "0.01", "--format", "json"]);
    let bound = rec[0]["error_estimate"].as_f64().unwrap();
    assert!(bound <= 1e-10, "default error estimate {bound}");
    let named = json(&[
        "eps",
        "--g",
        "0.01",
        "--accuracy",
        "integrated",
        "--format",
        "json",
    ]);
    let old = json(&[
        "eps",
        "--g",
        "0.01",
        "--accuracy",
        "balanced",
        "--format",
        "json",
    ]);
    assert_eq!(named, old, "balanced is the old name of integrated");
    let help = ok(&["help", "eps"]);
    assert!(help.contains("precise (default"), "{help}");
}

/// Issue 22: the shell completion offers preset names after `--preset` (it offered flags), run
/// in a real bash with the generated script; zsh and fish list them too.
#[test]
fn completion_offers_preset_names_after_preset_issue_22() {
    let script = ok(&["completions", "bash"]);
    let presets: Vec<&str> = rime_core::Preset::ALL.iter().map(|p| p.name()).collect();
    let probe = format!(
        "{script}\nCOMP_WORDS=(rime eps --preset ice-); COMP_CWORD=3; _rime; echo \"${{COMPREPLY[*]}}\"\n\
         COMP_WORDS=(rime eps --preset ''); COMP_CWORD=3; _rime; echo \"${{COMPREPLY[*]}}\"\n\
         COMP_WORDS=(rime eps --accuracy ''); COMP_CWORD=3; _rime; echo \"${{COMPREPLY[*]}}\"\n\
         COMP_WORDS=(rime eps --); COMP_CWORD=2; _rime; echo \"${{COMPREPLY[*]}}\"\n"
    );
    let out = std::process::Command::new("bash")
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
    assert_eq!(
        lines[0], "ice-frost ice-sticky ice-paper-viscosities",
        "{text}"
    );
    assert_eq!(lines[1], presets.join(" "), "{text}");
    assert_eq!(lines[2], "fast precise integrated", "{text}");
    assert!(
        lines[3].contains("--preset") && lines[3].contains("--g"),
        "{text}"
    );
    for sh in ["zsh", "fish"] {
        let s = ok(&["completions", sh]);
        assert!(s.contains(&presets.join(" ")), "{sh}: no preset names");
    }
}

/// Issue 22: `map` and `collision` JSON are pretty-printed like `eps` (they came out on one line
/// when piped), with arrays of numbers on one line; `compare --list` fits 80 columns.
#[test]
fn map_and_collision_json_are_pretty_like_eps_and_list_fits_80_columns_issue_22() {
    for args in [
        &["eps", "--g", "0.01", "--format", "json"][..],
        &["map", "--max", "0.02", "--n", "4", "--format", "json"][..],
        &[
            "collision",
            "--g",
            "0.01",
            "--points",
            "4",
            "--format",
            "json",
        ][..],
    ] {
        let text = ok(args);
        assert!(text.lines().count() > 5, "{args:?}: {text}");
        assert!(
            text.lines().nth(1).unwrap().starts_with("  "),
            "{args:?}: {text}"
        );
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert!(v.is_object() || v.is_array());
    }
    let map = ok(&["map", "--max", "0.02", "--n", "4", "--format", "json"]);
    assert!(map.contains("\n  \"g\": [0.0, "), "{map}");
    let list = ok(&["compare", "--list", "--format", "table"]);
    for line in list.lines() {
        assert!(
            line.chars().count() <= 80,
            "{} columns: {line}",
            line.chars().count()
        );
    }
    for m in ["hertzsch2002", "brilliantov2007", "bridges1984"] {
        assert!(list.contains(m), "{m} missing\n{list}");
    }
}

/// Issue 26: `rime curve`, `map` and `compare` use every core, and their output (stdout and
/// stderr) is the output of the same command pinned to one core (`taskset -c 0`, where the
/// command runs sequentially), byte for byte.
#[test]
fn subcommands_on_every_core_print_what_one_core_prints_issue_26() {
    let runs: [&[&str]; 4] = [
        &[
            "curve",
            "--from",
            "1e-6",
            "--to",
            "1",
            "--points",
            "400",
            "--preset",
            "ice-frost",
            "--format",
            "csv",
        ],
        &[
            "curve",
            "--from",
            "1e-5",
            "--to",
            "1",
            "--points",
            "150",
            "--preset",
            "ice-sticky",
            "--accuracy",
            "integrated",
            "--format",
            "json",
        ],
        &[
            "map",
            "--max",
            "0.05",
            "--n",
            "120",
            "--preset",
            "ice-frost",
            "--format",
            "json",
        ],
        &[
            "compare",
            "--g",
            "1e-4,1e-3,0.01,0.1",
            "--preset",
            "ice-sticky",
            "--format",
            "json",
        ],
    ];
    let run = |pinned: bool, args: &[&str]| {
        let mut c = if pinned {
            let mut c = Command::new("taskset");
            c.args(["-c", "0"]).arg(rime_binary());
            c
        } else {
            Command::new(rime_binary())
        };
        let out = c.args(args).output().expect("taskset (util-linux) runs");
        assert!(out.status.success(), "{args:?} pinned={pinned}: {out:?}");
        (out.stdout, out.stderr)
    };
    for args in runs {
        let every = run(false, args);
        let one = run(true, args);
        assert!(every.0.len() > 1000, "{args:?}");
        assert!(every == one, "{args:?}: the outputs differ");
    }
}
