"""The batched env's API: shapes and dtypes, determinism, buffers, state round trips, hero mode."""

import pickle
import threading
import time

import numpy as np
import pytest

import rinshan


def random_actions(ts, rng):
    m = ts.legal_action_mask
    return np.argmax(m * rng.random(m.shape), axis=1)


def play(env, steps, seed=0):
    rng = np.random.default_rng(seed)
    ts = env.reset()
    out = [ts.copy()]
    for _ in range(steps):
        ts = env.step(random_actions(ts, rng))
        out.append(ts.copy())
    return out


@pytest.mark.parametrize(
    "variant,actions",
    [
        ("red", 87),
        ("mjsoul", 87),
        ("mleague", 86),
        ("no-red", 79),
        ("wrc", 79),
        ("sanma", 82),
        ("mjsoul-sanma", 82),
    ],
)
def test_shapes_and_dtypes(variant, actions):
    env = rinshan.make(
        variant, num_envs=5, observation=("planes", "tokens"), analysis=True, num_threads=1
    )
    ts = env.reset()
    assert ts.legal_action_mask.shape == (5, actions) and ts.legal_action_mask.dtype == bool
    assert ts.current_player.shape == (5,) and ts.current_player.dtype == np.int32
    assert ts.rewards.shape == (5, 4) and ts.rewards.dtype == np.float32
    assert ts.terminated.dtype == bool and ts.truncated.dtype == bool
    assert ts.observation["planes"].shape == (5, 64, 34)
    assert ts.observation["planes"].dtype == np.uint8
    assert ts.observation["scalars"].shape == (5, 48)
    assert ts.observation["events"].shape == (5, 192, 4)
    assert ts.observation["discard_shanten"].shape[0] == 5
    assert env.spec.num_actions == actions == len(env.spec.action_names)
    assert ts.info["final_rank"].shape == (5, 4) and ts.info["yaku"].shape[1] == len(
        env.spec.yaku_names
    )
    assert (ts.info["env_id"] == np.arange(5)).all()
    # Every env has a legal action and the seat to act is a seat.
    assert ts.legal_action_mask.any(axis=1).all()
    assert set(ts.current_player) <= {0, 1, 2, 3}
    for f in env.spec.fields["planes"]:
        assert (
            ts.observation[f.name].dtype == f.dtype and ts.observation[f.name].shape[1:] == f.shape
        )


def test_outputs_are_reused_read_only_views():
    env = rinshan.make(num_envs=3, num_threads=1)
    ts = env.reset()
    ts2 = env.step(random_actions(ts, np.random.default_rng(1)))
    assert ts is ts2
    assert not ts.legal_action_mask.flags.writeable
    with pytest.raises(ValueError):
        ts.rewards[0, 0] = 1.0


def test_same_seed_same_games_and_thread_counts_agree():
    a = play(rinshan.make(num_envs=64, seed=3, num_threads=1), 300)
    b = play(rinshan.make(num_envs=64, seed=3, num_threads=2), 300)
    c = play(rinshan.make(num_envs=64, seed=4, num_threads=2), 300)
    for x, y in zip(a, b):
        assert (x.observation["planes"] == y.observation["planes"]).all()
        assert (x.rewards == y.rewards).all() and (x.legal_action_mask == y.legal_action_mask).all()
    assert any((x.observation["planes"] != z.observation["planes"]).any() for x, z in zip(a, c))


def same_timestep(x, y):
    assert x.info.keys() == y.info.keys() and x.observation.keys() == y.observation.keys()
    for k in x.info:
        assert (x.info[k] == y.info[k]).all(), k
    for k in x.observation:
        assert (x.observation[k] == y.observation[k]).all(), k
    assert (x.legal_action_mask == y.legal_action_mask).all()
    assert (x.current_player == y.current_player).all() and (x.rewards == y.rewards).all()
    assert (x.terminated == y.terminated).all() and (x.truncated == y.truncated).all()


