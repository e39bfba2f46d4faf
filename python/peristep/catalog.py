"""What the FMU offers, from its model description: scenes and variables."""
from ._model import open_model
from .errors import PeriStepError


def scenes(fmu=None):
    """Scene name -> Scene (value, description, recommended step and stop time, the input it names)."""
    return open_model(fmu).description.scenes()


def variables(scene=None, fmu=None):
    """Every variable (name, type, unit, causality, variability, dimensions, start, description, items)
    in the description's order.

    The model description does not say which scene reads which variable (the descriptions say it in
    words, e.g. "Specimen scene: ..."), so a ``scene`` is checked against the scene list and the list
    returned is the same for every scene."""
    md = open_model(fmu).description
    if scene is not None and scene not in md.scenes():
        raise PeriStepError(f"no scene {scene!r}; the scenes are {', '.join(md.scenes())}")
    return list(md.variables.values())
