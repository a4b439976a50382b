//! The comparison of planners the book shows (docs/book/src/command-line.md, "Planners side by
//! side"): the paper's four examples with every planner of `dvf::planner::PLANNERS` (the run
//! metrics of `dvf compare`), then the sweep families, COUNT scenes each from seed 0, without
//! limits and with `v_max = ω_max = 2`, with every planner (`dvf sweep --planner`), as Markdown
//! tables on standard output.
//!
//! Run: `make compare-table`, or `cargo run --release --example compare -- [COUNT [PLANNERS]]`
//! (COUNT 50 by default; PLANNERS a comma-separated list, all of them by default).

use dvf::compare::table::{book_sweeps, examples_table, families_table};
use dvf::compare::{all_planners, now_ms};
use dvf::planner::Spec;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let count: usize = args
        .first()
        .map_or(Ok(50), |c| c.parse())
        .expect("COUNT is a number of scenes");
    let planners: Vec<Spec> = args.get(1).map_or_else(all_planners, |list| {
        list.split(',').map(|n| Spec::named(n.trim())).collect()
    });
    let fail = |e: dvf::Error| -> ! {
        eprintln!("{e}");
        std::process::exit(2)
    };
    // Every planner runs with the shared safety barrier at its default rate: say so, and what
    // each avoids on its own, above the tables.
    println!(
        "Every planner runs on the same unicycles, sensing, limits and shared safety barrier \
         (barrier_rate = {} 1/s). What each avoids on its own:\n",
        dvf::params::DEFAULT_BARRIER_RATE
    );
    for spec in &planners {
        if let Ok(e) = dvf::planner::entry(&spec.name) {
            println!("- `{}`: {}", e.name, e.avoids);
        }
    }
    println!("\n### The paper's examples\n");
    print!(
        "{}",
        examples_table(&planners, now_ms).unwrap_or_else(|e| fail(e))
    );
    println!("\n### The sweep families, {count} scenes each from seed 0\n");
    print!(
        "{}",
        families_table(&planners, &book_sweeps(count)).unwrap_or_else(|e| fail(e))
    );
}
