"""`pipeline`'s presets: each names its annealing steps and fullness range, a bad name is a
one-line error naming the valid ones, and every scene draws its fullness from its own seed."""
from __future__ import annotations

import pytest

from indoorgen import GenerateConfig, generate
from indoorgen.constraints import Problem, scene
from indoorgen.errors import ConfigError, UnknownPresetError
from indoorgen.pipeline import PRESETS, HomeConfig, generate_home, get_preset, scene_fullness
from indoorgen.programs.relations import on_floor


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
