//! `model envelope` against the path a user takes by hand: at grid points chosen by a seeded
//! generator, the envelope's numbers equal those of `import jsbsim ... --load-factor N` followed
//! by the analysis of the first departure at the elevator increment (`analyze_first_departure`:
//! the certified route with its exact fallback) at that flight condition, with the roll rates
//! of `analyze` (the CLI's table) within their certified brackets, and the catalogue table's
//! row agrees with the
//! envelope's point at the same condition. Bad ranges are refused before any work, and `--json`
//! has the shape the documentation gives. Skipped with a message when the JSBSim models are not
//! installed.

mod support;

use model::aircraft;
use model::analysis::fast::{analyze_first_departure, analyze_routed_with, MAX_WIDTH};
use model::envelope::source::Source;
use model::envelope::{envelope, Elevator, Grid, Range};
use model::jsbsim::catalogue;
use model::jsbsim::condition::Speed;
use model::jsbsim::import::{import, Alpha, Request};
use model::present::envelope::command;
use model::present::envelope_maps::maps;
use model::present::failure::Failure;
use model::present::options::EnvelopeArgs;
use model::random::Rng;
use serde_json::Value;

/// The grid of the checks: 7 altitudes by 6 Mach numbers of the F-104.
const ALTITUDES: &str = "0:12000:2000";
const MACHS: &str = "0.4:0.9:0.1";

fn args(source: &str, altitude_m: &str, mach: &str) -> EnvelopeArgs {
    EnvelopeArgs {
        source: source.to_string(),
        altitude_m: altitude_m.to_string(),
        mach: Some(mach.to_string()),
        speed: None,
        load_factor: None,
        delta_e_deg: None,
        json: true,
        out: None,
        uncertainty: None,
        validate: false,
        validate_sample: 0.1,
    }
}

fn installed() -> bool {
    let found = catalogue::root(None).is_some();
    if !found {
        eprintln!("skipped: the JSBSim models are not installed (pip install jsbsim)");
    }
    found
}

/// The F-104's envelope trimmed at 0.5 g (a push), elevator increment 0.5 deg, against import
/// at the same trim + analyze at the same increment, at five random grid points.
#[test]
fn envelope_points_equal_import_then_analyze_at_random_grid_points() {
    if !installed() {
        return;
    }
    let source = Source::parse("jsbsim:f104").unwrap();
    let grid = Grid::new(
        Range::parse(ALTITUDES, "--altitude-m").unwrap(),
        Range::parse(MACHS, "--mach").unwrap(),
    )
    .unwrap();
    let n = 0.5;
    let increment = 0.5f64.to_radians();
    let elevator = Elevator {
        load_factor: n,
        increment,
    };
    let env = envelope(
        &source.load().unwrap(),
        "jsbsim:f104",
        &grid,
        elevator,
        &|_| {},
    );
    assert_eq!(env.points.len(), 42);
    let mut rng = Rng::new(38);
    let mut checked = 0;
    for _ in 0..5 {
        let p = &env.points[(rng.unit() * 42.0) as usize];
        let request = Request {
            model: "f104".to_string(),
            root: None,
            altitude_m: p.altitude_m,
            speed: Speed::Mach(p.mach),
            alpha: Alpha::Trim(n),
            settings: Vec::new(),
        };
        let text = match import(&request) {
            Ok(t) => t,
            Err(why) => {
                assert!(!p.trimmed, "{p:?}");
                assert_eq!(p.reason.as_deref(), Some(why.as_str()));
                continue;
            }
        };
        let ac = aircraft::parse(&text, "jsbsim:f104").unwrap();
        assert!(p.trimmed);
        assert!((p.speed_m_s - ac.speed).abs() <= 1e-9 * ac.speed);
        assert_eq!(p.delta_e_deg, Some(increment.to_degrees()));
        assert_eq!(p.load_factor, n);
        let (a, _) = analyze_first_departure(&ac, increment).unwrap();
        // `analyze` (the exact path for this aircraft's Hopf points) gives the same roots, each
        // within its certified bracket.
        let (full, _) = analyze_routed_with(&ac, increment, true).unwrap();
        let p0 = |a: &model::analysis::Analysis| {
            let d = a.first_departure.as_ref();
            [a.critical.as_ref().map(|c| c.p0), d.map(|d| d.p0)]
        };
        for (x, y) in p0(&a).into_iter().zip(p0(&full)) {
            match (x, y) {
                (Some(x), Some(y)) => assert!(support::close_roots(x, y, MAX_WIDTH), "{x} vs {y}"),
                (x, y) => assert_eq!(x, y),
            }
        }
        assert_eq!(
            a.first_departure.as_ref().map(|d| d.kind),
            full.first_departure.as_ref().map(|d| d.kind)
        );
        let critical = a.critical.as_ref();
        let envelope_critical = p.critical.as_ref();
        assert_eq!(critical.map(|c| c.p0), envelope_critical.map(|c| c.p0));
        assert_eq!(
            critical.map(|c| c.delta_a_deg),
            envelope_critical.map(|c| c.delta_a_deg)
        );
        assert_eq!(a.first_departure, p.first_departure);
        let limit = ac.limits.aileron_deg;
        let margin = critical.zip(limit).map(|(c, l)| l - c.delta_a_deg.abs());
        assert_eq!(p.margin_deg, margin);
        // A margin at or above zero is a jump a full-stick roll reaches: the aileron that
        // `analyze` marks within the limit (the elevator, an increment of at most a few
        // degrees, is within its own).
        if let (Some(m), Some(c)) = (p.margin_deg, critical) {
            assert_eq!(Some(m >= 0.0), c.within_limits, "{p:?}");
        }
        checked += 1;
    }
    println!("envelope: {checked} of 5 random grid points trimmed and equal to import + analysis");
}

