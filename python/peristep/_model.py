"""One FMU opened for this process: its description and its loaded library, shared by every simulation."""
from pathlib import Path

from ._description import ModelDescription
from ._fmi import Library
from ._fmu_file import find_fmu, unpack

_opened = {}


class Model:
    """An FMU's path, unpacked directory, model description and library."""

    def __init__(self, fmu):
        self.fmu = fmu
        self.root = unpack(fmu)
        self.description = ModelDescription((self.root / "modelDescription.xml").read_text(encoding="utf-8"),
                                            str(fmu))
        self.library = Library(self.root / "binaries" / "x86_64-linux" / f"{self.description.model_identifier}.so")
        resources = self.root / "resources"
        self.resource_path = f"{resources}/" if resources.is_dir() else None


def open_model(fmu=None):
    """The Model of ``fmu`` (see find_fmu), loaded once per process and FMU content."""
    path = find_fmu(fmu)
    st = Path(path).stat()
    key = (str(path), st.st_size, st.st_mtime_ns)
    if key not in _opened:
        _opened[key] = Model(path)
    return _opened[key]
