"""Annealing: fewer violations always win, Metropolis decides between equals; the temperature
falls from t_start to t_end; discrete moves fade as continuous ones grow; a run keeps to its
stage, leaves a consistent state, reports what it did and repeats itself for a seed."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.constraints.evaluator import Evaluator, Result
from indoorgen.solver.anneal import (
    MOVES_CONTINUOUS,
    MOVES_DISCRETE,
    AnnealConfig,
    Annealer,
    accept,
    move_weights,
    temperature_at,
)
from indoorgen.solver.moves import MOVES
from indoorgen.solver.stages import make_namer
from support.solverscene import (
    ROOM,
    assert_consistent,
    floor,
    make_state,
    put,
    snapshot,
    table_program,
    top_of,
)


def _result(violation: float, loss: float) -> Result:
    return Result({"c": violation}, {}, loss)


def test_fewer_violations_always_win_and_more_always_lose_without_a_draw():
    rng = np.random.default_rng(0)
    state = rng.bit_generator.state
    assert accept(_result(2.0, 0.0), _result(1.0, 1e9), 1e-6, rng)
    assert not accept(_result(1.0, 1e9), _result(2.0, 0.0), 1e9, rng)
    assert accept(_result(1.0, 5.0), _result(1.0, 4.0), 1e-6, rng)  # lower loss: no draw either
    assert rng.bit_generator.state == state


def test_equal_violations_go_to_metropolis_on_the_loss():
    old, new, t = _result(0.0, 1.0), _result(0.0, 1.5), 0.25
    rng, twin = np.random.default_rng(7), np.random.default_rng(7)
    p = math.exp(-0.5 / t)
    outcomes = [accept(old, new, t, rng) for _ in range(4000)]
    assert outcomes == [bool(twin.random() < p) for _ in range(4000)]
    assert np.mean(outcomes) == pytest.approx(p, abs=0.03)
    cold = [accept(old, new, 1e-3, rng) for _ in range(200)]
    assert not any(cold)  # a cold run never takes a worse loss


def test_temperature_falls_geometrically_from_t_start_to_t_end():
    cfg = AnnealConfig()
    fracs = np.linspace(0.0, 1.0, 11)
    temps = [temperature_at(cfg, f) for f in fracs]
    assert temps[0] == cfg.t_start and temps[-1] == pytest.approx(cfg.t_end)
    ratios = np.array(temps[1:]) / np.array(temps[:-1])
    assert (ratios < 1.0).all()
    np.testing.assert_allclose(ratios, ratios[0])


def test_discrete_moves_fade_and_continuous_ones_grow():
    cfg = AnnealConfig()
    names, w0 = move_weights(cfg, 0.0)
    _, w1 = move_weights(cfg, 1.0)
    assert names == list(MOVES_DISCRETE) + list(MOVES_CONTINUOUS)
    assert set(names) == set(MOVES)
    assert w0.sum() == pytest.approx(1.0) and w1.sum() == pytest.approx(1.0)
    discrete = np.array([n in MOVES_DISCRETE for n in names])
    assert (w0[discrete] > w1[discrete]).all() and (w0[~discrete] < w1[~discrete]).all()
    assert w0[discrete].sum() / w0[~discrete].sum() == pytest.approx(
        sum(MOVES_DISCRETE.values()) / (0.2 * sum(MOVES_CONTINUOUS.values())))


def test_fixed_weights_replace_the_schedule():
    cfg = AnnealConfig(moves={"translate": 3.0, "add": 1.0})
    for frac in (0.0, 0.5, 1.0):
        names, w = move_weights(cfg, frac)
        assert names == ["add", "translate"]
        np.testing.assert_allclose(w, [0.25, 0.75])


def _room():
    st = make_state(5.0, 4.0)
    table = put(st, "dining_table_rect", floor(), (2.5, 2.0))
    return st, table


def _run(seed: int, stage: str, steps: int = 60, **cfg):
    st, table = _room()
    problem = table_program()
    ev = Evaluator(problem, st)
    ann = Annealer(st, problem, ev, ROOM, stage, np.random.default_rng(seed),
                   AnnealConfig(**cfg), make_namer())
    return st, table, ev, ann, ann.run(steps)


def test_a_run_reports_what_it_did_and_leaves_a_consistent_state():
    st, _, ev, ann, stats = _run(0, "medium")
    assert stats.steps == sum(stats.proposed.values()) <= 60
    assert stats.accepted == sum(stats.taken.values())
    assert all(stats.taken.get(m, 0) <= v <= stats.proposed[m] for m, v in stats.valid.items())
    assert stats.objects == len(st.members(ROOM, "medium"))
    assert stats.violation == ann.result.violation == ev.evaluate().violation
    assert stats.violation == 0.0  # a picture is all this stage needs
    assert_consistent(st)
    assert not any(st.collides(n) for n in st.objects)
    assert stats.to_json()["accepted_by_move"] == stats.taken


def test_a_run_touches_only_its_own_stage():
    st, table = _room()
    plate = put(st, "plate", top_of(table), (2.5, 2.0), stage="small")
    before = snapshot(st)
    problem = table_program()
    Annealer(st, problem, Evaluator(problem, st), ROOM, "medium", np.random.default_rng(3),
             AnnealConfig(), make_namer()).run(60)
    after = snapshot(st)
    assert after[table] == before[table] and after[plate] == before[plate]
    assert all(st.objects[n].stage == "medium" for n in set(after) - set(before))


def test_a_run_repeats_itself_for_a_seed():
    a = snapshot(_run(5, "small", 40)[0])
    b = snapshot(_run(5, "small", 40)[0])
    assert a == b


def test_a_run_stops_early_once_nothing_improves():
    *_, stats = _run(0, "large", steps=400, patience=0.1)  # the table is all there is to do
    assert stats.stopped_early and stats.steps < 400


def test_the_temperature_is_set_before_the_first_step():
    st, _ = _room()
    problem = table_program()
    ann = Annealer(st, problem, Evaluator(problem, st), ROOM, "large", np.random.default_rng(0),
                   AnnealConfig(), make_namer())
    assert ann.ctx.temperature == AnnealConfig().t_start
