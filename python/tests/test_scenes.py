"""Every scene of the description steps, and values come back with their declared types and shapes."""
import numpy as np
import peristep
import pytest

# Coarse set-ups (tests/fmi_scene_setups.hpp): the quasi-static grids at 9 x 9, 001's Plexiglass square at
# h = 4 mm and beam at h = 3.125 mm, the 1D bar with 16 bonds, learnedFracture's own 20 x 20 grid.
COARSE = {
    "smooth": dict(nx=9, ny=9),
    "composite": dict(nx=9, ny=9, nModes=2),
    "interfaceCrack": dict(nx=9, ny=9, nModes=2),
    "klPlate": dict(nx=9, ny=9, nModes=2),
    "specimen": dict(nx=9, ny=9),
    "glassCeramic": dict(nx=26, ny=14, Lx=800e-6, Ly=416e-6, poissonRatio=0.25, crystalFraction=0.0),
    "plexiglassCrack": dict(nx=25, ny=25, Lx=0.096, Ly=0.096, poissonRatio=0.25, deltaOverH=2.0),
    "bendingOneNotch": dict(nx=80, ny=16, Lx=0.25 - 3.125e-3, Ly=0.05 - 3.125e-3, poissonRatio=0.25),
    "bendingTwoNotches": dict(nx=80, ny=16, Lx=0.25 - 3.125e-3, Ly=0.05 - 3.125e-3, poissonRatio=0.25),
    "gamutBar": dict(nx=2, ny=2, gamutBonds=16),
    "learnedFracture": dict(nx=20, ny=20),
    "patchTest": dict(nx=9, ny=9),
}


def test_every_scene_has_a_set_up():
    assert set(COARSE) == set(peristep.scenes())


@pytest.mark.parametrize("scene", sorted(COARSE))
def test_scene_steps(scene, fmu):
    with peristep.Simulation(scene, fmu=fmu, **COARSE[scene]) as sim:
        assert sim.step()
        assert sim.time == pytest.approx(sim.default_step)
        scalars = [v.name for v in peristep.variables() if v.causality == "output" and not v.is_array]
        assert all(np.isfinite(sim.get(name)) for name in scalars)
        assert sim.ux.shape == (COARSE[scene]["ny"], COARSE[scene]["nx"])


def test_dynamic_scenes_have_a_recommended_step():
    scenes = peristep.scenes()
    dynamic = [s for s in scenes.values() if s.description.startswith("Dynamic")]
    assert dynamic and all(s.step and s.stop_time for s in dynamic)
    assert scenes["plexiglassCrack"].step == 2e-6 and scenes["smooth"].step is None
    assert scenes["glassCeramic"].input == "loadDisplacement"


def test_values_by_type_and_shape(fmu):
    with peristep.Simulation("composite", fmu=fmu, nx=9, ny=5, Lx=2.0, xi=[0.5, -0.25]) as sim:
        assert sim.nModes == 2 and isinstance(sim.nModes, int)  # implied by xi
        assert sim.scene == "composite" and sim.get("linearSolver") == "umfpack"
        assert isinstance(sim.hasExactMoments, int) and isinstance(sim.errorL2, float)
        assert np.array_equal(sim.xi, [0.5, -0.25])
        assert list(sim.xiDistribution) == [0, 0]
        x = sim.x
        assert x.shape == (5, 9) and x[0, 0] == -1.0 and x[0, -1] == 1.0 and np.all(x[:, 0] == -1.0)
        assert sim.y[0, 0] == sim.y[0, -1] < sim.y[-1, 0]  # row 0 at y = -Ly/2


def test_enumeration_arrays_and_structural_from_shape(fmu):
    E = np.full((5, 9), 1e9)
    E[2, 4] = 0.0  # a hole
    boxes = dict(gripBoxHold=["held", "free"], gripBoxX0=[-0.5, 0], gripBoxX1=[-0.4, 0], gripBoxY0=[-0.25, 0],
                 gripBoxY1=[0.25, 0])  # box 0: the left column of points; box 1 unused
    with peristep.Simulation("specimen", fmu=fmu, materialYoungsModulus=E, specimenModel="dynamic", Lx=1.0,
                             Ly=0.5, **boxes) as sim:
        assert (sim.nx, sim.ny, sim.nGripBoxes) == (9, 5, 2)
        assert list(sim.gripBoxHold) == ["held", "free"]
        assert np.array_equal(sim.materialYoungsModulus, E)
        assert sim.gripBoxReactionX.shape == (2,)
