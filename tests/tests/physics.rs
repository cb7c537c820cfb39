//! Closed forms, limits, conservation laws and invariances of the normal models.

use rime_core::normal::viscoelastic::dimensionless;
use rime_core::{
    Accuracy, Contact, ContactEnd, Damping, Layer, LayerReading, Preset, Scene, Status,
};
use rime_tests::rel;

fn scene_with(a: f64) -> Scene {
    let mut s = Scene::default();
    s.bulk.damping = Damping::Time(a);
    s
}

#[test]
fn eps_depends_on_delta_alone() {
    // Two very different scenes and speeds with the same δ = A α^(2/5) g^(1/5) give the same ε_N.
    let a = Contact::new(&scene_with(1e-4)).unwrap();
    let g_a = 0.01;
    let delta = a.delta(g_a);
    let mut other = scene_with(1e-4);
    other.grains.radius_1 = 1e-3;
    other.grains.radius_2 = 5e-2;
    other.bulk.youngs_modulus = 3e9;
    other.grains.density = 2500.0;
    let c = Contact::new(&other).unwrap();
    // Choose g so that δ matches: g = (δ / (A α^(2/5)))^5.
    let g_b = (delta / (1e-4 * c.alpha.powf(0.4))).powi(5);
    assert!(rel(c.delta(g_b), delta) < 1e-12);
    for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
        let mut sa = scene_with(1e-4);
        sa.contact_end = end;
        let mut sb = other;
        sb.contact_end = end;
        let ea = Contact::new(&sa)
            .unwrap()
            .normal(g_a, Accuracy::Precise)
            .unwrap();
        let eb = Contact::new(&sb)
            .unwrap()
            .normal(g_b, Accuracy::Precise)
            .unwrap();
        assert!(
            rel(ea.eps, eb.eps) < 1e-11,
            "{end:?}: {} vs {}",
            ea.eps,
            eb.eps
        );
        // Durations scale with τ = ξ*/g, compressions with ξ*.
        let ta = ea.t_c / Contact::new(&sa).unwrap().time_scale(g_a);
        let tb = eb.t_c / Contact::new(&sb).unwrap().time_scale(g_b);
        assert!(rel(ta, tb) < 1e-9, "{ta} vs {tb}");
    }
}

#[test]
fn no_damping_conserves_energy_at_every_speed() {
    let c = Contact::new(&scene_with(0.0)).unwrap();
    let mut g = 1e-12;
    while g <= 1e2 {
        for acc in [Accuracy::Precise, Accuracy::Balanced] {
            let n = c.normal(g, acc).unwrap();
            assert!(
                (n.eps - 1.0).abs() <= acc.error_bound(),
                "g = {g}: {}",
                n.eps
            );
            assert_eq!(n.status, Status::Rebound);
            // Hertz: t_c = 3.21806545971904 τ, ξ_max = (5/4)^(2/5) ξ*, within the level's bound.
            let bound = acc.error_bound().max(1e-9);
            assert!(rel(n.t_c, 3.21806545971904 * c.time_scale(g)) < bound);
            assert!(rel(n.xi_max, 1.25f64.powf(0.4) * c.length_scale(g)) < bound);
        }
        g *= 10.0;
    }
}

#[test]
fn precise_agrees_with_a_tighter_tolerance() {
    // Second tolerance for everything without a closed form: 1e-10 relative wherever ε > 1e-6.
    for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
        let mut delta = 1e-6;
        while delta < 2e4 {
            let p = dimensionless(delta, end, 1e-12).unwrap();
            let t = dimensionless(delta, end, 1e-14).unwrap();
            if t.eps > 1e-6 {
                assert!(
                    rel(p.eps, t.eps) < 1e-10,
                    "{end:?} δ = {delta}: {} vs {}",
                    p.eps,
                    t.eps
                );
            }
            delta *= 3.0;
        }
    }
}

