//! Unit tests of the JSBSim reader on small hand-written models: the function language, the
//! units and signs of the mass properties, and the refusals (each naming file, line and element).

use super::evaluate::Env;
use super::model::Model;

/// A minimal model around `aero` (the body of `<aerodynamics>`) and `mass` (extra
/// `<mass_balance>` content).
fn model_xml(aero: &str, mass: &str) -> String {
    format!(
        r#"<?xml version="1.0"?>
<fdm_config name="Test">
 <metrics>
   <wingarea unit="M2">10</wingarea>
   <wingspan unit="FT">20</wingspan>
   <chord unit="IN">60</chord>
   <location name="AERORP" unit="IN"><x>100</x><y>0</y><z>0</z></location>
 </metrics>
 <mass_balance>
   <ixx unit="KG*M2">1000</ixx><iyy unit="SLUG*FT2">2000</iyy><izz unit="SLUG*FT2">3000</izz>
   <ixz unit="SLUG*FT2">50</ixz>
   <emptywt unit="KG">1000</emptywt>
   <location name="CG" unit="IN"><x>100</x><y>0</y><z>0</z></location>
   {mass}
 </mass_balance>
 <aerodynamics>
 {aero}
 </aerodynamics>
</fdm_config>"#
    )
}

fn model(aero: &str) -> Model {
    Model::parse(&model_xml(aero, ""), "test.xml").unwrap_or_else(|e| panic!("{e}"))
}

/// The value of function `name` with inputs `inputs`.
fn value(m: &Model, name: &str, inputs: &[(&str, f64)]) -> f64 {
    let mut env: Env = m.environment();
    for (k, v) in inputs {
        env.set(k, *v);
    }
    env.property(name).unwrap()
}

fn refusal(aero: &str) -> String {
    Model::parse(&model_xml(aero, ""), "bad.xml")
        .unwrap_err()
        .to_string()
}

#[test]
fn operations_and_negated_properties() {
    let m = model(
        r#"<function name="f/a"><sum><product><value>2</value><property>x</property></product>
             <property>-y</property><difference><value>1</value><value>3</value></difference>
             <quotient><value>1</value><value>4</value></quotient>
             <pow><value>2</value><value>3</value></pow><abs><value>-5</value></abs>
             <max><value>1</value><value>7</value></max><min><value>1</value><value>7</value></min>
           </sum></function>
           <function name="f/b"><ifthen><gt><property>f/a</property><value>0</value></gt>
             <atan2><value>1</value><value>1</value></atan2><value>9</value></ifthen></function>"#,
    );
    // 2*3 - 4 + (1-3) + 0.25 + 8 + 5 + 7 + 1 = 21.25
    assert_eq!(value(&m, "f/a", &[("x", 3.0), ("y", 4.0)]), 21.25);
    assert_eq!(
        value(&m, "f/b", &[("x", 3.0), ("y", 4.0)]),
        std::f64::consts::FRAC_PI_4
    );
}

#[test]
fn tables_of_one_two_and_three_variables_in_a_function() {
    let m = model(
        r#"<function name="t/two"><table>
             <independentVar lookup="row">r</independentVar>
             <independentVar lookup="column">c</independentVar>
             <tableData>
                     0   10
                0    0   1
                1    2   3
             </tableData></table></function>
           <function name="t/three"><table>
             <independentVar lookup="row">r</independentVar>
             <independentVar lookup="column">c</independentVar>
             <independentVar lookup="table">k</independentVar>
             <tableData breakPoint="0">  0 10
               0 0 0
               1 0 0 </tableData>
             <tableData breakPoint="2">  0 10
               0 4 4
               1 4 4 </tableData></table></function>"#,
    );
    assert_eq!(value(&m, "t/two", &[("r", 0.5), ("c", 5.0)]), 1.5);
    assert_eq!(value(&m, "t/two", &[("r", 5.0), ("c", -5.0)]), 2.0);
    assert_eq!(
        value(&m, "t/three", &[("r", 0.5), ("c", 5.0), ("k", 1.0)]),
        2.0
    );
}

