//! `rinshan render`: a picture of a table, from a log position (tenhou.net/6 or MJAI), a self-play seed or a
//! saved state; `--png` rasterises it; `--html` writes a log's whole game as a replay page.

use std::path::{Path, PathBuf};

use rinshan_engine::agents::Agent;
use rinshan_engine::env::{Config, Env, Mode};
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::Variant;
use rinshan_logs::read_log;
use rinshan_logs::tenhou::position::round_replay;
use rinshan_render::{Board, Options, RoundEndInput, TileMode};

use crate::args::VariantArg;
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// A log of one game, tenhou.net/6 or MJAI, plain or gzipped (`selfplay --export` writes them)
    #[arg(conflicts_with_all = ["seed", "state"])]
    log: Option<PathBuf>,
    /// Round: 0-based index into the log's rounds
    #[arg(long, default_value_t = 0)]
    round: usize,
    /// Decision, 0-based (a log: within the round, one past the last shows the result; a seed:
    /// steps played from the deal)
    #[arg(long, default_value_t = 0)]
    step: usize,
    /// Self-play a game from this seed with --agents and draw it after --step decisions
    #[arg(long)]
    seed: Option<u64>,
    /// The four seats' agents for --seed (random, rule, greedy, defensive)
    #[arg(long, default_value = "rule,rule,rule,rule", value_delimiter = ',')]
    agents: Vec<Agent>,
    /// A saved state: the little-endian u32 words of one env (Python's `env.get_state()[i]`)
    #[arg(long)]
    state: Option<PathBuf>,
    #[command(flatten)]
    variant: VariantArg,
    /// Tiles: ja (faces), en (faces with Latin labels) or ascii (labels only)
    #[arg(long, default_value = "en")]
    tiles: TileMode,
    /// The seat drawn at the bottom (0..3)
    #[arg(long, default_value_t = 0)]
    pov: u32,
    /// Show every hand face up
    #[arg(long)]
    reveal: bool,
    /// Write a PNG instead of SVG (needs --out)
    #[arg(long, requires = "out")]
    png: bool,
    /// PNG scale (1 = 960 pixels square)
    #[arg(long, default_value_t = 1.0)]
    scale: f32,
    /// Write here instead of standard output
    #[arg(long, short)]
    out: Option<PathBuf>,
    /// Write the log's whole game as a self-contained HTML replay page here
    #[arg(long)]
    html: Option<PathBuf>,
}

pub fn run(args: Args) -> Result<(), CliError> {
    if args.pov > 3 {
        return Err(CliError::input(format!("--pov {}: seats are 0..3", args.pov)));
    }
    if !(args.scale > 0.0 && args.scale <= 8.0) {
        return Err(CliError::input(format!(
            "--scale {}: give a number in (0, 8]",
            args.scale
        )));
    }
    if args.html.is_some() && args.log.is_none() {
        return Err(CliError::input("--html writes a logged game: give the log file"));
    }
    if let (Some(log), Some(html)) = (&args.log, &args.html) {
        let game = read_log(log).map_err(CliError::input)?;
        let page = rinshan_render::html::replay_html(&game, args.pov).map_err(CliError::input)?;
        return write(html, page.as_bytes());
    }
    let board = if let Some(log) = &args.log {
        log_board(log, args.round, args.step)?
    } else if let Some(seed) = args.seed {
        seed_board(seed, &args.agents, args.variant.variant, args.step)?
    } else if let Some(path) = &args.state {
        state_board(path, args.variant.variant)?
    } else {
        return Err(CliError::input("give a log file, --seed S or --state FILE"));
    };
    let opts = Options {
        tiles: args.tiles,
        pov: args.pov,
        reveal: args.reveal,
        defs: true,
    };
    let svg = rinshan_render::svg(&board, &opts);
    let bytes = if args.png {
        rinshan_render::png::png(&svg, args.scale).map_err(CliError::failure)?
    } else {
        svg.into_bytes()
    };
    match &args.out {
        Some(path) => write(path, &bytes),
        None => {
            use std::io::Write as _;
            std::io::stdout()
                .write_all(&bytes)
                .map_err(|e| CliError::failure(format!("standard output: {e}")))
        }
    }
}