@pytest.mark.parametrize("hero", [False, True])
def test_threads_write_every_array_as_one_thread_does(hero):
    # 1100 envs: the outputs are filled in parts of a few hundred rows on the env's threads, the
    # last part short; one-hand games end often, so final scores, ranks and the episode ids
    # numbered after the parts are exercised in every part.
    kw = dict(num_envs=1100, seed=5, mode="single", observation=("tokens",))
    if hero:
        kw.update(opponents="random", hero_seats=np.arange(1100) % 4)
    a = play(rinshan.make(num_threads=1, **kw), 120)
    b = play(rinshan.make(num_threads=2, **kw), 120)
    assert sum(int(x.terminated.sum()) for x in a) > 1100
    for x, y in zip(a, b):
        same_timestep(x, y)
    # What every row must show whatever part it is filled in: final scores are the start plus
    # the rewards, places only where a game ended, ids new exactly where one did, the hero flag
    # on the hero's turns only.
    sums = np.zeros((1100, 4))
    seen = set(b[0].info["episode_id"].tolist())
    assert len(seen) == 1100
    for prev, ts in zip(b, b[1:]):
        sums += ts.rewards * ~ts.info["illegal"][:, None]
        end = ts.terminated
        assert (ts.info["final_scores"][end] == 25000 + np.round(sums[end] * 100)).all()
        assert (ts.info["final_rank"][~end] == -1).all()
        sums[end] = 0
        moved = ts.info["episode_id"] != prev.info["episode_id"]
        assert (moved == prev.terminated).all()
        new = ts.info["episode_id"][moved].tolist()
        assert not seen & set(new) and len(set(new)) == len(new)
        seen |= set(new)
        if hero:
            on = ts.info["hero"]
            assert (ts.current_player[on] == (np.arange(1100) % 4)[on]).all() and on.any()


def test_reset_with_a_seed_repeats_and_without_deals_new_games():
    env = rinshan.make(num_envs=8, num_threads=1)
    first = env.reset(seed=5).copy()
    again = env.reset(seed=5).copy()
    fresh = env.reset().copy()
    assert (first.observation["planes"] == again.observation["planes"]).all()
    assert (first.observation["planes"] != fresh.observation["planes"]).any()


def test_observe_matches_the_step_observation_and_seats_differ():
    env = rinshan.make(num_envs=6, observation=("planes", "tokens"), num_threads=1)
    ts = env.reset(seed=2)
    for _ in range(40):
        ts = env.step(random_actions(ts, np.random.default_rng(0)))
    now = env.observe()
    for k in ("planes", "scalars"):
        assert (now[k] == ts.observation[k]).all()
    seats = ts.current_player
    assert (env.observe(seats)["planes"] == ts.observation["planes"]).all()
    tok = env.observe(seats, form="tokens")
    assert (tok["hand"] == ts.observation["hand"]).all()
    other = env.observe((seats + 1) % 4)
    assert (other["planes"] != ts.observation["planes"]).any()
    allseats = env.observe_all()
    assert allseats["planes"].shape == (6, 4, 64, 34)
    assert (allseats["planes"][np.arange(6), seats] == ts.observation["planes"]).all()


def test_oracle_shows_hidden_hands_only_when_asked():
    env = rinshan.make(num_envs=2, num_threads=1)
    env.reset()
    with pytest.raises(RuntimeError, match="oracle=True"):
        env.oracle()
    env = rinshan.make(num_envs=2, oracle=True, num_threads=1)
    env.reset(seed=1)
    o = env.oracle()
    hands = o["others_hand"].reshape(2, 3, 34).sum(axis=-1)
    # At the deal the three others hold 13 tiles each, or 14 for a dealer about to discard.
    assert set(hands.ravel()) <= {13, 14} and (hands.sum(axis=1) >= 39).all()