#[test]
fn offset_layer_threshold_is_exactly_eq_10() {
    let scene = Preset::IceFrost.scene();
    let c = Contact::new(&scene).unwrap();
    let layer = c.layer.unwrap();
    // Independent evaluation of Eq. (10): √R_eff η* D^(3/2) / m_eff.
    let r_eff: f64 = 0.02 * 0.02 / 0.04;
    let m = 900.0 * 4.0 / 3.0 * std::f64::consts::PI * 0.02f64.powi(3);
    let g_s = r_eff.sqrt() * 1000.0 * 1e-6f64.powf(1.5) / (m / 2.0);
    assert!(rel(layer.critical_velocity, g_s) < 1e-14);
    let below = c.normal(g_s * (1.0 - 1e-12), Accuracy::Precise).unwrap();
    assert_eq!(below.status, Status::StuckInLayer);
    assert_eq!(below.eps, 0.0);
    let at = c
        .normal(layer.critical_velocity, Accuracy::Precise)
        .unwrap();
    assert_eq!(at.status, Status::StuckInLayer);
    // Just above: ε_N → 0 continuously, like (g − g_s)/g.
    let above = c.normal(g_s * (1.0 + 1e-9), Accuracy::Precise).unwrap();
    assert_eq!(above.status, Status::Overdamped, "{above:?}");
    assert!(above.eps > 0.0 && above.eps < 2e-9, "{}", above.eps);
    let above = c.normal(g_s * 1.1, Accuracy::Precise).unwrap();
    assert_eq!(above.status, Status::Rebound);
}

#[test]
fn offset_layer_equals_clean_model_at_the_bulk_entry_speed() {
    // Eq. (9): the bulk is reached at g − g_s; ε = ε_ve(g − g_s)(g − g_s)/g.
    let clean = Contact::new(&Scene::default()).unwrap();
    let frost = Contact::new(&Preset::IceFrost.scene()).unwrap();
    let g_s = frost.layer.unwrap().critical_velocity;
    for g in [1e-5, 1e-4, 1e-2, 1.0] {
        let e = frost.normal(g, Accuracy::Precise).unwrap().eps;
        let ve = clean.normal(g - g_s, Accuracy::Precise).unwrap().eps;
        assert!(rel(e, ve * (g - g_s) / g) < 1e-13, "g = {g}");
    }
}

#[test]
fn zero_thickness_or_viscosity_layers_are_the_clean_model() {
    let clean = Contact::new(&Scene::default()).unwrap();
    for layer in [
        Layer {
            thickness: 0.0,
            viscosity: 1000.0,
            reading: LayerReading::Offset,
        },
        Layer {
            thickness: 1e-6,
            viscosity: 0.0,
            reading: LayerReading::Offset,
        },
        Layer {
            thickness: 0.0,
            viscosity: 1000.0,
            reading: LayerReading::Literal,
        },
    ] {
        let s = Scene {
            layer: Some(layer),
            ..Scene::default()
        };
        let c = Contact::new(&s).unwrap();
        for g in [1e-9, 1e-3, 1.0] {
            let a = c.normal(g, Accuracy::Precise).unwrap().eps;
            let b = clean.normal(g, Accuracy::Precise).unwrap().eps;
            assert!(rel(a, b) < 1e-12, "{layer:?} g = {g}: {a} vs {b}");
        }
    }
}

#[test]
fn paper_viscosities_are_promptly_overdamped() {
    let c = Contact::new(&Preset::IcePaperViscosities.scene()).unwrap();
    assert!(
        rel(c.damping_time, 404.4439051855896) < 1e-12,
        "{}",
        c.damping_time
    );
    // δ = A α^(2/5) g^(1/5) ≥ 4.8e5 for g ≥ 1e-6 m/s, where ε ≈ (2/3) δ^(-5/3) < 1e-9.
    for g in [1e-6, 1e-4, 1e-2, 1.0, 1e2] {
        for acc in [Accuracy::Precise, Accuracy::Balanced, Accuracy::Fast] {
            let n = c.normal(g, acc).unwrap();
            assert_eq!(n.status, Status::Overdamped, "g = {g}");
            assert!(n.eps < 1e-9);
        }
    }
    // Even at 1e-12 m/s (δ = 3.0e4) the rebound is tiny: ε ≈ (2/3) δ^(-5/3) = 2.3e-8.
    let slowest = c.normal(1e-12, Accuracy::Precise).unwrap();
    let delta = c.delta(1e-12);
    assert!(
        rel(slowest.eps, 2.0 / 3.0 * delta.powf(-5.0 / 3.0)) < 1e-3,
        "{}",
        slowest.eps
    );
}

