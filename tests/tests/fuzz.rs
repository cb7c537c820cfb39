//! Fuzzing without cargo-fuzz (issue 7): proptest-driven hostile input for the library paths the
//! CLI, the explorer and the web page share — scene JSON (`serde_json`, `validate`, `Contact::new`,
//! evaluations) and `Scene::set`. Bounded case counts so that it runs in every `make test`; the
//! number of executions is printed (`cargo test -- --nocapture`).

use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use rime_core::params::PARAMETERS;
use rime_core::{Accuracy, Contact, Scene};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Duration;

fn runner(cases: u32) -> TestRunner {
    TestRunner::new(Config {
        cases,
        failure_persistence: None,
        // Every case is interesting; shrinking hostile text is cheap.
        max_shrink_iters: 2000,
        ..Config::default()
    })
}

/// Runs `f` on a worker thread; a panic or more than `budget` is a failure (no hang, no panic).
/// The budget is a hang guard, not a speed check: it must be at least 10× the slowest case on an
/// idle machine (each call site says what that is).
fn guarded<T: Send + 'static>(
    budget: Duration,
    what: String,
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, TestCaseError> {
    let (tx, rx) = mpsc::channel();
    let timings = std::env::var_os("RIME_TIMINGS").is_some();
    let shown: String = what.chars().take(60).collect();
    std::thread::spawn(move || {
        let t = std::time::Instant::now();
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
        if timings && t.elapsed() > Duration::from_millis(20) {
            eprintln!("TIMING fuzz {shown:?}: {:?}", t.elapsed());
        }
        let _ = tx.send(r);
    });
    match rx.recv_timeout(budget) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(_)) => Err(TestCaseError::fail(format!("panicked on {what}"))),
        Err(_) => Err(TestCaseError::fail(format!(
            "no answer within {budget:?} on {what}"
        ))),
    }
}

/// Numbers and non-numbers that replace a number of a valid scene.
const HOSTILE_VALUES: &[&str] = &[
    "1e308",
    "-1e308",
    "1e309",
    "-1e999",
    "1e-400",
    "-0",
    "0",
    "-1",
    "NaN",
    "\"NaN\"",
    "Infinity",
    "\"inf\"",
    "\"1e-3\"",
    "null",
    "true",
    "[]",
    "{}",
    "[1,2]",
    "{\"time\":1}",
    "\"\"",
    "4.9e-324",
    "1.7976931348623157e308",
    "18446744073709551616",
    "0x10",
    "1e",
    ".5",
    "5.",
    "\"1 µm\"",
    "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[]]]]]]]",
];

#[derive(Debug, Clone)]
enum Mutation {
    Delete(usize),
    Duplicate(usize),
    Insert(usize, char),
    ReplaceNumber(usize, usize),
    UnknownField(usize),
    Truncate(usize),
    Nest(usize, usize),
    SwapKey(usize, usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        any::<usize>().prop_map(Mutation::Delete),
        any::<usize>().prop_map(Mutation::Duplicate),
        (
            any::<usize>(),
            prop_oneof![
                Just('{'),
                Just('}'),
                Just('['),
                Just(']'),
                Just('"'),
                Just(','),
                Just(':'),
                Just('-'),
                Just('e'),
                Just('\\'),
                Just('\u{0}'),
                Just('µ'),
                any::<char>()
            ]
        )
            .prop_map(|(i, c)| Mutation::Insert(i, c)),
        (any::<usize>(), 0..HOSTILE_VALUES.len()).prop_map(|(i, v)| Mutation::ReplaceNumber(i, v)),
        any::<usize>().prop_map(Mutation::UnknownField),
        any::<usize>().prop_map(Mutation::Truncate),
        (any::<usize>(), 1..300usize).prop_map(|(i, d)| Mutation::Nest(i, d)),
        (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::SwapKey(a, b)),
    ]
}

fn boundaries(s: &str) -> Vec<usize> {
    s.char_indices().map(|(i, _)| i).chain([s.len()]).collect()
}

/// Byte ranges of the numbers in `s`.
fn numbers(s: &str) -> Vec<(usize, usize)> {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_digit() || (b[i] == b'-' && i + 1 < b.len() && b[i + 1].is_ascii_digit()) {
            let start = i;
            i += 1;
            while i < b.len() && (b[i].is_ascii_digit() || b"+-.eE".contains(&b[i])) {
                i += 1;
            }
            out.push((start, i));
        } else {
            i += 1;
        }
    }
    out
}

fn keys(s: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in s.char_indices() {
        if c == '"' {
            match start.take() {
                None => start = Some(i),
                Some(a) if s[i + 1..].trim_start().starts_with(':') => out.push((a, i + 1)),
                Some(_) => {}
            }
        }
    }
    out
}

