//! The look-ahead's settings as users write them: `search`, or `search:rollouts=512:base=rule`
//! (colons, as commas separate the seats of `--agents`).

use rinshan_engine::agents::Agent;
use rinshan_engine::env::Backend;

/// How the look-ahead spends its budget.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Play-outs per decision, over all candidates (the budget: a decision with one legal action,
    /// or that is not the seat's own turn, spends none).
    pub rollouts: u32,
    /// Milliseconds per decision, a cap on top of `rollouts` (0: none). A time cap makes the
    /// decision depend on the machine's speed; a rollout budget alone is deterministic.
    pub ms: u32,
    /// The agent that plays every seat in the play-outs, and the decisions the look-ahead leaves
    /// alone (claim prompts).
    pub base: Agent,
    /// How sure the look-ahead must be to play other than `base`: the paired mean gain over the
    /// base agent's action, in standard errors.
    pub margin: f64,
    /// Seeds the worlds.
    pub seed: u64,
    /// Which own-turn decisions are looked ahead at.
    pub focus: Focus,
    /// Where the play-outs run: each round of the budget's halving, and the duel, is one batch,
    /// played one world after another on the CPU or all at once on the GPU (the same decisions:
    /// the same kernel plays them). Without a GPU they run on the CPU, with a warning.
    pub backend: Backend,
}

/// Which decisions the look-ahead plays out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Focus {
    /// Every own-turn decision with a choice.
    All,
    /// Those where much is at stake: another seat is in riichi (push or fold), or the seat may
    /// declare riichi. The base agent's efficient discards elsewhere differ from the alternatives
    /// by less than the play-outs can tell apart at these budgets (docs/strength.md).
    Threats,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            rollouts: 256,
            ms: 0,
            base: Agent::Defensive,
            margin: 2.0,
            seed: 0,
            focus: Focus::Threats,
            backend: Backend::Cpu,
        }
    }
}

impl Options {
    /// The agent's name in reports: `search`, with the settings that differ from the defaults.
    pub fn name(&self) -> String {
        let d = Options::default();
        let mut parts = Vec::new();
        if self.rollouts != d.rollouts {
            parts.push(format!("rollouts={}", self.rollouts));
        }
        if self.ms != d.ms {
            parts.push(format!("ms={}", self.ms));
        }
        if self.base != d.base {
            parts.push(format!("base={}", self.base));
        }
        if self.margin != d.margin {
            parts.push(format!("margin={}", self.margin));
        }
        if self.seed != d.seed {
            parts.push(format!("seed={}", self.seed));
        }
        if self.focus != d.focus {
            parts.push(format!("focus={}", ["all", "threats"][self.focus as usize]));
        }
        if self.backend != d.backend {
            parts.push(format!("backend={}", self.backend.name()));
        }
        match parts.is_empty() {
            true => "search".into(),
            false => format!("search:{}", parts.join(":")),
        }
    }
}

impl std::str::FromStr for Options {
    type Err = String;

    /// `search` or `search:KEY=VALUE:...` with keys `rollouts`, `ms`, `base`, `margin`, `seed`,
    /// `focus`, `backend`.
    fn from_str(s: &str) -> Result<Options, String> {
        let rest = match s.strip_prefix("search") {
            Some("") => return Ok(Options::default()),
            Some(r) => r
                .strip_prefix(':')
                .ok_or_else(|| format!("`{s}`: write search or search:rollouts=N:..."))?,
            None => {
                return Err(format!(
                    "`{s}` is not the look-ahead agent (search or search:rollouts=N:...)"
                ))
            }
        };
        let mut o = Options::default();
        for part in rest.split(':').filter(|p| !p.is_empty()) {
            let (key, value) = part
                .split_once('=')
                .ok_or_else(|| format!("search option `{part}`: write KEY=VALUE"))?;
            let bad = |e: &dyn std::fmt::Display| format!("search option {key}={value}: {e}");
            match key {
                "rollouts" => o.rollouts = value.parse().map_err(|e| bad(&e))?,
                "ms" => o.ms = value.parse().map_err(|e| bad(&e))?,
                "base" => o.base = value.parse().map_err(|e| bad(&e))?,
                "margin" => {
                    o.margin = value.parse().map_err(|e| bad(&e))?;
                    if !o.margin.is_finite() {
                        return Err(bad(&"a finite number"));
                    }
                }
                "seed" => o.seed = value.parse().map_err(|e| bad(&e))?,
                "focus" => {
                    o.focus = match value {
                        "all" => Focus::All,
                        "threats" => Focus::Threats,
                        _ => return Err(bad(&"all or threats")),
                    }
                }
                "backend" => o.backend = value.parse().map_err(|e| bad(&e))?,
                _ => {
                    return Err(format!(
                        "unknown search option `{key}` (rollouts, ms, base, margin, seed, focus, backend)"
                    ))
                }
            }
        }
        if o.rollouts == 0 {
            return Err("search needs a budget: rollouts=N above 0 (ms=M caps its time too)".into());
        }
        Ok(o)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_parse_back_to_the_same_options() {
        for text in [
            "search",
            "search:rollouts=64",
            "search:rollouts=8:ms=50:base=rule:margin=0.5:seed=3:focus=all:backend=gpu",
        ] {
            let o: Options = text.parse().unwrap();
            assert_eq!(o.name(), text);
            assert_eq!(o.name().parse::<Options>().unwrap(), o);
        }
    }

    #[test]
    fn bad_options_say_what_is_wrong() {
        for (text, says) in [
            ("search:rollouts=x", "rollouts=x"),
            ("search:depth=3", "unknown search option `depth`"),
            ("search:base=alpha", "base=alpha"),
            ("search:rollouts=0", "needs a budget"),
            ("search:margin=NaN", "finite"),
            ("search:backend=tpu", "backend=tpu"),
            ("searching", "write search"),
            ("rule", "not the look-ahead"),
        ] {
            let e = text.parse::<Options>().unwrap_err();
            assert!(e.contains(says), "{text}: {e}");
        }
    }
}
