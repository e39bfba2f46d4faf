"""run() against `peristep run`: the same ramp gives the same fields and scalar histories, bit for bit."""
import h5py
import numpy as np
import peristep
import pytest
from conftest import GLASS_CERAMIC, GLASS_CERAMIC_LOADING, scene_file


@pytest.fixture(scope="module")
def host_run(host, tmp_path_factory):
    work = tmp_path_factory.mktemp("host_run")
    host("run", scene_file(work / "plate.toml", GLASS_CERAMIC, GLASS_CERAMIC_LOADING), "--out", "plate.h5", cwd=work)
    with h5py.File(work / "plate.h5") as f:
        return {group: {name: f[group][name][()] for name in f[group]} for group in ("fields", "scalars", "inputs")}


@pytest.fixture(scope="module")
def history(fmu):
    with peristep.Simulation(fmu=fmu, **GLASS_CERAMIC) as sim:
        return sim.run(load=(GLASS_CERAMIC_LOADING["from"], GLASS_CERAMIC_LOADING["to"]),
                       steps=GLASS_CERAMIC_LOADING["steps"], fields=True)


def test_fields_equal_the_host(host_run, history):
    assert history["damage"].shape == (3, 14, 26) and history["damage"].max() > 0  # bonds broke
    for name, values in host_run["fields"].items():
        assert np.array_equal(history[name], values), name


def test_scalars_and_input_equal_the_host(host_run, history):
    for name, values in host_run["scalars"].items():
        assert np.array_equal(history[name], values), name
    assert np.array_equal(history["loadDisplacement"], host_run["inputs"]["loadDisplacement"])


def test_history_as_frame(fmu):
    """A DataFrame of the scalars where pandas is installed; a clear error where it is not."""
    try:
        import pandas
    except ImportError:
        pandas = None
    with peristep.Simulation("smooth", fmu=fmu, nx=9, ny=9) as sim:
        if pandas is None:
            with pytest.raises(peristep.PeriStepError, match="needs pandas"):
                sim.run(load=(0, 1), steps=2, as_frame=True)
            return
        frame = sim.run(load=(0, 1), steps=2, as_frame=True)
    assert isinstance(frame, pandas.DataFrame) and list(frame["loadFactor"]) == [0.5, 1.0]
