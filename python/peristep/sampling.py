"""Sample studies as ``peristep sample`` runs them: the same plan (nodes, weights, seeds), each sample in a
worker process, and the same statistics."""
import os
import time
from dataclasses import dataclass, field
from typing import Dict, List, Optional

import numpy as np

from . import _rules, _statistics
from ._model import open_model
from ._workers import run_in_workers
from .errors import PeriStepError
from .simulation import Simulation


@dataclass
class SampleResult:
    """One level of a study. Statistics map each Float64 output to a float (scalars) or an array (fields):
    ``mean``, ``std`` (direct, with the rule's weights; 0 where the estimate was negative, counted in
    ``clamped``); Smolyak ``pce_std``; Monte Carlo ``se_mean``, ``se_std``, ``se_variance``. ``error_mean``
    and ``error_std`` compare the displacement's moments with the exact ones where the scene has them;
    ``diff_mean``/``diff_std`` with the last level of the study."""

    rule: str
    level: int
    points: np.ndarray
    weights: np.ndarray
    seeds: Optional[np.ndarray]
    samples: Dict[str, np.ndarray]
    failures: List[str]
    seconds: float
    mean: Dict[str, object] = field(default_factory=dict)
    std: Dict[str, object] = field(default_factory=dict)
    pce_std: Dict[str, object] = field(default_factory=dict)
    se_mean: Dict[str, object] = field(default_factory=dict)
    se_std: Dict[str, object] = field(default_factory=dict)
    se_variance: Dict[str, object] = field(default_factory=dict)
    clamped: int = 0
    error_mean: Optional[float] = None
    error_std: Optional[float] = None
    diff_mean: Optional[float] = None
    diff_std: Optional[float] = None
    h: float = field(default=1.0, repr=False)  # grid spacing of the L2 norms

    def __repr__(self):
        varying = [n for n, v in self.samples.items() if v.ndim == 1 and np.nanmax(v) != np.nanmin(v)]
        rows = ", ".join(f"{n}: {self.mean[n]:.6g} +- {self.std[n]:.6g}" for n in varying)
        return (f"<SampleResult {self.rule} level {self.level}: {len(self.weights)} samples, "
                f"{len(self.failures)} failed; {rows or 'no scalar output varies'}>")


def sample(scene_or_parameters, rule="smolyak", level=None, samples=None, seed=1, processes=None, load=None,
           steps=None, dt=None, input=None, fmu=None, **parameters):
    """Statistics of every Float64 output over the scene's random coordinates (``xiDistribution``):
    ``rule`` "tensor" (``level`` points per coordinate), "smolyak" (Gauss rules, ``level`` >= 0) or "mc"
    (``samples`` draws from ``seed``; for a scene without random coordinates sample k is the realization
    of seed + k). Each sample is a ``Simulation`` with its ``xi`` (or ``seed``) whose ``run(load, steps,
    dt, input)`` gives the outputs after the last step. ``level``/``samples`` may be a list: one
    SampleResult per entry, in a list. Samples run in ``processes`` worker processes (default:
    one per core), each with OpenBLAS on one thread, as ``peristep sample`` runs them."""
    params = {"scene": scene_or_parameters} if isinstance(scene_or_parameters, str) else dict(scene_or_parameters)
    params.update(parameters)
    if rule not in ("tensor", "smolyak", "mc"):
        raise PeriStepError(f"unknown rule {rule!r} (tensor, smolyak or mc)")
    sizes, other = (samples, level) if rule == "mc" else (level, samples)
    if sizes is None or other is not None:
        raise PeriStepError("rule mc takes samples=Q (not level), rules tensor and smolyak level=L (not samples)")
    model = open_model(fmu)
    space = _random_space(model, params)
    laws = space[1]
    if not laws and rule != "mc":
        raise PeriStepError("the scene has no random coordinates (xiDistribution): only rule mc, which varies "
                            "the seed, applies")
    run = {"load": load, "steps": steps, "dt": dt, "input": input}
    results = [_study_level(model, params, run, rule, n, seed, space, processes)
               for n in (sizes if isinstance(sizes, (list, tuple)) else [sizes])]
    _compare_with_last(results)
    return results if isinstance(sizes, (list, tuple)) else results[0]


def _random_space(model, params):
    """(entries of xi that are random, their laws, the length of xi), asked of the component as the host
    does: in Initialization Mode, before the scene is built."""
    with Simulation(fmu=model.fmu, **params) as probe:
        codes = np.atleast_1d(probe._calculated_parameter("xiDistribution"))
    laws = model.description.xi_laws()
    random = [(k, laws[int(c)]) for k, c in enumerate(codes) if int(c) in laws]
    return [k for k, _ in random], [law for _, law in random], len(codes)


def _plan(rule, n, seed, laws):
    if rule == "tensor":
        return _rules.tensor_grid(laws, n) + (None,)
    if rule == "smolyak":
        return _rules.smolyak_grid(laws, n) + (_rules.sparse_projection(laws, n),)
    if n < 1:
        raise PeriStepError("rule mc needs samples >= 1")
    if laws:
        return _rules.monte_carlo(laws, n, seed) + (None,)
    return np.zeros((n, 0)), np.full(n, 1.0 / n), None