#[test]
fn every_preset_and_option_is_finite_from_1e_12_to_1e2() {
    for preset in Preset::ALL {
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            for reading in [LayerReading::Offset, LayerReading::Literal] {
                let mut s = preset.scene();
                s.contact_end = end;
                if let Some(l) = s.layer.as_mut() {
                    l.reading = reading;
                }
                let c = Contact::new(&s).unwrap();
                let mut g = 1e-12;
                while g <= 1e2 {
                    let n = c.normal(g, Accuracy::Balanced).unwrap();
                    assert!(
                        n.eps.is_finite() && (0.0..=1.0 + 1e-9).contains(&n.eps),
                        "{preset:?} g={g}"
                    );
                    assert!(n.xi_max.is_finite() && n.xi_max >= 0.0);
                    assert!(!n.t_c.is_nan());
                    g *= 10f64.sqrt();
                }
            }
        }
    }
}

#[test]
fn paper_figures_show_what_their_captions_say() {
    use rime_core::figure::paper;
    let fig2 = paper::fig2(Accuracy::Fast).unwrap();
    assert_eq!(fig2.len(), 2);
    // Calibrated A: every layer curve is 0 at and below its marker (Eq. (10)) and positive above.
    for (series, marker) in fig2[0].series.iter().zip(&fig2[0].markers) {
        for &(g, e) in &series.points {
            if g <= marker.x {
                assert_eq!(e, 0.0, "{} at {g}", series.name);
            } else if g > marker.x * 1.01 {
                assert!(e > 0.0, "{} at {g}", series.name);
            }
        }
    }
    // The paper's viscosities: overdamped everywhere above 1e-6 m/s.
    for s in &fig2[1].series[..5] {
        for &(g, e) in &s.points {
            if g >= 1e-6 {
                assert!(e < 1e-9, "{} at {g}: {e}", s.name);
            }
        }
    }
    let fig4 = paper::fig4(Accuracy::Fast, 40).unwrap();
    let hard = &fig4[0];
    let classes = &hard.map.as_ref().unwrap().classes;
    assert!(!classes.contains(&rime_core::StickClass::Aggregation));
    // The zoomed layer map contains the aggregation region the paper describes.
    let zoom = fig4.iter().find(|f| f.name == "fig4-layer-zoom").unwrap();
    assert!(
        zoom.map
            .as_ref()
            .unwrap()
            .classes
            .contains(&rime_core::StickClass::Aggregation)
    );
    for f in fig2.iter().chain(&fig4) {
        let svg = rime_core::figure::render_svg(f, 800, 500).unwrap();
        assert!(
            svg.starts_with("<svg") && svg.contains("</svg>"),
            "{}",
            f.name
        );
    }
}

/// `(x, y, content)` of every `<text>` element of an SVG.
fn svg_texts(svg: &str) -> Vec<(f64, f64, String)> {
    let mut out = Vec::new();
    for part in svg.split("<text").skip(1) {
        let attr = |name: &str| -> f64 {
            let key = format!(" {name}=\"");
            let start = part.find(&key).unwrap() + key.len();
            part[start..].split('"').next().unwrap().parse().unwrap()
        };
        let content = part
            .split('>')
            .nth(1)
            .unwrap_or("")
            .split('<')
            .next()
            .unwrap_or("");
        out.push((attr("x"), attr("y"), content.trim().to_string()));
    }
    out
}

/// `[x0, y0, x1, y1]` of every `<rect>` filled with `fill`.
fn svg_rects(svg: &str, fill: &str) -> Vec<[f64; 4]> {
    let mut out = Vec::new();
    for part in svg.split("<rect").skip(1) {
        let part = part.split('>').next().unwrap();
        if !part.contains(&format!("fill=\"{fill}\"")) {
            continue;
        }
        let attr = |name: &str| -> f64 {
            let key = format!(" {name}=\"");
            let start = part.find(&key).unwrap() + key.len();
            part[start..].split('"').next().unwrap().parse().unwrap()
        };
        let (x, y) = (attr("x"), attr("y"));
        out.push([x, y, x + attr("width"), y + attr("height")]);
    }
    out
}