fn write(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    std::fs::write(path, bytes).map_err(|e| CliError::input(format!("{}: {e}", path.display())))
}

fn log_board(path: &Path, round: usize, step: usize) -> Result<Board, CliError> {
    let game = read_log(path).map_err(CliError::input)?;
    let (positions, end) = round_replay(&game, round).map_err(CliError::input)?;
    let with_names = |mut b: Board| {
        b.names = game.names.clone();
        b
    };
    if let Some(p) = positions.get(step) {
        return Ok(with_names(Board::from_state(&p.state, game.variant)));
    }
    let result = match (positions.last(), &end) {
        (Some(last), Some(end)) if step == positions.len() => Board::logged_round_end(last, end),
        _ => None,
    };
    result.map(with_names).ok_or_else(|| {
        CliError::input(format!(
            "round {round} has {} decisions (0..{}; {} shows the result); --step {step} is past them",
            positions.len(),
            positions.len().saturating_sub(1),
            positions.len()
        ))
    })
}

fn seed_board(seed: u64, agents: &[Agent], variant: Variant, steps: usize) -> Result<Board, CliError> {
    let seats: [Agent; 4] = agents
        .try_into()
        .map_err(|_| CliError::input(format!("--agents names {} agents: give four", agents.len())))?;
    let mut env = Env::new(Config {
        mode: Mode::Half,
        seed,
        threads: Some(1),
        ..Config::new(variant, 1)
    })
    .map_err(CliError::failure)?;
    env.reset().map_err(CliError::failure)?;
    // Stopping right after a round ended shows that round's result over its last table.
    let mut ended = None;
    for _ in 0..steps {
        if env.last().terminated[0] {
            break;
        }
        let action = env.agent_actions(&[seats]).map_err(CliError::failure)?;
        let before = state(&env)?;
        let step = env.step(&action).map_err(CliError::failure)?.clone();
        let table = env.tables().map_err(CliError::failure)?.remove(0);
        let end = RoundEndInput {
            action: action[0],
            step: &step,
            env: 0,
            table: &table,
            variant,
            uma: env.uma(),
        };
        ended = Board::round_end(&before, &end);
    }
    let mut board = match ended {
        Some(board) => board,
        None => Board::from_state(&state(&env)?, variant),
    };
    let at_table = variant.seats() as usize;
    board.names = std::array::from_fn(|p| match p < at_table {
        true => format!("{} {p}", seats[p]),
        false => String::new(),
    });
    Ok(board)
}

fn state(env: &Env) -> Result<GameState, CliError> {
    let mut states = env.game_states().map_err(CliError::failure)?;
    states.pop().ok_or_else(|| CliError::failure("the env holds no game"))
}

fn state_board(path: &Path, variant: Variant) -> Result<Board, CliError> {
    // A state is a few hundred words: a file past a log's cap is no state and is not read whole.
    let bytes = rinshan_logs::file::read_log_bytes(path).map_err(CliError::input)?;
    if bytes.len() % 4 != 0 {
        return Err(CliError::input(format!(
            "{}: {} bytes is not a whole number of u32 words",
            path.display(),
            bytes.len()
        )));
    }
    let words: Vec<u32> = bytes
        .chunks(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    let mut env = Env::new(Config {
        threads: Some(1),
        ..Config::new(variant, 1)
    })
    .map_err(CliError::failure)?;
    if words.len() != env.saved_words() {
        return Err(CliError::input(format!(
            "{}: {} words; one saved {variant} game is {} (Python: env.get_state()[i].tofile(path))",
            path.display(),
            words.len(),
            env.saved_words()
        )));
    }
    env.load_states(&words)
        .map_err(|e| CliError::input(format!("{}: {e}", path.display())))?;
    Ok(Board::from_state(&state(&env)?, variant))
}
