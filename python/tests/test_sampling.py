"""sample() against `peristep sample`: the same nodes, weights, seeds, samples and statistics, bit for bit."""
import h5py
import numpy as np
import peristep
import pytest
from conftest import GLASS_CERAMIC, GLASS_CERAMIC_LOADING, scene_file

RAMP = {"from": 0.0, "to": 1.0, "steps": 1}
STUDIES = {  # name: parameters, loading, host options, sample() arguments
    "tensor": (dict(scene="smooth", nx=9, ny=9, xi=[0.0]), dict(input="loadFactor", **RAMP),
               ["--rule", "tensor", "--level", "3"], dict(rule="tensor", level=3)),
    "smolyak": (dict(scene="interfaceCrack", nx=9, ny=9, xi=[0.0, 0.0]), dict(input="loadFactor", **RAMP),
                ["--rule", "smolyak", "--level", "2"], dict(rule="smolyak", level=2)),
    "mc": (dict(scene="interfaceCrack", nx=9, ny=9, xi=[0.0, 0.0]), dict(input="loadFactor", **RAMP),
           ["--rule", "mc", "--samples", "5", "--seed", "3"], dict(rule="mc", samples=5, seed=3)),
    "mc_seeds": (GLASS_CERAMIC, GLASS_CERAMIC_LOADING,  # no random coordinates: sample k is seed 7 + k
                 ["--rule", "mc", "--samples", "3", "--seed", "7"], dict(rule="mc", samples=3, seed=7)),
}


@pytest.mark.parametrize("study", sorted(STUDIES))
def test_statistics_equal_the_host(study, host, fmu, tmp_path):
    parameters, loading, options, arguments = STUDIES[study]
    host("sample", scene_file(tmp_path / "study.toml", parameters, loading), *options, "--out", "study.h5",
         cwd=tmp_path)
    result = peristep.sample(parameters, fmu=fmu, processes=2, load=(loading["from"], loading["to"]),
                             steps=loading["steps"], input=loading["input"], **arguments)
    assert not result.failures
    with h5py.File(tmp_path / "study.h5") as f:
        level = f[f"level_{result.level}"]
        if "nodes" in level:
            assert np.array_equal(level["nodes"][()], result.points)
        assert np.array_equal(level["weights"][()], result.weights)
        if "seeds" in level:
            assert np.array_equal(level["seeds"][()], result.seeds)
        for name in level["samples"]:
            assert np.array_equal(level["samples"][name][()], result.samples[name]), name
        statistics = [g for g in level if isinstance(level[g], h5py.Group) and g != "samples"]
        assert {"mean", "std"} <= set(statistics)
        for statistic in statistics:
            mine = getattr(result, statistic)
            for name in level[statistic]:
                assert np.array_equal(level[statistic][name][()], mine[name], equal_nan=True), (statistic, name)
        for attribute, mine in (("errorMean", result.error_mean), ("errorStd", result.error_std)):
            assert level.attrs.get(attribute) == mine


def test_rules_refuse_what_they_cannot_do(fmu):
    with pytest.raises(peristep.PeriStepError, match="no random coordinates"):
        peristep.sample(dict(GLASS_CERAMIC), rule="smolyak", level=1, fmu=fmu)
    with pytest.raises(peristep.PeriStepError, match="takes samples"):
        peristep.sample("smooth", rule="mc", level=2, fmu=fmu)


def test_a_failed_sample_is_reported(fmu):
    # Large xi makes E = E0 (1 + g) negative somewhere: the component refuses those samples.
    result = peristep.sample(dict(scene="klPlate", nx=9, ny=9, nModes=2, fieldStd=3.0), rule="tensor", level=2,
                             fmu=fmu, steps=1, processes=2)
    assert len(result.failures) == 2  # the samples at xi = (-1, -1) and (-1, 1) of the two-point rule
    assert all("fmi3ExitInitializationMode returned fmi3Error: random field: E = E0 (1 + g)" in m
               for m in result.failures), result.failures
    assert all(np.isnan(v) for v in result.mean.values() if np.ndim(v) == 0)