#[test]
fn units_and_the_sign_of_the_product_of_inertia() {
    let m = Model::parse(
        &model_xml(
            "",
            r#"<pointmass name="p"><weight unit="LBS">100</weight>
                 <location unit="IN"><x>112</x><y>0</y><z>-12</z></location></pointmass>"#,
        ),
        "m.xml",
    )
    .unwrap();
    assert!((m.metrics.wing_area - 107.639_104).abs() < 1e-3);
    assert!((m.metrics.chord - 5.0).abs() < 1e-12);
    let t = m.totals();
    assert!((t.weight - (1000.0 / 0.453_592_37 + 100.0)).abs() < 1e-9);
    // The file's ixz = 50 is minus the integral of x z dm; the point mass aft (x < 0) and below
    // (z > 0) of the CG adds a negative x z.
    let [ix, _, _, ixz] = t.moments();
    assert!((ix - (1000.0 / 1.35594 + point_ixx(&t))).abs() < 1e-6);
    assert!(ixz < -50.0, "{ixz}");
}

/// The point mass's share of Ixx about the combined CG (y = 0, so z^2 terms only).
fn point_ixx(t: &super::mass::Totals) -> f64 {
    let slug = 1.0 / 32.174049;
    let dz_p = (-12.0 - t.cg[2]) / 12.0;
    let dz_e = (0.0 - t.cg[2]) / 12.0;
    100.0 * slug * dz_p * dz_p + (t.weight - 100.0) * slug * dz_e * dz_e
}

