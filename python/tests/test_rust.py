"""The package against the Rust engine it wraps: the same seeds and agents play the same games as
the `rinshan` CLI, and log records carry the same observations the CLI prints."""

import json
import subprocess

import numpy as np
import pytest

import rinshan


@pytest.mark.parametrize("variant", ["red", "mleague"])
def test_same_seed_same_games_as_the_cli(cli, tmp_path, variant):
    # The CLI's self-play with four rule agents, exported as Tenhou logs ...
    args = f"selfplay --variant {variant} --agents rule,rule,rule,rule --batch 4 --games 4 --seed 7"
    args += " --threads 1 --json"
    out = subprocess.run(
        [cli, *args.split(), "--export", str(tmp_path)], check=True, capture_output=True, text=True
    ).stdout
    summary = json.loads(out)
    # ... and the package's env with the same seed, stepped with the same agent's actions.
    env = rinshan.make(variant, num_envs=4, seed=7, num_threads=1, auto_reset=False)
    ts = env.reset()
    ack = env.spec.action_names.index("dummy")
    played = [[] for _ in range(4)]
    done = np.zeros(4, dtype=bool)
    final_scores = np.zeros((4, 4))
    rounds = np.zeros(4)
    while not done.all():
        a = env.agent_actions("rule")
        for i in np.nonzero(~done)[0]:
            if a[i] != ack:
                played[i].append(int(a[i]))
        ts = env.step(a)
        for i in np.nonzero(ts.terminated & ~done)[0]:
            final_scores[i] = ts.info["final_scores"][i]
            rounds[i] = ts.info["rounds"][i]
        done |= ts.terminated
    logged = []
    for path in sorted(tmp_path.glob("game-*.json")):
        game = rinshan.tenhou.read(str(path))
        # The log names its rule set and is replayed under it: actions are the variant's ids.
        assert game["variant"] == variant
        logged.append([int(a) for r in game["rounds"] for a in r["action"]])
    # The logs are numbered in the order games finished: match them to envs by content.
    assert sorted(map(tuple, logged)) == sorted(map(tuple, played))
    assert min(len(p) for p in played) > 100
    # The same rewards: the CLI's average final score by seat, and the same number of rounds.
    assert final_scores.mean(axis=0).tolist() == summary["avg_final_score"]
    assert rounds.mean() == summary["avg_rounds_per_game"]
    assert sum(map(len, played)) == summary["steps"]


def test_log_records_match_the_cli_observation(cli, log_path):
    game = rinshan.tenhou.read(log_path, observation=("planes", "tokens"))
    rounds = [r for r in game["rounds"] if "error" not in r]
    assert rounds and len(rounds) == len(game["rounds"])
    for r_index, step in [(0, 0), (0, 7), (1, 12), (2, 3)]:
        r = game["rounds"][r_index]
        for form in ("planes", "tokens"):
            out = subprocess.run(
                [
                    cli,
                    "observe",
                    log_path,
                    "--round",
                    str(r_index),
                    "--step",
                    str(step),
                    "--form",
                    form,
                    "--json",
                ],
                check=True,
                capture_output=True,
                text=True,
            ).stdout
            cli_obs = json.loads(out)
            assert cli_obs["deciding_seat"] == r["seat"][step]
            for name, f in cli_obs["fields"].items():
                got = r["observation"][name][step]
                want = np.array(f["values"], dtype=f["dtype"]).reshape(f["shape"])
                assert (got == want).all(), (r_index, step, name)


def test_replay_agrees_with_the_logs(log_path):
    report = rinshan.replay([log_path])
    assert report["games"] == 1 and report["all_agree"], report["mismatches"][:3]
    assert report["actions_accepted"] == report["actions"] > 100


def test_replay_under_a_rule_set_the_log_does_not_name(cli, tmp_path):
    # M-League games from the CLI, their rule set's name taken out of the logs ...
    out = tmp_path / "named"
    args = "selfplay --variant mleague --games 2 --batch 2 --seed 5"
    subprocess.run([cli, *args.split(), "--export", str(out)], check=True, capture_output=True)
    unnamed = tmp_path / "unnamed"
    unnamed.mkdir()
    for path in out.glob("game-*.json"):
        text = path.read_text()
        assert ',"variant":"mleague"' in text
        (unnamed / path.name).write_text(text.replace(',"variant":"mleague"', ""))
    # ... replay under M-League's rules when asked; a rule set without red fives refuses them.
    report = rinshan.replay([str(unnamed)], variant="mleague")
    assert report["games"] == 2 and report["all_agree"], report["mismatches"][:3]
    with pytest.raises(ValueError, match="the log plays red fives, wrc has none"):
        rinshan.replay([str(unnamed)], variant="wrc")
    with pytest.raises(ValueError, match="blue"):
        rinshan.replay([str(unnamed)], variant="blue")
