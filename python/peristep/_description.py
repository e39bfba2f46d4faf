"""modelDescription.xml read at run time: variables, types, units, dimensions, enumerations, scenes.

Nothing about the component is known in advance: every name, value reference, type and array shape the
package uses comes from here.
"""
import difflib
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Optional, Tuple, Union

from .errors import PeriStepError

# FMI 3.0: only Float32/Float64 default to continuous variability; every other type to discrete.
_FLOATS = ("Float32", "Float64")
_NUMBER = r"([0-9][0-9.]*(?:[eE][-+]?[0-9]+)?)"
# The scene descriptions state the recommended communication step and stop time in words, e.g.
# "communication step 2e-6 s, stop time 34e-6 s" or "each communication step is a whole number of MD
# frame intervals of 4.95e-14 s ... (stop time 1.98e-12 s)".
_STEP = re.compile(r"communication step (?:is a whole number of [^.;]*? intervals of )?" + _NUMBER + " s")
_STOP = re.compile(r"stop time " + _NUMBER + " s")


@dataclass(frozen=True)
class Variable:
    """One <ModelVariables> entry. ``dimensions`` holds, per dimension, a fixed extent (int) or the
    name of the structural parameter that sets it."""

    name: str
    value_reference: int
    type: str
    causality: str
    variability: str
    initial: str
    declared_type: str
    unit: str
    description: str
    start: Optional[str]
    dimensions: Tuple[Union[int, str], ...] = ()
    items: Tuple[str, ...] = field(default=(), compare=False)  # an enumeration's item names

    @property
    def is_array(self):
        return bool(self.dimensions)


@dataclass(frozen=True)
class Scene:
    """An item of the enumeration of the ``scene`` parameter, with what its description recommends."""

    name: str
    value: int
    description: str
    step: Optional[float]       # recommended communication step [s], None: any (quasi-static)
    stop_time: Optional[float]  # recommended stop time [s]
    input: Optional[str]        # the input variable the description names, if exactly one


class ModelDescription:
    """The parsed description of one FMU."""

    def __init__(self, xml_text, source="modelDescription.xml"):
        try:
            root = ET.fromstring(xml_text)
        except ET.ParseError as e:
            raise PeriStepError(f"{source}: not well-formed XML ({e})") from None
        if root.tag != "fmiModelDescription" or not root.get("fmiVersion", "").startswith("3."):
            raise PeriStepError(f"{source}: not an FMI 3.0 model description")
        cs = root.find("CoSimulation")
        if cs is None:
            raise PeriStepError(f"{source}: the FMU offers no Co-Simulation interface")
        self.source = source
        self.model_name = root.get("modelName")
        self.instantiation_token = root.get("instantiationToken")
        self.model_identifier = cs.get("modelIdentifier")
        self.description = root.get("description", "")
        ex = root.find("DefaultExperiment")
        self.default_experiment = {k: float(ex.get(k)) for k in ("startTime", "stopTime", "stepSize")
                                   if ex is not None and ex.get(k) is not None}
        # type name -> [(item name, value, description)]
        self.enumerations = {}
        type_units = {}
        defs = root.find("TypeDefinitions")
        for t in defs if defs is not None else ():
            if t.tag == "EnumerationType":
                self.enumerations[t.get("name")] = [(i.get("name"), int(i.get("value")), i.get("description", ""))
                                                    for i in t.findall("Item")]
            elif t.get("unit"):
                type_units[t.get("name")] = t.get("unit")
        self.variables = {}
        raw = list(root.find("ModelVariables"))
        by_vr = {int(v.get("valueReference")): v.get("name") for v in raw}
        for v in raw:
            declared = v.get("declaredType", "")
            dims = tuple(int(d.get("start")) if d.get("start") is not None else by_vr[int(d.get("valueReference"))]
                         for d in v.findall("Dimension"))
            self.variables[v.get("name")] = Variable(
                name=v.get("name"), value_reference=int(v.get("valueReference")), type=v.tag,
                causality=v.get("causality", "local"),
                variability=v.get("variability", "continuous" if v.tag in _FLOATS else "discrete"),
                initial=v.get("initial", ""), declared_type=declared,
                unit=v.get("unit", type_units.get(declared, "")), description=v.get("description", ""),
                start=v.get("start"), dimensions=dims,
                items=tuple(i[0] for i in self.enumerations.get(declared, ())))

    def variable(self, name):
        """The variable of this name; PeriStepError naming close names otherwise."""
        try:
            return self.variables[name]
        except KeyError:
            raise PeriStepError(f"{self.model_name} has no variable {name!r}{self.suggest(name)}") from None

    def suggest(self, name):
        """'; did you mean a, b?' for the variable names closest to name, or ''."""
        same_letters = [v for v in self.variables if v.lower() == name.lower()]
        close = same_letters + [v for v in difflib.get_close_matches(name, self.variables, n=3, cutoff=0.6)
                                if v not in same_letters]
        return f"; did you mean {', '.join(close)}?" if close else ""

    def item_value(self, variable, item):
        """The integer of an enumeration item given by name (or already as an integer)."""
        items = self.enumerations[variable.declared_type]
        for name, value, _ in items:
            if item == name or (isinstance(item, int) and not isinstance(item, bool) and item == value):
                return value
        names = ", ".join(i[0] for i in items)
        raise PeriStepError(f"{variable.name}: {item!r} is not an item of {variable.declared_type} ({names})")

    def item_name(self, variable, value):
        for name, v, _ in self.enumerations[variable.declared_type]:
            if v == value:
                return name
        return value

    def scenes(self):
        """The items of the ``scene`` parameter's enumeration, by name."""
        scene = self.variables.get("scene")
        if scene is None or scene.type != "Enumeration":
            return {}
        inputs = [v.name for v in self.variables.values() if v.causality == "input"]
        out = {}
        for name, value, text in self.enumerations[scene.declared_type]:
            step, stop = _STEP.search(text), _STOP.search(text)
            named = [i for i in inputs if re.search(rf"\b{re.escape(i)}\b", text)]
            out[name] = Scene(name, value, text, float(step.group(1)) if step else None,
                              float(stop.group(1)) if stop else None, named[0] if len(named) == 1 else None)
        return out

    def xi_laws(self):
        """Code -> law ('normal' or 'uniform') of xiDistribution, from its description ("0 normal, 1
        uniform, 2 unused by the scene")."""
        v = self.variable("xiDistribution")
        laws = {int(code): law for code, law in re.findall(r"\b(\d+) (normal|uniform)\b", v.description)}
        if sorted(laws.values()) != ["normal", "uniform"]:
            raise PeriStepError(f"the description of xiDistribution does not say which codes are normal and "
                                f"uniform: {v.description!r}")
        return laws