#[test]
fn refusals_name_the_file_line_and_element() {
    let e = refusal(r#"<function name="a"><frobnicate/></function>"#);
    assert!(
        e.contains("bad.xml:") && e.contains("<frobnicate>") && e.contains("expected"),
        "{e}"
    );
    let e = refusal(
        r#"<function name="a"><table><independentVar>x</independentVar><tableData>
             0 1
             1 2 3
           </tableData></table></function>"#,
    );
    assert!(e.contains("<tableData>") && e.contains("expected"), "{e}");
    let e = Model::parse("<fdm_config><metrics>", "cut.xml")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("cut.xml:") && e.contains("XML"), "{e}");
    let e = refusal(r#"<axis name="UP"><function name="a"><value>1</value></function></axis>"#);
    assert!(e.contains("axis `UP`"), "{e}");
}

#[test]
fn deep_nesting_and_long_chains_are_refused_not_a_stack_overflow() {
    let deep = format!(
        "<function name=\"d\">{}<value>1</value>{}</function>",
        "<sum>".repeat(5000),
        "</sum>".repeat(5000)
    );
    let e = Model::parse(&model_xml(&deep, ""), "deep.xml")
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(e.contains("nested"), "{e}");
    let chain: String = (0..1000)
        .map(|k| {
            format!(
                "<function name=\"f{k}\"><property>f{}</property></function>",
                k + 1
            )
        })
        .collect::<String>()
        + "<function name=\"f1000\"><value>1</value></function>";
    let m = model(&chain);
    let e = m.environment().property("f0").unwrap_err().to_string();
    assert!(e.contains("chain"), "{e}");
}

#[test]
fn a_function_that_reads_itself_is_an_error_not_a_hang() {
    let m = model(
        r#"<function name="a"><property>b</property></function>
           <function name="b"><sum><property>a</property><value>1</value></sum></function>"#,
    );
    let e = m.environment().property("a").unwrap_err().to_string();
    assert!(e.contains("property loop"), "{e}");
}

/// Runs the import's command line; returns the exit code and what it wrote.
fn cli(args: &[&str]) -> (u8, String) {
    let args: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    let mut out = Vec::new();
    let code = super::cli::run(&args, &mut out);
    (code, String::from_utf8(out).unwrap())
}

#[test]
fn bad_input_on_the_command_line_exits_2() {
    let dir = std::env::temp_dir().join(format!("jsbsim-cli-{}", std::process::id()));
    let bad = dir.join("aircraft/Cut");
    std::fs::create_dir_all(&bad).unwrap();
    std::fs::write(bad.join("Cut.xml"), "<fdm_config><metrics>").unwrap();
    let good = dir.join("good.xml");
    std::fs::write(
        &good,
        model_xml(
            r#"<axis name="LIFT"><function name="a"><value>1</value></function></axis>"#,
            "",
        ),
    )
    .unwrap();
    let root = dir.to_str().unwrap();
    let good = good.to_str().unwrap();
    let condition = "--altitude-m 1000 --mach 0.5 --alpha-deg 2";
    for case in [
        format!("jsbsim Cut --jsbsim-root {root} {condition}"),
        format!("jsbsim Nope --jsbsim-root {root} {condition}"),
        format!("jsbsim {good} --altitude-m x --mach 0.5 --alpha-deg 2"),
        format!("jsbsim {good} --altitude-m 1000 --alpha-deg 2"),
        format!("jsbsim {good} --altitude-m -500 --mach 0.5 --alpha-deg 2"),
        format!("jsbsim {good} {condition} --frob"),
        format!("jsbsim {good} {condition} --set x"),
        format!("xplane {good}"),
        format!("jsbsim {good} {condition} --set fcs/nothing=1"),
    ] {
        let args: Vec<&str> = case.split_whitespace().collect();
        assert_eq!(cli(&args).0, 2, "{case}");
    }
    let (code, text) = cli(&[
        "jsbsim",
        good,
        "--altitude-m",
        "1000",
        "--mach",
        "0.5",
        "--alpha-deg",
        "2",
    ]);
    assert_eq!(code, 0);
    assert!(
        text.contains("[coefficients]") && text.contains("CL_alpha = "),
        "{text}"
    );
    let (code, text) = cli(&["jsbsim", "--list", "--jsbsim-root", root]);
    assert_eq!(code, 0);
    assert!(
        text.contains("Cut") && text.contains("refused") && text.contains("XML"),
        "{text}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_setting_of_a_property_the_import_moves_is_refused_a_configuration_input_is_not() {
    let dir = std::env::temp_dir().join(format!("jsbsim-set-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("set.xml");
    let aero = r#"<axis name="ROLL"><function name="l"><product>
        <property>fcs/aileron-pos-rad</property><property>aero/alpha-rad</property>
        <property>fcs/flap-pos-norm</property></product></function></axis>"#;
    std::fs::write(&file, model_xml(aero, "")).unwrap();
    let path = file.to_str().unwrap();
    let load = |name: &str| super::import::Loaded::new(path, None, &[(name.to_string(), 0.1)]);
    for moved in ["fcs/aileron-pos-rad", "aero/alpha-rad"] {
        let e = load(moved).expect_err(moved);
        assert!(e.contains(&format!("--set {moved}")), "{e}");
        assert!(e.contains("sets this property itself"), "{e}");
    }
    assert!(load("fcs/flap-pos-norm").is_ok());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_table_read_beyond_its_breakpoints_is_recorded_once_with_its_function() {
    let m = model(
        r#"<function name="f/t"><sum><table><independentVar>x</independentVar>
             <tableData>0 1
                        1 3</tableData></table>
             <table><independentVar>aero/h_b-mac-ft</independentVar>
             <tableData>0 1
                        1 3</tableData></table></sum></function>
           <function name="f/u"><product><property>f/t</property><property>f/t</property>
             </product></function>"#,
    );
    let mut env: Env = m.environment();
    env.set("x", 2.0);
    env.set("aero/h_b-mac-ft", 5.0);
    assert_eq!(env.property("f/u").unwrap(), 36.0);
    // The ground-effect table held beyond its end is not a warning; the other one is, once.
    let [c] = env.clamps() else {
        panic!("one clamp expected: {:?}", env.clamps());
    };
    assert_eq!(c.value, 2.0);
    assert_eq!(c.range, (0.0, 1.0));
    let f = c.function.expect("in a function");
    assert_eq!(m.functions.list[f].name, "f/t");
    let w = super::clamp::warnings(env.clamps(), &m.functions, "here");
    assert_eq!(
        w,
        [
            "the imported flight state (here) reads `x` = 2 beyond the breakpoints of 1 table, \
          where JSBSim holds the end value (no extrapolation): 0 to 1 in f/t"
        ]
    );
}

/// The refusal of the first non-finite function among `names`, as the import words it.
fn non_finite(m: &Model, names: &[&str], inputs: &[(&str, f64)]) -> String {
    let mut env: Env = m.environment();
    for (k, v) in inputs {
        env.set(k, *v);
    }
    for name in names {
        let f = m
            .functions
            .list
            .iter()
            .position(|f| f.name == *name)
            .unwrap();
        let v = env.function(f).unwrap();
        if !v.is_finite() {
            return super::finite::refusal(&mut env, f, v, "the state", &[]).to_string();
        }
    }
    panic!("every function finite");
}

#[test]
fn a_non_finite_function_is_refused_naming_where_it_arose() {
    let m = model(
        r#"<function name="f/a"><product><property>p</property>
             <quotient><value>2</value><property>d</property></quotient></product></function>
           <function name="f/b"><sum><value>1</value><property>f/a</property></sum></function>
           <function name="f/c"><sqrt><difference><property>p</property><value>1</value>
             </difference></sqrt></function>
           <function name="f/d"><atan><quotient><value>1</value><property>d</property>
             </quotient></atan></function>"#,
    );
    let zero = [("p", 0.0), ("d", 0.0)];
    // JSBSim: the quotient by zero is HUGE_VAL, times p = 0 NaN.
    let e = non_finite(&m, &["f/b"], &zero);
    assert!(e.starts_with("test.xml:"), "{e}");
    assert!(
        e.contains("`f/b` is NaN at the state: it reads `f/a` = NaN (line")
            && e.contains("where <quotient> divides 2 by `d` = 0 (JSBSim gives HUGE_VAL there)"),
        "{e}"
    );
    // JSBSim's square root of a negative number is -HUGE_VAL.
    let e = non_finite(&m, &["f/c"], &zero);
    assert!(
        e.contains("`f/c` is -inf at the state: <sqrt> of <difference> = -1 is -inf"),
        "{e}"
    );
    // An infinity inside a function whose value is finite is no refusal.
    assert_eq!(value(&m, "f/d", &zero), std::f64::consts::FRAC_PI_2);
}

#[test]
fn mass_properties_no_aircraft_has_are_refused() {
    let refused = |from: &str, to: &str| {
        let xml = model_xml("", "").replace(from, to);
        assert_ne!(xml, model_xml("", ""), "{from}");
        Model::parse(&xml, "m.xml").unwrap_err().to_string()
    };
    let empty = r#"<emptywt unit="KG">1000</emptywt>"#;
    let e = refused(empty, r#"<emptywt unit="KG">0</emptywt>"#);
    assert!(
        e.contains("m.xml:9: <mass_balance>: the total weight is 0 lbs"),
        "{e}"
    );
    let e = refused(empty, r#"<emptywt unit="KG">-5</emptywt>"#);
    assert!(e.contains("the weight of empty is"), "{e}");
    let e = refused(
        r#"<iyy unit="SLUG*FT2">2000</iyy>"#,
        r#"<iyy unit="SLUG*FT2">-1</iyy>"#,
    );
    assert!(
        e.contains("the moment of inertia iyy about the CG is -1 slug ft^2"),
        "{e}"
    );
    // ixx = 1000 kg m^2 = 737.56 slug ft^2, izz 3000: an ixz of 1500 leaves ixx izz < ixz^2.
    let e = refused(
        r#"<ixz unit="SLUG*FT2">50</ixz>"#,
        r#"<ixz unit="SLUG*FT2">1500</ixz>"#,
    );
    assert!(e.contains("ixx izz - ixz^2 = -"), "{e}");
}

#[test]
fn a_non_finite_reference_point_shift_is_refused_with_the_flight_state() {
    use super::coefficients::Setup;
    use super::condition::{Condition, Speed, State};
    let m = model(
        r#"<aero_ref_pt_shift_x><function><quotient><value>1</value>
             <property>fcs/shift</property></quotient></function></aero_ref_pt_shift_x>
           <axis name="LIFT"><function name="aero/lift"><product>
             <property>aero/qbar-area</property><value>0.3</value></product></function></axis>"#,
    );
    let setup = Setup::new(
        &m,
        Condition::new(3000.0, Speed::Mach(0.5)).unwrap(),
        Vec::new(),
        vec![("fcs/shift".to_string(), 0.0)],
    );
    let state = State {
        alpha: 2f64.to_radians(),
        beta: 0.0,
        rates: [0.1, 0.0, 0.0],
        surfaces: [0.0; 3],
    };
    let e = setup.coefficients(&state).unwrap_err().to_string();
    assert!(
        e.contains(
            "the coefficient Cm is -inf at altitude 3000 m, Mach 0.5, alpha 2 deg, p 1e-1 rad/s: \
                    <aero_ref_pt_shift_x>: <quotient> divides 1 by `fcs/shift` = 0"
        ),
        "{e}"
    );
}