/// The F-16 at 8,600 m, Mach 0.87, 1 g: its primary branch turns in P0 before its critical
/// jump; the envelope's route gives the exact path's jump and first departure there too.
#[test]
fn a_branch_that_turns_before_its_jump_gets_the_exact_paths_answer() {
    if !installed() {
        return;
    }
    let request = Request {
        model: "f16".to_string(),
        root: None,
        altitude_m: 8600.0,
        speed: Speed::Mach(0.87),
        alpha: Alpha::Trim(1.0),
        settings: Vec::new(),
    };
    let text = import(&request).unwrap();
    let ac = aircraft::parse(&text, "jsbsim:f16").unwrap();
    let (a, _) = analyze_first_departure(&ac, 0.0).unwrap();
    let exact = model::analysis::analyze(&ac, 0.0).unwrap();
    let jump = |a: &model::analysis::Analysis| a.critical.as_ref().map(|c| (c.p0, c.delta_a_deg));
    let ((p0, da), (exact_p0, exact_da)) = (jump(&a).unwrap(), jump(&exact).unwrap());
    assert!(
        support::close_roots(p0, exact_p0, MAX_WIDTH),
        "{p0} vs {exact_p0}"
    );
    assert!(
        (da - exact_da).abs() <= 1e-6 * exact_da.abs(),
        "{da} vs {exact_da}"
    );
    assert_eq!(a.critical_note, exact.critical_note);
    let departure =
        |a: &model::analysis::Analysis| a.first_departure.as_ref().map(|d| (d.kind, d.p0));
    match (departure(&a), departure(&exact)) {
        (Some((kind, x)), Some((exact_kind, y))) => {
            assert_eq!(kind, exact_kind);
            assert!(support::close_roots(x, y, MAX_WIDTH), "{x} vs {y}");
        }
        (x, y) => assert_eq!(x, y),
    }
}

