"""indoorgen: procedural, constraint-solved indoor scenes in pure Python.

    import indoorgen
    result = indoorgen.generate(seed=0, config=indoorgen.GenerateConfig(room_type="dining_room"))
    indoorgen.write_scene_dir(result, "scene_0")
"""
from indoorgen.errors import IndoorGenError
from indoorgen.model.scene import Pose, Room, Scene, SceneObject
from indoorgen.pipeline import GenerateConfig, Generated, HomeConfig, generate, generate_home, write_scene_dir

__version__ = "0.1.0"
__all__ = ["GenerateConfig", "Generated", "HomeConfig", "IndoorGenError", "Pose", "Room", "Scene",
           "SceneObject", "generate", "generate_home", "write_scene_dir", "__version__"]
