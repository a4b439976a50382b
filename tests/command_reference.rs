//! The controller's commands on a fixed set of robots, stored in tests/data/commands.json with
//! their inputs: this test keeps the file equal to `dvf::command`, bit for bit, and the Python
//! package's tests (python/tests/test_core.py) check its vectorised `dvf.command` against the
//! same file. `DVF_WRITE_REFERENCE=1 cargo test --test command_reference` rewrites the file.
//!
//! Native only: it reads the file from disk.
#![cfg(not(target_arch = "wasm32"))]

use dvf::{command, Obstacle, Params, Pose};
use glam::DVec2;
use serde_json::{json, Value};

const PATH: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/commands.json");

/// One set of robots: the parameters, poses, goals, the obstacles all of them sense, and each
/// robot's neighbours.
type Case = (Params, Vec<Pose>, Vec<Pose>, Vec<Obstacle>, Vec<Vec<DVec2>>);

/// Robots on a spiral around the origin with every kind of heading; goals, obstacles and
/// neighbours from the same indices, so that every branch of the controller is taken (free
/// space, inside an obstacle's ring, beside neighbours, at the goal).
fn cases() -> Vec<Case> {
    let obstacles = vec![
        Obstacle {
            center: DVec2::new(6.0, 4.0),
            radius: 2.0,
            influence: 5.0,
        },
        Obstacle {
            center: DVec2::new(-9.0, -3.0),
            radius: 1.5,
            influence: 3.0,
        },
    ];
    let paper = Params {
        avoidance: dvf::params::Avoidance::Paper,
        v_max: Some(3.0),
        omega_max: Some(2.0),
        ..Params::default()
    };
    let mut out = Vec::new();
    for (params, obstacles) in [
        (Params::default(), Vec::new()),
        (Params::default(), obstacles.clone()),
        (paper, obstacles),
    ] {
        let n = 48;
        let mut poses = Vec::new();
        let mut goals = Vec::new();
        let mut neighbours = Vec::new();
        for i in 0..n {
            let a = i as f64 * 0.7;
            let r = 1.0 + 0.45 * i as f64;
            let p = DVec2::new(r * a.cos(), r * a.sin());
            poses.push(Pose::new(p.x, p.y, -3.0 + 0.13 * i as f64));
            goals.push(match i % 4 {
                0 => Pose::new(0.0, 0.0, 0.0),
                1 => Pose::new(12.0, -7.0, 1.2),
                2 => Pose::new(p.x, p.y, 2.5),
                _ => Pose::new(-15.0, 10.0, -2.0),
            });
            neighbours.push(
                (0..i % 4)
                    .map(|k| p + DVec2::new(1.5 + k as f64, 0.8 * k as f64 - 1.0))
                    .collect(),
            );
        }
        out.push((params, poses, goals, obstacles, neighbours));
    }
    out
}

fn document() -> Value {
    let pose = |p: &Pose| json!([p.p.x, p.p.y, p.theta]);
    let cases: Vec<Value> = cases()
        .into_iter()
        .map(|(params, poses, goals, obstacles, neighbours)| {
            let commands: Vec<Value> = poses
                .iter()
                .zip(&goals)
                .zip(&neighbours)
                .map(|((p, g), n)| {
                    let c = command(&params, *p, *g, &obstacles, n);
                    json!([c.v, c.omega])
                })
                .collect();
            json!({
                "params": params,
                "poses": poses.iter().map(pose).collect::<Vec<_>>(),
                "goals": goals.iter().map(pose).collect::<Vec<_>>(),
                "obstacles": obstacles,
                "neighbours": neighbours
                    .iter()
                    .map(|n| n.iter().map(|q| json!([q.x, q.y])).collect::<Vec<_>>())
                    .collect::<Vec<_>>(),
                "commands": commands,
            })
        })
        .collect();
    json!({ "cases": cases })
}

#[test]
fn the_stored_commands_are_the_controllers() {
    let ours = document();
    if std::env::var_os("DVF_WRITE_REFERENCE").is_some() {
        let text = serde_json::to_string_pretty(&ours).expect("serialises");
        std::fs::write(PATH, text + "\n").expect("writes the reference");
    }
    let stored: Value =
        serde_json::from_str(&std::fs::read_to_string(PATH).expect("tests/data/commands.json"))
            .expect("parses");
    // serde_json reads every number back to the bits that wrote it (float_roundtrip).
    assert_eq!(stored, ours);
}
