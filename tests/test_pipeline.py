"""`pipeline`'s presets: each names its annealing steps and fullness range, a bad name is a
one-line error naming the valid ones, and every scene draws its fullness from its own seed;
a generated home whose plan fails is furnished on the seed's next plan."""
from __future__ import annotations

from types import SimpleNamespace

import pytest

from indoorgen import GenerateConfig, generate, pipeline
from indoorgen.constraints import Problem, scene
from indoorgen.errors import ConfigError, InvalidGeometryError, UnknownPresetError
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.model.floorplan_io import to_json as floorplan_json
from indoorgen.pipeline import PRESETS, HomeConfig, generate_home, get_preset, scene_fullness
from indoorgen.programs.relations import on_floor
from indoorgen.solver.stages import RoomSolution, RoomUnmet

#: a small home (its plan is quick to draw)
SMALL_HOME = "bedroom=1,bathroom=1,kitchen=1"


def test_presets_trade_time_for_density():
    fast, default, dense = (PRESETS[n] for n in ("fast", "default", "dense"))
    for stage in ("large", "medium", "small"):
        assert fast.steps[stage] <= default.steps[stage] <= dense.steps[stage]
    assert fast.fullness[1] <= dense.fullness[0]
    assert fast.fullness[0] <= default.fullness[0] <= default.fullness[1] <= dense.fullness[1]


@pytest.mark.parametrize("make", [lambda: generate(0, GenerateConfig(preset="turbo")),
                                  lambda: generate_home(0, HomeConfig(preset="turbo")),
                                  lambda: get_preset("turbo")])
def test_an_unknown_preset_names_the_valid_ones(make):
    with pytest.raises(UnknownPresetError, match="'turbo'.*fast, default, dense"):
        make()
    assert issubclass(UnknownPresetError, ConfigError)


def test_fullness_is_drawn_per_scene_from_its_seed():
    for name, preset in PRESETS.items():
        values = [scene_fullness(seed, preset) for seed in range(40)]
        assert all(preset.fullness[0] <= v <= preset.fullness[1] for v in values), name
        assert values == [scene_fullness(seed, preset) for seed in range(40)]
        assert len(set(values)) > 30  # sparse and cluttered scenes, not one fullness


@pytest.mark.slow
def test_fast_preset_room_is_recorded_and_within_its_range():
    gen = generate(3, GenerateConfig(room_type="bedroom", preset="fast"))
    assert gen.scene.config["preset"] == "fast"
    lo, hi = PRESETS["fast"].fullness
    assert lo <= gen.report["fullness"] <= hi
    assert all(s["steps"] <= PRESETS["fast"].steps[s["stage"]] for s in gen.report["stages"])


@pytest.mark.parametrize("make, needle", [
    (lambda: generate(2**63, GenerateConfig()), "seed must be an integer from 0 to"),
    (lambda: generate(0, GenerateConfig(steps={"large": 10**12})), r"steps\['large'\]"),
    (lambda: generate(0, GenerateConfig(steps={"tiny": 5})), "unknown stage 'tiny'; valid: large"),
    (lambda: generate(0, GenerateConfig(wall_thickness=50.0)), "wall thickness 50.0 m"),
    (lambda: generate_home(0, HomeConfig(area=1e9)), "--area 1000000000.0 is out of range"),
    (lambda: generate_home(0, HomeConfig(contour=[[0, 0], [1e6, 0], [1e6, 1e6], [0, 1e6]])),
     "less than or equal to 1000"),
    (lambda: generate_home(0, HomeConfig(contour=[[0, 0], [float("nan"), 0], [9, 9]])), "finite"),
    (lambda: generate_home(0, HomeConfig(steps={"large": -1})), "out of range"),
])
def test_the_python_api_has_the_command_lines_bounds(make, needle):
    """The API refuses what the command line refuses, before any work (no 30 GiB grid)."""
    with pytest.raises(ConfigError, match=needle):
        make()


def test_a_custom_programs_fault_while_solving_is_named_with_it():
    def my_room(room):
        floor = scene().related_to(room, on_floor)
        return Problem(constraints={"x": floor.of_generator("sofa", width=-3.0).count() == 1})
    with pytest.raises(ConfigError, match="program 'my_room' failed while solving: parameter "
                                          "width=-3.0 is invalid"):
        generate(0, GenerateConfig(program=my_room, steps={"large": 5, "medium": 0, "small": 0}))