/// Bad ranges exit 2 (an input error) naming the option, before the model is even read (the
/// source names a model that does not exist).
#[test]
fn bad_ranges_are_refused_before_any_work() {
    let source = "jsbsim:no-such-model";
    let bad = [
        ("9000:0:500", "0.5", "reversed"),
        ("0:9000:0", "0.5", "step"),
        ("0", "0.3:0.9:-0.1", "step"),
        ("0:1e9:1", "0.5", "more than"),
        ("0:1e6:1", "0.1:1:0.01", "points"),
        ("-100:1000:100", "0.5", "atmosphere"),
        ("0:100000:1000", "0.5", "atmosphere"),
        ("0:1000", "0.5", "three"),
    ];
    for (h, m, why) in bad {
        let mut out = Vec::new();
        match command(&args(source, h, m), &mut out) {
            Err(Failure::Input(msg)) => assert!(msg.contains(why), "{h} {m}: {msg}"),
            _ => panic!("{h} {m}: not refused as input"),
        }
        assert!(out.is_empty());
    }
}

/// `--json` prints one object whose `points` carry the documented keys, with no number that is
/// not finite; a point without a trim says which limit.
#[test]
fn json_has_one_entry_per_point_with_the_documented_keys() {
    if !installed() {
        return;
    }
    let mut out = Vec::new();
    command(
        &args("jsbsim:f104", "0:12000:12000", "0.3:0.6:0.3"),
        &mut out,
    )
    .unwrap();
    let v: Value = serde_json::from_slice(&out).unwrap();
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 4);
    let keys = [
        "altitude_m",
        "mach",
        "speed_m_s",
        "load_factor",
        "alpha_deg",
        "elevator_trim_deg",
        "delta_e_deg",
        "trimmed",
        "critical",
        "critical_note",
        "first_departure",
        "margin_deg",
    ];
    for p in points {
        assert_eq!(p["delta_e_deg"].as_f64(), Some(0.0), "{p}");
        for k in keys {
            assert!(p.get(k).is_some(), "{k} missing in {p}");
        }
        if p["trimmed"] == Value::Bool(false) {
            assert!(
                p["reason"]
                    .as_str()
                    .unwrap()
                    .starts_with("untrimmable at n = 1: "),
                "{p}"
            );
            assert!(p["critical"].is_null());
        } else if p["critical"].is_null() {
            assert!(p["critical_note"].is_string(), "{p}");
        } else {
            let c = &p["critical"];
            assert!(c["p0"].is_f64() && c["delta_a_deg"].is_f64(), "{p}");
            assert!(c.get("within_limits").is_some());
        }
    }
    let text = String::from_utf8(out).unwrap();
    assert!(!text.contains("NaN") && !text.contains("inf"));
    // 12,000 m: at Mach 0.3 no lift solution up to 30 deg alpha, at Mach 0.6 the trim needs
    // more nose-up elevator (-23.2 deg) than the stabilator's travel (-20.05 deg).
    assert_eq!(v["untrimmed"], 2, "{text}");
    assert!(text.contains("no lift solution") && text.contains("beyond its travel"));
}

/// The catalogue table (`import jsbsim --list --analyze`) and the envelope use the same trim
/// (1 g unless `--load-factor`) and the same elevator (increment 0 from it): the F-104's row
/// and the envelope's point at the same condition give the same critical jump (or the same
/// reason for none) and the same first departure, to the digits the row prints. At 1 g the
/// F-104 jumps only low and fast; unloaded (0 g) it jumps or meets a Hopf point first.
#[test]
fn the_catalogue_row_and_the_envelope_point_agree_at_the_same_condition() {
    if !installed() {
        return;
    }
    let source = Source::parse("jsbsim:f104").unwrap();
    let loaded = source.load().unwrap();
    for (h, mach, n) in [
        (0.0, 0.8, 1.0),
        (6000.0, 0.6, 1.0),
        (6000.0, 0.9, 0.0),
        (4000.0, 0.5, 0.0),
    ] {
        let elevator = Elevator {
            load_factor: n,
            increment: 0.0,
        };
        let point = model::envelope::Point::at(&loaded, "f104", h, mach, elevator);
        let spec = format!("jsbsim:f104 --altitude-m {h} --mach {mach} --load-factor {n}");
        let row = model::present::catalogue::row("f104", &model::jsbsim::cli::source(&spec));
        let cells = match point.critical.as_ref() {
            Some(c) => format!(
                "| {:.4} | {:.2} | {} |",
                c.p0,
                c.delta_a_deg,
                if c.within_limits == Some(true) {
                    "yes"
                } else {
                    "no"
                }
            ),
            None => format!(
                "| none: {}",
                point.critical_note.as_deref().unwrap().replace('|', "\\|")
            ),
        };
        assert!(
            row.contains(&cells),
            "{h} m, Mach {mach}, {n} g: {row} vs {cells}"
        );
        let first = match point.first_departure.as_ref() {
            Some(d) => format!("| {} | {:.4} | {:.2} |", d.kind, d.p0, d.delta_a_deg),
            None => "| none within the aileron range |".to_string(),
        };
        assert!(
            row.contains(&first),
            "{h} m, Mach {mach}, {n} g: {row} vs {first}"
        );
    }
}