def test_get_state_pickles_and_restores_the_same_future():
    env = rinshan.make(num_envs=16, seed=9, num_threads=1)
    ts = env.reset()
    rng = np.random.default_rng(4)
    for _ in range(100):
        ts = env.step(random_actions(ts, rng))
    saved = pickle.loads(pickle.dumps(env.get_state()))
    actions = []
    future = []
    for _ in range(200):
        a = random_actions(ts, rng)
        actions.append(a)
        ts = env.step(a)
        future.append(ts.copy())
    other = rinshan.make(num_envs=16, seed=0, num_threads=2)
    other.set_state(saved)
    for a, want in zip(actions, future):
        got = other.step(a)
        assert (got.observation["planes"] == want.observation["planes"]).all()
        assert (got.rewards == want.rewards).all()
        assert (got.info["final_scores"] == want.info["final_scores"]).all()
    edited = saved.copy()
    edited[3, 10] ^= 1
    with pytest.raises(ValueError, match="env 3: its check words do not match"):
        other.set_state(edited)
    with pytest.raises(ValueError, match="shape"):
        other.set_state(saved[:5])


def test_final_scores_and_ranks_where_games_end():
    env = rinshan.make(num_envs=32, seed=1, num_threads=1)
    ts = env.reset()
    rng = np.random.default_rng(0)
    sums = np.zeros((32, 4))
    ended = 0
    while ended < 40:
        ts = env.step(random_actions(ts, rng))
        sums += ts.rewards * ~ts.info["illegal"][:, None]
        for i in np.nonzero(ts.terminated)[0]:
            scores, rank = ts.info["final_scores"][i], ts.info["final_rank"][i]
            assert sorted(rank) == [0, 1, 2, 3]
            assert (scores == 25000 + np.round(sums[i] * 100)).all()
            order = np.argsort(rank)
            assert (np.diff(scores[order]) <= 0).all()
            sums[i] = 0
            ended += 1
        live = ~ts.terminated
        assert (ts.info["final_rank"][live] == -1).all()


def test_episode_ids_are_unique_per_game():
    env = rinshan.make(num_envs=4, num_threads=1)
    rng = np.random.default_rng(2)
    seen = {}
    for _ in range(2):
        # Ids stay unique across resets too.
        ts = env.reset()
        for _ in range(3000):
            ids = ts.info["episode_id"].copy()
            ts = env.step(random_actions(ts, rng))
            for i in range(4):
                assert seen.setdefault(int(ids[i]), i) == i
    assert len(seen) > 8


def test_hero_mode_asks_only_the_hero():
    env = rinshan.make(num_envs=16, opponents="greedy", hero_seats=np.arange(16) % 4, num_threads=1)
    ts = env.reset(seed=1)
    rng = np.random.default_rng(3)
    steps = 0
    for _ in range(2000):
        hero = ts.info["hero"]
        assert (ts.current_player[hero] == (np.arange(16) % 4)[hero]).all()
        ts = env.step(random_actions(ts, rng))
        steps += 1
    assert ts.info["hero"].mean() > 0.5


def test_evaluate_duplicate_rates_rule_over_random():
    r = rinshan.evaluate("rule", opponents="random", games=40, seed=1, num_threads=1)
    assert r.games == 40 and sum(r.rank_counts) == 40
    assert r.average_rank < 1.5 and r.illegal == 0

    def first_legal(ts):
        return np.argmax(ts.legal_action_mask, axis=1)

    r = rinshan.evaluate(first_legal, opponents="rule", games=20, seed=1, num_threads=1)
    assert r.average_rank > 2.5 and r.ci95 > 0

    def first_illegal(ts):
        return np.argmin(ts.legal_action_mask, axis=1)

    r = rinshan.evaluate(first_illegal, opponents="rule", games=8, seed=1, num_threads=1)
    assert r.illegal == 8 and r.average_rank == 4.0 and r.rank_counts == [0, 0, 0, 8]


def test_hand_calculator_mirrors_the_cli():
    assert rinshan.shanten("123m456p789s1122z")["shanten"] == 0
    s = rinshan.score("234567m234p4566s", "6s", tsumo=True, riichi=True)
    assert s["han"] == 4 and s["fu"] == 20 and s["points"]["total"] == 5200
    with pytest.raises(ValueError, match="ippatsu needs riichi"):
        rinshan.score("234567m234p4566s", "6s", ippatsu=True)
    with pytest.raises(ValueError, match="5 copies"):
        rinshan.shanten("11111m")
    with pytest.raises(TypeError, match="unknown flag"):
        rinshan.score("234567m234p4566s", "6s", tsumoo=True)