/// The largest x of every polyline point of an SVG.
fn svg_polyline_right(svg: &str) -> f64 {
    let mut right = f64::NEG_INFINITY;
    for part in svg.split("<polyline").skip(1) {
        let points = part
            .split("points=\"")
            .nth(1)
            .unwrap()
            .split('"')
            .next()
            .unwrap();
        for p in points.split_whitespace() {
            right = right.max(p.split(',').next().unwrap().parse::<f64>().unwrap());
        }
    }
    right
}

/// Issue 22 (`rime figures`): legends never cover data (they sit in their own column), the Bridges
/// law is drawn only over its measured speeds (0.15–20 mm/s, Bridges et al. 1984), the Fig. 4
/// caption names the colour the sliding gap is drawn in, and the gap is labelled for people and
/// flagged as the printed law's artifact.
#[test]
fn figures_legends_beside_the_data_bridges_over_its_speeds_gap_labelled_issue_22() {
    use rime_core::StickClass;
    use rime_core::explorer::palette;
    use rime_core::figure::paper;
    let mut figures = paper::fig2(Accuracy::Fast).unwrap();
    figures.extend(paper::fig3(Accuracy::Fast).unwrap());
    let fig4 = paper::fig4(Accuracy::Fast, 40).unwrap();
    for f in &figures {
        let bridges = f
            .series
            .iter()
            .find(|s| s.name.starts_with("Bridges"))
            .expect("Bridges drawn");
        for &(g, _) in &bridges.points {
            assert!(
                (1.5e-4..=2e-2).contains(&g),
                "{}: Bridges at {g} m/s",
                f.name
            );
        }
        // Every legend label starts right of every point of every curve.
        let svg = rime_core::figure::render_svg(f, 1000, 680).unwrap();
        let right = svg_polyline_right(&svg);
        let labels: Vec<String> = f.series.iter().map(|s| s.name.clone()).collect();
        let mut found = 0;
        for (x, _, text) in svg_texts(&svg) {
            let first = text.split_whitespace().next().unwrap_or("");
            if !text.is_empty()
                && labels
                    .iter()
                    .any(|l| l.starts_with(&text) || (l.starts_with(first) && first.len() > 3))
            {
                found += 1;
                assert!(
                    x > right,
                    "{}: legend '{text}' at x = {x} over a curve (right end {right})",
                    f.name
                );
            }
        }
        assert!(
            found >= labels.len(),
            "{}: {found} legend labels found",
            f.name
        );
    }
    let hard = &fig4[0];
    let gap = palette::class(StickClass::SlidingGap);
    assert_eq!(gap, palette::GREY_LIGHT);
    assert!(
        hard.caption.contains("light grey wedge"),
        "{}",
        hard.caption
    );
    assert!(!hard.caption.contains("orange"), "{}", hard.caption);
    for f in &fig4 {
        let svg = rime_core::figure::render_svg(f, 1000, 680).unwrap();
        assert!(
            !svg.contains("sliding_gap"),
            "{}: snake_case in a figure",
            f.name
        );
        let map = f.map.as_ref().unwrap();
        let mut cells = Vec::new();
        for c in StickClass::ALL
            .into_iter()
            .filter(|c| map.classes.contains(c))
        {
            let (r, g, b) = rime_core::figure::class_color(c);
            cells.extend(svg_rects(&svg, &format!("#{r:02X}{g:02X}{b:02X}")));
        }
        let texts = svg_texts(&svg);
        for c in StickClass::ALL
            .into_iter()
            .filter(|c| map.classes.contains(c))
        {
            let first = c.label().split(' ').next().unwrap();
            let (x, y, _) = texts
                .iter()
                .find(|(_, _, t)| c.label().starts_with(t.as_str()) && t.starts_with(first))
                .unwrap_or_else(|| panic!("{}: no legend for {}", f.name, c.label()));
            let width = 7.0 * c.label().chars().count().min(45) as f64;
            for r in &cells {
                let overlaps = r[0] < x + width && r[2] > *x && r[1] < y + 13.0 && r[3] > *y;
                assert!(
                    !overlaps,
                    "{}: legend '{}' covers the map cell {r:?}",
                    f.name,
                    c.label()
                );
            }
        }
        if map.classes.contains(&StickClass::SlidingGap) {
            assert!(
                svg.contains("sliding gap (artifact of the printed Eq."),
                "{}",
                f.name
            );
        }
    }
}
