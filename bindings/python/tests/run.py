"""Runs the binding's tests (python3 -m unittest discover over this
directory) in one array mode:
  run.py --numpy      numpy arrays; exits 77 (CTest: skipped) without numpy
  run.py --no-numpy   the list/tuple fallback, forced by CYCLIDE_NO_NUMPY=1
Extra arguments go to unittest (e.g. -v, -k blend)."""

import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))


def main(argv):
    mode = "--numpy"
    if argv and argv[0] in ("--numpy", "--no-numpy"):
        mode, argv = argv[0], argv[1:]
    if mode == "--no-numpy":
        os.environ["CYCLIDE_NO_NUMPY"] = "1"
    else:
        os.environ.pop("CYCLIDE_NO_NUMPY", None)
        try:
            import numpy  # noqa: F401
        except ImportError:
            print("numpy is not installed (python3-numpy): skipped")
            return 77
    sys.path.insert(0, HERE)
    prog = unittest.main(module=None, argv=["run.py", "discover", "-s", HERE] + argv,
                         exit=False)
    r = prog.result
    return 0 if r.wasSuccessful() and r.testsRun > 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
