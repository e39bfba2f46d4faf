#!/usr/bin/env bash
# The Python package's tests as CTest runs them (test python/package): a virtual environment in WORK on
# Debian's /usr/bin/python3 that sees its numpy, h5py and pytest (--system-site-packages), the package
# installed into it offline from a copy of python/ (the source tree stays clean), then pytest.
#
#   run_tests.sh WORK FMU HOST [pytest arguments]     e.g. run_tests.sh build/tests/python build/PeriStep.fmu build/host/peristep
set -euo pipefail
if (($# < 3)); then
  echo "usage: $0 WORK FMU HOST [pytest arguments]" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$1 fmu=$(realpath "$2") host=$(realpath "$3")
shift 3
python=/usr/bin/python3

rm -rf "$work"
mkdir -p "$work"
"$python" -m venv --system-site-packages "$work/venv"
cp -r "$here/.." "$work/source"
rm -rf "$work/source/tests"
"$work/venv/bin/pip" install --quiet --no-index --no-build-isolation "$work/source"

cd "$work"
export PERISTEP_FMU=$fmu PERISTEP_HOST=$host XDG_CACHE_HOME=$work/cache PYTHONDONTWRITEBYTECODE=1
exec "$work/venv/bin/python" -m pytest -p no:cacheprovider -q "$here" "$@"