fn apply(mut s: String, m: &Mutation) -> String {
    let bounds = boundaries(&s);
    let at = |i: usize| bounds[i % bounds.len()];
    match *m {
        Mutation::Delete(i) => {
            let a = at(i);
            if let Some(c) = s[a..].chars().next() {
                s.replace_range(a..a + c.len_utf8(), "");
            }
        }
        Mutation::Duplicate(i) => {
            let a = at(i);
            if let Some(c) = s[a..].chars().next() {
                s.insert(a, c);
            }
        }
        Mutation::Insert(i, c) => s.insert(at(i), c),
        Mutation::ReplaceNumber(i, v) => {
            let n = numbers(&s);
            if !n.is_empty() {
                let (a, b) = n[i % n.len()];
                s.replace_range(a..b, HOSTILE_VALUES[v]);
            }
        }
        Mutation::UnknownField(i) => {
            let opens: Vec<usize> = s.match_indices('{').map(|(k, _)| k + 1).collect();
            if !opens.is_empty() {
                s.insert_str(opens[i % opens.len()], "\"colour\": 1, ");
            }
        }
        Mutation::Truncate(i) => s.truncate(at(i)),
        Mutation::Nest(i, d) => {
            let n = numbers(&s);
            if !n.is_empty() {
                let (a, b) = n[i % n.len()];
                let v = s[a..b].to_string();
                s.replace_range(a..b, &format!("{}{v}{}", "[".repeat(d), "]".repeat(d)));
            }
        }
        Mutation::SwapKey(i, j) => {
            let k = keys(&s);
            if k.len() >= 2 {
                let (a, b) = k[i % k.len()];
                let other = {
                    let (c, d) = k[j % k.len()];
                    s[c..d].to_string()
                };
                s.replace_range(a..b, &other);
            }
        }
    }
    s
}

/// Everything a front end does with a scene text; returns whether it got as far as evaluating.
fn evaluate(text: &str) -> bool {
    let Ok(scene) = serde_json::from_str::<Scene>(text) else {
        return false;
    };
    if let Err(e) = scene.validate() {
        assert!(!e.to_string().is_empty());
        return false;
    }
    let contact = Contact::new(&scene).unwrap();
    for g in [1e-9, 1e-3, 1.0] {
        for acc in [Accuracy::Fast, Accuracy::Balanced] {
            // Errors are allowed (and must name something); NaN or out-of-range values are not.
            if let Ok(n) = contact.normal(g, acc) {
                assert!((0.0..=1.0).contains(&n.eps), "{text}: {n:?}");
            }
            if let Ok(e) = contact.eps_n(g, acc) {
                assert!((0.0..=1.0).contains(&e), "{text}: {e}");
            }
        }
        if contact.friction.is_some()
            && let Ok(t) = contact.tangential(g, 0.5 * g, Accuracy::Fast)
        {
            assert!((-1.0..=1.0).contains(&t.eps_t), "{text}: {t:?}");
        }
    }
    true
}

#[test]
fn fuzz_scene_json_parse_validate_evaluate() {
    static RUNS: AtomicUsize = AtomicUsize::new(0);
    static EVALUATED: AtomicUsize = AtomicUsize::new(0);
    let seeds = prop_oneof![
        3 => crate::properties::scene().prop_map(|s| serde_json::to_string_pretty(&s).unwrap()),
        1 => ".{0,200}",
        1 => prop::collection::vec(any::<u8>(), 0..200)
            .prop_map(|b| String::from_utf8_lossy(&b).to_string()),
    ];
    let strategy = (seeds, prop::collection::vec(mutation(), 0..6));
    runner(2000)
        .run(&strategy, |(seed, mutations)| {
            let text = mutations.iter().fold(seed, apply);
            RUNS.fetch_add(1, Ordering::Relaxed);
            let shown = text.clone();
            // The slowest case (a literal layer with zero-overlap ends, A = 7.6 ms on µm grains) took
            // 2.6–3.5 s with the machine's 2 cores loaded 3.5 times over, and every other case under
            // 20 ms; the guard of 60 s is over 15× that. `RIME_TIMINGS=1` prints cases over 20 ms.
            let evaluated = guarded(Duration::from_secs(60), shown, move || evaluate(&text))?;
            if evaluated {
                EVALUATED.fetch_add(1, Ordering::Relaxed);
            }
            Ok(())
        })
        .unwrap();
    // Deep nesting alone (serde_json's recursion limit must answer, not the stack).
    for depth in [127, 128, 129, 10_000, 1_000_000] {
        let text = format!("{}{}", "[".repeat(depth), "]".repeat(depth));
        assert!(serde_json::from_str::<Scene>(&text).is_err());
        let text = format!("{{\"grains\": {}", "{\"a\":".repeat(depth));
        assert!(serde_json::from_str::<Scene>(&text).is_err());
        RUNS.fetch_add(2, Ordering::Relaxed);
    }
    let (runs, ok) = (
        RUNS.load(Ordering::Relaxed),
        EVALUATED.load(Ordering::Relaxed),
    );
    eprintln!("fuzz scene JSON: {runs} executions, {ok} reached evaluation, no panic or hang");
    assert!(
        ok > 100,
        "the mutations should leave some scenes valid: {ok}"
    );
}

