"""Errors a user can cause. The CLI turns any of these into one line on stderr and exit 2."""


class IndoorGenError(Exception):
    """Base class: a problem with the user's input, config or environment, not a bug."""


class ConfigError(IndoorGenError):
    """A bad option or configuration value."""


class UnknownRoomTypeError(ConfigError):
    """A room type that no program exists for."""


class UnknownGeneratorError(ConfigError):
    """A program or command names an asset generator that is not registered."""


class InvalidGeometryError(ConfigError):
    """A polygon or size that cannot make a room (zero area, self-intersecting...)."""


class ConstraintError(IndoorGenError):
    """A constraint program that is malformed or contradictory (e.g. in_range(5, 2))."""


class OutputError(IndoorGenError):
    """An output location that cannot be written."""


class ParameterError(ConfigError):
    """An asset parameter override with an unknown name or an out-of-range value."""


class UnknownPresetError(ConfigError):
    """A `--preset` name that is not one of the presets."""


class BatchConfigError(ConfigError):
    """A batch's seeds, counts or output directory that cannot make a dataset (a seeds file that
    does not parse, a directory written with other options or another version)."""


class SchedulerError(IndoorGenError):
    """A Dask scheduler that does not answer, or Dask not installed."""
