//! How long the GPU adapter takes to compile each pipeline of a variant's shader module: every
//! stage's first use, timed on its own (a cold driver cache gives the figures CI pays; on Mesa set
//! `MESA_SHADER_CACHE_DISABLE=true`).
//!
//! `cargo run --release -p rinshan-engine --example pipeline_times -- [variant] [stage...]`
//! with stages from `new step planes tokens packed analysis oracle agent play` (default: all). The reset (the
//! new-game and view pipelines) is always timed first; `play` is hero mode (its agents'
//! pipeline, `game_play_action_main`, beside the step's).

use std::time::Instant;

use rinshan_engine::agents::Agent;
use rinshan_engine::env::{Backend, Config, Env};
use rinshan_engine::observe::Form;
use rinshan_engine::Variant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let variant: Variant = args.first().map(String::as_str).unwrap_or("red").parse()?;
    let all = [
        "new", "step", "planes", "tokens", "packed", "analysis", "oracle", "agent", "play",
    ];
    let stages: Vec<&str> = if args.len() > 1 {
        args[1..].iter().map(String::as_str).collect()
    } else {
        all.to_vec()
    };
    let mut config = Config::new(variant, 4);
    config.backend = Backend::Gpu;
    let mut env = Env::new(config.clone())?;
    println!("{variant} on {}", env.adapter().unwrap_or_default());
    let time = |name: &str, f: &mut dyn FnMut() -> Result<(), Box<dyn std::error::Error>>| {
        let started = Instant::now();
        let result = f();
        println!("{name:<8} {:8.1} s", started.elapsed().as_secs_f64());
        result
    };
    // A reset compiles the new-game and view pipelines; every later stage needs a game to run on.
    time("new+view", &mut || env.reset().map(|_| ()).map_err(Into::into))?;
    for stage in stages {
        match stage {
            "new" => {}
            "step" => time("step", &mut || {
                let actions = first_legal(&env);
                env.step(&actions).map(|_| ()).map_err(Into::into)
            })?,
            "planes" | "tokens" | "packed" | "analysis" | "oracle" => {
                let form: Form = stage.parse()?;
                time(stage, &mut || env.observe_all(form).map(|_| ()).map_err(Into::into))?
            }
            "agent" => time("agent", &mut || {
                env.agent_actions(&[[Agent::Rule, Agent::Greedy, Agent::Defensive, Agent::Random]])
                    .map(|_| ())
                    .map_err(Into::into)
            })?,
            "play" => {
                let mut hero = config.clone();
                hero.agents = vec![[None, Some(Agent::Rule), Some(Agent::Greedy), Some(Agent::Defensive)]];
                // A second env opens its own device, so its reset compiles the reset's pipelines
                // again (untimed), and its first step the step's (timed, unless `step` ran before
                // and Mesa's cache serves it).
                let mut played = Env::new(hero)?;
                played.reset()?;
                time("play", &mut || {
                    let actions = first_legal(&played);
                    played.step(&actions).map(|_| ()).map_err(Into::into)
                })?
            }
            other => return Err(format!("unknown stage {other:?} (one of {all:?})").into()),
        }
    }
    Ok(())
}

/// Each env's first legal action: any legal step compiles the pipeline.
fn first_legal(env: &Env) -> Vec<u32> {
    (0..env.batch())
        .map(|i| env.last().legal_actions(i).next().unwrap_or(0))
        .collect()
}
