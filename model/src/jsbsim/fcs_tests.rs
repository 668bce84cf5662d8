//! Unit tests of the flight control system at steady state on small hand-written systems, each
//! answer worked by hand from JSBSim's documented component semantics, and of the system files
//! a model references (a missing one is an error naming it).

use super::fcs::{name_property, Fcs};
use super::surfaces::{travel, Control};

/// The components of a `<flight_control>` whose one channel holds `channel`.
fn fcs(channel: &str) -> Fcs {
    let text = format!(
        "<flight_control name=\"t\"><channel name=\"c\">{channel}</channel></flight_control>"
    );
    let doc = roxmltree::Document::parse(&text).unwrap();
    let mut fcs = Fcs::default();
    fcs.add_system(doc.root_element(), "t.xml");
    fcs
}

/// The aileron's steady value of `property` at command `cmd`.
fn at(fcs: &Fcs, property: &str, cmd: f64) -> Result<f64, String> {
    fcs.value(property, &[("fcs/aileron-cmd-norm", cmd)])
}

const ROLL_SUM: &str = "<summer name=\"Roll Trim Sum\"><input>fcs/aileron-cmd-norm</input>\
    <input>fcs/roll-trim-cmd-norm</input><clipto><min>-1</min><max>1</max></clipto></summer>";

#[test]
fn a_component_name_writes_fcs_and_the_name_in_lower_case_with_dashes() {
    assert_eq!(name_property("Roll Trim Sum"), "fcs/roll-trim-sum");
    assert_eq!(name_property("ap/roll-cmd"), "ap/roll-cmd");
}

#[test]
fn aerosurface_scale_range_in_degrees_times_the_gain_is_radians_each_side_on_its_own() {
    let f = fcs(&format!(
        "{ROLL_SUM}<aerosurface_scale name=\"Left Aileron Control\"><input>fcs/roll-trim-sum</input>\
         <range><min>-20</min><max>15</max></range><gain>0.01745</gain>\
         <output>fcs/left-aileron-pos-rad</output></aerosurface_scale>"
    ));
    // +1 maps to the range's max, -1 to its min (zero centred), times the gain: 15 * 0.01745
    // and -20 * 0.01745.
    assert_eq!(at(&f, "fcs/left-aileron-pos-rad", 1.0), Ok(0.26175));
    assert_eq!(at(&f, "fcs/left-aileron-pos-rad", -1.0), Ok(-0.349));
    assert_eq!(
        at(&f, "fcs/left-aileron-pos-rad", 0.5),
        Ok(0.5 * 15.0 * 0.01745)
    );
    let r = travel(&f, Control::Aileron, &|_| true).unwrap().unwrap();
    // The smaller end (15 deg of travel, reached at +1) is the symmetric limit.
    assert_eq!((r.min, r.max, r.limit()), (-0.349, 0.26175, 0.26175));
    assert_eq!(r.limiting_command(), 1.0);
    assert!(r.source.contains("\"Roll Trim Sum\""), "{}", r.source);
}

#[test]
fn aerosurface_scale_domain_and_an_uncentred_map() {
    let f = fcs(
        "<aerosurface_scale name=\"n\"><input>fcs/aileron-cmd-norm</input>\
         <domain><min>-20</min><max>10</max></domain><range><min>-1</min><max>1</max></range>\
         </aerosurface_scale>\
         <aerosurface_scale name=\"u\"><input>fcs/aileron-cmd-norm</input>\
         <zero_centered>false</zero_centered><range><min>0</min><max>10</max></range>\
         </aerosurface_scale>",
    );
    // Zero centred: -10 of the domain's -20 is half the range's -1; 10 is the max.
    assert_eq!(at(&f, "fcs/n", 1.0), Ok(0.1));
    assert_eq!(at(&f, "fcs/n", -10.0), Ok(-0.5));
    // Not centred: the domain's -1..1 maps end to end onto 0..10, so 0 is 5.
    assert_eq!(at(&f, "fcs/u", 0.0), Ok(5.0));
    assert_eq!(at(&f, "fcs/u", -1.0), Ok(0.0));
}

#[test]
fn summer_bias_clip_pure_gain_and_a_negated_input() {
    let f = fcs(
        "<summer name=\"s\"><input>fcs/aileron-cmd-norm</input><bias>0.5</bias>\
         <clipto><min>-1</min><max>1</max></clipto></summer>\
         <pure_gain name=\"g\"><input>-fcs/s</input><gain>2</gain></pure_gain>",
    );
    // 1 + 0.5 clipped to 1; -1 + 0.5 = -0.5; the gain doubles the negated sum.
    assert_eq!(at(&f, "fcs/s", 1.0), Ok(1.0));
    assert_eq!(at(&f, "fcs/g", 1.0), Ok(-2.0));
    assert_eq!(at(&f, "fcs/g", -1.0), Ok(1.0));
}

