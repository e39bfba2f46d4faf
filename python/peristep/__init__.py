"""PeriStep from Python: the FMU's C ABI through ctypes, driven by its modelDescription.xml.

    import peristep
    with peristep.Simulation("smooth", nx=17, ny=17) as sim:
        sim.step(loadFactor=1.0)
        print(sim.errorL2, sim.damage.shape)
"""
from . import _process

_process.prefer()  # before anything imports numpy, which loads OpenBLAS

from .catalog import scenes, variables  # noqa: E402
from .errors import PeriStepError  # noqa: E402
from .sampling import sample  # noqa: E402
from .simulation import Simulation, State  # noqa: E402

__all__ = ["PeriStepError", "Simulation", "State", "sample", "scenes", "variables"]
