"""The FMU and host under test: PERISTEP_FMU and PERISTEP_HOST (run_tests.sh sets both from the build tree)."""
import os
import subprocess
from pathlib import Path

import peristep  # noqa: F401 (first: it sets the process environment before numpy loads OpenBLAS)
import pytest


def _required(name):
    value = os.environ.get(name)
    if not value or not Path(value).is_file():
        pytest.fail(f"set {name} to the build tree's file (run_tests.sh does)")
    return value


@pytest.fixture(scope="session")
def fmu():
    return _required("PERISTEP_FMU")


@pytest.fixture(scope="session")
def host(fmu):
    """Runs `peristep ARGS --fmu FMU`, returning its output; fails with it when the host fails."""
    binary = _required("PERISTEP_HOST")

    def run(*args, cwd):
        done = subprocess.run([binary, *map(str, args), "--fmu", fmu], cwd=cwd, capture_output=True, text=True)
        assert done.returncode == 0, done.stdout + done.stderr
        return done.stdout

    return run


def scene_file(path, parameters, loading):
    """A scene file for the host with these [parameters] and [loading]."""
    def text(v):
        if isinstance(v, str):
            return f'"{v}"'
        if isinstance(v, (list, tuple)):
            return "[" + ", ".join(text(e) for e in v) + "]"
        return repr(v)

    lines = ["[parameters]"] + [f"{k} = {text(v)}" for k, v in parameters.items()]
    lines += ["", "[loading]"] + [f"{k} = {text(v)}" for k, v in loading.items()]
    Path(path).write_text("\n".join(lines) + "\n")
    return path


# A small glass-ceramic plate (h = 32 um) opened in three steps: fracture, the microstructure, reactions.
GLASS_CERAMIC = dict(scene="glassCeramic", nx=26, ny=14, Lx=800e-6, Ly=416e-6, deltaOverH=3.0, poissonRatio=0.25,
                     crystalFraction=0.2, seed=1)
GLASS_CERAMIC_LOADING = dict(input="loadDisplacement", **{"from": 0.0}, to=0.05e-6, steps=3)