#[test]
fn actuator_settles_at_its_input_less_half_the_deadband_plus_bias_within_its_clip() {
    let f = fcs(
        "<actuator name=\"a\"><input>fcs/aileron-cmd-norm</input><lag>10</lag>\
         <rate_limit>0.5</rate_limit><deadband_width>0.2</deadband_width><bias>0.05</bias>\
         <clipto><min>-0.6</min><max>0.8</max></clipto></actuator>",
    );
    // +1: 1 - 0.1 + 0.05 = 0.95, clipped to 0.8; -1: -1 + 0.1 + 0.05 = -0.85, clipped to -0.6.
    assert_eq!(at(&f, "fcs/a", 1.0), Ok(0.8));
    assert_eq!(at(&f, "fcs/a", -1.0), Ok(-0.6));
    assert_eq!(at(&f, "fcs/a", 0.5), Ok(0.5 - 0.1 + 0.05));
}

#[test]
fn kinematic_scales_by_its_last_setting_and_holds_to_its_ends() {
    let f = fcs(
        "<kinematic name=\"k\"><input>fcs/aileron-cmd-norm</input><traverse>\
         <setting><position>0</position><time>0</time></setting>\
         <setting><position>15</position><time>2</time></setting></traverse></kinematic>",
    );
    // 0.5 of the last setting is 7.5; -1 would be -15, held at the first setting, 0.
    assert_eq!(at(&f, "fcs/k", 0.5), Ok(7.5));
    assert_eq!(at(&f, "fcs/k", -1.0), Ok(0.0));
}

#[test]
fn switch_takes_its_default_until_a_test_holds() {
    let switch = "<switch name=\"ap/cmd\"><default value=\"0\"/>\
         <test logic=\"AND\" value=\"fcs/aileron-cmd-norm\">ap/hold == 1\n gear/unit/WOW == 0</test>\
         </switch>";
    // The hold is off (0 until set): the AND is false whatever the gear reads.
    assert_eq!(at(&fcs(switch), "ap/cmd", 1.0), Ok(0.0));
    let on = fcs(&format!(
        "{switch}</channel><property value=\"1\">ap/hold</property><channel name=\"d\">"
    ));
    // On, the test needs the gear, the flight state: not followed, and said so.
    let err = at(&on, "ap/cmd", 1.0).unwrap_err();
    assert!(
        err.contains("gear/unit/WOW") && err.contains("ap/cmd"),
        "{err}"
    );
}

#[test]
fn a_table_or_a_function_in_the_path_stops_the_chain_naming_the_component() {
    let f = fcs(
        "<scheduled_gain name=\"Roll Feel\"><input>fcs/aileron-cmd-norm</input>\
         <table><independentVar>velocities/mach</independentVar><tableData>0 1\n1 0.7</tableData>\
         </table></scheduled_gain>\
         <scheduled_gain name=\"Yaw Damper\"><input>velocities/r-aero-rad_sec</input>\
         <table><independentVar>velocities/mach</independentVar><tableData>0 1\n1 0.7</tableData>\
         </table></scheduled_gain>\
         <fcs_function name=\"f\"><function><property>fcs/aileron-cmd-norm</property></function>\
         </fcs_function>",
    );
    let err = at(&f, "fcs/roll-feel", 1.0).unwrap_err();
    assert!(
        err.contains("<scheduled_gain> \"Roll Feel\" (t.xml:1)"),
        "{err}"
    );
    // A damper of the yaw rate adds nothing with no rates: zero, whatever the table.
    assert_eq!(at(&f, "fcs/yaw-damper", 1.0), Ok(0.0));
    let err = at(&f, "fcs/f", 1.0).unwrap_err();
    assert!(err.contains("<fcs_function> \"f\""), "{err}");
}

#[test]
fn an_unfollowed_chain_gives_no_limit_and_says_which_component() {
    let f = fcs(
        "<integrator name=\"i\"><input>fcs/aileron-cmd-norm</input><c1>1</c1></integrator>\
         <aerosurface_scale name=\"s\"><input>fcs/i</input><range><min>-0.3</min><max>0.3</max>\
         </range><output>fcs/left-aileron-pos-rad</output></aerosurface_scale>",
    );
    let err = travel(&f, Control::Aileron, &|_| true)
        .unwrap()
        .unwrap_err();
    assert!(
        err.starts_with("no aileron limit") && err.contains("<integrator> \"i\""),
        "{err}"
    );
    // The flight control system writes no elevator: no travel and nothing to say.
    assert!(travel(&f, Control::Elevator, &|_| true).is_none());
}

#[test]
fn a_missing_system_file_is_an_error_naming_it() {
    let dir = std::env::temp_dir().join(format!("fcs-missing-{}", std::process::id()));
    let aircraft = dir.join("aircraft").join("m");
    std::fs::create_dir_all(aircraft.join("Systems")).unwrap();
    let model = aircraft.join("m.xml");
    std::fs::write(
        &model,
        "<fdm_config><system file=\"controls\"/></fdm_config>",
    )
    .unwrap();
    let err = super::systems::system_files(&model).unwrap_err();
    assert!(
        err.contains("<system file=\"controls\">") && err.contains("no such file"),
        "{err}"
    );
    std::fs::write(
        aircraft.join("Systems").join("controls.xml"),
        "<system name=\"c\"/>",
    )
    .unwrap();
    assert_eq!(super::systems::system_files(&model).unwrap().len(), 2);
    std::fs::write(aircraft.join("Systems").join("controls.xml"), "<system").unwrap();
    let err = super::systems::system_files(&model).unwrap_err();
    assert!(err.contains("controls.xml: not well-formed XML"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}
