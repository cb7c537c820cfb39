//! Issue 11: one explorer model behind every surface. The frame the terminal and the web page draw
//! (`rime_core::explorer::frame::compute`) gives bit-identical numbers to the command line for the
//! same scene, speeds and level.

use crate::bin::rime_json;
use rime_core::explorer::frame::{Frame, Request, compute};
use rime_core::{Accuracy, Preset};

/// The core's frame of a preset at `level` with `points` curve speeds and an `map_n`² stick map.
fn frame(preset: &str, level: Accuracy, points: usize, map_n: usize) -> Frame {
    let scene = Preset::ALL
        .iter()
        .find(|p| p.name() == preset)
        .unwrap()
        .scene();
    let mut req = Request::new(scene, level);
    req.points = points;
    req.map_n = map_n;
    compute(&req, &|| false).unwrap()
}

#[test]
fn frame_and_command_line_give_bit_identical_numbers_issue_11() {
    for (preset, level) in [
        ("ice-frost", Accuracy::Fast),
        ("ice-sticky", Accuracy::Precise),
        ("ice", Accuracy::Balanced),
    ] {
        let f = frame(preset, level, 25, 9);
        assert!(f.errors.is_empty(), "{:?}", f.errors);
        let list: Vec<String> = f.g.iter().map(|g| format!("{g:?}")).collect();
        let level_name = level.name();
        let cli = rime_json(&[
            "eps",
            "--preset",
            preset,
            "--accuracy",
            level_name,
            "--g",
            &list.join(","),
        ]);
        let curve = f.curve.as_ref().unwrap();
        for (row, point) in cli.as_array().unwrap().iter().zip(&curve.points) {
            let n = point.unwrap();
            assert_eq!(
                row["eps_n"].as_f64().unwrap().to_bits(),
                n.eps.to_bits(),
                "{preset}: {row}"
            );
            assert_eq!(row["status"], n.status.name());
        }
        // The stick map: same range, same classes, same ε_T.
        let part = f.map.as_ref().unwrap();
        let map = part.map.as_ref().unwrap();
        let max = format!("{:?}", part.max);
        let cli = rime_json(&[
            "map",
            "--preset",
            preset,
            "--accuracy",
            level_name,
            "--max",
            &max,
            "--n",
            "9",
        ]);
        let classes = cli["class"].as_array().unwrap();
        for i in 0..9 {
            for j in 0..9 {
                assert_eq!(
                    classes[i][j],
                    map.class[i * 9 + j].name(),
                    "{preset} ({i}, {j})"
                );
                let et = cli["eps_t"][i][j].as_f64().unwrap();
                assert_eq!(
                    et.to_bits(),
                    map.eps_t[i * 9 + j].to_bits(),
                    "{preset} ({i}, {j})"
                );
            }
        }
    }
}

/// Issue 11: the records the explorer exports (terminal `x`, page downloads) are byte for byte the
/// CSV `rime curve` and `rime map` print for the same scene, speeds, grid and level. The frame's
/// speeds are chosen by the core (range policy and log spacing) and read back from the records, so
/// the test also checks that the printed speeds round-trip.
#[test]
fn explorer_records_equal_the_command_lines_csv_issue_11() {
    use rime_core::explorer::records;
    for (preset, level) in [
        ("ice-frost", Accuracy::Fast),
        ("ice-sticky", Accuracy::Precise),
    ] {
        let f = frame(preset, level, 31, 7);
        let curve = records::frame_curve_csv(&f);
        let lines: Vec<&str> = curve.lines().collect();
        let first = lines[1].split(',').next().unwrap();
        let last = lines[lines.len() - 1].split(',').next().unwrap();
        let points = (lines.len() - 1).to_string();
        let (code, out, err) = crate::bin::rime(&[
            "curve",
            "--preset",
            preset,
            "--accuracy",
            level.name(),
            "--from",
            first,
            "--to",
            last,
            "--points",
            &points,
            "--format",
            "csv",
        ]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(
            out, curve,
            "{preset}: rime curve and the explorer's records differ"
        );

        let map = records::frame_map_csv(&f).expect("the presets have friction");
        let max = records::cell(f.map.as_ref().unwrap().max);
        let (code, out, err) = crate::bin::rime(&[
            "map",
            "--preset",
            preset,
            "--accuracy",
            level.name(),
            "--max",
            &max,
            "--n",
            "7",
            "--format",
            "csv",
        ]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(
            out, map,
            "{preset}: rime map and the explorer's records differ"
        );
    }
}

/// Issue 22: one number rule. The family around A = 1e-4 s is 1e-5, 3e-5, 3e-4, 1e-3 s exactly (3 ×
/// 1e-4 is 3.0000000000000003e-4 in doubles): the legend reads `A = 300 µs`, the CSV header
/// `A = 3e-4 s`, and no float noise reaches either.
#[test]
fn family_values_legends_and_csv_headers_carry_no_float_noise_issue_22() {
    let f = frame("ice", Accuracy::Fast, 20, 4);
    let values: Vec<f64> = f.family.iter().map(|m| m.value).collect();
    assert_eq!(values, vec![1e-5, 3e-5, 3e-4, 1e-3]);
    let fig = rime_core::explorer::figures::eps_figure(&f, &Default::default(), "test");
    let names: Vec<&str> = fig.series.iter().map(|s| s.name.as_str()).collect();
    // Text people read has an SI prefix and four digits: 3e-4 s reads 300 µs.
    assert!(
        names.iter().any(|n| n.starts_with("A = 300 µs")),
        "{names:?}"
    );
    let csv = rime_core::explorer::records::family_csv(&f);
    let header = csv.lines().find(|l| l.starts_with("g_n")).unwrap();
    // The shortest form by the one number rule (plain from 1e-4, issue 21).
    assert!(header.contains("A = 0.0003 s"), "{header}");
    for text in names.iter().copied().chain([header]) {
        assert!(!text.contains("0000000"), "float noise in '{text}'");
    }
}
