//! The JavaScript facade (`src/wasm.rs`) in Chromium:
//! `wasm-pack test --headless --chrome -- --test web_facade`.
#![cfg(target_arch = "wasm32")]

use dvf::presets::{DEFAULT_PRESET, PRESETS};
use dvf::wasm::{default_preset, preset_scenario, presets, Run, SAMPLE_STRIDE};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};

wasm_bindgen_test_configure!(run_in_browser);

/// The message of a `JsError` as JavaScript sees it.
fn message(e: wasm_bindgen::JsError) -> String {
    let v: JsValue = e.into();
    v.dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

fn scenario_from_json(text: &str) -> JsValue {
    js_sys::JSON::parse(text).expect("test JSON parses")
}

#[wasm_bindgen_test]
fn preset_list_starts_with_the_default() {
    let list = js_sys::Array::from(&presets().unwrap());
    assert_eq!(list.length() as usize, PRESETS.len());
    let first = js_sys::Reflect::get(&list.get(0), &"name".into()).unwrap();
    assert_eq!(first.as_string().as_deref(), Some(DEFAULT_PRESET));
    assert_eq!(default_preset(), DEFAULT_PRESET);
}

#[wasm_bindgen_test]
fn trajectories_hold_robots_times_samples_times_six() {
    let run = Run::from_preset(DEFAULT_PRESET).unwrap();
    let (robots, samples) = (run.robot_count(), run.sample_count());
    assert!(robots > 0 && samples >= 2);
    assert!(samples <= dvf::wasm::MAX_SAMPLES_PER_ROBOT);
    let traj = run.trajectories().to_vec();
    assert_eq!(traj.len(), robots * samples * SAMPLE_STRIDE);
    // Sample 0 is t = 0 at the start pose; the last sample is the end of the run.
    let starts = run.starts().to_vec();
    assert_eq!(starts.len(), robots * 3);
    assert_eq!(traj[0], 0.0);
    assert_eq!(&traj[1..3], &starts[0..2]);
    assert_eq!(traj[(samples - 1) * SAMPLE_STRIDE], run.duration());
    assert_eq!(run.goals().length() as usize, robots * 3);
    assert_eq!(run.bounds().length(), 4);
    assert_eq!(run.obstacles().length() % 4, 0);
}

#[wasm_bindgen_test]
fn a_preset_round_trips_through_js() {
    let object = preset_scenario("table2-obstacles").unwrap();
    let from_object = Run::new(object.clone()).unwrap();
    let direct = Run::from_preset("table2-obstacles").unwrap();
    assert_eq!(
        from_object.trajectories().to_vec(),
        direct.trajectories().to_vec()
    );
    // And as JSON text.
    let text = String::from(js_sys::JSON::stringify(&object).unwrap());
    let from_text = Run::new(text.into()).unwrap();
    assert_eq!(from_text.name(), direct.name());
    assert_eq!(from_text.bounds().to_vec(), direct.bounds().to_vec());
}

#[wasm_bindgen_test]
fn bad_scenarios_name_the_field() {
    let cases = [
        (
            r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"params":{"k_v":-1}}"#,
            "params.k_v: must be positive",
        ),
        (
            r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"params":{"kv":1}}"#,
            "params.kv",
        ),
        (
            r#"{"robots":[{"start":[0,0],"goal":[1,2,3]}]}"#,
            "robots[0].start",
        ),
        (r#"{"robots":[]}"#, "robots: needs at least one robot"),
    ];
    for (json, expected) in cases {
        let from_object = message(Run::new(scenario_from_json(json)).err().unwrap());
        assert!(from_object.starts_with(expected), "{from_object}");
        let from_text = message(Run::new(json.into()).err().unwrap());
        assert!(from_text.starts_with(expected), "{from_text}");
    }
    // JSON has no NaN: from an object it arrives as null, still reported at its field.
    let nan = scenario_from_json(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"dt":0.01}"#);
    js_sys::Reflect::set(&nan, &"dt".into(), &JsValue::from_f64(f64::NAN)).unwrap();
    let nan = message(Run::new(nan).err().unwrap());
    assert!(nan.starts_with("dt:"), "{nan}");
    let not_a_scenario = message(Run::new(JsValue::from_f64(3.0)).err().unwrap());
    assert!(
        not_a_scenario.starts_with("malformed scenario"),
        "{not_a_scenario}"
    );
    let unknown = message(preset_scenario("nope").err().unwrap());
    assert!(unknown.contains(DEFAULT_PRESET), "{unknown}");
}
