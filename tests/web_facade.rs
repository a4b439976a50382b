//! The JavaScript facade (`src/wasm/`) in Chromium:
//! `wasm-pack test --headless --chrome -- --test web_facade`.
#![cfg(target_arch = "wasm32")]

use dvf::params::{AVOIDANCE_MODES, PARAMETERS};
use dvf::playground::{
    CURVE_POINTS, FIELD_STRIDE, MAX_LIVE_ROBOTS, MAX_PREDICTED_ROBOTS, MAX_TRAIL_SAMPLES,
    POSE_STRIDE, STATUS_STRIDE,
};
use dvf::presets::{DEFAULT_PRESET, PRESETS};
use dvf::wasm::playground::Buffer;
use dvf::wasm::{
    default_preset, parameters, playground_limits, preset_scenario, presets, Playground, Run,
    SAMPLE_STRIDE,
};
use js_sys::Float64Array;
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
fn the_parameter_table_crosses_as_rows_and_modes() {
    let table = parameters().unwrap();
    let field = |v: &JsValue, key: &str| js_sys::Reflect::get(v, &key.into()).unwrap();
    let rows = js_sys::Array::from(&field(&table, "rows"));
    assert_eq!(rows.length() as usize, PARAMETERS.len());
    for (k, p) in PARAMETERS.iter().enumerate() {
        let row = rows.get(k as u32);
        assert_eq!(field(&row, "name").as_string().as_deref(), Some(p.name));
        assert_eq!(field(&row, "symbol").as_string().as_deref(), Some(p.symbol));
        assert_eq!(field(&row, "unit").as_string().as_deref(), Some(p.unit));
        assert_eq!(field(&row, "panel").as_bool(), Some(p.panel));
        let kind = field(&row, "kind").as_string().unwrap();
        assert!(["number", "optional", "mode"].contains(&kind.as_str()));
    }
    let modes = js_sys::Array::from(&field(&table, "modes"));
    let modes: Vec<String> = modes.iter().filter_map(|m| m.as_string()).collect();
    assert_eq!(modes, AVOIDANCE_MODES);
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

fn get(object: &JsValue, key: &str) -> JsValue {
    js_sys::Reflect::get(object, &key.into()).unwrap()
}

fn text(v: &JsValue) -> String {
    String::from(js_sys::JSON::stringify(v).unwrap())
}

#[wasm_bindgen_test]
fn playground_arrays_have_the_documented_layouts() {
    let mut pg = Playground::from_preset(DEFAULT_PRESET).unwrap();
    let n = pg.robot_count();
    assert_eq!(n, 10);
    assert_eq!(buf(pg.layout_now().poses).len(), n * POSE_STRIDE);
    assert_eq!(buf(pg.layout_now().status).len(), n * STATUS_STRIDE);
    assert_eq!(
        buf(pg.layout_now().trails).len(),
        n * MAX_TRAIL_SAMPLES * POSE_STRIDE
    );
    assert_eq!(buf(pg.layout_now().trail_times).len(), MAX_TRAIL_SAMPLES);
    assert_eq!(buf(pg.layout_now().trail_min_pair).len(), MAX_TRAIL_SAMPLES);
    // At t = 0 the history holds the start, and the prediction starts there too.
    assert_eq!(
        (pg.layout_now().history_length, pg.layout_now().trail_head),
        (1, 1)
    );
    assert_eq!(pg.live().trails().len_of(0), 1);
    let samples = pg.layout_now().predicted_times.length;
    assert!(samples >= 2);
    let predicted = buf(pg.layout_now().predicted).to_vec();
    assert_eq!(predicted.len(), n * samples * POSE_STRIDE);
    assert_eq!(buf(pg.layout_now().predicted_times).len(), samples);
    assert_eq!(buf(pg.layout_now().predicted_min_pair).len(), samples);
    assert_eq!(&predicted[..3], &buf(pg.layout_now().poses).to_vec()[..3]);
    // Robot 2's prediction starts at robot 2's pose: robot-major layout.
    assert_eq!(
        &predicted[samples * POSE_STRIDE..samples * POSE_STRIDE + 3],
        &buf(pg.layout_now().poses).to_vec()[3..6]
    );
    let len = pg
        .refresh_field(0.0, -10.0, -5.0, 10.0, 5.0, 5.0, 3.0)
        .unwrap();
    let field = view(pg.layout_now().field.pointer, len);
    assert_eq!(field.len(), 5 * 3 * FIELD_STRIDE);
    assert_eq!(&field[..2], &[-10.0, -5.0]);
    assert_eq!(&field[(5 * 3 - 1) * FIELD_STRIDE..][..2], &[10.0, 5.0]);
    let curves = pg
        .integral_curves(0.0, 1.5, -10.0, -10.0, 10.0, 10.0, 2.0)
        .unwrap();
    assert_eq!(curves.length() as usize, 2 * 2 * CURVE_POINTS * 2);
    // Stepping fills the rings and moves the clock.
    assert_eq!(pg.step(10.0).unwrap(), 10);
    assert!((pg.time() - 0.1).abs() < 1e-12);
    let limits = playground_limits().unwrap();
    assert_eq!(
        get(&limits, "trailCapacity").as_f64(),
        Some(MAX_TRAIL_SAMPLES as f64)
    );
    assert_eq!(
        get(&limits, "maxRobots").as_f64(),
        Some(MAX_LIVE_ROBOTS as f64)
    );
    assert_eq!(
        get(&limits, "maxPredictedRobots").as_f64(),
        Some(MAX_PREDICTED_ROBOTS as f64)
    );
}

/// The `len` values at `ptr` in the module's memory, read through a `Float64Array` view. The
/// output is allocated first: an allocation may grow the memory and detach a view made before.
fn view(ptr: usize, len: usize) -> Vec<f64> {
    let mut out = vec![0.0; len];
    let memory: js_sys::WebAssembly::Memory = wasm_bindgen::memory().unchecked_into();
    Float64Array::new_with_byte_offset_and_length(&memory.buffer(), ptr as u32, len as u32)
        .copy_to(&mut out);
    out
}

/// A buffer of the layout, read through a view.
fn buf(b: Buffer) -> Vec<f64> {
    view(b.pointer, b.length)
}

/// The same through a `Uint32Array` view.
fn view_u32(ptr: usize, len: usize) -> Vec<u32> {
    let mut out = vec![0; len];
    let memory: js_sys::WebAssembly::Memory = wasm_bindgen::memory().unchecked_into();
    js_sys::Uint32Array::new_with_byte_offset_and_length(&memory.buffer(), ptr as u32, len as u32)
        .copy_to(&mut out);
    out
}

/// Every buffer of the layout addresses the model's array it names, at every step; the
/// crowd plays with no prediction and smaller trail rings.
#[wasm_bindgen_test]
fn pointers_address_the_arrays_they_name() {
    for name in [DEFAULT_PRESET, "crowd-1000"] {
        let mut pg = Playground::from_preset(name).unwrap();
        let n = pg.robot_count();
        for _ in 0..3 {
            // The object JavaScript gets names the same buffers as the Rust layout.
            let js = pg.layout().unwrap();
            let l = pg.layout_now();
            for (key, b) in [
                ("poses", l.poses),
                ("status", l.status),
                ("trails", l.trails),
                ("trailLengths", l.trail_lengths),
                ("trailTimes", l.trail_times),
                ("trailMinPair", l.trail_min_pair),
                ("predicted", l.predicted),
                ("predictedTimes", l.predicted_times),
                ("predictedMinPair", l.predicted_min_pair),
                ("field", l.field),
            ] {
                let o = get(&js, key);
                let field = |k: &str| get(&o, k).as_f64().unwrap() as usize;
                assert_eq!(
                    (field("pointer"), field("length"), field("stride")),
                    (b.pointer, b.length, b.stride),
                    "{key}"
                );
            }
            assert_eq!(l.poses.length, n * l.poses.stride);
            pg.step(7.0).unwrap();
            let cap = pg.layout_now().trail_times.length;
            assert_eq!(
                view(pg.layout_now().poses.pointer, n * POSE_STRIDE),
                pg.live().poses().to_vec()
            );
            let status = pg.live().status().to_vec();
            let seen = view(pg.layout_now().status.pointer, n * STATUS_STRIDE);
            // NaN marks "no virtual obstacle": compare bit patterns.
            assert!(status
                .iter()
                .zip(&seen)
                .all(|(a, b)| a.to_bits() == b.to_bits()));
            let trails = pg.live().trails().poses().to_vec();
            let seen = view(pg.layout_now().trails.pointer, n * cap * POSE_STRIDE);
            assert!(trails
                .iter()
                .zip(&seen)
                .all(|(a, b)| a.to_bits() == b.to_bits()));
            assert_eq!(
                view(pg.layout_now().trail_times.pointer, 1)[0],
                pg.live().trails().times()[0]
            );
            let lens = view_u32(pg.layout_now().trail_lengths.pointer, n);
            assert!(lens
                .iter()
                .enumerate()
                .all(|(i, &l)| l as usize == pg.live().trails().len_of(i)));
            assert_eq!(
                pg.layout_now().trail_head,
                pg.layout_now().trail_recorded % cap
            );
            let len = pg
                .refresh_field(3.0, -40.0, -30.0, 40.0, 30.0, 9.0, 7.0)
                .unwrap();
            assert_eq!(len, 9 * 7 * FIELD_STRIDE);
            let seen = view(pg.layout_now().field.pointer, len);
            let copy = pg.live().field().to_vec();
            assert_eq!(seen, copy);
            let samples = pg.layout_now().predicted_times.length;
            assert_eq!(
                view(pg.layout_now().predicted.pointer, n * samples * POSE_STRIDE),
                pg.live().prediction().poses().to_vec()
            );
            assert_eq!(
                view(pg.layout_now().predicted_times.pointer, samples),
                pg.live().prediction().times().to_vec()
            );
        }
        if n > MAX_PREDICTED_ROBOTS {
            assert_eq!(pg.layout_now().predicted_times.length, 0);
            assert!(pg.layout_now().trail_times.length < MAX_TRAIL_SAMPLES);
        } else {
            assert!(pg.layout_now().predicted_times.length >= 2);
            assert_eq!(pg.layout_now().trail_times.length, MAX_TRAIL_SAMPLES);
        }
    }
}

#[wasm_bindgen_test]
fn playground_scenarios_round_trip() {
    let object = preset_scenario("example3-line-swap").unwrap();
    let mut pg = Playground::new(object.clone()).unwrap();
    assert_eq!(text(&pg.scenario().unwrap()), text(&object));
    // A drag at t = 0 edits the start, and the scenario read back runs the same.
    pg.move_robot(1.0, 3.0, 4.0, 0.5).unwrap();
    let edited = pg.scenario().unwrap();
    let start = js_sys::Array::from(&get(
        &js_sys::Array::from(&get(&edited, "robots")).get(1),
        "start",
    ));
    assert_eq!(
        start
            .to_vec()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect::<Vec<_>>(),
        [3.0, 4.0, 0.5]
    );
    let again = Playground::new(text(&edited).into()).unwrap();
    assert_eq!(
        buf(again.layout_now().predicted),
        buf(pg.layout_now().predicted).to_vec()
    );
    // An edit through an object; at t > 0 the clock and the poses stay.
    pg.step(50.0).unwrap();
    let poses = buf(pg.layout_now().poses).to_vec();
    let changed = scenario_from_json(&text(&edited).replace("\"k_v\":1.0", "\"k_v\":2.0"));
    pg.edit(changed).unwrap();
    assert_eq!(buf(pg.layout_now().poses).to_vec(), poses);
    assert!((pg.time() - 0.5).abs() < 1e-12);
    pg.reset();
    assert_eq!(pg.time(), 0.0);
}

#[wasm_bindgen_test]
fn playground_rejects_bad_input_with_the_field_named() {
    let mut pg = Playground::from_preset("example3-line-swap").unwrap();
    let n = pg.robot_count();
    let cases: Vec<(Result<(), wasm_bindgen::JsError>, String)> = vec![
        (
            pg.move_robot(f64::NAN, 0.0, 0.0, 0.0),
            "robot: must be a whole number".into(),
        ),
        (
            pg.move_robot(-1.0, 0.0, 0.0, 0.0),
            "robot: must be a whole number".into(),
        ),
        (
            pg.move_robot(0.5, 0.0, 0.0, 0.0),
            "robot: must be a whole number".into(),
        ),
        (
            pg.move_robot(n as f64, 0.0, 0.0, 0.0),
            format!("robot: index {n} is out of range"),
        ),
        (
            pg.move_robot(0.0, f64::NAN, 0.0, 0.0),
            "robots[0].start[0]: must be a finite number".into(),
        ),
        (
            pg.move_robot(0.0, 0.0, f64::INFINITY, 0.0),
            "robots[0].start[1]: must be a finite number".into(),
        ),
        (pg.step(-1.0).map(drop), "n: must be a whole number".into()),
        (
            pg.step(f64::NAN).map(drop),
            "n: must be a whole number".into(),
        ),
        (
            pg.refresh_field(0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 4.0)
                .map(drop),
            "nx: must be between 2".into(),
        ),
        (
            pg.refresh_field(0.0, 0.0, 0.0, f64::NAN, 1.0, 4.0, 4.0)
                .map(drop),
            "bounds: must be four finite numbers".into(),
        ),
        (
            pg.integral_curves(0.0, f64::NAN, 0.0, 0.0, 1.0, 1.0, 3.0)
                .map(drop),
            "theta0: must be a finite angle".into(),
        ),
        (
            pg.edit(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"params":{"kv":1}}"#.into()),
            "params.kv".into(),
        ),
        (
            pg.edit(
                r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"params":{"safe_radius":5}}"#
                    .into(),
            ),
            "params.avoid_radius: must exceed params.safe_radius".into(),
        ),
    ];
    for (result, expected) in cases {
        let m = message(result.expect_err(&expected));
        assert!(m.starts_with(&expected), "{m} (expected {expected})");
    }
    // Nothing was changed by the refused calls.
    assert_eq!(
        text(&pg.scenario().unwrap()),
        text(&preset_scenario("example3-line-swap").unwrap())
    );
    let many = format!(
        r#"{{"robots":[{}]}}"#,
        (0..=MAX_LIVE_ROBOTS)
            .map(|k| format!(r#"{{"start":[{},0,0],"goal":[{},50,0]}}"#, 10 * k, 10 * k))
            .collect::<Vec<_>>()
            .join(",")
    );
    let m = message(Playground::new(many.into()).err().unwrap());
    assert!(m.starts_with("robots: at most 10000 robots"), "{m}");
    // A scenario too long to predict on every edit is refused before it can freeze the page.
    let long = r#"{"duration":3000,"dt":0.002,"robots":[{"start":[0,0,0],"goal":[1,2,3]}]}"#;
    let m = message(Playground::new(long.into()).err().unwrap());
    assert!(
        m.starts_with("duration: the playground runs at most"),
        "{m}"
    );
}

/// `planners()` lists the registry; `compare(scenario, planners)` returns the comparison of
/// `dvf compare --json`, every number but the compute time the native library's (serialised
/// here from the same call, its clock replaced by zero); a bad list is refused naming its field.
#[wasm_bindgen_test]
fn compare_crosses_as_the_command_lines_json() {
    use dvf::compare::compare_with;
    use dvf::planner::{Spec, PLANNERS};
    use dvf::wasm::{compare, planners};
    let list = js_sys::Array::from(&planners().unwrap());
    assert_eq!(list.length() as usize, PLANNERS.len());
    for (k, e) in PLANNERS.iter().enumerate() {
        let name = js_sys::Reflect::get(&list.get(k as u32), &"name".into()).unwrap();
        assert_eq!(name.as_string().as_deref(), Some(e.name));
    }
    let json = r#"{"name": "two", "duration": 6,
        "robots": [{"start": [0, 0, 0], "goal": [6, 0, 0]},
                   {"start": [6, 0.4, 3.14159], "goal": [0, 0.4, 3.14159]}]}"#;
    let names = js_sys::JSON::parse(r#"["dvf-paper", "dvf"]"#).unwrap();
    let ours = compare(scenario_from_json(json), names).unwrap();
    let text: String = js_sys::JSON::stringify(&ours).unwrap().into();
    let mut ours: serde_json::Value = serde_json::from_str(&text).unwrap();
    let s = dvf::Scenario::from_json(json).unwrap();
    let lib = compare_with(&s, &[Spec::named("dvf-paper"), Spec::named("dvf")], || 0.0).unwrap();
    let lib = serde_json::to_value(&lib).unwrap();
    for p in ours["planners"].as_array_mut().unwrap() {
        assert!(p["metrics"]["ms_per_step"].as_f64().unwrap() >= 0.0);
        p["metrics"]["ms_per_step"] = 0.0.into();
    }
    // JSON.stringify writes 6.0 as 6, which reads back as an integer: numbers compare as f64.
    fn numbers(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Number(n) => *v = n.as_f64().into(),
            serde_json::Value::Array(a) => a.iter_mut().for_each(numbers),
            serde_json::Value::Object(o) => o.values_mut().for_each(numbers),
            _ => {}
        }
    }
    let mut lib = lib;
    numbers(&mut ours);
    numbers(&mut lib);
    assert_eq!(ours, lib);
    let all = compare(scenario_from_json(json), JsValue::UNDEFINED).unwrap();
    let runs = js_sys::Reflect::get(&all, &"planners".into()).unwrap();
    assert_eq!(js_sys::Array::from(&runs).length() as usize, PLANNERS.len());
    let bad = js_sys::JSON::parse(r#"["dvf", "rrt"]"#).unwrap();
    let e = message(compare(scenario_from_json(json), bad).err().unwrap());
    assert!(e.starts_with("planners[1]: unknown planner \"rrt\""), "{e}");
    let e = message(
        compare(scenario_from_json(json), "dvf".into())
            .err()
            .unwrap(),
    );
    assert!(e.starts_with("planners: expected an array"), "{e}");
    let bad = js_sys::JSON::parse(r#"["dvf", 3]"#).unwrap();
    let e = message(compare(scenario_from_json(json), bad).err().unwrap());
    assert!(e.starts_with("planners[1]"), "{e}");
}
