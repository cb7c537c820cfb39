//! Issue 11: one explorer model behind every surface. The frame the terminal and the web page draw
//! (`rime_core::explorer::frame::compute`) gives bit-identical numbers to the command line for the
//! same scene, speeds and level.

use rime_core::explorer::frame::{Request, compute};
use rime_core::{Accuracy, Preset};
use rime_tests::rime_json;

#[test]
fn frame_and_command_line_give_bit_identical_numbers_issue_11() {
    for (preset, level) in [
        ("ice-frost", Accuracy::Fast),
        ("ice-sticky", Accuracy::Precise),
        ("ice", Accuracy::Balanced),
    ] {
        let scene = Preset::ALL
            .iter()
            .find(|p| p.name() == preset)
            .unwrap()
            .scene();
        let mut req = Request::new(scene, level);
        req.points = 25;
        req.map_n = 9;
        let f = compute(&req, &|| false).unwrap();
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
