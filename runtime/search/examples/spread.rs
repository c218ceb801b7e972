//! Fits the spread of the look-ahead's placement value ([`rinshan_search::value`]) to `defensive`
//! self-play (docs/strength.md):
//!
//!     cargo run --release -p rinshan-search --example spread -- [variant] [games]
//!
//! At the start of every round but the first, each pair of seats whose scores differ: the lead,
//! the rounds left, and whether the seat ahead finished ahead. The value's model gives the chance
//! of that as a normal spread of the rounds left; the spread under which the counted outcomes are
//! likeliest is printed, overall and by rounds left (the model says it is one number), with the
//! model's chances against the counts at the hand-set spread of before (5,600 points) and at the
//! fitted one.

use rinshan_engine::Variant;
use rinshan_search::value::{finishes_ahead, fit, leads, log_likelihood, spread, Lead};

/// The spread set by hand before it was fitted.
const HAND_SET: f64 = 5600.0;

fn main() {
    let mut args = std::env::args().skip(1);
    let variant: Variant = args.next().unwrap_or_else(|| "red".into()).parse().expect("a variant");
    let games: u64 = args.next().map_or(2000, |a| a.parse().expect("a number of games"));
    let all = leads(variant, games, 9000);
    let best = fit(&all);
    let per_lead = |spread: f64| log_likelihood(&all, spread) / all.len() as f64;
    println!("{variant}: {games} half games of defensive, {} leads", all.len());
    println!(
        "likeliest spread {best:.0} points (the look-ahead's: {:.0}); log-likelihood per lead {:.4}, at {HAND_SET:.0} {:.4}",
        spread(variant),
        per_lead(best),
        per_lead(HAND_SET)
    );
    let mut lefts: Vec<f64> = all.iter().map(|l| l.left).collect();
    lefts.sort_by(f64::total_cmp);
    lefts.dedup();
    println!("\nrounds left | leads | likeliest spread");
    for left in lefts {
        let some: Vec<Lead> = all.iter().filter(|l| l.left == left).copied().collect();
        println!("{left:>11} | {:>5} | {:.0}", some.len(), fit(&some));
    }
    println!("\nchance the lead holds (fitted) | leads | held | model at {HAND_SET:.0} | model at {best:.0}");
    for bin in 5..10 {
        let (lo, hi) = (f64::from(bin) / 10.0, f64::from(bin + 1) / 10.0);
        let inside: Vec<&Lead> = all
            .iter()
            .filter(|l| {
                let p = finishes_ahead(l.points, l.left, best);
                (lo..hi).contains(&p) || (bin == 9 && p >= 1.0)
            })
            .collect();
        if inside.is_empty() {
            continue;
        }
        let n = inside.len() as f64;
        let held = inside.iter().filter(|l| l.held).count() as f64 / n;
        let model = |s| inside.iter().map(|l| finishes_ahead(l.points, l.left, s)).sum::<f64>() / n;
        println!(
            "{lo:.1}-{hi:.1} | {} | {held:.3} | {:.3} | {:.3}",
            inside.len(),
            model(HAND_SET),
            model(best)
        );
    }
}