def _study_level(model, params, run, rule, n, seed, space, processes):
    index, laws, modes = space
    started = time.monotonic()
    points, weights, projection = _plan(rule, n, seed, laws)
    seeds = np.arange(seed, seed + len(weights)) if not laws else None
    jobs = []
    for k in range(len(weights)):
        xi = np.zeros(modes)
        xi[index] = points[k]
        jobs.append(dict(params, xi=xi, **({} if seeds is None else {"seed": int(seeds[k])})))
    records = _run_jobs(model.fmu, jobs, run, processes)
    result = SampleResult(rule, n, points, weights, seeds, {}, [], 0.0)
    result.failures = [f"sample {k + 1} of {len(jobs)} (xi = [{', '.join(f'{x + 0.0:.6g}' for x in jobs[k]['xi'])}]"
                       f"{'' if seeds is None else ', seed ' + str(seeds[k])}): {r}"
                       for k, r in enumerate(records) if isinstance(r, str)]
    if len(result.failures) < len(records):
        _statistics_of(result, records, projection)
    result.seconds = time.monotonic() - started
    return result


def _statistics_of(result, records, projection):
    """Fills the samples and, as the host does, the moments: Monte Carlo over the successful samples with
    equal weights, tensor and Smolyak rules only when no sample failed (NaN otherwise)."""
    good = [r for r in records if not isinstance(r, str)]
    first = good[0]
    for name, value in first["outputs"].items():
        nan = np.full_like(value, np.nan, dtype=float)
        result.samples[name] = np.array([nan if isinstance(r, str) else r["outputs"][name] for r in records])
    result.h = first["h"]
    monte_carlo = result.rule == "mc"
    if result.failures and not monte_carlo:
        for stat in ("mean", "std") + (("pce_std",) if projection is not None else ()):
            getattr(result, stat).update((name, np.nan * v[0]) for name, v in result.samples.items())
    else:
        used = [k for k, r in enumerate(records) if not isinstance(r, str)]
        w = np.full(len(used), 1.0 / len(used)) if result.failures else result.weights
        for name, samples in result.samples.items():
            values = [samples[k] for k in used]
            result.mean[name], result.std[name], clamped = _statistics.weighted_moments(values, w)
            result.clamped += clamped
            if monte_carlo:
                result.se_mean[name], result.se_variance[name], result.se_std[name] = \
                    _statistics.standard_errors(values, result.mean[name], result.std[name])
            if projection is not None:
                result.pce_std[name] = _statistics.pce_std(values, projection)
        if first["exact"]:  # the exact moments do not depend on the sample: the first one's serve
            out = first["outputs"]
            result.error_mean = _statistics.l2_distance(result.mean["ux"], result.mean["uy"], out["exactMeanUx"],
                                                        out["exactMeanUy"], result.h)
            result.error_std = _statistics.l2_distance(result.std["ux"], result.std["uy"], out["exactStdUx"],
                                                       out["exactStdUy"], result.h)
    for stat in ("mean", "std", "pce_std", "se_mean", "se_std", "se_variance"):
        table = getattr(result, stat)
        for name, value in table.items():
            table[name] = float(value) if np.ndim(value) == 0 else value


def _compare_with_last(results):
    """diff_mean, diff_std: the L2 distance of the displacement's moments to the last level's."""
    last = results[-1]
    if len(results) < 2 or "ux" not in last.mean or not np.all(np.isfinite(last.mean["ux"])):
        return
    for r in results[:-1]:
        if "ux" in r.mean and np.all(np.isfinite(r.mean["ux"])):
            r.diff_mean, r.diff_std = (
                _statistics.l2_distance(a["ux"], a["uy"], b["ux"], b["uy"], last.h)
                for a, b in ((r.mean, last.mean), (r.std, last.std)))


def _run_jobs(fmu, jobs, run, processes):
    processes = processes or os.cpu_count() or 1
    # OpenBLAS' results change in the last bits with its thread count, so samples run on one BLAS thread
    # as the host's do; the cores are shared among the workers.
    environment = {"OPENBLAS_NUM_THREADS": "1", "GLIBC_TUNABLES": "glibc.malloc.hugetlb=1",
                   "OMP_NUM_THREADS": str(max(1, (os.cpu_count() or 1) // min(processes, len(jobs))))}
    return run_in_workers(_run_job, [(fmu, job, run) for job in jobs], processes, environment)


def _run_job(arguments):
    """One sample: the Float64 outputs after the run's last step, or the component's message."""
    fmu, params, run = arguments
    try:
        with Simulation(fmu=fmu, **params) as sim:
            md = sim._md
            sim.run(**run)
            exact = "hasExactMoments" in md.variables and sim.get("hasExactMoments") == 1
            outputs = {v.name: sim.get(v.name) for v in md.variables.values()
                       if v.causality == "output" and v.type == "Float64"}
            if not all(np.isfinite(v) for v in outputs.values() if np.ndim(v) == 0):
                raise PeriStepError("a sample produced a non-finite output")
            x = sim.get("x") if "x" in md.variables else None
            h = abs(x[0, 1] - x[0, 0]) if x is not None and x.ndim == 2 and x.shape[1] > 1 else 1.0
            return {"outputs": outputs, "exact": exact, "h": float(h)}
    except PeriStepError as e:
        return str(e)
