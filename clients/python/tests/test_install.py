"""pip installs the client (offline: no index, no build isolation)."""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from support import CLIENT_ROOT

BUILD_TOOLS = "import setuptools, wheel, pip"


def installer():
    """An interpreter that has pip, setuptools and wheel, or None."""
    for python in (sys.executable, shutil.which("python3"), "/usr/bin/python3"):
        if python and os.path.exists(python) and subprocess.run(
                [python, "-c", BUILD_TOOLS], capture_output=True).returncode == 0:
            return python
    return None


class InstallTest(unittest.TestCase):

    def test_pip_install_target(self):
        python = installer()
        if python is None:
            self.skipTest("no Python here has pip, setuptools and wheel")
        with tempfile.TemporaryDirectory() as tmp:
            source = os.path.join(tmp, "src")
            shutil.copytree(CLIENT_ROOT, source,
                            ignore=shutil.ignore_patterns("build", "*.egg-info",
                                                          "__pycache__"))
            os.makedirs(os.path.join(source, "otherpkg"))          # a second package
            with open(os.path.join(source, "otherpkg", "__init__.py"), "w") as f:
                f.write("NAME = 'other'\n")
            target = os.path.join(tmp, "site")
            env = dict(os.environ, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
            env.pop("PYTHONPATH", None)
            run = subprocess.run(
                [python, "-m", "pip", "install", "--no-index", "--no-build-isolation",
                 "--no-deps", "--target", target, source],
                capture_output=True, text=True, env=env, timeout=300)
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            check = subprocess.run(
                [python, "-c", "import pyoro, otherpkg; from pyoro import Oro, "
                 "OroServerError; print(pyoro.__file__, otherpkg.NAME)"],
                capture_output=True, text=True, env=dict(env, PYTHONPATH=target),
                cwd=tmp, timeout=60)
            self.assertEqual(check.returncode, 0, check.stderr)
            self.assertTrue(check.stdout.startswith(os.path.join(target, "pyoro")),
                            check.stdout)
            self.assertTrue(check.stdout.strip().endswith("other"))
            self.assertFalse(os.path.exists(os.path.join(target, "tests")))


if __name__ == "__main__":
    unittest.main()
