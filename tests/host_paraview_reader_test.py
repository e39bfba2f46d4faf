# `peristep run` results opened the way a ParaView user opens them: the .xmf through the reader
# ParaView picks for the extension (OpenDataFile: XDMF 3 in 5.11) and through the legacy XDMF reader.
# At the first, a middle and the last step every point field, the geometry, the ramped input and
# every scalar output must equal the values of the HDF5 file (the data of record, read with h5py).
#
#   pvpython host_paraview_reader_test.py PERISTEP WORKDIR SCENE...     (SCENE "default": no scene file)
#
# Without ParaView's Python modules or h5py it prints PERISTEP_SKIP, except in CI (CI set), where it fails.
import os
import subprocess
import sys

try:
    import h5py
    import numpy as np
    from paraview import servermanager, simple
    from vtkmodules.numpy_interface import dataset_adapter as dsa
except ImportError as e:
    if os.environ.get("CI"):
        sys.exit(f"{e}: ParaView's Python modules and h5py must import in CI")
    print(f"PERISTEP_SKIP: {e}")
    sys.exit(0)

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED:", message)


def dataset(reader, time):
    reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    while data.IsA("vtkMultiBlockDataSet"):  # the legacy reader wraps the grid in a block
        data = data.GetBlock(0)
    return dsa.WrapDataObject(data)


def compare(label, reader, h5):
    times = h5["time"][...]
    shown = list(reader.TimestepValues) if len(times) > 1 else [reader.TimestepValues]
    check(np.array_equal(np.array(shown, dtype=float), times), f"{label}: time steps {shown} != {list(times)}")
    grid_fields = [n for n in h5["fields"] if h5["fields"][n].shape[1:] == h5["grid/x"].shape]
    # Parameters on the grid (the specimen's material maps) are constant point arrays, stored in /grid.
    grid_parameters = [n for n in h5["grid"] if n not in ("x", "y") and h5["grid"][n].shape == h5["grid/x"].shape]
    for k in sorted({0, len(times) // 2, len(times) - 1}):
        where = f"{label}, step {k + 1} of {len(times)}"
        d = dataset(reader, times[k])
        points = np.asarray(d.Points)
        check(np.array_equal(points[:, 0], h5["grid/x"][...].ravel()), f"{where}: x differs")
        check(np.array_equal(points[:, 1], h5["grid/y"][...].ravel()), f"{where}: y differs")
        check(sorted(d.PointData.keys()) == sorted(grid_fields + grid_parameters),
              f"{where}: point arrays {sorted(d.PointData.keys())}")
        stored_arrays = [(n, h5["fields"][n][k]) for n in grid_fields] + [(n, h5["grid"][n]) for n in grid_parameters]
        for name, stored in stored_arrays:
            shown_values, stored = np.asarray(d.PointData[name]), stored[...].ravel()
            check(shown_values.shape == stored.shape and np.array_equal(shown_values, stored),
                  f"{where}: field {name} differs (max |stored| {np.max(np.abs(stored)):.3e})")
        series = [("scalars/" + n, n) for n in h5["scalars"]] + [("inputs/" + n, n) for n in h5.get("inputs", {})]
        for path, name in series:
            value = d.FieldData[name]
            check(not isinstance(value, dsa.VTKNoneArray) and np.asarray(value).ravel().tolist() == [h5[path][k]],
                  f"{where}: {name} is {value}, the HDF5 file holds {h5[path][k]}")
        print(f"{where}: {len(grid_fields)} fields, {len(series)} scalars as stored")


peristep, workdir, scenes = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3:]
os.makedirs(workdir, exist_ok=True)
for scene in scenes:
    stem = "default" if scene == "default" else os.path.splitext(os.path.basename(scene))[0]
    command = [peristep, "run"] + ([] if scene == "default" else [scene]) + ["--out", stem + ".h5"]
    subprocess.run(command, cwd=workdir, check=True, stdout=subprocess.DEVNULL)
    xmf = os.path.join(workdir, stem + ".xmf")  # absolute, as ParaView's file dialog passes it
    with h5py.File(os.path.join(workdir, stem + ".h5"), "r") as h5:
        default = simple.OpenDataFile(xmf)
        compare(f"{stem} ({default.GetXMLName()})", default, h5)
        compare(f"{stem} (XdmfReader)", simple.XDMFReader(FileNames=[xmf]), h5)
        check(len(h5["time"]) >= 3, f"{stem}: {len(h5['time'])} steps, the test wants a first, middle and last one")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("all checks passed")
