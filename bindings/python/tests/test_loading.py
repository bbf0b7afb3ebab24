"""Library loading: CYCLIDE_LIBRARY, CYCLIDE_LIB_DIR, pkg-config, and a
clear ImportError when the library is missing (each in a fresh python)."""

import os
import shutil
import subprocess
import sys
import unittest

from cyclide import _lib

PKG = os.path.dirname(os.path.dirname(os.path.abspath(_lib.__file__)))
PROBE = "import cyclide, cyclide._lib as L; print(L.lib_path); print(cyclide.__version__)"


def run(env_changes):
    env = {k: v for k, v in os.environ.items()
           if k not in ("CYCLIDE_LIBRARY", "CYCLIDE_LIB_DIR", "PKG_CONFIG_PATH")}
    env["PYTHONPATH"] = PKG
    env.update(env_changes)
    return subprocess.run([sys.executable, "-c", PROBE], env=env, capture_output=True,
                          text=True, timeout=60)


class Loading(unittest.TestCase):
    libdir = os.path.dirname(os.path.realpath(_lib.lib_path))

    def test_full_path(self):
        r = run({"CYCLIDE_LIBRARY": _lib.lib_path})
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.split()[0], _lib.lib_path)

    def test_lib_dir(self):
        r = run({"CYCLIDE_LIB_DIR": self.libdir})
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(r.stdout.split()[0].startswith(self.libdir))

    def test_missing_library_is_an_import_error(self):
        r = run({"CYCLIDE_LIBRARY": "/nonexistent/libcyclide.so"})
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("LibraryNotFound", r.stderr)
        self.assertIn("/nonexistent/libcyclide.so", r.stderr)

    @unittest.skipUnless(shutil.which("pkg-config"), "no pkg-config")
    def test_pkg_config(self):
        pc = os.path.join(self.libdir, "pkgconfig")
        if not os.path.exists(os.path.join(pc, "cyclide.pc")):
            self.skipTest("no cyclide.pc next to the library")
        r = run({"PKG_CONFIG_PATH": pc})
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(os.path.realpath(os.path.dirname(r.stdout.split()[0])), self.libdir)


if __name__ == "__main__":
    unittest.main()
