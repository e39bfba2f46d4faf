"""The loop of a worker process (see _workers.py): (module, function, job) in, function(job) out."""
import importlib
import os
import pickle
import sys

# The protocol owns the original stdout; anything the libraries print goes to stderr instead.
answers = os.fdopen(os.dup(1), "wb")
os.dup2(2, 1)
while True:
    try:
        module, name, job = pickle.load(sys.stdin.buffer)
    except EOFError:
        break
    pickle.dump(getattr(importlib.import_module(module), name)(job), answers)
    answers.flush()