fn text() -> impl Strategy<Value = String> {
    prop_oneof![
        (-1e3..1e3f64).prop_map(|v| v.to_string()),
        any::<f64>().prop_map(|v| format!("{v:e}")),
        (
            any::<f64>(),
            prop_oneof![
                Just(""),
                Just(" m"),
                Just("um"),
                Just(" µm"),
                Just("μm"),
                Just(" kPa s"),
                Just("Pa·s"),
                Just(" J/m^2"),
                Just("J/m²"),
                Just(" g/cm3"),
                Just("kg/m³"),
                Just(" s"),
                Just("ms"),
                Just(" Pa"),
                Just("GPa"),
                Just(" m/s"),
                Just("   "),
                Just("e"),
                Just("e+"),
                Just(" 1"),
                Just("µµµ"),
                Just("\u{0}")
            ]
        )
            .prop_map(|(v, u)| format!("{v}{u}")),
        prop_oneof![
            Just("on"),
            Just("off"),
            Just("null"),
            Just("true"),
            Just("0"),
            Just("1"),
            Just("offset"),
            Just("literal"),
            Just("\"walton\""),
            Just("paper"),
            Just("zero_overlap"),
            Just("brilliantov"),
            Just("as_printed"),
            Just("consistent"),
            Just("nan"),
            Just("NaN"),
            Just("inf"),
            Just("-inf"),
            Just("1e309"),
            Just("-0"),
            Just("1e-400"),
            Just(""),
            Just(" "),
            Just("1e"),
            Just("--1"),
            Just("1..2"),
            Just("0x10"),
            Just("1_000")
        ]
        .prop_map(str::to_string),
        ".{0,40}",
    ]
}

fn path() -> impl Strategy<Value = String> {
    let known: Vec<String> = PARAMETERS.iter().map(|p| p.path.to_string()).collect();
    prop_oneof![
        4 => proptest::sample::select(known.clone()),
        1 => (proptest::sample::select(known), ".{0,3}").prop_map(|(p, x)| format!("{p}{x}")),
        1 => "[a-z_.]{0,30}",
        1 => ".{0,20}",
    ]
}

#[test]
fn fuzz_scene_set_never_panics_and_keeps_the_scene_on_error() {
    static RUNS: AtomicUsize = AtomicUsize::new(0);
    static ACCEPTED: AtomicUsize = AtomicUsize::new(0);
    let strategy = (
        crate::properties::scene(),
        prop::collection::vec((path(), text()), 1..4),
    );
    runner(5000)
        .run(&strategy, |(scene, sets)| {
            let mut s = scene;
            for (p, t) in sets {
                RUNS.fetch_add(1, Ordering::Relaxed);
                let before = s;
                let (p2, t2) = (p.clone(), t.clone());
                let (after, result) =
                    // No `set` took 20 ms even with the machine loaded 3.5 times over: 30 s
                    // is over 1000× that.
                    guarded(Duration::from_secs(30), format!("{p}={t}"), move || {
                        let mut s = before;
                        let r = s.set(&p2, &t2);
                        (s, r)
                    })?;
                match result {
                    Ok(()) => {
                        ACCEPTED.fetch_add(1, Ordering::Relaxed);
                        after
                            .validate()
                            .map_err(|e| TestCaseError::fail(format!("{p}={t}: {e}")))?;
                        // get() answers for every known path after a successful set.
                        prop_assert!(after.get(&p).is_ok(), "{p}");
                        s = after;
                    }
                    Err(e) => {
                        prop_assert_eq!(after, before, "{}={} changed the scene on error", p, t);
                        prop_assert!(!e.to_string().is_empty());
                    }
                }
            }
            Ok(())
        })
        .unwrap();
    let (runs, ok) = (
        RUNS.load(Ordering::Relaxed),
        ACCEPTED.load(Ordering::Relaxed),
    );
    eprintln!("fuzz Scene::set: {runs} executions, {ok} accepted, no panic or hang");
}