def test_step_releases_the_gil():
    # A Python thread can only run while the main thread is inside `step` if `step` released the
    # GIL: count its ticks that fall strictly within step calls.
    env = rinshan.make(num_envs=4096, num_threads=1)
    ts = env.reset()
    ticks, stop = [], threading.Event()

    def spin():
        while not stop.is_set():
            ticks.append(time.perf_counter())

    thread = threading.Thread(target=spin)
    thread.start()
    inside = []
    try:
        rng = np.random.default_rng(0)
        for _ in range(30):
            a = random_actions(ts, rng)
            t0 = time.perf_counter()
            ts = env.step(a)
            inside.append((t0, time.perf_counter()))
    finally:
        stop.set()
        thread.join()
    ticks = np.array(ticks)
    during = sum(
        int(np.searchsorted(ticks, t1) - np.searchsorted(ticks, t0, "right")) for t0, t1 in inside
    )
    assert during > 0


def test_render_draws_what_the_seat_holds():
    import xml.etree.ElementTree as ET

    env = rinshan.make(num_envs=3, num_threads=1, observation="tokens")
    ts = play(env, 37, seed=4)[-1]
    names = [f"{n}{s}" for s in "mps" for n in range(1, 10)] + [f"{n}z" for n in range(1, 8)]
    for i in range(3):
        seat = int(ts.current_player[i])
        svg = env.render(i, tiles="ascii")
        tiles = [
            g
            for g in ET.fromstring(svg).iter("{http://www.w3.org/2000/svg}g")
            if g.get("class") == "tile"
        ]
        mine = [
            g.get("data-tile")
            for g in tiles
            if g.get("data-seat") == str(seat) and g.get("data-zone") in ("hand", "drawn")
        ]
        others = [
            g.get("data-tile")
            for g in tiles
            if g.get("data-seat") not in (str(seat), "4")
            and g.get("data-zone") in ("hand", "drawn")
        ]
        # The seat to act sees its own hand, as its observation counts it (red fives as fives).
        counts = np.zeros(34, dtype=int)
        for t in mine:
            counts[names.index(t.replace("0", "5"))] += 1
        assert (counts == ts.observation["hand"][i]).all()
        assert others and set(others) == {"back"}
        revealed = env.render(i, pov=(seat + 1) % 4, reveal=True)
        assert 'data-tile="back" data-seat="0" data-zone="hand"' not in revealed
    png = env.render(0, tiles="ja", png=True)
    assert isinstance(png, bytes) and png[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ValueError, match="env 3 does not exist"):
        env.render(3)
    with pytest.raises(ValueError, match="unknown tile mode"):
        env.render(0, tiles="kanji")
    with pytest.raises(ValueError, match="seats are 0..3"):
        env.render(0, pov=4)
    with pytest.raises(TypeError):
        env.render(-1)


def test_evaluate_against_a_function_seats_the_opponents_by_turn():
    def first_legal(ts):
        return np.argmax(ts.legal_action_mask, axis=1)

    # The same deterministic function in all four seats: each wall set is the same game four
    # times, so the policy takes each place exactly once.
    r = rinshan.evaluate(first_legal, opponents=first_legal, games=40, seed=2, mode="single")
    assert r.average_rank == 2.5 and r.ci95 == 0 and r.rank_counts == [10, 10, 10, 10]

    # Random play written in Python loses to `rule` as the built-in random agent does.
    rng = np.random.default_rng(0)

    def random_legal(ts):
        return np.argmax(ts.legal_action_mask * rng.random(ts.legal_action_mask.shape), axis=1)

    r = rinshan.evaluate("rule", opponents=random_legal, games=40, seed=1, mode="east")
    assert r.average_rank < 1.5 and r.illegal == 0 and sum(r.rank_counts) == 40

    def first_illegal(ts):
        return np.argmin(ts.legal_action_mask, axis=1)

    with pytest.raises(ValueError, match="opponents function played an illegal action"):
        rinshan.evaluate("rule", opponents=first_illegal, games=4, seed=1, mode="single")


