"""Finding PeriStep.fmu and unpacking it once into a cache directory shared by processes."""
import hashlib
import os
import shutil
import stat
import tempfile
import zipfile
from pathlib import Path

from .errors import PeriStepError

FMU_NAME = "PeriStep.fmu"
ENVIRONMENT_VARIABLE = "PERISTEP_FMU"


def find_fmu(path=None):
    """The FMU to use: ``path`` if given, else $PERISTEP_FMU, else build/PeriStep.fmu in the nearest
    directory above the current directory or above this package that has one."""
    if path is None:
        path = os.environ.get(ENVIRONMENT_VARIABLE) or None
    if path is not None:
        path = Path(path).expanduser().resolve()
        if not path.is_file():
            raise PeriStepError(f"no FMU at {path}")
        return path
    starts = [Path.cwd().resolve(), Path(__file__).resolve().parent]
    for start in starts:
        for directory in (start, *start.parents):
            candidate = directory / "build" / FMU_NAME
            if candidate.is_file():
                return candidate
    raise PeriStepError(f"cannot find build/{FMU_NAME} above {' or '.join(map(str, starts))}: build it "
                        f"(bash scripts/setup.sh), pass fmu=PATH or set {ENVIRONMENT_VARIABLE}")


def cache_root():
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "peristep"


def _digest(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()[:24]


def unpack(fmu):
    """The directory holding the unpacked ``fmu``, keyed by its content hash. Two processes may unpack
    at once: each extracts into a private temporary directory and renames it into place; the loser of
    the race removes its copy and uses the winner's."""
    fmu = Path(fmu)
    target = cache_root() / _digest(fmu)
    if not (target / "modelDescription.xml").is_file():
        target.parent.mkdir(parents=True, exist_ok=True)
        scratch = Path(tempfile.mkdtemp(prefix=".unpacking-", dir=target.parent))
        try:
            with zipfile.ZipFile(fmu) as archive:
                archive.extractall(scratch)
            for so in (scratch / "binaries").glob("*/*.so*"):
                so.chmod(so.stat().st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
            try:
                os.rename(scratch, target)
            except OSError:
                if not (target / "modelDescription.xml").is_file():
                    raise
        except (OSError, zipfile.BadZipFile) as e:
            raise PeriStepError(f"cannot unpack {fmu} into {target.parent}: {e}") from None
        finally:
            shutil.rmtree(scratch, ignore_errors=True)
    return target