/// `--out` writes the CSV (one row per point), the summaries and the three maps.
#[test]
fn out_writes_the_csv_the_summaries_and_the_maps() {
    if !installed() {
        return;
    }
    let dir = support::scratch("envelope-out");
    let mut a = args("jsbsim:f104", "0:12000:12000", "0.3:0.6:0.3");
    a.json = false;
    a.out = Some(dir.clone());
    let mut out = Vec::new();
    command(&a, &mut out).unwrap();
    let csv = std::fs::read_to_string(dir.join("envelope.csv")).unwrap();
    assert_eq!(csv.lines().count(), 5, "{csv}");
    assert!(csv.starts_with("altitude_m,mach,speed_m_s,trimmed,alpha_deg,elevator_trim_deg,"));
    for stem in ["critical_aileron", "critical_roll_rate", "first_departure"] {
        for ext in ["svg", "png", "csv"] {
            assert!(dir.join(format!("{stem}.{ext}")).is_file(), "{stem}.{ext}");
        }
    }
    for name in ["summary.md", "summary.json"] {
        assert!(dir.join(name).is_file(), "{name}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The F-104's envelope trimmed at 0 g (the unloaded roll) written by `--out` to a scratch
/// folder: the map's files and the envelope's CSV, read back.
struct Written {
    svg: String,
    map_csv: String,
    envelope_csv: String,
}

fn written(altitude_m: &str, mach: &str, name: &str) -> Written {
    let dir = support::scratch(&format!("envelope-{name}"));
    let mut a = args("jsbsim:f104", altitude_m, mach);
    a.json = false;
    a.out = Some(dir.clone());
    a.load_factor = Some(0.0);
    command(&a, &mut Vec::new()).unwrap();
    let read = |f: &str| std::fs::read_to_string(dir.join(f)).unwrap();
    let w = Written {
        svg: read("critical_aileron.svg"),
        map_csv: read("critical_aileron.csv"),
        envelope_csv: read("envelope.csv"),
    };
    let _ = std::fs::remove_dir_all(&dir);
    w
}

/// (Mach, altitude, margin) of every point of envelope.csv, each with a margin.
fn margins_of(csv: &str) -> Vec<(f64, f64, f64)> {
    csv.lines()
        .skip(1)
        .map(|row| {
            let f: Vec<&str> = row.split(',').collect();
            let num = |k: usize| f[k].parse::<f64>().unwrap();
            (num(1), num(0), num(11))
        })
        .collect()
}

/// The texts of the SVG, trimmed.
fn texts(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter_map(|n| n.text())
        .map(|t| t.trim().to_string())
        .collect()
}

/// The polylines of the SVG drawn in black, 3 px wide (the contour's stroke), left of the
/// legend column (which starts at 72 % of the 1000 px width), as their point lists.
fn contour_polylines(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .filter(|n| n.attribute("stroke") == Some("#000000"))
        .filter(|n| n.attribute("stroke-width") == Some("3"))
        .filter_map(|n| n.attribute("points").map(str::to_string))
        .filter(|pts| {
            pts.split_whitespace()
                .all(|xy| xy.split(',').next().unwrap().parse::<f64>().unwrap() < 720.0)
        })
        .collect()
}

/// Where the margin to the aileron limit changes sign between neighbouring grid points, the
/// critical aileron map draws the aileron-limit contour: a legend entry and a black polyline
/// in the SVG, and in the map's CSV a series each of whose points lies on a grid edge whose
/// ends have margins of opposite signs, where the straight line between those two margins
/// (read from envelope.csv) is zero. Where no margin changes sign, no contour.
#[test]
fn the_critical_aileron_map_draws_the_aileron_limit_contour_where_the_margin_changes_sign() {
    if !installed() {
        return;
    }
    // At 6,000 and 7,000 m a full-stick unloaded roll of the F-104 jumps up to about Mach 0.8
    // and not beyond.
    let w = written("6000:7000:1000", "0.7:0.9:0.1", "contour");
    let margins = margins_of(&w.envelope_csv);
    assert_eq!(margins.len(), 6);
    assert!(margins.iter().any(|m| m.2 < 0.0) && margins.iter().any(|m| m.2 > 0.0));
    let margin = |x: f64, y: f64| {
        let m = margins.iter().find(|m| (m.0 - x).abs() < 1e-9 && m.1 == y);
        m.map(|m| m.2)
    };
    let contour: Vec<(f64, f64)> = w
        .map_csv
        .lines()
        .filter(|row| row.contains(",line,aileron limit ("))
        .map(|row| {
            let f: Vec<&str> = row.rsplitn(3, ',').collect();
            (f[1].parse().unwrap(), f[0].parse().unwrap())
        })
        .collect();
    assert!(contour.len() >= 2, "{}", w.map_csv);
    let (machs, alts) = ([0.7, 0.8, 0.9], [6000.0, 7000.0]);
    for &(x, y) in &contour {
        // The grid edge through (x, y): along an altitude row or a Mach column.
        let (a, b, t) = if alts.contains(&y) {
            let k = machs.iter().rposition(|&m| m <= x + 1e-12).unwrap().min(1);
            let t = (x - machs[k]) / 0.1;
            ((machs[k], y), (machs[k + 1], y), t)
        } else {
            let k = machs.iter().position(|&m| (m - x).abs() < 1e-12).unwrap();
            let t = (y - 6000.0) / 1000.0;
            ((machs[k], 6000.0), (machs[k], 7000.0), t)
        };
        let (ma, mb) = (margin(a.0, a.1).unwrap(), margin(b.0, b.1).unwrap());
        assert!(ma * mb <= 0.0, "({x}, {y}) between margins {ma} and {mb}");
        let zero = ma / (ma - mb);
        assert!(
            (t - zero).abs() < 1e-9,
            "({x}, {y}): t = {t}, margin zero at {zero}"
        );
    }
    let legend = texts(&w.svg);
    assert!(
        legend.iter().any(|t| t.starts_with("aileron limit (")),
        "no legend entry: {legend:?}"
    );
    assert!(!contour_polylines(&w.svg).is_empty(), "no contour polyline");

    // At 12,000 and 13,000 m between Mach 0.6 and 0.7 every full-stick unloaded roll reaches
    // its critical aileron: the margin keeps its sign.
    let w = written("12000:13000:1000", "0.6:0.7:0.1", "no-contour");
    let margins = margins_of(&w.envelope_csv);
    assert!(
        margins.len() == 4 && margins.iter().all(|m| m.2 > 0.0),
        "{margins:?}"
    );
    assert!(!w.map_csv.contains("aileron limit"));
    assert!(!texts(&w.svg).iter().any(|t| t.contains("aileron limit")));
    assert!(contour_polylines(&w.svg).is_empty());
}

/// The bare F-16 (Cm_alpha > 0) at 12,000 m and Mach 0.5 starts from an unstable trim, at Mach
/// 0.9 from a stable one (`tests/tests/jsbsim.rs` checks the eigenvalue at the first): the JSON
/// says `unstable_trim` for the first, the CSV too, the first-departure map gives it its own
/// legend entry, and the table counts it.
#[test]
fn an_unstable_trim_is_its_own_class_in_the_json_csv_map_and_counts() {
    if !installed() {
        return;
    }
    let dir = support::scratch("envelope-unstable");
    let mut a = args("jsbsim:f16", "12000", "0.5:0.9:0.4");
    a.out = Some(dir.clone());
    let mut out = Vec::new();
    command(&a, &mut out).unwrap();
    let v: Value = serde_json::from_slice(&out).unwrap();
    let kinds: Vec<&Value> = v["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| &p["first_departure"]["kind"])
        .collect();
    assert_eq!(kinds[0], "unstable_trim", "{v}");
    assert_ne!(kinds[1], "unstable_trim", "{v}");
    let mode = &v["points"][0]["first_departure"]["unstable_trim"]["modes"][0];
    assert_eq!(
        (&mode["motion"], &mode["subsystem"]),
        (&"divergence".into(), &"pitch".into())
    );
    let read = |f: &str| std::fs::read_to_string(dir.join(f)).unwrap();
    let csv = read("envelope.csv");
    assert!(
        csv.lines().nth(1).unwrap().contains(",unstable_trim,0,0,"),
        "{csv}"
    );
    assert!(
        read("first_departure.svg").contains("unstable trim (bare airframe)"),
        "the map's legend"
    );
    assert!(
        read("first_departure.csv").contains("unstable trim (bare airframe)"),
        "the map's data"
    );
    assert!(
        read("summary.md").contains("1 with an unstable trim at P0 = 0"),
        "the counts"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The first-departure map tells a departure a full-stick roll reaches from one beyond the
/// aileron's travel: the F-104 at sea level, Mach 0.9, jumps from 1-g flight only beyond its
/// 20.05 deg aileron (margin < 0), at 12,000 m, Mach 0.9, unloaded, well within it; each cell
/// gets the legend entry its JSON margin says.
#[test]
fn the_departure_map_tells_departures_within_the_stick_from_those_beyond_it() {
    if !installed() {
        return;
    }
    for (altitude, n, within) in [("0", 1.0, false), ("12000", 0.0, true)] {
        let dir = support::scratch(&format!("envelope-beyond-{altitude}"));
        let mut a = args("jsbsim:f104", altitude, "0.9");
        (a.out, a.load_factor) = (Some(dir.clone()), Some(n));
        let mut out = Vec::new();
        command(&a, &mut out).unwrap();
        let v: Value = serde_json::from_slice(&out).unwrap();
        let p = &v["points"][0];
        let margin = p["margin_deg"].as_f64().expect("a margin");
        assert_eq!(margin >= 0.0, within, "{p}");
        let kind = p["first_departure"]["kind"].as_str().unwrap();
        let want = format!(
            "{} {} the stick's travel",
            if kind == "hopf" { "Hopf" } else { kind },
            if within { "within" } else { "beyond" }
        );
        let map = std::fs::read_to_string(dir.join("first_departure.csv")).unwrap();
        assert!(map.contains(&want), "{want} in {map}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// The F-104's unloaded envelope over 0, 6,000 and 12,000 m and Mach 0.4, 0.65 and 0.9, and
/// its maps.
fn f104_maps() -> (
    model::envelope::Envelope,
    Vec<(&'static str, model::plot::Figure)>,
) {
    let source = Source::parse("jsbsim:f104").unwrap();
    let grid = Grid::new(
        Range::parse("0:12000:6000", "--altitude-m").unwrap(),
        Range::parse("0.4:0.9:0.25", "--mach").unwrap(),
    )
    .unwrap();
    let unloaded = Elevator {
        load_factor: 0.0,
        increment: 0.0,
    };
    let env = envelope(
        &source.load().unwrap(),
        "jsbsim:f104",
        &grid,
        unloaded,
        &|_| {},
    );
    let figures = maps(&env, &model::plot::PlotStyle::default());
    (env, figures)
}

/// The legend entries of a map's cells and lines.
fn legend(f: &model::plot::Figure) -> Vec<String> {
    f.panels[0]
        .lines
        .iter()
        .filter_map(|l| l.label.clone())
        .collect()
}

/// The maps read at a glance: titled with the aircraft's own name (JSBSim's `<fdm_config
/// name="F-104C">`, not the source `jsbsim:f104`), axes spanning the grid and no more (no
/// altitude below sea level), and on the critical-aileron map the smallest critical |delta_a|
/// (the dangerous end) warm, red above blue, the largest cool.
#[test]
fn the_maps_name_the_aircraft_span_the_grid_and_paint_danger_warm() {
    if !installed() {
        return;
    }
    let (_, figures) = f104_maps();
    for (stem, f) in &figures {
        assert!(f.title.starts_with("F-104C: "), "{stem}: {}", f.title);
        let (x, y) = (&f.panels[0].x, &f.panels[0].y);
        assert_eq!((x.lo, x.hi), (0.4, 0.9), "{stem}: Mach axis");
        assert_eq!((y.lo, y.hi), (0.0, 12000.0), "{stem}: altitude axis");
    }
    let aileron = &figures
        .iter()
        .find(|f| f.0 == "critical_aileron")
        .unwrap()
        .1;
    // Bands "A to B deg" with their colours, by their lower end.
    let mut bands: Vec<(f64, model::plot::Rgb)> = aileron.panels[0]
        .lines
        .iter()
        .filter_map(|l| {
            let label = l.label.as_deref()?.strip_suffix(" deg")?;
            let (a, _) = label.split_once(" to ")?;
            Some((a.parse().ok()?, l.color))
        })
        .collect();
    bands.sort_by(|a, b| a.0.total_cmp(&b.0));
    assert!(bands.len() >= 2, "{:?}", legend(aileron));
    let (small, large) = (bands[0].1, bands[bands.len() - 1].1);
    assert!(
        small.0 > small.2,
        "smallest critical aileron not warm: {small:?}"
    );
    assert!(
        large.2 > large.0,
        "largest critical aileron not cool: {large:?}"
    );
}

/// One legend entry per meaning: a point analysed without a critical jump, one whose analysis
/// failed and one without a trim each get their own entry, on both heat maps; on the
/// departure map a jump of a model without an aileron limit is not called "within the stick's
/// travel". (The points are the F-104's, their fields set as such points have them.)
#[test]
fn the_legends_tell_no_jump_from_not_analysed_and_unknown_travel() {
    if !installed() {
        return;
    }
    let (mut env, _) = f104_maps();
    let analysed: Vec<usize> = (0..env.points.len())
        .filter(|&k| env.points[k].route.is_some() && env.points[k].critical.is_some())
        .collect();
    assert!(analysed.len() >= 3, "{:?}", env.points);
    let (none, failed, no_limit) = (analysed[0], analysed[1], analysed[2]);
    env.points[none].critical = None;
    env.points[failed].critical = None;
    env.points[failed].route = None;
    env.points[failed].error = Some("a failed analysis".into());
    let jump = env.points[no_limit].first_departure.as_mut().unwrap();
    jump.kind = "jump";
    env.points[no_limit].aileron_limit_deg = None;
    env.points[no_limit].margin_deg = None;
    for (stem, f) in maps(&env, &model::plot::PlotStyle::default()) {
        let entries = legend(&f);
        if stem == "first_departure" {
            assert!(
                entries.contains(&"jump (no aileron limit known)".to_string()),
                "{entries:?}"
            );
            continue;
        }
        for want in ["no critical jump", "not analysed"] {
            assert!(entries.contains(&want.to_string()), "{stem}: {entries:?}");
        }
    }
}

/// JSBSim's verdict over the F-104's aileron steps `from..=to` (1 deg apart, 10 s each) at a
/// 0-g trim, by the oracle's own rule: the step past its jump, if any.
fn jsbsim_jump_to(altitude_m: f64, mach: f64, from: f64, to: f64) -> Option<f64> {
    let v = support::oracle::six_dof(
        "f104",
        (altitude_m, mach, 0.0),
        &[
            "--flat-earth".into(),
            "--sweep".into(),
            format!("{from}:{to}:1"),
            "--time".into(),
            "10".into(),
        ],
    );
    (v["jump"]["jump"] == Value::Bool(true)).then(|| v["jump"]["between_deg"][1].as_f64().unwrap())
}

/// `--validate` on the F-104 at 0 g over a small grid (two points that predict a jump within
/// the aileron limit, two that do not): with `--validate-sample 1` every analysed point has the
/// 6-DOF's verdict in the JSON and the CSV and the agreement map is written; with
/// `--validate-sample 0` only the predicted jumps are validated; one predicted point's verdict
/// is JSBSim's over the same aileron steps, within one step; bad options are refused.
#[test]
fn validate_gives_the_6_dof_verdict_at_predicted_jumps_and_a_sample() {
    if !installed() {
        return;
    }
    let dir = support::scratch("envelope-validate");
    let mut a = args("jsbsim:f104", "2000:10000:8000", "0.6:0.8:0.2");
    a.load_factor = Some(0.0);
    a.validate = true;
    a.validate_sample = 1.0;
    a.out = Some(dir.clone());
    let mut out = Vec::new();
    command(&a, &mut out).unwrap();
    let v: Value = serde_json::from_slice(&out).unwrap();
    let points = v["points"].as_array().unwrap();
    let predicted = |p: &Value| p["margin_deg"].as_f64().is_some_and(|m| m >= 0.0);
    assert_eq!(points.iter().filter(|p| predicted(p)).count(), 2);
    for p in points {
        let val = &p["validation"];
        assert_eq!(val["predicted"].as_bool(), Some(predicted(p)), "{p}");
        let jumps = val["jumps"].as_bool().unwrap();
        assert_eq!(val["between_deg"].is_array(), jumps, "{p}");
        let [from, to] = [0, 1].map(|i| val["swept_deg"][i].as_f64().unwrap());
        if predicted(p) {
            let c = p["critical"]["delta_a_deg"].as_f64().unwrap().abs();
            assert!(from < c && c < to, "{p}");
        } else {
            assert_eq!(to, p["aileron_limit_deg"].as_f64().unwrap(), "{p}");
        }
    }
    // One predicted point against JSBSim's own sweep over the same steps.
    let p = points.iter().find(|p| predicted(p)).unwrap();
    let val = &p["validation"];
    let ours = val["between_deg"][1].as_f64();
    let [from, to] = [0, 1].map(|i| val["swept_deg"][i].as_f64().unwrap());
    let (h, m) = (
        p["altitude_m"].as_f64().unwrap(),
        p["mach"].as_f64().unwrap(),
    );
    if std::process::Command::new("python3")
        .args(["-c", "import jsbsim"])
        .status()
        .is_ok_and(|s| s.success())
    {
        let theirs = jsbsim_jump_to(h, m, from, to);
        assert!(
            ours.zip(theirs).is_some_and(|(a, b)| (a - b).abs() <= 1.0) || ours == theirs,
            "{h} m Mach {m}: 6-DOF {ours:?}, JSBSim {theirs:?}"
        );
    }
    let csv = std::fs::read_to_string(dir.join("envelope.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    assert!(header.ends_with(",validation_agrees,validation_mach_change"));
    let jumps = header.split(',').position(|h| h == "validation_jumps");
    assert!(
        csv.lines().skip(1).all(|row| row
            .split(',')
            .nth(jumps.unwrap())
            .is_some_and(|j| j == "true" || j == "false")),
        "{csv}"
    );
    for ext in ["svg", "png", "csv"] {
        assert!(
            dir.join(format!("validation.{ext}")).is_file(),
            "validation.{ext}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
    // Without the sample, only the predicted jumps.
    a.validate_sample = 0.0;
    a.out = None;
    let mut out = Vec::new();
    command(&a, &mut out).unwrap();
    let v: Value = serde_json::from_slice(&out).unwrap();
    for p in v["points"].as_array().unwrap() {
        assert_eq!(p.get("validation").is_some(), predicted(p), "{p}");
    }
    // Bad options: a sample outside 0..1, an elevator increment the 6-DOF does not hold.
    a.validate_sample = 1.5;
    assert!(matches!(
        command(&a, &mut Vec::new()),
        Err(Failure::Input(_))
    ));
    a.validate_sample = 0.1;
    a.delta_e_deg = Some(1.0);
    assert!(matches!(
        command(&a, &mut Vec::new()),
        Err(Failure::Input(_))
    ));
}
