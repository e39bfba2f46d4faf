"""What goes wrong is said: the component's own message, close names, shapes; instances are independent."""
import numpy as np
import peristep
import pytest


def test_a_refused_parameter_raises_with_the_components_message(fmu):
    with pytest.raises(peristep.PeriStepError) as e:
        peristep.Simulation("smooth", fmu=fmu, poissonRatio=0.7)
    assert "fmi3SetFloat64 returned fmi3Error" in str(e.value)
    assert any("poissonRatio" in m for m in e.value.messages), e.value.messages


def test_a_refused_initialization_raises_with_the_estimate(fmu):
    # The glass-ceramic plate at its start values: 1 m of 12 um crystals.
    sim = peristep.Simulation("glassCeramic", fmu=fmu)
    with pytest.raises(peristep.PeriStepError, match="fmi3ExitInitializationMode|fmi3EnterInitializationMode"):
        sim.step()
    sim.close()


def test_names_types_and_shapes_are_checked(fmu):
    with pytest.raises(peristep.PeriStepError, match="did you mean poissonRatio"):
        peristep.Simulation("smooth", fmu=fmu, poissonratio=0.3)
    with pytest.raises(peristep.PeriStepError, match="is not an item of PeriStep.Scene"):
        peristep.Simulation("smoth", fmu=fmu)
    with pytest.raises(peristep.PeriStepError, match=r"expected shape \(ny = 9, nx = 9\)"):
        peristep.Simulation("specimen", fmu=fmu, nx=9, ny=9, materialYoungsModulus=np.ones(81))
    with pytest.raises(peristep.PeriStepError, match="expected integers"):
        peristep.Simulation("smooth", fmu=fmu, seed=1.5)
    with pytest.raises(peristep.PeriStepError, match="output and cannot be set"):
        peristep.Simulation("smooth", fmu=fmu, damage=0.0)
    with peristep.Simulation("smooth", fmu=fmu, nx=9, ny=9) as sim:
        with pytest.raises(AttributeError, match="did you mean damage"):
            sim.damge
        with pytest.raises(peristep.PeriStepError, match="not an input"):
            sim.step(poissonRatio=0.2)


def test_two_simulations_are_independent(fmu):
    a = peristep.Simulation("smooth", fmu=fmu, nx=9, ny=9, xi=[1.0])
    b = peristep.Simulation("smooth", fmu=fmu, nx=17, ny=9, Lx=2.0, xi=[-1.0])
    a.step(loadFactor=1.0)
    b.step(loadFactor=0.5)
    b.step(loadFactor=1.0)
    assert a.ux.shape == (9, 9) and b.ux.shape == (9, 17) and (a.time, b.time) == (0.25, 0.5)
    with peristep.Simulation("smooth", fmu=fmu, nx=9, ny=9, xi=[1.0]) as alone:
        alone.step(loadFactor=1.0)
        assert np.array_equal(alone.ux, a.ux) and alone.errorL2 == a.errorL2
    a.close()
    assert b.errorL2 > 0 and b.step(loadFactor=1.0)
    b.close()


def test_variables_and_scenes(fmu):
    names = [v.name for v in peristep.variables(fmu=fmu)]
    assert {"nx", "xi", "damage", "toughnessKIC"} <= set(names)
    xi = next(v for v in peristep.variables("smooth", fmu=fmu) if v.name == "xi")
    assert xi.dimensions == ("nModes",) and xi.causality == "parameter" and xi.type == "Float64"
    assert next(v for v in peristep.variables(fmu=fmu) if v.name == "toughnessKIC").unit == "Pa.m^0.5"
    with pytest.raises(peristep.PeriStepError, match="no scene"):
        peristep.variables("smoth", fmu=fmu)
