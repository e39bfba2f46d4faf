"""Finding the FMU and unpacking it once, also when two processes unpack at the same moment."""
import os
import subprocess
import sys
from pathlib import Path

import pytest
from peristep import PeriStepError, _fmu_file


def test_found_by_argument_environment_and_build_tree(fmu, tmp_path, monkeypatch):
    assert _fmu_file.find_fmu(fmu) == Path(fmu).resolve()
    monkeypatch.setenv("PERISTEP_FMU", fmu)
    assert _fmu_file.find_fmu() == Path(fmu).resolve()
    monkeypatch.delenv("PERISTEP_FMU")
    (tmp_path / "build").mkdir()
    (tmp_path / "build" / "PeriStep.fmu").symlink_to(fmu)
    (tmp_path / "a" / "b").mkdir(parents=True)
    monkeypatch.chdir(tmp_path / "a" / "b")
    assert _fmu_file.find_fmu() == tmp_path / "build" / "PeriStep.fmu"
    with pytest.raises(PeriStepError, match="no FMU at"):
        _fmu_file.find_fmu(tmp_path / "missing.fmu")


def test_two_processes_unpack_into_one_directory(fmu, tmp_path):
    env = dict(os.environ, XDG_CACHE_HOME=str(tmp_path))
    script = "import sys; from peristep import _fmu_file; print(_fmu_file.unpack(sys.argv[1]))"
    runs = [subprocess.Popen([sys.executable, "-c", script, fmu], env=env, stdout=subprocess.PIPE, text=True)
            for _ in range(2)]
    out = [r.communicate()[0].strip() for r in runs]
    assert all(r.returncode == 0 for r in runs) and out[0] == out[1]
    entries = list((tmp_path / "peristep").iterdir())
    assert [e.name for e in entries] == [Path(out[0]).name]  # no scratch directory left behind
    assert (Path(out[0]) / "binaries" / "x86_64-linux" / "PeriStep.so").is_file()
