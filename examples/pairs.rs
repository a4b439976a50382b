//! Random pose pairs: how many converge (scratch experiment).
use dvf::scenario::{RobotSpec, Scenario};
use dvf::sim::Simulation;
use dvf::Params;

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().unwrap())
        .collect();
    let (kv, kw, ka, fade, n) = (args[0], args[1], args[2], args[3], args[4] as usize);
    let mut seed = 12345u64;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let params = Params {
        k_v: kv,
        k_omega: kw,
        k_a: ka,
        align_fade: fade,
        ..Params::default()
    };
    let mut fails = 0;
    let mut worst_p: f64 = 0.0;
    let mut worst_h: f64 = 0.0;
    let mut nan = 0;
    let mut times = vec![];
    for k in 0..n {
        let pi = std::f64::consts::PI;
        let start = [rnd() * 100.0, rnd() * 100.0, (2.0 * rnd() - 1.0) * pi];
        let goal = [rnd() * 100.0, rnd() * 100.0, (2.0 * rnd() - 1.0) * pi];
        let s = Scenario {
            name: "p".into(),
            bounds: None,
            duration: 60.0,
            dt: 0.01,
            params,
            independent: true,
            robots: vec![RobotSpec { start, goal }],
            obstacles: vec![],
        };
        let mut sim = Simulation::new(&s);
        for _ in 0..s.steps() {
            sim.step();
        }
        let r = &sim.report().robots[0];
        if r.final_pose.iter().any(|x| !x.is_finite()) {
            nan += 1;
        }
        worst_p = worst_p.max(r.position_error);
        worst_h = worst_h.max(r.heading_error);
        if !(r.position_error <= 0.05 && r.heading_error <= 0.02) {
            fails += 1;
            if fails < 6 {
                eprintln!(
                    "fail {k}: {:?} -> {:?}: pe {} he {}",
                    start, goal, r.position_error, r.heading_error
                );
            }
        } else {
            times.push(r.converged_at.unwrap_or(60.0));
        }
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!("fails {fails}/{n} nan {nan} worst pe {worst_p:.3e} he {worst_h:.3e} median t {:.2} p99 t {:.2}", times[times.len()/2], times[times.len()*99/100]);
}