def test_packed_planes_unpack_to_the_planes():
    env = rinshan.make(num_envs=7, observation=("planes", "packed"), num_threads=1)
    spec = {f.name: f for f in env.spec.fields["packed"]}
    assert spec["bits"].dtype == np.uint64 and spec["counts"].shape == (28, 34)
    rng = np.random.default_rng(3)
    ts = env.reset(seed=5)
    for _ in range(300):
        unpacked = rinshan.unpack_planes(ts.observation)
        assert (unpacked["planes"] == ts.observation["planes"]).all()
        ts = env.step(random_actions(ts, rng))
    # Any seat, and a leading shape of seats.
    every = env.observe_all("packed")
    assert (rinshan.unpack_planes(every)["planes"] == env.observe_all("planes")["planes"]).all()
    rows = rinshan.packed_rows()
    assert sorted(i for kind, i in rows if kind == "bits") == list(range(36))
    assert sorted(i for kind, i in rows if kind == "counts") == list(range(28))
    with pytest.raises(ValueError, match="packed arrays"):
        rinshan.unpack_planes(
            {"bits": every["bits"].astype(np.int64), "counts": every["counts"], "scalars": None}
        )
    with pytest.raises(ValueError, match="packed arrays"):
        rinshan.unpack_planes(
            {"bits": every["bits"], "counts": every["counts"][..., :27, :], "scalars": None}
        )


def test_three_player_games_end_with_three_places():
    env = rinshan.make("sanma", num_envs=16, seed=5, num_threads=1)
    assert env.spec.num_players == 3 and "kita" in env.spec.action_names
    assert not any(n.startswith("chi") for n in env.spec.action_names)
    ts = env.reset()
    rng = np.random.default_rng(1)
    sums = np.zeros((16, 4))
    ended = 0
    while ended < 24:
        assert set(ts.current_player) <= {0, 1, 2}
        ts = env.step(random_actions(ts, rng))
        sums += ts.rewards * ~ts.info["illegal"][:, None]
        for i in np.nonzero(ts.terminated)[0]:
            scores, rank = ts.info["final_scores"][i], ts.info["final_rank"][i]
            # The fourth seat of the state holds the place no one does, and no points.
            assert sorted(rank[:3]) == [0, 1, 2] and rank[3] == 3 and scores[3] == 0
            assert (scores[:3] == 35000 + np.round(sums[i, :3] * 100)).all()
            assert sums[i, 3] == 0
            sums[i] = 0
            ended += 1
    assert env.observe_all()["planes"].shape == (16, 3, 64, 34)
    with pytest.raises(ValueError, match="seats are 0..2"):
        env.observe(3)
    svg = env.render(0, reveal=True)
    assert svg.count('<g class="seat"') == 3
    with pytest.raises(ValueError, match="seats are 0..2"):
        env.render(0, pov=3)


def test_evaluate_rotates_over_three_seats_in_sanma():
    r = rinshan.evaluate(
        "rule", opponents="random", games=30, seed=1, variant="sanma", num_threads=1
    )
    assert r.games == 30 and len(r.rank_counts) == 3 and sum(r.rank_counts) == 30
    assert r.average_rank < 1.6 and r.illegal == 0


def test_version_is_the_workspace_version():
    # One place declares the version, the workspace's Cargo.toml; `rinshan --version` prints it too.
    import pathlib
    import re

    cargo = (pathlib.Path(__file__).resolve().parents[2] / "Cargo.toml").read_text()
    section = cargo.split("[workspace.package]", 1)[1].split("\n[", 1)[0]
    want = re.search(r'^version = "([^"]+)"', section, re.M).group(1)
    assert rinshan.__version__ == want
