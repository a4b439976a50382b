//! The comparison of planners the book shows (docs/book/src/command-line.md, "Planners side by
//! side"): the paper's four examples with every planner of `dvf::planner::PLANNERS` (the run
//! metrics of `dvf compare`), then the sweep families, COUNT scenes each from seed 0, without
//! limits and with `v_max = ω_max = 2`, with every planner (`dvf sweep --planner`), as Markdown
//! tables on standard output.
//!
//! Run: `make compare-table`, or `cargo run --release --example compare -- [COUNT [PLANNERS]]`
//! (COUNT 50 by default; PLANNERS a comma-separated list, all of them by default). Each planner
//! runs with the gains `book_planners` gives it (src/compare/table.rs): its source's, but where
//! they describe the source's own robot.

use dvf::compare::now_ms;
use dvf::compare::table::{book_planners, book_sweeps, examples_table, families_table};
use dvf::planner::Spec;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let count: usize = args
        .first()
        .map_or(Ok(50), |c| c.parse())
        .expect("COUNT is a number of scenes");
    // The book's planners (`book_planners`: the gains that fit the scenes' robot), or those
    // named, with their gains as the book sets them.
    let book = book_planners();
    let planners: Vec<Spec> = args.get(1).map_or_else(
        || book.clone(),
        |list| {
            list.split(',')
                .map(|n| {
                    let n = n.trim();
                    book.iter()
                        .find(|s| s.name == n)
                        .cloned()
                        .unwrap_or_else(|| Spec::named(n))
                })
                .collect()
        },
    );
    let fail = |e: dvf::Error| -> ! {
        eprintln!("{e}");
        std::process::exit(2)
    };
    // Every planner runs with the shared safety barrier at its default rate: say so, and what
    // each avoids on its own, above the tables.
    println!(
        "Every planner runs on the same unicycles, sensing, limits and shared safety barrier \
         (barrier_rate = {} 1/s). The planners, with the gains that differ from their sources', and what each avoids on its own:\n",
        dvf::params::DEFAULT_BARRIER_RATE
    );
    for spec in &planners {
        if let Ok(e) = dvf::planner::entry(&spec.name) {
            let gains = if spec.gains.is_empty() {
                String::new()
            } else {
                format!(" with `{}`", serde_json::Value::Object(spec.gains.clone()))
            };
            println!("- `{}`{gains}: avoids {}", e.name, e.avoids);
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
