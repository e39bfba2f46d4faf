"""Worker processes for sample studies: fresh interpreters (``python -m peristep._worker_main``) that take
pickled jobs on stdin and answer on stdout.

Not multiprocessing: its spawn method re-imports the caller's main script (a script without an
``if __name__ == "__main__"`` guard would start a study in every worker), and a fork copies OpenMP and
OpenBLAS thread pools the child cannot use. A fresh process also takes its environment at start, as
glibc's tunables and OpenBLAS want."""
import os
import pickle
import queue
import site
import subprocess
import sys
import threading
from pathlib import Path

from .errors import PeriStepError


def run_in_workers(function, jobs, processes, environment):
    """[function(job) for job in jobs], computed by ``processes`` workers whose environment is ours
    updated by ``environment`` where unset. ``function`` is a module-level function of this package."""
    env = dict(os.environ)
    for name, value in environment.items():
        env.setdefault(name, value)
    # The workers import this very package: where it is not installed, from the directory it was found in
    # (an installed one stays off PYTHONPATH, which would put site-packages before the standard library).
    here = str(Path(__file__).resolve().parent.parent)
    if here not in {str(Path(p).resolve()) for p in site.getsitepackages() + [site.getusersitepackages()]}:
        env["PYTHONPATH"] = os.pathsep.join([here] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
    pending = queue.Queue()
    for k, job in enumerate(jobs):
        pending.put(k)
    results = [None] * len(jobs)
    errors = []

    def serve():
        worker = subprocess.Popen([sys.executable, "-m", f"{__package__}._worker_main"], stdin=subprocess.PIPE,
                                  stdout=subprocess.PIPE, env=env)
        try:
            while not errors:
                try:
                    k = pending.get_nowait()
                except queue.Empty:
                    break
                try:
                    pickle.dump((function.__module__, function.__name__, jobs[k]), worker.stdin)
                    worker.stdin.flush()
                    results[k] = pickle.load(worker.stdout)
                except (EOFError, OSError):  # the worker died: its stderr has said why
                    errors.append(f"a worker process ended (exit status {worker.wait()}) during job {k + 1}")
        finally:
            try:
                worker.stdin.close()
            except OSError:
                pass
            worker.wait()

    threads = [threading.Thread(target=serve) for _ in range(max(1, min(processes, len(jobs))))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    if errors:
        raise PeriStepError(errors[0])
    return results
