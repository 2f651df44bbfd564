#!/usr/bin/python3
"""siconos_server.py -- the witness's driver kept warm for many models (make crosscheck).

Reads requests from the standard input, one per line: ID, the path of a model (JSON, as
siconos_driver.py reads it) and the path its answer goes to, separated by tabs. For each,
simulates the model as siconos_driver.py would (Python and Siconos started once), writes
the s-expression answer to the answer's path, then prints the line "@@done ID" on the
standard output and flushes it. Anything else on the standard output (Siconos's own
messages) is to be ignored by the reader. The server ends at the end of its input; the
caller kills it when a model takes too long and starts another.
"""

import contextlib
import io
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import siconos_driver  # noqa: E402


def answer(model_path):
    """The s-expression answer of the model at MODEL_PATH, never an exception."""
    buffer = io.StringIO()
    try:
        with open(model_path) as stream:
            model = json.load(stream)
        with contextlib.redirect_stdout(buffer):
            siconos_driver.simulate(model)
    except Exception as e:  # the witness failed: say so, never a result
        return "(:status :error :message %s)" % siconos_driver.sx_string(
            "%s: %s" % (type(e).__name__, e))
    text = buffer.getvalue()
    return text if text.strip() else '(:status :error :message "the driver printed nothing")'


def serve():
    for line in sys.stdin:
        fields = line.rstrip("\n").split("\t")
        if len(fields) != 3:
            continue
        ident, model_path, answer_path = fields
        text = answer(model_path)
        with open(answer_path, "w") as stream:
            stream.write(text)
        sys.stdout.write("\n@@done %s\n" % ident)
        sys.stdout.flush()


if __name__ == "__main__":
    serve()
