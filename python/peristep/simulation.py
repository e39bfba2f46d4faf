"""One co-simulation of a scene: parameters by name, steps, outputs as numbers and numpy arrays, FMU
states, and a loading run that returns its history."""
import weakref

import numpy as np

from . import _values
from ._fmi import Instance
from ._model import open_model
from .errors import PeriStepError

_SETTABLE = ("structuralParameter", "parameter", "input")


class Simulation:
    """``Simulation(scene, fmu=None, **parameters)``: an instance of the FMU with its parameters set.

    Structural parameters (``nx``, ``ny``, ``nModes``, ...) are set in Configuration Mode, the other
    parameters and any inputs after it, in Instantiated state, as the host does. An array parameter left
    without its structural parameter sets it (``xi=[0.1, 0.2]`` gives ``nModes = 2``). The instance is
    initialized by the first ``step``, ``run``, ``get`` or ``state``, so that ``run`` can first put its
    input at the start of the ramp (a fracture scene solves at its inputs when initialized).
    """

    def __init__(self, scene=None, *, fmu=None, **parameters):
        self._model = model = open_model(fmu)
        self._md = md = model.description
        if scene is not None:
            if "scene" in parameters:
                raise PeriStepError("the scene is given twice")
            parameters["scene"] = scene
        settings = []
        for name, value in parameters.items():
            v = md.variable(name)
            if v.causality not in _SETTABLE:
                raise PeriStepError(f"{name} is a {v.causality} and cannot be set")
            settings.append((v, value))
        self._structural, configured = self._structural_values(settings)
        structural = self._structural
        flat = [(v, _values.to_flat(md, v, value, [structural[d] if isinstance(d, str) else d for d in v.dimensions]))
                for v, value in settings]

        self._instance = Instance(model.library, md.instantiation_token, "peristep.Simulation", model.resource_path)
        self._states = weakref.WeakSet()
        try:
            if configured:
                self._instance.enter_configuration_mode()
                for name in configured:
                    self._instance.set(md.variables[name], np.array([structural[name]], dtype=np.uint64))
                self._instance.exit_configuration_mode()
            for v, values in flat:
                if v.causality != "structuralParameter":
                    self._instance.set(v, values)
        except PeriStepError:
            self._instance.free()  # a refused value ends the instance: no one else can free it
            raise

        scene_name = parameters.get("scene")
        if scene_name is None and "scene" in md.variables and md.variables["scene"].start is not None:
            scene_name = md.item_name(md.variables["scene"], int(md.variables["scene"].start))
        self.scene_info = md.scenes().get(scene_name)  # the Scene record; sim.scene is the variable
        ex = md.default_experiment
        self._start = ex.get("startTime", 0.0)
        self.time = self._start
        self._initialized = False
        self._finished = False

    def _structural_values(self, settings):
        """Every structural parameter's value (given, implied by an array's shape, or its start value),
        and the names of those given or implied, which Configuration Mode sets."""
        values = {v.name: int(v.start) for v in self._md.variables.values()
                  if v.causality == "structuralParameter" and v.start is not None}
        configured = []
        for v, value in settings:
            if v.causality == "structuralParameter":
                values[v.name] = int(np.asarray(value))
                configured.append(v.name)
        for v, value in settings:
            shape = np.shape(value)
            if v.is_array and len(shape) == len(v.dimensions):
                for d, n in zip(v.dimensions, shape):
                    if isinstance(d, str) and d not in configured:
                        values[d] = n
                        configured.append(d)
        return values, configured

    # --- life cycle ---------------------------------------------------------------------------------

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        """Frees the FMU states still held, then the instance. Safe to call twice."""
        instance = self.__dict__.get("_instance")
        if instance is None or not instance.alive:
            return
        for state in list(self._states):
            state.free()
        instance.free()

    def _initialize(self):
        if not self._initialized:
            self._instance.enter_initialization_mode(self._start)
            self._instance.exit_initialization_mode()
            self._initialized = True

    def _calculated_parameter(self, name):
        """A calculated parameter read in Initialization Mode, before the scene is built (what a sample
        plan needs to know: xiDistribution); the instance is of no further use."""
        self._instance.enter_initialization_mode(self._start)
        self._initialized = True
        return self.get(name)

    # --- stepping -----------------------------------------------------------------------------------

    @property
    def default_step(self):
        """The scene's recommended communication step, else the DefaultExperiment's."""
        if self.scene_info is not None and self.scene_info.step is not None:
            return self.scene_info.step
        return self._md.default_experiment.get("stepSize", 1.0)

    @property
    def finished(self):
        """True once the component has asked to stop (terminateSimulation)."""
        return self._finished

    def step(self, dt=None, **inputs):
        """Sets the inputs, then one fmi3DoStep of ``dt`` (default: ``default_step``). Returns False when
        the component asks to stop; a further step then raises."""
        for name, value in inputs.items():
            v = self._md.variable(name)
            if v.causality != "input":
                raise PeriStepError(f"{name} is a {v.causality}, not an input: set it when creating the Simulation")
            self._instance.set(v, _values.to_flat(self._md, v, value, self._shape(v)))
        self._initialize()
        if self._finished:
            raise PeriStepError(f"the component asked to stop at t = {self.time}; no further step is allowed")
        dt = self.default_step if dt is None else float(dt)
        self._finished = self._instance.do_step(self.time, dt)
        self.time = self.time + dt  # as the component counts it
        return not self._finished

    def run(self, load=None, steps=None, dt=None, input=None, fields=False, as_frame=False):
        """A loading ramp, as the host's ``[loading]``: step k of ``steps`` holds the input at
        from + k (to - from) / steps. ``load`` is ``(from, to)`` for ``input`` (default: the input the
        scene's description names, else the model's first input), or ``{name: (from, to)}``, or None
        (the inputs keep their values). Stops early when the component asks to.

        Returns the history: ``time`` (end of each step), the input, every scalar output, and with
        ``fields=True`` (or a list of names) the array outputs as ``(steps, *shape)`` arrays; a pandas
        DataFrame of the scalars with ``as_frame=True``."""
        md = self._md
        if isinstance(load, dict):
            if len(load) != 1 or input is not None:
                raise PeriStepError("load as a dict names exactly one input: {name: (from, to)}")
            (input, load), = load.items()
        if load is not None:
            if input is None:
                inputs = [v.name for v in md.variables.values() if v.causality == "input"]
                input = self.scene_info.input if self.scene_info is not None and self.scene_info.input else inputs[0]
            ramped = md.variable(input)
            if ramped.causality != "input":
                raise PeriStepError(f"{input} is a {ramped.causality}, not an input")
            start, end = (float(x) for x in load)
        dt = self.default_step if dt is None else float(dt)
        if steps is None:
            stop = self.scene_info.stop_time if self.scene_info is not None and self.scene_info.stop_time else None
            stop = stop or md.default_experiment.get("stopTime", self._start + dt)
            steps = max(1, round((stop - self._start) / dt))
        if fields and as_frame:
            raise PeriStepError("as_frame holds the scalar outputs only; ask for fields separately")
        if load is not None and not self._initialized:
            self._instance.set(ramped, np.array([start]))  # initialized at the start of the ramp, as the host does
        self._initialize()
        scalars = [v for v in md.variables.values() if v.causality == "output" and not v.is_array]
        arrays = [v for v in md.variables.values() if v.causality == "output" and v.is_array and v.type == "Float64"]
        if fields is not True:
            arrays = [md.variable(n) for n in (fields or ())]
        history = {"time": []}
        if load is not None:
            history[input] = []
        history.update((v.name, []) for v in scalars + arrays)
        for k in range(1, steps + 1):
            if load is not None:
                value = end if k == steps else start + (end - start) * k / steps
                history[input].append(value)
                go_on = self.step(dt, **{input: value})
            else:
                go_on = self.step(dt)
            history["time"].append(self.time)
            for v in scalars + arrays:
                history[v.name].append(self.get(v.name))
            if not go_on:
                break
        history = {k: np.array(v) for k, v in history.items()}
        if as_frame:
            try:
                import pandas
            except ImportError:
                raise PeriStepError("as_frame=True needs pandas, which is not installed") from None
            return pandas.DataFrame(history)
        return history

    # --- values ---------------------------------------------------------------------------------------

    def _shape(self, variable):
        """Extent of each dimension: fixed, or the structural parameter's value. Before initialization the
        value set (a refused read would end the instance); after it, the instance's own, which a restored
        state may have changed."""
        shape = []
        for d in variable.dimensions:
            if isinstance(d, str):
                d = int(self._instance.get(self._md.variables[d], 1)[0]) if self._initialized else self._structural[d]
            shape.append(d)
        return shape

    def get(self, name):
        """The variable's value: a float, int, bool or enumeration item name, or a numpy array of the
        declared shape (fields ``(ny, nx)``, row 0 at y = -Ly/2, x varying fastest)."""
        v = self._md.variable(name)
        self._initialize()
        shape = self._shape(v)
        return _values.from_flat(self._md, v, self._instance.get(v, _values.elements(shape)), shape)

    def __getattr__(self, name):
        md = self.__dict__.get("_md")
        if name.startswith("_") or md is None:
            raise AttributeError(name)
        if name in md.variables:
            return self.get(name)
        raise AttributeError(f"{md.model_name} has no variable or attribute {name!r}{md.suggest(name)}")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._md.variables))

    # --- FMU states -----------------------------------------------------------------------------------

    def state(self):
        """The instance's current FMU state (fmi3GetFMUState). ``bytes(state)`` serializes it; it is
        freed by ``state.free()``, when it is garbage collected, or by ``close()``."""
        self._initialize()
        state = State(self, self._instance.get_state())
        self._states.add(state)
        return state

    def restore(self, state):
        """Continues from a State of this simulation or from the bytes of any serialized state."""
        if isinstance(state, State):
            if state._simulation() is not self or state._handle is None:
                raise PeriStepError("this state belongs to another simulation or has been freed; restore its bytes")
            self._instance.set_state(state._handle)
            finished = state.finished
        else:
            handle = self._instance.deserialize_state(bytes(state))
            try:
                self._instance.set_state(handle)
            finally:
                self._instance.free_state(handle)
            finished = False  # not recorded in the bytes: the next step says again
        self._initialized = True
        self._finished = finished
        independent = next(v for v in self._md.variables.values() if v.causality == "independent")
        self.time = float(self._instance.get(independent, 1)[0])


class State:
    """An FMU state held by the component for one Simulation."""

    def __init__(self, simulation, handle):
        self._simulation = weakref.ref(simulation)
        self._handle = handle
        self.time = simulation.time
        self.finished = simulation.finished

    def __bytes__(self):
        """fmi3SerializeFMUState: the state as bytes that any instance of the FMU can restore."""
        simulation = self._simulation()
        if simulation is None or self._handle is None or not simulation._instance.alive:
            raise PeriStepError("the state has been freed")
        return simulation._instance.serialize_state(self._handle)

    def free(self):
        """fmi3FreeFMUState; safe to call twice."""
        simulation = self._simulation()
        handle, self._handle = self._handle, None
        if handle is not None and simulation is not None and simulation._instance.alive:
            simulation._instance.free_state(handle)

    def __del__(self):
        try:
            self.free()
        except Exception:
            pass  # at interpreter exit or after a fatal error there is nothing left to free