def _fake_furnishing(monkeypatch, fails, *, mid_solve=False):
    """Replace the furnishing of a home by a record of the plans it was given (and whether it
    could give up): a plan `fails` (called with its redraw number) says is failed is reported
    failed, or with `mid_solve` given up (RoomUnmet) where the furnishing may give up."""
    furnished = []

    def furnished_home(seed, cfg, plan, preset, style, progress, give_up=False):
        redraw = plan.info.get("redraws", -1)  # -1: a predefined plan
        furnished.append((redraw, give_up))
        if fails(redraw) and mid_solve and give_up:
            raise RoomUnmet(RoomSolution("kitchen_0", [], [], {}, {"a fridge": 1.0}))
        reasons = [f"room kitchen_0: hard constraint a fridge violated (1) on plan "
                   f"{redraw}"] if fails(redraw) else []
        return SimpleNamespace(report={"status": {"failed": bool(reasons), "reasons": reasons},
                                       "timings_s": {}})
    monkeypatch.setattr(pipeline, "_furnished_home", furnished_home)
    return furnished


def test_a_home_whose_first_plan_fails_is_furnished_on_the_seeds_next_plan(monkeypatch):
    furnished = _fake_furnishing(monkeypatch, lambda redraw: redraw == 0)
    gen = generate_home(3, HomeConfig(rooms=SMALL_HOME, area=60.0))
    assert [f[0] for f in furnished][:1] == [0] and furnished[1][0] >= 1 and len(furnished) == 2
    assert all(give_up for _, give_up in furnished)  # neither is the last plan
    assert not gen.report["status"]["failed"]
    assert gen.report["replanned"] == [{"plan": 0, "reasons": [
        "room kitchen_0: hard constraint a fridge violated (1) on plan 0"]}]
    # the same seed gives way to the same next plan
    again = _fake_furnishing(monkeypatch, lambda redraw: redraw == 0)
    generate_home(3, HomeConfig(rooms=SMALL_HOME, area=60.0))
    assert again == furnished


def test_a_home_failing_on_every_plan_is_reported_failed_after_home_plans(monkeypatch):
    furnished = _fake_furnishing(monkeypatch, lambda redraw: True, mid_solve=True)
    gen = generate_home(3, HomeConfig(rooms=SMALL_HOME, area=60.0))
    plans = [redraw for redraw, _ in furnished]
    assert len(plans) == pipeline.HOME_PLANS == len(set(plans))
    # the plans before the last were given up mid-solve; the last is furnished whole, failed
    assert [give_up for _, give_up in furnished] == [True] * (pipeline.HOME_PLANS - 1) + [False]
    assert gen.report["status"]["failed"]
    assert gen.report["replanned"] == [
        {"plan": p, "reasons": ["room kitchen_0: hard constraint a fridge violated (1)"]}
        for p in plans[:-1]]


def test_a_predefined_floorplan_is_never_replaced(monkeypatch, tmp_path):
    plan = generate_floorplan(3, FloorplanConfig(rooms=SMALL_HOME, area=60.0))
    furnished = _fake_furnishing(monkeypatch, lambda redraw: True)
    gen = generate_home(3, HomeConfig(floorplan=floorplan_json(plan)))
    assert furnished == [(-1, False)] and gen.report["status"]["failed"]
    assert gen.report["replanned"] == []


def test_a_seeds_later_plans_differ_from_its_first():
    cfg = FloorplanConfig(rooms=SMALL_HOME, area=60.0)
    first = generate_floorplan(3, cfg)
    later = generate_floorplan(3, cfg, first_redraw=first.info["redraws"] + 1)
    assert later.info["redraws"] > first.info["redraws"]
    assert floorplan_json(later) != floorplan_json(first)
    assert floorplan_json(generate_floorplan(3, cfg, first_redraw=later.info["redraws"])) \
        == floorplan_json(later)


def test_a_seed_with_no_further_plan_reports_its_failed_home_whole(monkeypatch):
    furnished = _fake_furnishing(monkeypatch, lambda redraw: True, mid_solve=True)
    real = pipeline.generate_floorplan

    def only_the_first(seed, cfg, *, first_redraw=0):
        if first_redraw:
            raise InvalidGeometryError("cannot lay out this seed's home after 4 plans")
        return real(seed, cfg)
    monkeypatch.setattr(pipeline, "generate_floorplan", only_the_first)
    gen = generate_home(3, HomeConfig(rooms=SMALL_HOME, area=60.0))
    # given up mid-solve, then furnished whole (nothing given up: it is the seed's only plan)
    assert furnished == [(0, True), (0, False)]
    assert gen.report["status"]["failed"] and gen.report["replanned"] == []
